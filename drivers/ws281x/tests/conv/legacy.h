/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The conversion ws281x_conv.c replaced, and a plain one bit at a time,
 * for the host unit test and benchmark of drivers/ws281x/ws281x_conv.c.
 */
#ifndef _WS281X_CONV_LEGACY_H
#define _WS281X_CONV_LEGACY_H

#include "../../ws281x_conv.h"

/**
 * struct ws281x_layout - a controller's strings and frame, as the driver
 * had them
 * @strings: the strings, in frame order
 * @nstrings: how many
 * @max_leds: LEDs of the longest string
 * @bpl: bytes per LED in the frame, 3 or 4
 * @frame: the user's frame
 */
struct ws281x_layout {
	const struct ws281x_string *strings;
	unsigned int nstrings;
	unsigned int max_leds;
	unsigned int bpl;
	const u8 *frame;
};

unsigned int ws281x_ref_slots(const struct ws281x_layout *lay, unsigned int core);
void ws281x_ref_tab(u8 *tab, const u8 *lut, unsigned int brightness);
void ws281x_ref_convert(const struct ws281x_layout *lay, unsigned int core, const u8 *tab,
			struct ws281x_slot *slots, unsigned int nslots);
void ws281x_legacy_convert(const struct ws281x_layout *lay, unsigned int core, const u8 *tab,
			   struct ws281x_slot *slots, unsigned int nslots);

#endif /* _WS281X_CONV_LEGACY_H */
