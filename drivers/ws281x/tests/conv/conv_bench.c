// SPDX-License-Identifier: GPL-2.0-only
/*
 * conv_bench - the ARM's work per frame, measured on the host: converts one
 * 48-string x 600-LED frame (two cores, each with 8 strings on R30 bits and
 * 16 on GPIO pins, 4 per bank; WS2812B, GRB on the wire) with
 * drivers/ws281x/ws281x_conv.c compiled unchanged, for bench.sh to count
 * the instructions of ws281x_convert() under callgrind (--toggle-collect).
 *
 * usage: conv_bench new|legacy
 *   new:    ws281x_convert() for both cores
 *   legacy: the conversion the driver had before (legacy.c)
 * Both check their slots against the other's and print a checksum.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "legacy.h"

#define CORES		2
#define PER_CORE	24
#define R30_STRINGS	8
#define LEDS		600

int main(int argc, char **argv)
{
	static struct ws281x_string st[CORES * PER_CORE];
	static struct ws281x_tab tab;
	unsigned int n = CORES * PER_CORE, c, s, v;
	struct ws281x_layout lay;
	u8 lut[256], tab8[256];
	u64 seed = 600, sum = 0;
	int legacy;
	u8 *frame;
	size_t i;

	if (argc != 2 || (strcmp(argv[1], "new") && strcmp(argv[1], "legacy"))) {
		fprintf(stderr, "usage: conv_bench new|legacy\n");
		return 2;
	}
	legacy = !strcmp(argv[1], "legacy");
	for (c = 0; c < CORES; c++)
		for (s = 0; s < PER_CORE; s++) {
			struct ws281x_string *t = &st[c * PER_CORE + s];

			t->core = c;
			t->gpio = s >= R30_STRINGS;
			t->bank = t->gpio ? s % WS281X_GPIO_BANKS : 0;
			t->bit = t->gpio ? 16 * c + s - R30_STRINGS : s;
			t->leds = LEDS;
			t->bpl = 3;
			t->order[0] = 1;	/* G, R, B */
			t->order[1] = 0;
			t->order[2] = 2;
		}
	frame = malloc((size_t)n * LEDS * 3);
	if (!frame)
		return 2;
	for (i = 0; i < (size_t)n * LEDS * 3; i++) {
		seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
		frame[i] = seed >> 56;
	}
	for (v = 0; v < 256; v++)
		lut[v] = v;
	lay = (struct ws281x_layout){ .strings = st, .nstrings = n, .max_leds = LEDS, .bpl = 3,
				      .frame = frame };
	ws281x_conv_tab(&tab, lut, 255);
	ws281x_ref_tab(tab8, lut, 255);
	for (c = 0; c < CORES; c++) {
		struct ws281x_conv *conv = malloc(ws281x_conv_size(st, n, c));
		unsigned int nslots = ws281x_ref_slots(&lay, c);
		size_t bytes = (size_t)nslots * sizeof(struct ws281x_slot);
		struct ws281x_slot *a = malloc(bytes), *b = malloc(bytes);
		const u32 *w;

		if (!conv || !a || !b)
			return 2;
		ws281x_conv_init(conv, st, n, c, LEDS, 3);
		if (legacy) {
			ws281x_legacy_convert(&lay, c, tab8, a, nslots);
			ws281x_convert(conv, &tab, frame, b);	/* not counted: the check */
		} else {
			ws281x_convert(conv, &tab, frame, a);
			ws281x_legacy_convert(&lay, c, tab8, b, nslots);
		}
		if (memcmp(a, b, bytes)) {
			fprintf(stderr, "conv_bench: pru%u: the two conversions differ\n", c);
			return 1;
		}
		for (w = (const u32 *)a; w < (const u32 *)(a + nslots); w++)
			sum = sum * 31 + *w;
		printf("conv_bench: pru%u: %u strings, %u slots, %u groups\n", c, PER_CORE, nslots,
		       conv->ngroups);
		free(b);
		free(a);
		free(conv);
	}
	printf("conv_bench: %s conversion, %u LEDs, checksum %016llx\n", argv[1], n * LEDS,
	       (unsigned long long)sum);
	free(frame);
	return 0;
}
