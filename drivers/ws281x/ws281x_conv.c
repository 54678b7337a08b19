// SPDX-License-Identifier: GPL-2.0-only
/*
 * ws281x_conv - turning a ws281x frame into the bit slots its PRU sends
 *
 * Slot j of a core carries, for every string of the core, bit 7 - j % 8 of
 * the string's wire byte j / 8 (a string's wire bytes: each LED's bytes in
 * its chip's order, after brightness and lookup table), as a bit of one of
 * the slot's five output words (ws281x_proto.h): R30, or a GPIO bank's.
 *
 * The strings of a core are taken in groups of up to 8 with the same output
 * word and the same wire bytes per LED.  For each wire byte of the frame
 * (8 slots) and each group, the members' bytes are looked up in
 * struct ws281x_tab, which gives each byte's 8 bits in 8 byte lanes, one
 * per slot, and are ORed together shifted by the member's place in the
 * group: a bit transpose, each lane now saying which members send a 1 in
 * its slot.  A lane then becomes the output word's bits through the
 * group's @spread table.  The slots are filled in order, 8 at a time, each
 * word written by its first group (the others OR into it) or set to 0 if
 * no string uses it: nothing needs clearing first.
 *
 * Compiled unchanged in the kernel module and in host programs (see
 * ws281x_conv.h): it needs nothing but <linux/types.h>.
 */
#include "ws281x_conv.h"

static unsigned int ws281x_word(const struct ws281x_string *st)
{
	return st->gpio ? 1 + st->bank : 0;
}

static bool ws281x_member(const struct ws281x_string *st, unsigned int core,
			  unsigned int word, unsigned int bpl)
{
	return st->core == core && ws281x_word(st) == word && st->bpl == bpl;
}

/* Longer strings first; of equal ones, the first in the frame first. */
static bool ws281x_before(const struct ws281x_string *strings, unsigned int a, unsigned int b)
{
	return strings[a].leds > strings[b].leds || (strings[a].leds == strings[b].leds && a < b);
}

/* The string after @prev (@nstrings: none yet) of a class, or @nstrings. */
static unsigned int ws281x_next(const struct ws281x_string *strings, unsigned int nstrings,
				unsigned int core, unsigned int word, unsigned int bpl,
				unsigned int prev)
{
	unsigned int s, best = nstrings;

	for (s = 0; s < nstrings; s++) {
		if (!ws281x_member(&strings[s], core, word, bpl))
			continue;
		if (prev < nstrings && !ws281x_before(strings, prev, s))
			continue;
		if (best == nstrings || ws281x_before(strings, s, best))
			best = s;
	}
	return best;
}

/**
 * ws281x_conv_size() - bytes of a core's struct ws281x_conv
 * @strings: the controller's strings, in frame order
 * @nstrings: how many
 * @core: the core
 *
 * Return: the size to allocate for ws281x_conv_init().
 */
size_t ws281x_conv_size(const struct ws281x_string *strings, unsigned int nstrings,
			unsigned int core)
{
	unsigned int n[WS281X_SLOT_WORDS][2] = { { 0 } };
	unsigned int s, w, groups = 0;

	for (s = 0; s < nstrings; s++)
		if (strings[s].core == core)
			n[ws281x_word(&strings[s])][strings[s].bpl - 3]++;
	for (w = 0; w < WS281X_SLOT_WORDS; w++)
		groups += (n[w][0] + WS281X_GROUP_STRINGS - 1) / WS281X_GROUP_STRINGS +
			  (n[w][1] + WS281X_GROUP_STRINGS - 1) / WS281X_GROUP_STRINGS;
	return sizeof(struct ws281x_conv) + groups * sizeof(struct ws281x_group);
}

static void ws281x_group_spread(struct ws281x_group *g, const u32 *bits)
{
	unsigned int j, m;

	g->spread[0] = 0;
	for (j = 0; j < WS281X_GROUP_STRINGS; j++) {
		u32 bit = j < g->n ? (u32)1 << bits[j] : 0;

		for (m = 1u << j; m < 2u << j; m++)
			g->spread[m] = g->spread[m - (1u << j)] | bit;
	}
}

/**
 * ws281x_conv_init() - plan a core's conversion
 * @conv: ws281x_conv_size() bytes
 * @strings: the controller's strings, in frame order (each with 3 or 4
 *	wire bytes per LED, at least one LED, and an output of its own)
 * @nstrings: how many
 * @core: the core, which drives at least one of them
 * @max_leds: LEDs of the longest string: each string's place in the frame
 * @bpl: bytes per LED in the frame, 3 or 4
 */
void ws281x_conv_init(struct ws281x_conv *conv, const struct ws281x_string *strings,
		      unsigned int nstrings, unsigned int core, unsigned int max_leds,
		      unsigned int bpl)
{
	struct ws281x_group *g = conv->groups;
	unsigned int w, wbpl;

	conv->slots = 0;
	conv->bpl = bpl;
	conv->nempty = 0;
	for (w = 0; w < WS281X_SLOT_WORDS; w++) {
		struct ws281x_group *first = g;

		for (wbpl = 3; wbpl <= 4; wbpl++) {
			unsigned int s = ws281x_next(strings, nstrings, core, w, wbpl, nstrings);

			while (s < nstrings) {
				u32 bits[WS281X_GROUP_STRINGS];
				unsigned int j, k;

				g->word = w;
				g->first = g == first;
				g->bpl = wbpl;
				for (j = 0; j < WS281X_GROUP_STRINGS; j++) {
					g->leds[j] = 0;
					bits[j] = 0;
					for (k = 0; k < 4; k++)
						g->off[k][j] = 0;
				}
				for (j = 0; j < WS281X_GROUP_STRINGS && s < nstrings; j++) {
					const struct ws281x_string *st = &strings[s];

					g->leds[j] = st->leds;
					bits[j] = st->bit;
					for (k = 0; k < wbpl; k++)
						g->off[k][j] = s * max_leds * bpl + st->order[k];
					if (st->leds * wbpl * 8 > conv->slots)
						conv->slots = st->leds * wbpl * 8;
					s = ws281x_next(strings, nstrings, core, w, wbpl, s);
				}
				g->n = j;
				ws281x_group_spread(g, bits);
				g++;
			}
		}
		if (g == first)
			conv->empty[conv->nempty++] = w;
	}
	conv->ngroups = g - conv->groups;
}

/**
 * ws281x_conv_tab() - what each value of a frame's byte becomes
 * @tab: the table to fill
 * @lut: the lookup table (256 values), applied after @brightness
 * @brightness: 0..255, scaling each value first (rounded to nearest)
 */
void ws281x_conv_tab(struct ws281x_tab *tab, const u8 *lut, unsigned int brightness)
{
	unsigned int v, t;

	for (v = 0; v < 256; v++) {
		u8 b = lut[(v * brightness + 127) / 255];

		tab->lanes[v][0] = 0;
		tab->lanes[v][1] = 0;
		for (t = 0; t < 8; t++)
			if (b & (0x80 >> t))
				tab->lanes[v][t / 4] |= (u32)1 << (8 * (t % 4));
	}
}

/* Member j's wire byte @v into the group's lanes: a transpose step. */
static inline void ws281x_add(u32 *lanes, const struct ws281x_tab *tab, u8 v, unsigned int j)
{
	lanes[0] |= tab->lanes[v][0] << j;
	lanes[1] |= tab->lanes[v][1] << j;
}

/**
 * ws281x_convert() - turn a frame into a core's bit slots
 * @conv: the core's plan, from ws281x_conv_init()
 * @tab: the values' wire bits, from ws281x_conv_tab()
 * @frame: the user's frame: each string's LEDs, @conv->bpl bytes each
 *	(R, G, B, W), at the string's place
 * @slots: @conv->slots slots, every word of which is written
 */
void ws281x_convert(const struct ws281x_conv *conv, const struct ws281x_tab *tab,
		    const u8 *frame, struct ws281x_slot *slots)
{
	/* the slots as words: slot i's word w is out[i * 5 + w] */
	u32 *out = (u32 *)slots;
	/* per wire bytes per LED (3, 4): the LED sent now, its place, its byte */
	unsigned int led[2] = { 0, 0 }, k[2] = { 0, 0 };
	const u8 *px[2] = { frame, frame };
	const struct ws281x_group *end = &conv->groups[conv->ngroups];
	unsigned int byte, e, p;

	for (byte = 0; byte < conv->slots / 8; byte++, out += 8 * WS281X_SLOT_WORDS) {
		const struct ws281x_group *g;

		for (g = conv->groups; g < end; g++) {
			unsigned int c = g->bpl - 3, i = led[c], n = g->n;
			const u32 *off = g->off[k[c]];
			const u32 *sp = g->spread;
			const u8 *pl = px[c];
			u32 *o = out + g->word;
			u32 lanes[2] = { 0, 0 };

			/* members are longest first: those still sending */
			while (n && g->leds[n - 1] <= i)
				n--;
			switch (n) {
			default:
				ws281x_add(lanes, tab, pl[off[7]], 7);
				fallthrough;
			case 7:
				ws281x_add(lanes, tab, pl[off[6]], 6);
				fallthrough;
			case 6:
				ws281x_add(lanes, tab, pl[off[5]], 5);
				fallthrough;
			case 5:
				ws281x_add(lanes, tab, pl[off[4]], 4);
				fallthrough;
			case 4:
				ws281x_add(lanes, tab, pl[off[3]], 3);
				fallthrough;
			case 3:
				ws281x_add(lanes, tab, pl[off[2]], 2);
				fallthrough;
			case 2:
				ws281x_add(lanes, tab, pl[off[1]], 1);
				fallthrough;
			case 1:
				ws281x_add(lanes, tab, pl[off[0]], 0);
				fallthrough;
			case 0:
				break;
			}
			/* the word's first group writes it, the others add to it */
			if (g->first) {
				o[0 * WS281X_SLOT_WORDS] = sp[lanes[0] & 0xff];
				o[1 * WS281X_SLOT_WORDS] = sp[(lanes[0] >> 8) & 0xff];
				o[2 * WS281X_SLOT_WORDS] = sp[(lanes[0] >> 16) & 0xff];
				o[3 * WS281X_SLOT_WORDS] = sp[lanes[0] >> 24];
				o[4 * WS281X_SLOT_WORDS] = sp[lanes[1] & 0xff];
				o[5 * WS281X_SLOT_WORDS] = sp[(lanes[1] >> 8) & 0xff];
				o[6 * WS281X_SLOT_WORDS] = sp[(lanes[1] >> 16) & 0xff];
				o[7 * WS281X_SLOT_WORDS] = sp[lanes[1] >> 24];
			} else {
				o[0 * WS281X_SLOT_WORDS] |= sp[lanes[0] & 0xff];
				o[1 * WS281X_SLOT_WORDS] |= sp[(lanes[0] >> 8) & 0xff];
				o[2 * WS281X_SLOT_WORDS] |= sp[(lanes[0] >> 16) & 0xff];
				o[3 * WS281X_SLOT_WORDS] |= sp[lanes[0] >> 24];
				o[4 * WS281X_SLOT_WORDS] |= sp[lanes[1] & 0xff];
				o[5 * WS281X_SLOT_WORDS] |= sp[(lanes[1] >> 8) & 0xff];
				o[6 * WS281X_SLOT_WORDS] |= sp[(lanes[1] >> 16) & 0xff];
				o[7 * WS281X_SLOT_WORDS] |= sp[lanes[1] >> 24];
			}
		}
		/* the words no string uses */
		for (e = 0; e < conv->nempty; e++) {
			u32 *o = out + conv->empty[e];

			for (p = 0; p < 8; p++)
				o[p * WS281X_SLOT_WORDS] = 0;
		}
		for (p = 0; p < 2; p++)
			if (++k[p] == p + 3) {
				k[p] = 0;
				led[p]++;
				px[p] += conv->bpl;
			}
	}
}
