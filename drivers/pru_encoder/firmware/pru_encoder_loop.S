/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * pru_encoder firmware: the sampling loop (pru_encoder_proto.h has the
 * protocol).
 *
 *   uint32_t pru_enc_loop(volatile struct pru_enc_ctrl *c,
 *                         const uint32_t *table, uint32_t last_cmd,
 *                         uint32_t strobe);
 *
 * Samples R31 bits 14..16 (A, B, index in the order the table was built
 * for) and decodes each change with the table, until the command word
 * differs from @last_cmd; returns the new command word.  @strobe is what is
 * written to R31 to raise the driver's event (0: none).  The count, the
 * direction, the inputs and every counter are in the control block after
 * each change, so the ARM reads them at any time and the loop keeps no
 * state of its own across calls.
 *
 * Cycle counts (every instruction 1 cycle, LBBO from the PRU's own data RAM
 * 3, SBBO 1: Documentation/prusim.rst, ../shared/reference/pru-isa-timing.md).
 * A sample is the "lsr" from r31; the gap, the cycles from one sample to the
 * next, depends on what the sample saw (measured on the simulator's trace
 * by drivers/pru_encoder/tests/check.sh):
 *
 *   no change                                   7  (reads the command word)
 *   step forward / backward                    19 / 20
 *   step with a reversal                       28  (reads @irq_armed)
 *   step forward with an overflow              27
 *   step backward with an underflow            28
 *   reversal with an underflow                 32
 *   index rising edge                          +3
 *   skipped state                              23
 *   @irq_armed set: the strobe                 +4
 *
 * The longest gap is a reversal with an underflow, an index edge and the
 * strobe: 39 cycles, 195 ns at 200 MHz.  Two changes of the inputs at
 * least that far apart never land in one gap, so nothing is missed at up
 * to 5.1 million edges per second (an x4 count rate: A and B at 1.28 MHz),
 * whatever the encoder does; turning one way without wrapping, up to 20
 * cycles apart (10 M edges/s).  Closer edges may land in one gap: A and B
 * both changed is a skipped state (counted in @skips, not in @count); an
 * edge undone within one gap (jitter on one input) is not seen at all,
 * which leaves the count right.
 *
 * GCC's PRU ABI: arguments in r14..r17, the result in r14; r0, r1 and
 * r14..r29 are the caller's; r3.w2 holds the return address.
 *
 * Registers: r14 &ctrl, r15 &table, r16 @last_cmd, r17 @strobe, r18 the
 * previous window, r19 count, r20 ceiling, r21 floor, r22 direction, r23 the
 * window, r24 table offset / scratch, r25 table entry, r26 skips, r27 event
 * pending, r0 overflows, r1 underflows, r28 indexes, r29 reversals.
 */
#include "pru_encoder_proto.h"

	.text
	.section .text.pru_enc_loop, "ax", @progbits
	.global	pru_enc_loop
	.type	pru_enc_loop, @function
pru_enc_loop:
	lbbo	&r0, r14, PRU_ENC_OFF_OVERFLOWS, 8	/* r0, r1 */
	lbbo	&r28, r14, PRU_ENC_OFF_INDEXES, 8	/* r28, r29 */
	lbbo	&r26, r14, PRU_ENC_OFF_SKIPS, 4
	lbbo	&r18, r14, PRU_ENC_OFF_INPUTS, 4
	lbbo	&r19, r14, PRU_ENC_OFF_COUNT, 4
	lbbo	&r20, r14, PRU_ENC_OFF_CEILING, 8	/* r20, r21 */
	lbbo	&r22, r14, PRU_ENC_OFF_DIRECTION, 4

sample:
	lsr	r23, r31, PRU_ENC_WIN_SHIFT
	and	r23, r23, (1 << PRU_ENC_WIN_BITS) - 1
	qbne	change, r23, r18
	lbbo	&r24, r14, PRU_ENC_OFF_COMMAND, 4
	qbeq	sample, r24, r16
	mov	r14, r24
	jmp	r3.w2

change:
	lsl	r24, r18, PRU_ENC_WIN_BITS + 2		/* (prev << 3 | cur) * 4 */
	lsl	r25, r23, 2
	or	r24, r24, r25
	mov	r18, r23
	sbbo	&r18, r14, PRU_ENC_OFF_INPUTS, 4
	lbbo	&r25, r15, r24, 4
	ldi	r27, 0
	qbbc	no_index, r25, 2			/* PRU_ENC_T_INDEX */
	add	r28, r28, 1
	sbbo	&r28, r14, PRU_ENC_OFF_INDEXES, 4
	ldi	r27, 1
no_index:
	qbbs	up, r25, 0				/* PRU_ENC_T_UP */
	qbbs	down, r25, 1				/* PRU_ENC_T_DOWN */
	qbbs	skip, r25, 3				/* PRU_ENC_T_SKIP */
	qba	done

up:
	qbeq	overflow, r19, r20
	add	r19, r19, 1
up_count:
	sbbo	&r19, r14, PRU_ENC_OFF_COUNT, 4
	qbeq	done, r22, 0
	ldi	r22, 0
	qba	reversal

overflow:
	mov	r19, r21
	add	r0, r0, 1
	sbbo	&r0, r14, PRU_ENC_OFF_OVERFLOWS, 4
	ldi	r27, 1
	qba	up_count

down:
	qbeq	underflow, r19, r21
	sub	r19, r19, 1
down_count:
	sbbo	&r19, r14, PRU_ENC_OFF_COUNT, 4
	qbne	done, r22, 0
	ldi	r22, 1
reversal:
	sbbo	&r22, r14, PRU_ENC_OFF_DIRECTION, 4
	add	r29, r29, 1
	sbbo	&r29, r14, PRU_ENC_OFF_REVERSALS, 4
	qba	event

underflow:
	mov	r19, r20
	add	r1, r1, 1
	sbbo	&r1, r14, PRU_ENC_OFF_UNDERFLOWS, 4
	ldi	r27, 1
	qba	down_count

skip:
	add	r26, r26, 1
	sbbo	&r26, r14, PRU_ENC_OFF_SKIPS, 4
	qba	event

done:
	qbeq	sample, r27, 0
event:
	lbbo	&r24, r14, PRU_ENC_OFF_IRQ_ARMED, 4
	qbeq	sample, r24, 0
	ldi	r24, 0
	sbbo	&r24, r14, PRU_ENC_OFF_IRQ_ARMED, 4
	mov	r31, r17
	qba	sample
	.size	pru_enc_loop, . - pru_enc_loop
