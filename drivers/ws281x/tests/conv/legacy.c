// SPDX-License-Identifier: GPL-2.0-only
/*
 * Two conversions to hold drivers/ws281x/ws281x_conv.c against, on the
 * host: a reference that works out every bit of every slot on its own,
 * from the definition in ws281x_proto.h, and the driver's conversion before
 * ws281x_conv.c (a read-modify-write per set bit, after a memset), kept
 * as it was for the benchmark's "before" figure.
 */
#include <string.h>

#include "legacy.h"

/* The core's slots: its longest string's bits. */
unsigned int ws281x_ref_slots(const struct ws281x_layout *lay, unsigned int core)
{
	unsigned int s, n = 0;

	for (s = 0; s < lay->nstrings; s++) {
		const struct ws281x_string *st = &lay->strings[s];

		if (st->core == core && st->leds * st->bpl * 8 > n)
			n = st->leds * st->bpl * 8;
	}
	return n;
}

/* The driver's table: the value scaled by brightness, then the lut. */
void ws281x_ref_tab(u8 *tab, const u8 *lut, unsigned int brightness)
{
	unsigned int v;

	for (v = 0; v < 256; v++)
		tab[v] = lut[(v * brightness + 127) / 255];
}

static u32 *ref_word(struct ws281x_slot *slot, const struct ws281x_string *st)
{
	return st->gpio ? &slot->gpio[st->bank] : &slot->r30;
}

/*
 * Slot i of string s: bit 7 - i % 8 of its wire byte i / 8, which is byte
 * order[k] of its LED led, where led, k = divmod(i / 8, bytes per LED);
 * 0 past the string's end.
 */
void ws281x_ref_convert(const struct ws281x_layout *lay, unsigned int core, const u8 *tab,
			struct ws281x_slot *slots, unsigned int nslots)
{
	unsigned int i, s;

	for (i = 0; i < nslots; i++) {
		struct ws281x_slot *slot = &slots[i];
		unsigned int b;

		slot->r30 = 0;
		for (b = 0; b < WS281X_GPIO_BANKS; b++)
			slot->gpio[b] = 0;
		for (s = 0; s < lay->nstrings; s++) {
			const struct ws281x_string *st = &lay->strings[s];
			unsigned int byte = i / 8, led = byte / st->bpl, k = byte % st->bpl;
			u8 v;

			if (st->core != core || led >= st->leds)
				continue;
			v = lay->frame[((size_t)s * lay->max_leds + led) * lay->bpl + st->order[k]];
			v = tab[v];
			if ((v >> (7 - i % 8)) & 1)
				*ref_word(slot, st) |= (u32)1 << st->bit;
		}
	}
}

/*
 * The kernel's find_next_bit() on one word of a constant size, as the
 * generic 6.1 code inlines it (small_const_nbits): cheaper than on 32-bit
 * ARM, whose 6.1 headers call _find_next_bit_le() for each set bit.
 */
static unsigned int next_set_bit(unsigned long v, unsigned int size, unsigned int from)
{
	v &= ~0UL >> (8 * sizeof(long) - size);
	v &= ~0UL << from;
	return v ? (unsigned int)__builtin_ctzl(v) : size;
}

/* The driver's ws281x_convert() before ws281x_conv.c, unchanged but for its arguments. */
void ws281x_legacy_convert(const struct ws281x_layout *lay, unsigned int c, const u8 *tab,
			   struct ws281x_slot *slots, unsigned int nslots)
{
	unsigned int s;

	memset(slots, 0, (size_t)nslots * sizeof(*slots));
	for (s = 0; s < lay->nstrings; s++) {
		const struct ws281x_string *st = &lay->strings[s];
		const u8 *px = lay->frame + (size_t)s * lay->max_leds * lay->bpl;
		u32 *word;
		unsigned int i, k;
		u32 bit;

		if (st->core != c)
			continue;
		bit = (u32)1 << st->bit;
		for (i = 0; i < st->leds; i++, px += lay->bpl) {
			struct ws281x_slot *slot = slots + (size_t)i * st->bpl * 8;

			for (k = 0; k < st->bpl; k++, slot += 8) {
				unsigned long v = tab[px[st->order[k]]];
				unsigned int b;

				/* for_each_set_bit(b, &v, 8) */
				for (b = next_set_bit(v, 8, 0); b < 8;
				     b = next_set_bit(v, 8, b + 1)) {
					struct ws281x_slot *t = &slot[7 - b];

					word = st->gpio ? &t->gpio[st->bank] : &t->r30;
					*word |= bit;
				}
			}
		}
	}
}
