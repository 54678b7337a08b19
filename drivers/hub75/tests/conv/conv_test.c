// SPDX-License-Identifier: GPL-2.0-only
/*
 * conv_test - drivers/hub75/hub75_conv.c on the host, for conv_check.py
 * (which compares its output with hub75_model.py) and for make bench.
 *
 *   conv_test lut PLANES cie1931|linear
 *	the 256 levels, one per line
 *   conv_test frame PLANES CORR WIDTH HEIGHT ROWS ENTRY_BYTES B0..B5 FMT A [X1 Y1 X2 Y2 B]
 *	the frame buffer of image file A (FMT xrgb8888 or rgb565, WIDTH x
 *	HEIGHT, tightly packed), data line bits B0..B5; with a rectangle and
 *	image B: then B converted over the rectangle only (B equals A
 *	outside it).  Written to stdout.  A last argument mux=NAME:PANEL_WIDTH
 *	drives each PANEL_WIDTH x HEIGHT panel of the chain as an outdoor
 *	panel NAME (hub75_mux_names) with ROWS address rows.
 *   conv_test mux NAME PANEL_WIDTH PANEL_HEIGHT CHAIN
 *	hub75_mux_table(): "bad" or per position as driven, the "x y" of
 *	the pixel it lights, one per line
 *   conv_test banks PLANES CORR PANEL_W PANEL_H CHAIN OUTPUTS MUX LINES A [SERP ROT]
 *	HUB75_DATA_BANKS: the frame buffer of image A (XRGB8888, PANEL_W *
 *	CHAIN x PANEL_H * OUTPUTS, or turned by ROT), LINES "slot:bit,..." for
 *	the six lines of each output in turn, SERP 1 for a serpentine; written
 *	to stdout
 *   conv_test bench-banks N
 *	N conversions of the Octoscroller's wall, 8 outputs of 3 64x32
 *	panels (192x256), 12 planes, CIE 1931
 *   conv_test bench N
 *	N conversions of a whole 64x32 XRGB8888 frame, 8 planes, CIE 1931
 *	(callgrind counts hub75_convert()'s instructions)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../hub75_conv.h"

#ifndef ARRAY_SIZE
#define ARRAY_SIZE(a)	(sizeof(a) / sizeof((a)[0]))
#endif

static void *slurp(const char *path, size_t want)
{
	FILE *f = fopen(path, "rb");
	void *buf = malloc(want);

	if (!f || !buf || fread(buf, 1, want, f) != want) {
		fprintf(stderr, "conv_test: cannot read %zu bytes of %s\n", want, path);
		exit(2);
	}
	fclose(f);
	return buf;
}

static enum hub75_correction corr(const char *s)
{
	if (!strcmp(s, "linear"))
		return HUB75_LINEAR;
	if (!strcmp(s, "cie1931"))
		return HUB75_CIE1931;
	fprintf(stderr, "conv_test: correction %s\n", s);
	exit(2);
}

static enum hub75_mux mux_of(const char *name)
{
	unsigned int i;

	for (i = 0; i < HUB75_MUX_COUNT; i++)
		if (!strcmp(hub75_mux_names[i], name))
			return i;
	fprintf(stderr, "conv_test: multiplexing %s\n", name);
	exit(2);
}

static u32 *mux_table(enum hub75_mux mux, unsigned int w, unsigned int h, unsigned int chain)
{
	u32 *table = malloc(sizeof(*table) * w * h * chain);

	if (!table || !hub75_mux_table(mux, w, h, chain, 1, table)) {
		free(table);
		return NULL;
	}
	return table;
}

/* A HUB75_DATA_BANKS layout; false if the wiring does not fit */
static bool banks_layout(struct hub75_layout *l, unsigned int planes,
			 enum hub75_correction c, unsigned int pw, unsigned int ph,
			 unsigned int chain, unsigned int outputs, enum hub75_mux mux,
			 const char *lines, bool serp, unsigned int rot)
{
	unsigned int o, k, s = hub75_mux_stretch(mux);
	u32 *table = malloc(sizeof(*table) * pw * chain * ph * outputs);

	if (!table || !hub75_mux_table(mux, pw, ph, chain, outputs, table)) {
		free(table);
		return false;
	}
	hub75_arrange(table, (size_t)pw * chain * ph * outputs, pw * chain, ph * outputs, ph,
		      serp, rot);
	*l = (struct hub75_layout){ .width = pw * chain, .height = ph * outputs,
		.clocks = pw * chain * s, .rows = ph / s / 2, .planes = planes,
		.entry_bytes = 16, .outputs = outputs, .mux = table };
	l->row_bytes = l->clocks * 16;
	if (rot == 90 || rot == 270) {
		l->width = ph * outputs;
		l->height = pw * chain;
	}
	for (o = 0; o < outputs; o++) {
		for (k = 0; k < HUB75_LINES; k++) {
			unsigned int slot, bit;
			int n;

			if (sscanf(lines, "%u:%u%n", &slot, &bit, &n) != 2 || slot > 3 ||
			    bit > 31) {
				fprintf(stderr, "conv_test: bad lines at %s\n", lines);
				exit(2);
			}
			l->bank_slot[o][k] = slot;
			l->bank_bit[o][k] = bit;
			lines += n + (lines[n] == ',');
		}
	}
	hub75_layout_lut(l, c);
	hub75_layout_finish(l);
	return true;
}

int main(int argc, char **argv)
{
	static struct hub75_layout l;
	u32 *table = NULL;
	struct hub75_rect all, rect;
	enum hub75_format fmt;
	unsigned int i, bpp;
	size_t size;
	void *a, *b;
	u8 *buf;

	if (argc == 4 && !strcmp(argv[1], "lut")) {
		l.planes = atoi(argv[2]);
		hub75_layout_lut(&l, corr(argv[3]));
		for (i = 0; i < 256; i++)
			printf("%u\n", l.lut[i]);
		return 0;
	}
	if (argc == 3 && !strcmp(argv[1], "bench")) {
		unsigned int n = atoi(argv[2]);
		static u32 img[64 * 32];
		u8 line_bits[HUB75_LINES] = { 0, 1, 2, 3, 4, 5 };

		l = (struct hub75_layout){ .width = 64, .height = 32, .clocks = 64, .rows = 16,
					   .planes = 8, .entry_bytes = 1, .row_bytes = 64 };
		memcpy(l.line_bit, line_bits, sizeof(line_bits));
		hub75_layout_lut(&l, HUB75_CIE1931);
		hub75_layout_finish(&l);
		for (i = 0; i < 64 * 32; i++)
			img[i] = i * 2654435761u;
		buf = calloc(1, hub75_buffer_size(&l));
		all = (struct hub75_rect){ 0, 0, 64, 32 };
		for (i = 0; i < n; i++)
			hub75_convert(&l, buf, img, 64 * 4, HUB75_XRGB8888, &all);
		printf("%u\n", buf[i % hub75_buffer_size(&l)]);
		free(buf);
		return 0;
	}
	if ((argc == 11 || argc == 13) && !strcmp(argv[1], "banks")) {
		unsigned int pw = atoi(argv[4]), ph = atoi(argv[5]), chain = atoi(argv[6]);
		unsigned int outputs = atoi(argv[7]);

		if (outputs < 1 || outputs > HUB75_MAX_OUTPUTS ||
		    !banks_layout(&l, atoi(argv[2]), corr(argv[3]), pw, ph, chain, outputs,
				  mux_of(argv[8]), argv[9], argc == 13 && atoi(argv[11]),
				  argc == 13 ? atoi(argv[12]) : 0)) {
			fprintf(stderr, "conv_test: the layout does not fit\n");
			return 2;
		}
		a = slurp(argv[10], (size_t)l.width * l.height * 4);
		buf = calloc(1, hub75_buffer_size(&l));
		all = (struct hub75_rect){ 0, 0, l.width, l.height };
		hub75_convert(&l, buf, a, l.width * 4, HUB75_XRGB8888, &all);
		fwrite(buf, 1, hub75_buffer_size(&l), stdout);
		free(buf);
		free(a);
		free((void *)l.mux);
		return 0;
	}
	if (argc == 3 && !strcmp(argv[1], "bench-banks")) {
		/* the Octoscroller's lines: slots 0..3 are GPIO banks 0, 2, 3 and 1 */
		static const u8 octo[HUB75_MAX_OUTPUTS * HUB75_LINES][2] = {
			{ 1, 2 }, { 1, 3 }, { 1, 5 }, { 0, 23 }, { 1, 4 }, { 0, 26 },
			{ 0, 27 }, { 1, 1 }, { 0, 22 }, { 1, 22 }, { 1, 23 }, { 1, 24 },
			{ 0, 30 }, { 3, 18 }, { 0, 31 }, { 3, 16 }, { 0, 3 }, { 0, 5 },
			{ 0, 2 }, { 0, 15 }, { 3, 17 }, { 2, 21 }, { 2, 19 }, { 0, 4 },
			{ 1, 25 }, { 0, 11 }, { 0, 10 }, { 0, 9 }, { 0, 8 }, { 1, 17 },
			{ 1, 16 }, { 1, 15 }, { 1, 14 }, { 1, 13 }, { 1, 10 }, { 1, 12 },
			{ 1, 11 }, { 1, 9 }, { 1, 8 }, { 1, 6 }, { 0, 7 }, { 1, 7 },
			{ 2, 17 }, { 2, 16 }, { 2, 15 }, { 2, 14 }, { 0, 14 }, { 0, 20 },
		};
		char lines[sizeof(octo) / 2 * 6], *at = lines;

		for (i = 0; i < ARRAY_SIZE(octo); i++)
			at += sprintf(at, "%s%u:%u", i ? "," : "", octo[i][0], octo[i][1]);
		unsigned int n = atoi(argv[2]);
		u32 *img;

		banks_layout(&l, 12, HUB75_CIE1931, 64, 32, 3, 8, HUB75_MUX_DIRECT, lines, false,
			     0);
		img = malloc((size_t)l.width * l.height * 4);
		for (i = 0; i < l.width * l.height; i++)
			img[i] = i * 2654435761u;
		buf = calloc(1, hub75_buffer_size(&l));
		all = (struct hub75_rect){ 0, 0, l.width, l.height };
		for (i = 0; i < n; i++)
			hub75_convert(&l, buf, img, l.width * 4, HUB75_XRGB8888, &all);
		printf("%u\n", buf[i % hub75_buffer_size(&l)]);
		free(buf);
		free(img);
		free((void *)l.mux);
		return 0;
	}
	if (argc == 6 && !strcmp(argv[1], "mux")) {
		unsigned int w = atoi(argv[3]), h = atoi(argv[4]), chain = atoi(argv[5]);

		table = mux_table(mux_of(argv[2]), w, h, chain);
		if (!table) {
			printf("bad\n");
			return 0;
		}
		for (i = 0; i < w * h * chain; i++)
			printf("%u %u\n", table[i] & 0xffff, table[i] >> 16);
		free(table);
		return 0;
	}
	if (argc > 16 && !strncmp(argv[argc - 1], "mux=", 4)) {
		char *name = strdup(argv[argc - 1] + 4), *colon = strchr(name, ':');
		enum hub75_mux mux;

		if (!colon) {
			fprintf(stderr, "conv_test: mux=NAME:PANEL_WIDTH\n");
			return 2;
		}
		*colon = 0;
		mux = mux_of(name);
		argc--;
		l.clocks = atoi(argv[4]) * hub75_mux_stretch(mux);
		table = mux_table(mux, atoi(colon + 1), atoi(argv[5]),
				  atoi(argv[4]) / atoi(colon + 1));
		free(name);
		if (!table) {
			fprintf(stderr, "conv_test: the wiring does not fit\n");
			return 2;
		}
		l.mux = table;
	}
	if ((argc != 16 && argc != 21) || strcmp(argv[1], "frame")) {
		fprintf(stderr, "usage: see conv_test.c\n");
		return 2;
	}
	l.planes = atoi(argv[2]);
	l.width = atoi(argv[4]);
	l.height = atoi(argv[5]);
	l.rows = atoi(argv[6]);
	l.entry_bytes = atoi(argv[7]);
	for (i = 0; i < HUB75_LINES; i++)
		l.line_bit[i] = atoi(argv[8 + i]);
	if (!l.clocks)
		l.clocks = l.width;
	l.row_bytes = l.clocks * l.entry_bytes;
	hub75_layout_lut(&l, corr(argv[3]));
	hub75_layout_finish(&l);
	fmt = strcmp(argv[14], "rgb565") ? HUB75_XRGB8888 : HUB75_RGB565;
	bpp = fmt == HUB75_RGB565 ? 2 : 4;
	size = (size_t)l.width * l.height * bpp;
	a = slurp(argv[15], size);
	buf = calloc(1, hub75_buffer_size(&l));
	all = (struct hub75_rect){ 0, 0, l.width, l.height };
	hub75_convert(&l, buf, a, l.width * bpp, fmt, &all);
	if (argc == 21) {
		rect = (struct hub75_rect){ atoi(argv[16]), atoi(argv[17]), atoi(argv[18]),
					    atoi(argv[19]) };
		b = slurp(argv[20], size);
		hub75_convert(&l, buf, b, l.width * bpp, fmt, &rect);
		free(b);
	}
	fwrite(buf, 1, hub75_buffer_size(&l), stdout);
	free(buf);
	free(a);
	free(table);
	return 0;
}
