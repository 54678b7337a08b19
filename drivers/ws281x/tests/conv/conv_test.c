// SPDX-License-Identifier: GPL-2.0-only
/*
 * conv_test - drivers/ws281x/ws281x_conv.c, compiled unchanged on the host,
 * against a reference that works out each bit of each slot on its own
 * (legacy.c), on fixed and random controllers: one or two cores, 1..24
 * strings each (and 48 on one core), on R30 bits and GPIO bank bits, RGB
 * and RGBW chips in every wire order, different lengths, random frames,
 * brightness and lookup tables.  Every slot word is compared, the slot
 * buffer starts as garbage (the conversion writes all of it) and is
 * followed by a guard slot it must not touch.  The conversion the driver
 * had before (legacy.c) is held against the same reference.
 *
 * usage: conv_test [CASES [SEED]]    (default 400 random cases, seed 281)
 * Prints a PASS:/FAIL: line per case; exits 1 if any failed.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "legacy.h"

#define MAX_STRINGS	48

static u64 rng_state;

static u32 rnd(u32 n)
{
	rng_state ^= rng_state << 13;
	rng_state ^= rng_state >> 7;
	rng_state ^= rng_state << 17;
	return n ? (u32)((rng_state >> 16) % n) : 0;
}

struct tcase {
	struct ws281x_string st[MAX_STRINGS];
	unsigned int n;
	unsigned int ncores;
	unsigned int max_leds;
	unsigned int bpl;
	unsigned int brightness;
	const char *lut_kind;
	u8 lut[256];
	u8 *frame;
	size_t frame_size;
};

static int failed, passed;

static void *xmalloc(size_t n)
{
	void *p = malloc(n ? n : 1);

	if (!p) {
		fprintf(stderr, "conv_test: out of memory\n");
		exit(2);
	}
	return p;
}

/* A wire order: a random permutation of R, G, B (and W). */
static void random_order(struct ws281x_string *st)
{
	unsigned int k;

	for (k = 0; k < st->bpl; k++)
		st->order[k] = k;
	for (k = st->bpl - 1; k > 0; k--) {
		unsigned int j = rnd(k + 1);
		u8 t = st->order[k];

		st->order[k] = st->order[j];
		st->order[j] = t;
	}
}

/* Outputs are unique per core for R30, per controller for GPIO pins. */
static void place(struct tcase *tc, struct ws281x_string *st, unsigned int core, int r30)
{
	unsigned int s;

	for (;;) {
		int taken = 0;

		st->core = core;
		st->gpio = !r30;
		st->bank = r30 ? 0 : rnd(WS281X_GPIO_BANKS);
		st->bit = rnd(32);
		for (s = 0; s < tc->n; s++) {
			const struct ws281x_string *o = &tc->st[s];

			if (o->gpio == st->gpio && o->bit == st->bit &&
			    (st->gpio ? o->bank == st->bank : o->core == core))
				taken = 1;
		}
		if (!taken)
			return;
	}
}

static void finish(struct tcase *tc, unsigned int max_len, int fill)
{
	unsigned int s, v;
	size_t i;

	tc->max_leds = 0;
	tc->bpl = 3;
	for (s = 0; s < tc->n; s++) {
		if (tc->st[s].leds > tc->max_leds)
			tc->max_leds = tc->st[s].leds;
		if (tc->st[s].bpl > tc->bpl)
			tc->bpl = tc->st[s].bpl;
	}
	(void)max_len;
	tc->frame_size = (size_t)tc->n * tc->max_leds * tc->bpl;
	tc->frame = xmalloc(tc->frame_size);
	for (i = 0; i < tc->frame_size; i++)
		tc->frame[i] = fill >= 0 ? (u32)fill : rnd(4) ? rnd(256) : rnd(2) * 255;
	switch (rnd(3)) {
	case 0:
		tc->lut_kind = "identity lut";
		for (v = 0; v < 256; v++)
			tc->lut[v] = v;
		break;
	case 1:
		tc->lut_kind = "random lut";
		for (v = 0; v < 256; v++)
			tc->lut[v] = rnd(256);
		break;
	default:
		tc->lut_kind = "gamma lut";
		for (v = 0; v < 256; v++)
			tc->lut[v] = (v * v * v + 255 * 255 * 127) / (255 * 255);
	}
	switch (rnd(4)) {
	case 0:
		tc->brightness = 255;
		break;
	case 1:
		tc->brightness = rnd(3) ? 1 + rnd(254) : 0;
		break;
	default:
		tc->brightness = rnd(256);
	}
}

/* A string's length: mostly short (fast), sometimes long. */
static unsigned int random_leds(void)
{
	return rnd(8) ? 1 + rnd(12) : 1 + rnd(300);
}

static void random_case(struct tcase *tc)
{
	unsigned int per[2], c, s;

	memset(tc, 0, sizeof(*tc));
	tc->ncores = 1 + rnd(2);
	for (c = 0; c < tc->ncores; c++)
		per[c] = rnd(4) ? 1 + rnd(24) : 24;
	for (c = 0; c < tc->ncores; c++)
		for (s = 0; s < per[c]; s++) {
			struct ws281x_string *st = &tc->st[tc->n];

			place(tc, st, c, rnd(2));
			st->leds = random_leds();
			st->bpl = rnd(4) ? 3 : 4;
			random_order(st);
			tc->n++;
		}
	/* frame order: the cores' strings interleaved at random */
	for (s = tc->n - 1; s > 0; s--) {
		unsigned int j = rnd(s + 1);
		struct ws281x_string t = tc->st[s];

		tc->st[s] = tc->st[j];
		tc->st[j] = t;
	}
	/* sometimes every string as long as the others */
	if (!rnd(4))
		for (s = 1; s < tc->n; s++)
			tc->st[s].leds = tc->st[0].leds;
	finish(tc, 0, -1);
}

/* The benchmark's controller: 2 cores x (8 R30 + 16 GPIO) x 600 RGB LEDs. */
static void bench_case(struct tcase *tc, unsigned int cores, unsigned int per_core, int fill)
{
	unsigned int c, s;

	memset(tc, 0, sizeof(*tc));
	tc->ncores = cores;
	for (c = 0; c < cores; c++)
		for (s = 0; s < per_core; s++) {
			struct ws281x_string *st = &tc->st[tc->n++];

			st->core = c;
			st->gpio = s >= per_core / 3;
			st->bank = st->gpio ? s % WS281X_GPIO_BANKS : 0;
			st->bit = st->gpio ? 16 * c + (s - per_core / 3) % 16 : s;
			st->leds = 600;
			st->bpl = 3;
			st->order[0] = 1;
			st->order[1] = 0;
			st->order[2] = 2;
		}
	finish(tc, 0, fill);
}

static int run_case(unsigned int no, struct tcase *tc, const char *what)
{
	unsigned int c, s, r30[2] = { 0 }, gpio[2] = { 0 }, rgbw = 0;
	struct ws281x_layout lay = {
		.strings = tc->st, .nstrings = tc->n, .max_leds = tc->max_leds,
		.bpl = tc->bpl, .frame = tc->frame,
	};
	struct ws281x_tab *tab = xmalloc(sizeof(*tab));
	char detail[200] = "";
	u8 tab8[256];
	int ok = 1;

	ws281x_conv_tab(tab, tc->lut, tc->brightness);
	ws281x_ref_tab(tab8, tc->lut, tc->brightness);
	for (s = 0; s < tc->n; s++) {
		if (tc->st[s].gpio)
			gpio[tc->st[s].core]++;
		else
			r30[tc->st[s].core]++;
		rgbw += tc->st[s].bpl == 4;
	}
	for (c = 0; c < tc->ncores && ok; c++) {
		unsigned int nslots = ws281x_ref_slots(&lay, c), i;
		size_t bytes = (size_t)(nslots + 1) * sizeof(struct ws281x_slot);
		struct ws281x_slot *want = xmalloc(bytes), *got = xmalloc(bytes);
		struct ws281x_slot *old = xmalloc(bytes);
		struct ws281x_conv *conv = xmalloc(ws281x_conv_size(tc->st, tc->n, c));

		ws281x_conv_init(conv, tc->st, tc->n, c, tc->max_leds, tc->bpl);
		memset(got, 0xa5, bytes);
		memset(old, 0x5a, bytes);
		ws281x_ref_convert(&lay, c, tab8, want, nslots);
		ws281x_convert(conv, tab, tc->frame, got);
		ws281x_legacy_convert(&lay, c, tab8, old, nslots);
		if (conv->slots != nslots) {
			snprintf(detail, sizeof(detail), "pru%u: %u slots, want %u", c,
				 conv->slots, nslots);
			ok = 0;
		}
		for (i = 0; i < nslots && ok; i++) {
			if (memcmp(&got[i], &want[i], sizeof(got[i]))) {
				const struct ws281x_slot *a = &got[i], *b = &want[i];

				snprintf(detail, sizeof(detail),
					 "pru%u slot %u: %x %x %x %x %x, want %x %x %x %x %x",
					 c, i, a->r30, a->gpio[0], a->gpio[1], a->gpio[2],
					 a->gpio[3], b->r30, b->gpio[0], b->gpio[1], b->gpio[2],
					 b->gpio[3]);
				ok = 0;
			} else if (memcmp(&old[i], &want[i], sizeof(old[i]))) {
				snprintf(detail, sizeof(detail), "pru%u slot %u: old one differs",
					 c, i);
				ok = 0;
			}
		}
		if (ok && (got[nslots].r30 != 0xa5a5a5a5 || got[nslots].gpio[3] != 0xa5a5a5a5)) {
			snprintf(detail, sizeof(detail), "pru%u: wrote past its %u slots",
				 c, nslots);
			ok = 0;
		}
		free(conv);
		free(old);
		free(got);
		free(want);
	}
	printf("%s: conv %u: %s%u core(s), %u strings ", ok ? "PASS" : "FAIL", no, what,
	       tc->ncores, tc->n);
	printf("(R30/GPIO pru0 %u/%u pru1 %u/%u, %u RGBW), %u LEDs max, ",
	       r30[0], gpio[0], r30[1], gpio[1], rgbw, tc->max_leds);
	printf("brightness %u, %s: ", tc->brightness, tc->lut_kind);
	printf("ws281x_convert() and the old conversion == reference%s%s\n",
	       ok ? "" : ": ", detail);
	free(tab);
	free(tc->frame);
	if (ok)
		passed++;
	else
		failed++;
	return ok;
}

int main(int argc, char **argv)
{
	struct tcase *tc = xmalloc(sizeof(*tc));
	unsigned int cases = 400, i, no = 0;

	rng_state = 281;
	if (argc > 1)
		cases = strtoul(argv[1], NULL, 0);
	if (argc > 2)
		rng_state = strtoull(argv[2], NULL, 0);
	if (!rng_state)
		rng_state = 1;
	bench_case(tc, 2, 24, -1);
	run_case(no++, tc, "the benchmark's 48 x 600, ");
	bench_case(tc, 1, 48, -1);
	run_case(no++, tc, "48 strings on one core, ");
	bench_case(tc, 1, 1, 0xff);
	tc->brightness = 255;
	tc->lut_kind = "identity lut";
	for (i = 0; i < 256; i++)
		tc->lut[i] = i;
	run_case(no++, tc, "all ones, ");
	bench_case(tc, 2, 3, -1);
	tc->brightness = 0;
	run_case(no++, tc, "brightness 0, ");
	for (i = 0; i < cases; i++) {
		random_case(tc);
		run_case(no++, tc, "");
	}
	printf("info: conv_test: %d cases passed, %d failed\n", passed, failed);
	free(tc);
	return failed ? 1 : 0;
}
