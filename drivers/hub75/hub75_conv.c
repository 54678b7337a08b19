// SPDX-License-Identifier: GPL-2.0-only
/*
 * hub75_conv.c - framebuffer pixels to the hub75 firmware's blocks.
 *
 * A frame buffer (hub75_proto.h) is @planes * @rows blocks in the order
 * they are shown: block k * rows + r holds address row r of plane
 * order[k].  Entry x of a block is what the data lines carry at the row's
 * x-th clock: R1 G1 B1 from display row r (the top half), R2 G2 B2 from row
 * r + rows (the bottom half), each line's bit of the pixel's level in that
 * plane.  The x-th pixel clocked ends up in column x of the chain.
 *
 * Compiled unchanged in the kernel and on the host (hub75_conv.h).
 */
#include <linux/types.h>

#include "hub75_conv.h"

/*
 * Once @planes, @entry_bytes and @lut are set: the plane order - the
 * longest plane, the shortest, the second longest, the second shortest ...:
 * each row's lit time is then spread over the refresh instead of coming in
 * one piece (Documentation/hub75.rst) - and @spread, which hub75_convert()
 * ORs together, a word per lanes planes, into the entries of six lines
 * (1- and 2-byte entries only).
 */
void hub75_layout_finish(struct hub75_layout *l)
{
	unsigned int k, lo = 0, hi = l->planes, v, p;

	for (k = 0; k < l->planes; k++)
		l->order[k] = k % 2 ? lo++ : --hi;
	for (k = 0; k < l->planes; k++)
		l->block_of_plane[l->order[k]] = k;
	/* HUB75_DATA_BANKS has no use for @spread */
	if (l->entry_bytes > 2)
		return;
	l->lanes = 8 / l->entry_bytes;
	for (v = 0; v < 256; v++) {
		for (k = 0; k < HUB75_SPREAD_WORDS; k++)
			l->spread[v][k] = 0;
		for (p = 0; p < l->planes; p++)
			if (l->lut[v] >> p & 1)
				l->spread[v][p / l->lanes] |=
					1ull << (p % l->lanes * 8 * l->entry_bytes);
	}
}

/* round(num / den), halves up, without a 64-bit division (32-bit ARM) */
static u32 hub75_round_div(u64 num, u64 den, u32 max)
{
	u32 lo = 0, hi = max;

	/* the largest level L with (2L - 1) * den <= 2 * num */
	while (lo < hi) {
		u32 mid = (lo + hi + 1) / 2;

		if ((2 * (u64)mid - 1) * den <= 2 * num)
			lo = mid;
		else
			hi = mid - 1;
	}
	return lo;
}

/*
 * The level of each 8-bit value v, M = 2^planes - 1:
 *  linear: round(v * M / 255);
 *  cie1931: round(Y * M), Y the CIE 1931 luminance of lightness
 *	L* = 100 * v / 255: L* / 903.3 up to L* = 8, ((L* + 16) / 116)^3
 *	above, computed exactly in integers:
 *	v <= 20: Y = 1000 v / (255 * 9033),
 *	v > 20:  Y = (100 v + 4080)^3 / 29580^3.
 */
void hub75_layout_lut(struct hub75_layout *l, enum hub75_correction corr)
{
	u32 max = (1u << l->planes) - 1;
	unsigned int v;

	for (v = 0; v < 256; v++) {
		u64 t = 100 * v + 4080;

		if (corr == HUB75_LINEAR)
			l->lut[v] = hub75_round_div((u64)v * max, 255, max);
		else if (v <= 20)
			l->lut[v] = hub75_round_div((u64)v * 1000 * max, 255 * 9033, max);
		else
			l->lut[v] = hub75_round_div(t * t * t * max, 29580ull * 29580 * 29580, max);
	}
}

size_t hub75_buffer_size(const struct hub75_layout *l)
{
	return (size_t)l->planes * l->rows * l->row_bytes;
}

/* The 8-bit components of pixel (x, y) of @src */
static void hub75_pixel(const u8 *src, unsigned int pitch, enum hub75_format format,
			unsigned int x, unsigned int y, u8 *rgb)
{
	const u8 *line = src + (size_t)y * pitch;

	if (format == HUB75_RGB565) {
		u16 p = line[2 * x] | line[2 * x + 1] << 8;
		unsigned int r5 = p >> 11, g6 = (p >> 5) & 0x3f, b5 = p & 0x1f;

		rgb[0] = r5 << 3 | r5 >> 2;
		rgb[1] = g6 << 2 | g6 >> 4;
		rgb[2] = b5 << 3 | b5 >> 2;
	} else {
		/* little endian 0xXXRRGGBB: bytes B, G, R, X */
		rgb[0] = line[4 * x + 2];
		rgb[1] = line[4 * x + 1];
		rgb[2] = line[4 * x];
	}
}

/* The six 8-bit components of clock x of address row r */
static void hub75_components(const struct hub75_layout *l, const u8 *src, unsigned int pitch,
			     enum hub75_format format, unsigned int x, unsigned int r, u8 *v)
{
	unsigned int half;

	for (half = 0; half < 2; half++) {
		unsigned int y = r + half * l->rows;

		if (l->mux) {
			u32 at = l->mux[y * l->clocks + x];

			hub75_pixel(src, pitch, format, at & 0xffff, at >> 16, v + 3 * half);
		} else {
			hub75_pixel(src, pitch, format, x, y, v + 3 * half);
		}
	}
}

const char *const hub75_mux_names[HUB75_MUX_COUNT] = {
	[HUB75_MUX_DIRECT] = "direct",
	[HUB75_MUX_STRIPE] = "stripe",
	[HUB75_MUX_CHECKERED] = "checkered",
	[HUB75_MUX_SPIRAL] = "spiral",
	[HUB75_MUX_ZSTRIPE] = "zstripe",
	[HUB75_MUX_ZN_MIRROR_ZSTRIPE] = "zn-mirror-zstripe",
	[HUB75_MUX_ZSTRIPE_UNEVEN] = "zstripe-uneven",
	[HUB75_MUX_INVERSED_ZSTRIPE] = "inversed-zstripe",
	[HUB75_MUX_P10_1R1G1_1] = "p10-outdoor-1r1g1-1",
	[HUB75_MUX_P10_1R1G1_2] = "p10-outdoor-1r1g1-2",
	[HUB75_MUX_P10_1R1G1_3] = "p10-outdoor-1r1g1-3",
	[HUB75_MUX_FLIPPED_STRIPE] = "flipped-stripe",
	[HUB75_MUX_P3_64X64] = "p3-outdoor-64x64",
};

#define HUB75_MUX_UNSET	0xffffffffu

unsigned int hub75_mux_stretch(enum hub75_mux mux)
{
	return mux == HUB75_MUX_DIRECT ? 1 : 2;
}

/*
 * Where LED (x, y) of a w x h panel is in the panel as driven, 2w x h/2
 * but for HUB75_MUX_DIRECT.  Stripes: the rows of the top quarter of each
 * half and those of the quarter below it share an address, one set of
 * columns each.  Tiles: 8 x 4 blocks, rows of blocks alternately "even"
 * and "odd", two rows of blocks on one address, one block's 8 columns
 * after the other's.
 */
static void hub75_mux_map(enum hub75_mux mux, unsigned int w, unsigned int h,
			  unsigned int x, unsigned int y, unsigned int *mx, unsigned int *my)
{
	unsigned int h2 = h / 2, h4 = h / 4, q = w / 4, k = x / 8, o = x % 8;
	bool top = y % h2 < h4, odd = y / 4 % 2;

	*my = y / h2 * h4 + y % h4;
	switch (mux) {
	case HUB75_MUX_STRIPE:
		*mx = top ? x + w : x;
		return;
	case HUB75_MUX_FLIPPED_STRIPE:
		*mx = top ? x : x + w;
		return;
	case HUB75_MUX_CHECKERED:
		if (top)
			*mx = x < w / 2 ? x + w / 2 : x + w;
		else
			*mx = x < w / 2 ? x : x + w / 2;
		return;
	case HUB75_MUX_SPIRAL:
		*mx = 2 * (x / q) * q + (top ? q - 1 - x % q : q + x % q);
		return;
	case HUB75_MUX_P3_64X64:
		*mx = 2 * x + top;
		return;
	default:
		break;
	}
	*my = y % 4 + 4 * (y / 8);
	switch (mux) {
	case HUB75_MUX_ZSTRIPE:
		*mx = 16 * k + o + (odd ? 8 : 0);
		return;
	case HUB75_MUX_ZN_MIRROR_ZSTRIPE:
		*mx = odd ? 16 * k + o + 4 : x + 8 * ((x + 4) / 8);
		return;
	case HUB75_MUX_ZSTRIPE_UNEVEN:
		*mx = 16 * k + o + (odd ? 0 : 8);
		return;
	case HUB75_MUX_INVERSED_ZSTRIPE:
		*mx = odd ? 16 * k + o : 16 * k + 15 - o;
		return;
	case HUB75_MUX_P10_1R1G1_1:
		*mx = odd ? 16 * k + 7 - o : 16 * k + 15 - o;
		return;
	case HUB75_MUX_P10_1R1G1_2:
		*mx = odd ? 16 * k + 8 + o : 16 * k + 7 - o;
		return;
	case HUB75_MUX_P10_1R1G1_3:
		*mx = odd ? 16 * k + 15 - o : 16 * k + o;
		return;
	default:
		*mx = x;
		*my = y;
	}
}

/**
 * hub75_mux_table() - struct hub75_layout's @mux of chains of panels
 * @mux: how each panel is wired
 * @panel_width: a panel's width as seen
 * @panel_height: its height as seen
 * @chain: panels in a chain, left to right on the display
 * @outputs: chains, output o showing rows o * @panel_height and on
 * @table: room for @panel_width * @chain * @panel_height * @outputs entries
 *
 * Return: false if the wiring does not fit the panel (not every position
 * of the panel as driven lights exactly one LED).
 */
bool hub75_mux_table(enum hub75_mux mux, unsigned int panel_width, unsigned int panel_height,
		     unsigned int chain, unsigned int outputs, u32 *table)
{
	unsigned int s = hub75_mux_stretch(mux), clocks = panel_width * chain * s;
	unsigned int n = panel_width * chain * panel_height, i, o, x, y, mx, my;

	if (mux >= HUB75_MUX_COUNT || panel_height % (4 * s) || panel_width % 8 ||
	    panel_width * chain > 0xffff || panel_height * outputs > 0xffff)
		return false;
	for (i = 0; i < n; i++)
		table[i] = HUB75_MUX_UNSET;
	for (y = 0; y < panel_height; y++) {
		for (x = 0; x < panel_width * chain; x++) {
			hub75_mux_map(mux, panel_width, panel_height, x % panel_width, y, &mx, &my);
			if (mx >= panel_width * s || my >= panel_height / s)
				return false;
			i = my * clocks + x / panel_width * panel_width * s + mx;
			if (table[i] != HUB75_MUX_UNSET)
				return false;
			table[i] = y << 16 | x;
		}
	}
	/* the other outputs: the same, @panel_height rows further down */
	for (o = 1; o < outputs; o++)
		for (i = 0; i < n; i++)
			table[o * n + i] = table[i] + (o * panel_height << 16);
	return true;
}

/**
 * hub75_arrange() - the outputs' chains as the wall is built
 * @table: a hub75_mux_table(), its pixels those of the chains one under
 *	the other (@width x @height)
 * @n: its entries
 * @width: a chain's width
 * @height: the outputs' bands together
 * @band: a band's height (a panel's)
 * @serpentine: the chains of outputs 2, 4, ... run right to left, their
 *	panels upside down (the cable snakes back at the end of each row)
 * @rotation: 0, 90, 180 or 270: the picture turned that far clockwise
 *	onto the wall (90 and 270: the display is @height wide, @width high)
 *
 * Pixel (x, y) of the chains becomes, after @serpentine flipped it in its
 * band, (h - 1 - y, x) at 90, (w - 1 - x, h - 1 - y) at 180, (y, w - 1 - x)
 * at 270 (w, h: @width, @height).
 */
void hub75_arrange(u32 *table, size_t n, unsigned int width, unsigned int height,
		   unsigned int band, bool serpentine, unsigned int rotation)
{
	size_t i;

	for (i = 0; i < n; i++) {
		unsigned int x = table[i] & 0xffff, y = table[i] >> 16, t;

		if (serpentine && y / band % 2) {
			x = width - 1 - x;
			y = y / band * band + band - 1 - y % band;
		}
		switch (rotation) {
		case 90:
			t = x;
			x = height - 1 - y;
			y = t;
			break;
		case 180:
			x = width - 1 - x;
			y = height - 1 - y;
			break;
		case 270:
			t = x;
			x = y;
			y = width - 1 - t;
			break;
		}
		table[i] = y << 16 | x;
	}
}

static void hub75_put32(u8 *p, u32 v)
{
	p[0] = v;
	p[1] = v >> 8;
	p[2] = v >> 16;
	p[3] = v >> 24;
}

/* HUB75_DATA_BANKS: output @o's bits of clock @x of row @r into @w */
static void hub75_bank_words(const struct hub75_layout *l, const u8 *src, unsigned int pitch,
			     enum hub75_format format, unsigned int o, unsigned int r,
			     unsigned int x, u32 (*w)[HUB75_BANK_SLOTS])
{
	unsigned int half, c, p;
	u8 v[HUB75_LINES];

	for (half = 0; half < 2; half++) {
		u32 at = l->mux[((o * 2 + half) * l->rows + r) * l->clocks + x];

		hub75_pixel(src, pitch, format, at & 0xffff, at >> 16, v + 3 * half);
	}
	for (c = 0; c < HUB75_LINES; c++) {
		u32 bit = 1u << l->bank_bit[o][c];
		unsigned int slot = l->bank_slot[o][c];
		u16 lv = l->lut[v[c]];

		for (p = 0; lv; p++, lv >>= 1)
			if (lv & 1)
				w[p][slot] |= bit;
	}
}

/*
 * HUB75_DATA_BANKS: every entry of every block.  Entry x of row r: per
 * slot, the bits of each output's lines whose level has the plane's bit
 * set; output o's lines show rows r and r + rows of its band (@mux).
 */
static void hub75_convert_banks(const struct hub75_layout *l, u8 *buf, const u8 *src,
				unsigned int pitch, enum hub75_format format)
{
	size_t plane_bytes = (size_t)l->rows * l->row_bytes;
	unsigned int r, x, o, k, p;
	u8 *blocks[HUB75_MAX_PLANES];

	for (p = 0; p < l->planes; p++)
		blocks[p] = buf + l->block_of_plane[p] * plane_bytes;
	for (r = 0; r < l->rows; r++) {
		for (x = 0; x < l->clocks; x++) {
			u32 w[HUB75_MAX_PLANES][HUB75_BANK_SLOTS] = { };
			size_t off = (size_t)r * l->row_bytes + (size_t)x * l->entry_bytes;

			for (o = 0; o < l->outputs; o++)
				hub75_bank_words(l, src, pitch, format, o, r, x, w);
			for (p = 0; p < l->planes; p++)
				for (k = 0; k < HUB75_BANK_SLOTS; k++)
					hub75_put32(blocks[p] + off + 4 * k, w[p][k]);
		}
	}
}

/**
 * hub75_convert() - write the blocks of a rectangle of the display
 * @l: the layout
 * @buf: the frame buffer, hub75_buffer_size() bytes
 * @src: the source image, the whole display: @l->width x @l->height
 * @pitch: bytes per line of @src
 * @format: pixel format of @src
 * @rect: the pixels that changed (clipped to the display)
 *
 * Each changed pixel shares its blocks' entries with the pixel @rows lines
 * above or below: both are read from @src, so @src must hold the whole
 * current image, not only @rect.  With @mux every block is converted:
 * an outdoor panel scatters a rectangle over them.
 *
 * Per entry, each word of @spread of the six components, shifted by their
 * lines' bits, ORed together: lane q of word k is then the entry of plane
 * k * lanes + q.
 */
void hub75_convert(const struct hub75_layout *l, u8 *buf, const void *src,
		   unsigned int pitch, enum hub75_format format,
		   const struct hub75_rect *rect)
{
	unsigned int x1 = rect->x1, x2 = rect->x2 < l->width ? rect->x2 : l->width;
	unsigned int y1 = rect->y1, y2 = rect->y2 < l->height ? rect->y2 : l->height;
	size_t plane_bytes = (size_t)l->rows * l->row_bytes;
	unsigned int bits[HUB75_LINES];
	bool touched[HUB75_MAX_ROWS] = { };
	unsigned int y, r, x, p, c, k;
	u8 *blocks[HUB75_MAX_PLANES];

	if (l->entry_bytes == 4 * HUB75_BANK_SLOTS) {
		hub75_convert_banks(l, buf, src, pitch, format);
		return;
	}
	for (p = 0; p < l->planes; p++)
		blocks[p] = buf + l->block_of_plane[p] * plane_bytes;
	for (c = 0; c < HUB75_LINES; c++)
		bits[c] = l->line_bit[c];
	if (l->mux) {
		x1 = 0;
		x2 = l->clocks;
		y1 = 0;
		y2 = 2 * l->rows;
	}
	for (y = y1; y < y2; y++)
		touched[y % l->rows] = true;
	for (r = 0; r < l->rows; r++) {
		if (!touched[r])
			continue;
		for (x = x1; x < x2; x++) {
			size_t off = (size_t)r * l->row_bytes + (size_t)x * l->entry_bytes;
			u8 v[HUB75_LINES];

			hub75_components(l, src, pitch, format, x, r, v);
			for (k = 0, p = 0; p < l->planes; k++) {
				unsigned int end = p + l->lanes;
				u64 w = 0;

				if (end > l->planes)
					end = l->planes;
				for (c = 0; c < HUB75_LINES; c++)
					w |= l->spread[v[c]][k] << bits[c];
				if (l->entry_bytes == 1) {
					for (; p < end; p++, w >>= 8)
						blocks[p][off] = w;
				} else {
					for (; p < end; p++, w >>= 16) {
						blocks[p][off] = w;
						blocks[p][off + 1] = w >> 8;
					}
				}
			}
		}
	}
}
