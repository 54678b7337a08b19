/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * rpmsg-neopixel:
 * void ws2812_send(const uint8_t *grb, uint32_t nbytes, uint32_t r30)
 *
 * Bit-bangs nbytes bytes, MSB first, on R30 bit NEOPIXEL_BIT with the WS2812
 * timing of neopixel.h, exact to the cycle.  Every instruction here takes one
 * cycle except the LBBO of the next byte from data RAM (3 cycles); the cycle
 * at which each R30 write issues is the edge.  Per bit, counting from the
 * rising edge (cycle 0):
 *
 *   "1": mov r30 (0), qbbc not taken (1), DELAY T1H-2 (2..), mov r30 at T1H;
 *        DELAY T1L-2-TAIL, qba .Ltail, TAIL cycles, next rising edge at T1L
 *   "0": mov r30 (0), qbbc taken (1), DELAY T0H-2, mov r30 at T0H;
 *        DELAY T0L-1-TAIL, TAIL cycles, next rising edge at T0L
 *
 * TAIL, from .Ltail to the next rising edge, is 11 cycles whether or not a
 * new byte is loaded: lsl, sub, qbeq, DELAY 7, qba in a byte; lsl, sub,
 * qbeq (taken), qbeq, lbbo (3), add, sub, ldi, qba between bytes.
 * tests/rpmsg-fw checks every edge of a frame in the simulator.
 *
 * GCC's ABI: r14 = grb, r15 = nbytes, r16 = r30; r0 and r17..r20 are the
 * caller's to lose.
 */
#include "neopixel.h"

#define TAIL	11

/* DELAY n: exactly n cycles (n >= 0), with r0 as the counter. */
	.macro	DELAY n
	.if (\n) < 0
	.error	"DELAY: negative cycle count"
	.elseif (\n) < 3
	.rept	\n
	nop
	.endr
	.else
	ldi	r0, ((\n) - 1) / 2		/* 1 + 2 * k cycles */
1:
	sub	r0, r0, 1
	qbne	1b, r0, 0
	.if ((\n) - 1) % 2
	nop
	.endif
	.endif
	.endm

	.section .text.ws2812_send, "ax", @progbits
	.global	ws2812_send
	.type	ws2812_send, @function
ws2812_send:
	set	r19, r16, NEOPIXEL_BIT		/* R30 with the data bit high */
	clr	r20, r16, NEOPIXEL_BIT		/* ... and low */
	qbeq	.Ldone, r15, 0
	lbbo	&r17.b0, r14, 0, 1
	add	r14, r14, 1
	sub	r15, r15, 1
	ldi	r18, 8
.Lbit:
	mov	r30, r19			/* rising edge: cycle 0 */
	qbbc	.Lzero, r17, 7
	DELAY	(WS2812_T1H - 2)
	mov	r30, r20			/* falling edge: T1H */
	DELAY	(WS2812_T1L - 2 - TAIL)
	qba	.Ltail
.Lzero:
	DELAY	(WS2812_T0H - 2)
	mov	r30, r20			/* falling edge: T0H */
	DELAY	(WS2812_T0L - 1 - TAIL)
.Ltail:
	lsl	r17, r17, 1
	sub	r18, r18, 1
	qbeq	.Lnext_byte, r18, 0
	DELAY	(TAIL - 4)
	qba	.Lbit
.Lnext_byte:
	qbeq	.Ldone, r15, 0
	lbbo	&r17.b0, r14, 0, 1		/* data RAM: 3 cycles */
	add	r14, r14, 1
	sub	r15, r15, 1
	ldi	r18, 8
	qba	.Lbit
.Ldone:
	ret
	.size	ws2812_send, . - ws2812_send
