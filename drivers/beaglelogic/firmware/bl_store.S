/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * beaglelogic firmware, PRU0: the storing loop (beaglelogic_proto.h has the
 * protocol, bl_sample.S the sampler's side).
 *
 *   uint32_t bl_store(volatile struct bl_ctrl *c, uint32_t status);
 *
 * Clears the scratchpad banks 10 and 11 (block numbers 0), sets the stop
 * flag (bank 12, r19) to BL_RUN_FLAG, sets c->state to BL_FW_RUNNING (the
 * sampler starts only then) and writes @status into c->hdr.status (the
 * answer to START: the driver then starts the sampler), and stores the
 * sampler's blocks 1, 2, 3 ... in order into the c->nbufs buffers of
 * c->bufsize bytes at c->bufs[].  After each full buffer: c->filled + 1,
 * then system event c->event.  Returns BL_STORE_DONE (one-shot: every
 * buffer full), BL_STORE_MISSED (a block overwritten before it was taken;
 * c->error BL_ERR_MISSED) or BL_STORE_COMMAND (c->hdr.command changed),
 * with the stop flag set to BL_STOP_FLAG; the caller sets c->state.
 *
 * Timing (pru_sim's defaults; the sampler publishes a block every 32
 * cycles at 100 Msps in 16-bit units, and each bank holds a block for 64):
 * an idle poll round takes 8 cycles (XIN, two compares, the command
 * word's load: 3, compare, jump), a block 13 (XIN, compare, SBBO of 32
 * bytes: 8, two adds, compare), a full buffer's bookkeeping 14 more (the
 * count's store, the event, the next buffer's address: a load of 3).  So
 * the storer has taken each block at most 8 + 13 + 14 = 35 cycles after it
 * was published, within the 64.
 *
 * GCC's PRU ABI: arguments in r14, r15, the result in r14; r4..r13 are
 * saved here; r2 is the stack pointer, r3.w2 the return address.
 *
 * Registers: r4 number of the next block, r5 where it goes, r6 the end of
 * the current buffer, r7 its index, r8 c->nbufs, r9 c->bufsize, r10
 * buffers filled, r11 c->mode, r12 the event's R31 strobe, r13 the START
 * command word, r14 &ctrl, r19 stop flag, r21..r28 a block, r29 its number.
 */
#include "beaglelogic_proto.h"
#include "bl_fw.h"

#define CTRL_COMMAND	8
#define CTRL_STATUS	12
#define CTRL_MODE	24
#define CTRL_NBUFS	28	/* and bufsize at 32 */
#define CTRL_EVENT	36
#define R31_VEC_VALID	0x20

/* Wait for block r4 in \bank; store it; go on at \next (the other bank). */
	.macro	POLL bank, next
1:
	xin	\bank, &r21, 36
	qbeq	2f, r29, r4
	qblt	missed, r29, r4		/* r4 < r29: the bank was overwritten */
	lbbo	&r0, r14, CTRL_COMMAND, 4
	qbne	new_command, r0, r13
	jmp	1b
2:
	sbbo	&r21, r5, 0, BL_BLOCK_BYTES
	add	r4, r4, 1
	add	r5, r5, BL_BLOCK_BYTES
	qbne	\next, r5, r6
	/* the buffer is full */
	add	r10, r10, 1
	sbbo	&r10, r14, BL_CTRL_FILLED, 4
	mov	r31, r12
	add	r7, r7, 1
	qbne	3f, r7, r8
	qbeq	done, r11, BL_MODE_ONESHOT
	ldi	r7, 0
3:
	lsl	r0, r7, 2
	add	r0, r0, BL_CTRL_BUFS
	lbbo	&r5, r14, r0, 4
	add	r6, r5, r9
	jmp	\next
	.endm

	.text
	.section .text.bl_store,"ax",@progbits
	.global	bl_store
	.type	bl_store, @function
bl_store:
	sub	r2, r2, 40
	sbbo	&r4, r2, 0, 40
	ldi	r21, 0
	ldi	r22, 0
	ldi	r23, 0
	ldi	r24, 0
	ldi	r25, 0
	ldi	r26, 0
	ldi	r27, 0
	ldi	r28, 0
	ldi	r29, 0
	xout	10, &r21, 36
	xout	11, &r21, 36
	ldi	r19, BL_RUN_FLAG
	xout	12, &r19, 4
	lbbo	&r13, r14, CTRL_COMMAND, 4
	lbbo	&r11, r14, CTRL_MODE, 4
	lbbo	&r8, r14, CTRL_NBUFS, 8		/* r8 nbufs, r9 bufsize */
	lbbo	&r12, r14, CTRL_EVENT, 4
	sub	r12, r12, 16
	or	r12, r12, R31_VEC_VALID
	ldi	r10, 0
	ldi	r7, 0
	lbbo	&r5, r14, BL_CTRL_BUFS, 4
	add	r6, r5, r9
	ldi	r4, 1
	ldi	r0, BL_FW_RUNNING
	sbbo	&r0, r14, BL_CTRL_STATE, 4	/* the sampler waits for this */
	sbbo	&r15, r14, CTRL_STATUS, 4	/* the answer: the driver starts it */
	jmp	odd

odd:
	POLL	11, even
even:
	POLL	10, odd

done:
	ldi	r14, BL_STORE_DONE
	jmp	stop
missed:
	ldi	r0, BL_ERR_MISSED
	sbbo	&r0, r14, BL_CTRL_ERROR, 4
	ldi	r14, BL_STORE_MISSED
	jmp	stop
new_command:
	ldi	r14, BL_STORE_COMMAND
stop:
	ldi32	r19, BL_STOP_FLAG
	xout	12, &r19, 4
	lbbo	&r4, r2, 0, 40
	add	r2, r2, 40
	jmp	r3.w2
	.size	bl_store, . - bl_store
