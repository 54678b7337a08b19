/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * hub75_conv.h - turning a framebuffer into the blocks the hub75 firmware
 * clocks out (hub75_proto.h).
 *
 * hub75_conv.c is compiled unchanged in the kernel module and in host
 * programs (drivers/hub75/tests/conv: its unit test and its benchmark),
 * which put drivers/ws281x/tests/include first on the include path: its
 * <linux/types.h> gives them the kernel's names for the types used here.
 */
#ifndef _HUB75_CONV_H
#define _HUB75_CONV_H

#include <linux/types.h>

#include "hub75_proto.h"

/* Source pixel formats (the DRM formats of the same names) */
enum hub75_format {
	HUB75_XRGB8888,
	HUB75_RGB565,
};

/* The six data lines, in the order of the binding's pin lists */
enum hub75_line {
	HUB75_R1, HUB75_G1, HUB75_B1, HUB75_R2, HUB75_G2, HUB75_B2,
	HUB75_LINES
};

/*
 * How an outdoor panel's driver outputs are wired to its LEDs: the panel,
 * W x H as seen, is driven as a (W * stretch) x (H / stretch) one (scan
 * H / (2 * stretch)), whose pixel (mx, my) is the LED at (x, y).  The names
 * are those of hzeller's rpi-rgb-led-matrix (--led-multiplexing), lower
 * case with dashes; Documentation/hub75.rst has each rule.
 */
enum hub75_mux {
	HUB75_MUX_DIRECT,
	HUB75_MUX_STRIPE,
	HUB75_MUX_CHECKERED,
	HUB75_MUX_SPIRAL,
	HUB75_MUX_ZSTRIPE,
	HUB75_MUX_ZN_MIRROR_ZSTRIPE,
	HUB75_MUX_ZSTRIPE_UNEVEN,
	HUB75_MUX_INVERSED_ZSTRIPE,
	HUB75_MUX_P10_1R1G1_1,
	HUB75_MUX_P10_1R1G1_2,
	HUB75_MUX_P10_1R1G1_3,
	HUB75_MUX_FLIPPED_STRIPE,
	HUB75_MUX_P3_64X64,
	HUB75_MUX_COUNT
};

extern const char *const hub75_mux_names[HUB75_MUX_COUNT];

#define HUB75_MAX_OUTPUTS	8

/* u64 words of struct hub75_layout's @spread: 16-bit lanes, 4 a word */
#define HUB75_SPREAD_WORDS	((HUB75_MAX_PLANES + 3) / 4)

/* Brightness correction of each 8-bit component */
enum hub75_correction {
	HUB75_CIE1931,
	HUB75_LINEAR,
};

/**
 * struct hub75_layout - where each pixel's bits go in a frame buffer
 * @width: pixels in a row of the display, the chain's
 * @height: rows of the display
 * @clocks: clocks per row: @width, times the stretch of @mux
 * @rows: address rows (the panel's scan): @height / 2 / the stretch
 * @mux: NULL, or for each position of the panels as driven (output o, row
 *	r of the top half or r + @rows, clock x: index ((o * 2 * @rows + r) *
 *	@clocks + x)), the pixel of the display it lights, y << 16 | x
 *	(hub75_mux_table()); always set with HUB75_DATA_BANKS
 * @outputs: parallel outputs (chains), each a band of the display's rows
 *	(HUB75_DATA_BANKS; 1 otherwise)
 * @bank_slot: HUB75_DATA_BANKS: the slot (word of an entry) of each
 *	output's lines
 * @bank_bit: HUB75_DATA_BANKS: their bits in the slot's bank
 * @planes: bit planes, 1..HUB75_MAX_PLANES
 * @entry_bytes: bytes per clock in a block: 1 (HUB75_DATA_R30), 2
 *	(HUB75_DATA_GPIO) or 16 (HUB75_DATA_BANKS)
 * @row_bytes: bytes of a block: @width * @entry_bytes rounded up to
 *	HUB75_CHUNK_BYTES (the driver refuses geometries that need rounding)
 * @order: the planes in the order they are shown (@order[0] first)
 * @line_bit: bit of each data line in a block's entry
 * @lut: level (0 .. 2^@planes - 1) of each 8-bit component value
 * @block_of_plane: position of each plane in @order
 * @lanes: planes per word of @spread: 8 / @entry_bytes
 * @spread: for each 8-bit component value, its level's bits spread out:
 *	bit q * 8 * @entry_bytes of word k is bit k * @lanes + q of the
 *	level (shifted by a line's bit, each lane is that line's entry)
 */
struct hub75_layout {
	unsigned int width;
	unsigned int height;
	unsigned int clocks;
	unsigned int rows;
	const u32 *mux;
	unsigned int outputs;
	u8 bank_slot[HUB75_MAX_OUTPUTS][HUB75_LINES];
	u8 bank_bit[HUB75_MAX_OUTPUTS][HUB75_LINES];
	unsigned int planes;
	unsigned int entry_bytes;
	unsigned int row_bytes;
	u8 order[HUB75_MAX_PLANES];
	u8 line_bit[HUB75_LINES];
	u16 lut[256];
	u8 block_of_plane[HUB75_MAX_PLANES];
	unsigned int lanes;
	u64 spread[256][HUB75_SPREAD_WORDS];
};

/**
 * struct hub75_rect - pixels [x1, x2) x [y1, y2) of the display
 */
struct hub75_rect {
	unsigned int x1, y1, x2, y2;
};

void hub75_layout_lut(struct hub75_layout *l, enum hub75_correction corr);
void hub75_layout_finish(struct hub75_layout *l);
size_t hub75_buffer_size(const struct hub75_layout *l);
unsigned int hub75_mux_stretch(enum hub75_mux mux);
void hub75_arrange(u32 *table, size_t n, unsigned int width, unsigned int height,
		   unsigned int band, bool serpentine, unsigned int rotation);
bool hub75_mux_table(enum hub75_mux mux, unsigned int panel_width, unsigned int panel_height,
		     unsigned int chain, unsigned int outputs, u32 *table);
void hub75_convert(const struct hub75_layout *l, u8 *buf, const void *src,
		   unsigned int pitch, enum hub75_format format,
		   const struct hub75_rect *rect);

#endif /* _HUB75_CONV_H */
