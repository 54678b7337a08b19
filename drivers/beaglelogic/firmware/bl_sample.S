/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * beaglelogic firmware, PRU1: the sampling loops (beaglelogic_proto.h has
 * the protocol).
 *
 *   void bl_sample(volatile struct bl_ctrl *c, uint32_t pad, int32_t rounds);
 *
 * Copies R31 into r21..r28 every 2 * c->divisor cycles: one byte (bits
 * 0..7, BL_UNIT_8) or one half word (bits 0..15, BL_UNIT_16) per sample.
 * Each 32-byte block is published with its number (r29, from 1) in a
 * scratchpad bank: even blocks in bank 10, odd ones in bank 11.  Returns
 * once the storer sets the stop flag (bank 12, r19: 1 runs, 0x80000000
 * stops; looked at every other sample, and every 3 cycles of a delay), after
 * writing c->first_iep.
 *
 * Every sample takes the same 2 * divisor cycles, block boundaries and
 * loop jumps included, so the samples are evenly spaced from the first to
 * the last: each sample is the "mov" from r31, followed by a delay of
 * 2 * divisor - 2 cycles and by one more instruction, the slot, which does
 * the bookkeeping of the block:
 *
 *   sample 0      into r16 (r21 still holds the finished block); slot:
 *                 XOUT r21..r29 (the finished block and its number)
 *   sample 1      slot: sample 0 from r16 into r21
 *   sample 2      slot: the block number + 1
 *   samples 3..   slots: XIN the stop flag, then branch out on it, in turn
 *   last sample   slot: "nop", or the jump back after the second block
 *
 * Every instruction here takes one cycle (XIN and XOUT too, branches taken
 * or not); the delays, with @pad and @rounds from bl_main.c (no division
 * here):
 *
 *   divisor 1     none (100 Msps: a sample every 2 cycles)
 *   divisor 2, 3  a branch on @pad (0 or 1) over two "nop"s, and a "nop"
 *   divisor >= 4  mov, two branches on @pad's bits 0 and 1 over a "nop"
 *                 each, then -@rounds rounds of XIN (the stop flag), add,
 *                 branch: 3 + bit 0 + bit 1 + 3 * rounds = 2 * divisor - 2
 *
 * The first sample comes right after the load of the IEP counter, which
 * samples it in its first cycle and takes 4: so c->first_iep is the loaded
 * value + 4, the counter's value in the cycle of the first "mov".
 *
 * GCC's PRU ABI: the arguments in r14, r15, r16; r0, r1 and r14..r29 are
 * the caller's (r4..r13 are not used); r3.w2 is the return address.
 *
 * Registers: r14 &ctrl, r15 @pad, r16 sample 0 of a block, r17 @rounds,
 * r18 the IEP counter before the first sample, r19 stop flag, r20 delay
 * count, r21..r28 the block, r29 its number.
 */
#include "beaglelogic_proto.h"

#define IEP_COUNT	0x0c	/* in the IEP's registers, constant table entry 26 */

	.macro	D_1
	.endm

/* divisor 2 (r15 = 0): 2 cycles; divisor 3 (r15 = 1): 4 cycles */
	.macro	D_23
	qbeq	1f, r15, 0
	nop
	nop
1:
	nop
	.endm

/*
 * divisor >= 4: 3 + (r15 bit 0) + (r15 bit 1) + 3 * m cycles = 2 * divisor
 * - 2, m = -r17 rounds of a loop that also reads the stop flag: it ends
 * early when the flag (0x80000000) makes r20 non-negative.
 */
	.macro	D_N
	mov	r20, r17
	qbbc	1f, r15, 0
	nop
1:
	qbbc	2f, r15, 1
	nop
2:
	xin	12, &r19, 4
	add	r20, r20, r19
	qbbs	2b, r20, 31
	.endm

/* Half of the loop: one block of 32 bytes; \bank takes the previous one. */
	.macro	HALF8 delay, bank, last, top, stop
	mov	r16.b0, r31.b0
	\delay
	xout	\bank, &r21, 36
	mov	r21.b1, r31.b0
	\delay
	mov	r21.b0, r16.b0
	mov	r21.b2, r31.b0
	\delay
	add	r29, r29, 1
	mov	r21.b3, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r22.b0, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r22.b1, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r22.b2, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r22.b3, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r23.b0, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r23.b1, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r23.b2, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r23.b3, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r24.b0, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r24.b1, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r24.b2, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r24.b3, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r25.b0, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r25.b1, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r25.b2, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r25.b3, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r26.b0, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r26.b1, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r26.b2, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r26.b3, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r27.b0, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r27.b1, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r27.b2, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r27.b3, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r28.b0, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r28.b1, r31.b0
	\delay
	xin	12, &r19, 4
	mov	r28.b2, r31.b0
	\delay
	qbbs	\stop, r19, 31
	mov	r28.b3, r31.b0
	\delay
	.if \last
	jmp	\top
	.else
	nop
	.endif
	.endm

	.macro	HALF16 delay, bank, last, top, stop
	mov	r16.w0, r31.w0
	\delay
	xout	\bank, &r21, 36
	mov	r21.w2, r31.w0
	\delay
	mov	r21.w0, r16.w0
	mov	r22.w0, r31.w0
	\delay
	add	r29, r29, 1
	mov	r22.w2, r31.w0
	\delay
	xin	12, &r19, 4
	mov	r23.w0, r31.w0
	\delay
	qbbs	\stop, r19, 31
	mov	r23.w2, r31.w0
	\delay
	xin	12, &r19, 4
	mov	r24.w0, r31.w0
	\delay
	qbbs	\stop, r19, 31
	mov	r24.w2, r31.w0
	\delay
	xin	12, &r19, 4
	mov	r25.w0, r31.w0
	\delay
	qbbs	\stop, r19, 31
	mov	r25.w2, r31.w0
	\delay
	xin	12, &r19, 4
	mov	r26.w0, r31.w0
	\delay
	qbbs	\stop, r19, 31
	mov	r26.w2, r31.w0
	\delay
	xin	12, &r19, 4
	mov	r27.w0, r31.w0
	\delay
	qbbs	\stop, r19, 31
	mov	r27.w2, r31.w0
	\delay
	xin	12, &r19, 4
	mov	r28.w0, r31.w0
	\delay
	qbbs	\stop, r19, 31
	mov	r28.w2, r31.w0
	\delay
	.if \last
	jmp	\top
	.else
	nop
	.endif
	.endm

/*
 * A loop: the IEP load, then blocks in pairs until the stop flag.  Each
 * half branches out to the stop nearest to it (a quick branch reaches 511
 * words): the first half back to \stopa, before \entry, the second
 * forward to \stopb.
 */
	.macro	PATH half, delay, entry, top, stopa, stopb
\stopa:
	jmp	bl_sample_end
\entry:
	lbco	&r18, 26, IEP_COUNT, 4
\top:
	\half	\delay, 10, 0, \top, \stopa
	\half	\delay, 11, 1, \top, \stopb
\stopb:
	jmp	bl_sample_end
	.endm

	.text
	.section .text.bl_sample,"ax",@progbits
	.global	bl_sample
	.type	bl_sample, @function
bl_sample:
	lbbo	&r0, r14, BL_CTRL_UNIT, 8	/* r0 unit, r1 divisor */
	mov	r17, r16
	ldi	r29, 0
	ldi	r19, 1
	qbeq	unit16, r0, BL_UNIT_16
	qbne	1f, r1, 1
	jmp	s8_1
1:
	qblt	2f, r1, 3		/* 3 < divisor */
	jmp	s8_23
2:
	jmp	s8_n
unit16:
	qbne	1f, r1, 1
	jmp	s16_1
1:
	qblt	2f, r1, 3
	jmp	s16_23
2:
	jmp	s16_n

	PATH	HALF8, D_1, s8_1, s8_1_top, s8_1_stopa, s8_1_stopb
	PATH	HALF8, D_23, s8_23, s8_23_top, s8_23_stopa, s8_23_stopb
	PATH	HALF8, D_N, s8_n, s8_n_top, s8_n_stopa, s8_n_stopb
	PATH	HALF16, D_1, s16_1, s16_1_top, s16_1_stopa, s16_1_stopb
	PATH	HALF16, D_23, s16_23, s16_23_top, s16_23_stopa, s16_23_stopb
	PATH	HALF16, D_N, s16_n, s16_n_top, s16_n_stopa, s16_n_stopb

bl_sample_end:
	add	r18, r18, 4
	sbbo	&r18, r14, BL_CTRL_FIRST_IEP, 4
	jmp	r3.w2
	.size	bl_sample, . - bl_sample
