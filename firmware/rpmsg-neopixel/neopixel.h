/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * rpmsg-neopixel: constants of the rpmsg NeoPixel firmware
 * (firmware/rpmsg-neopixel), shared by neopixel.c and ws2812.S, by
 * firmware/examples/cookbook-rpmsg-neopixel and by the test that checks the
 * wire timing cycle by cycle (tests/rpmsg-fw).
 */
#ifndef _PRUKIT_RPMSG_NEOPIXEL_H
#define _PRUKIT_RPMSG_NEOPIXEL_H

#define NEOPIXEL_BIT		1	/* R30 bit 1: pr1_pru0_pru_r30_1, P9_29 */
#define NEOPIXEL_COUNT		24	/* pixels in the string */
#define NEOPIXEL_LINE_MAX	64	/* longer lines are malformed */

/* WS2812 bit timing in 5 ns PRU cycles */
#define WS2812_T0H		70	/* 350 ns */
#define WS2812_T0L		160	/* 800 ns */
#define WS2812_T1H		140	/* 700 ns */
#define WS2812_T1L		120	/* 600 ns */
/* Low after a frame: > 50 us for the WS2812, ~280 us for newer chips */
#define WS2812_RESET		60000	/* 300 us */

#ifndef __ASSEMBLER__
#include <stdint.h>

/*
 * Send nbytes bytes (GRB, MSB first) on R30 bit NEOPIXEL_BIT; r30 is the
 * latch value for the other bits.  Returns with the bit low, right after the
 * last bit's high phase; the caller keeps it low for WS2812_RESET.
 */
void ws2812_send(const uint8_t *grb, uint32_t nbytes, uint32_t r30);

/* Counters, in data RAM (symbol neopixel_stats) */
struct neopixel_stats {
	uint32_t msgs;		/* messages received */
	uint32_t lines_ok;	/* pixel lines applied */
	uint32_t lines_bad;	/* malformed lines ignored */
	uint32_t frames;	/* "-1": frames sent */
};
#endif

#endif /* _PRUKIT_RPMSG_NEOPIXEL_H */
