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
 *   conv_test bench N
 *	N conversions of a whole 64x32 XRGB8888 frame, 8 planes, CIE 1931
 *	(callgrind counts hub75_convert()'s instructions)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../hub75_conv.h"

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

	if (!table || !hub75_mux_table(mux, w, h, chain, table)) {
		free(table);
		return NULL;
	}
	return table;
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
