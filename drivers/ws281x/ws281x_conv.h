/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * ws281x_conv.h - turning a ws281x frame into the bit slots its PRU sends.
 *
 * ws281x_conv.c is compiled unchanged in the kernel module and in host
 * programs (drivers/ws281x/tests: its unit test and its benchmark), which
 * put drivers/ws281x/tests/include first on the include path: its
 * <linux/types.h> gives them the kernel's names for the types used here.
 */
#ifndef _WS281X_CONV_H
#define _WS281X_CONV_H

#include <linux/types.h>

#include "ws281x_proto.h"

/* Strings of one core converted together, per output word */
#define WS281X_GROUP_STRINGS	8
/* Output words of a slot: r30, then gpio[0..3] */
#define WS281X_SLOT_WORDS	(1 + WS281X_GPIO_BANKS)

/**
 * struct ws281x_string - one string of LEDs
 * @core: index of its core in "ti,prus"
 * @gpio: on a GPIO pin (else an R30 bit)
 * @bank: GPIO bank, when @gpio
 * @bit: R30 bit, or bit in the GPIO bank
 * @leds: LEDs on the string
 * @bpl: bytes per LED on the wire: 3, or 4 for RGBW chips
 * @order: the wire's bytes, as indices into the user's R, G, B, W
 */
struct ws281x_string {
	unsigned int core;
	bool gpio;
	unsigned int bank;
	unsigned int bit;
	unsigned int leds;
	unsigned int bpl;
	u8 order[4];
};

/**
 * struct ws281x_tab - what each value of a frame's byte becomes on the wire
 * @lanes: the wire byte (the value scaled by the brightness, then looked
 *	up in the lookup table), one bit per byte lane, in sending order:
 *	lanes[v][0] holds bits 7, 6, 5, 4 of the wire byte in bit 0 of its
 *	bytes 0, 1, 2, 3; lanes[v][1] bits 3, 2, 1, 0
 */
struct ws281x_tab {
	u32 lanes[256][2];
};

/**
 * struct ws281x_group - up to 8 strings of a core converted together
 * @word: their output word: 0 for R30, 1 + b for GPIO bank b
 * @first: the word's first group, which writes it (the others OR into it)
 * @bpl: wire bytes per LED of every one of them
 * @n: how many
 * @leds: LEDs of each, longest first (member j is the j-th)
 * @off: per wire byte k of an LED, where member j's byte is in the frame,
 *	counted from the LED's place in the frame's first string: its
 *	string's place plus order[k]
 * @spread: the output word's bits for each set of members sending a 1
 *	(member j: bit j of the index)
 */
struct ws281x_group {
	unsigned int word;
	bool first;
	unsigned int bpl;
	unsigned int n;
	u32 leds[WS281X_GROUP_STRINGS];
	u32 off[4][WS281X_GROUP_STRINGS];
	u32 spread[256];
};

/**
 * struct ws281x_conv - how a core's slots are made from the frame
 * @slots: bit slots per frame: the core's longest string's bits
 * @bpl: bytes per LED in the user's frame, 3 or 4
 * @empty: the output words no string of the core uses (always 0)
 * @nempty: how many
 * @ngroups: groups
 * @groups: the core's strings, in groups of the same output word and
 *	wire bytes per LED, by output word
 */
struct ws281x_conv {
	unsigned int slots;
	unsigned int bpl;
	unsigned int empty[WS281X_SLOT_WORDS];
	unsigned int nempty;
	unsigned int ngroups;
	struct ws281x_group groups[];
};

size_t ws281x_conv_size(const struct ws281x_string *strings, unsigned int nstrings,
			unsigned int core);
void ws281x_conv_init(struct ws281x_conv *conv, const struct ws281x_string *strings,
		      unsigned int nstrings, unsigned int core, unsigned int max_leds,
		      unsigned int bpl);
void ws281x_conv_tab(struct ws281x_tab *tab, const u8 *lut, unsigned int brightness);
void ws281x_convert(const struct ws281x_conv *conv, const struct ws281x_tab *tab,
		    const u8 *frame, struct ws281x_slot *slots);

#endif /* _WS281X_CONV_H */
