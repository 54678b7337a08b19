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
 * with the stop flag set to BL_STOP_FLAG; the caller sets c->state.  With
 * a trigger (c->trig_mode) the capture ends BL_STORE_DONE @trig_post
 * blocks after the trigger's (beaglelogic_proto.h).
 *
 * Timing (the simulator's defaults; the sampler publishes a block every 32
 * cycles at 100 Msps in 16-bit units, and each bank holds a block for 64):
 * an idle poll round takes 11 cycles (XIN, two compares, the command
 * word's load: 3, compare, the ping's load: 3, compare and branch back), a
 * block 13 (XIN, compare, SBBO of 32 bytes: 8, two adds, compare), a full
 * buffer's bookkeeping 14 more (the count's store, the event, the next
 * buffer's address: a load of 3).  So the storer has taken each block at
 * most 11 + 13 + 14 = 38 cycles after it was published, within the 64; a
 * trigger adds up to 18 (see below).  A new ping (the driver's, some ten a
 * second while a reader waits) costs one round 3 cycles more (the answer's
 * move and store, a jump); a round that stores nothing leaves the
 * simulator free to skip the idle loop.
 *
 * GCC's PRU ABI: arguments in r14, r15, the result in r14; r4..r13 are
 * saved here; r2 is the stack pointer, r3.w2 the return address.
 *
 * Registers: r4 number of the next block, r5 where it goes, r6 the end of
 * the current buffer, r7 its index, r8 c->nbufs, r9 c->bufsize, r10
 * buffers filled, r11 c->mode, r12 the event's R31 strobe, r13 the START
 * command word, r14 &ctrl, r19 stop flag, r21..r28 a block, r29 its number,
 * r15.w2 the offset of c->ping;
 * the trigger (below): r1.w2 the link, r15.w0 its state, r16 lanes or
 * mask, r17 bit or value, r18 the states to go to after arming, r20 a
 * count.
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
	lbbo	&r0, r14, r15.w2, 4	/* r0.w0 the ping, r0.w2 the pong */
	qbeq	1b, r0.w0, r0.w2
	mov	r0.w2, r0.w0		/* a new ping: answer it (the ping goes */
					/* back unchanged: the driver sends */
					/* another only once this is answered) */
	sbbo	&r0, r14, r15.w2, 4
	jmp	1b
2:
	sbbo	&r21, r5, 0, BL_BLOCK_BYTES
	jal	r1.w2, r15.w0		/* the trigger's state: see below */
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
	ldi	r15.w2, BL_CTRL_PING		/* beyond an immediate offset */
	/*
	 * The trigger: r15.w0 its state, r16, r17 and r18 its parameters
	 * (after the answer, which is r15: the sampler starts milliseconds
	 * later, when the driver has it)
	 */
	ldi	r0, BL_CTRL_TRIG_MODE
	add	r0, r0, r14
	lbbo	&r16, r0, 4, 12			/* r16 lanes, r17 bit, r18 pre */
	lbbo	&r0, r0, 0, 4
	ldi	r15.w0, %pmem(trg_none)
	qbeq	7f, r0, BL_TRIG_NONE
	mov	r20, r18
	ldi	r15.w0, %pmem(trg_arm)
	ldi	r18.w0, %pmem(any_low)		/* edge: after a high sample */
	ldi	r18.w2, %pmem(any_high)		/* after a low one */
	qbne	1f, r0, BL_TRIG_RISING
	ldi	r18.w0, %pmem(rise_low)
1:
	qbne	2f, r0, BL_TRIG_FALLING
	ldi	r18.w2, %pmem(fall_high)
2:
	qbne	3f, r0, BL_TRIG_PATTERN8
	ldi	r18.w0, %pmem(pattern8)
	mov	r18.w2, r18.w0
3:
	qbne	4f, r0, BL_TRIG_PATTERN16
	ldi	r18.w0, %pmem(pattern16)
	mov	r18.w2, r18.w0
4:
	qbne	7f, r0, BL_TRIG_PATTERN16_HALF
	ldi	r18.w0, %pmem(pattern16_half)
	mov	r18.w2, r18.w0
7:
	jmp	odd

odd:
	POLL	11, even
even:
	POLL	10, odd

/*
 * The trigger.  The block just stored is in r21..r28, its number in r4;
 * each state is a routine called with JAL (link r1.w2) after the block's
 * SBBO, r15.w0 the current one, r20 its count:
 *
 *   trg_none   no trigger (2 cycles with the call)
 *   trg_arm    the first @trig_pre blocks; then, after the last of them,
 *              the "after a high sample" state in r18.w0 or the "after a
 *              low sample" one in r18.w2, by the channel's level in the
 *              block's last sample (r28, bit r17)
 *   rise_low   (rising, the line was high) a low sample, and the last high:
 *              it rose in this block; a low one: on to any_high
 *   any_high   (rising or edge, the line was low) a high sample
 *   fall_high  (falling, the line was low) a high sample, and the last low:
 *              it fell in this block; a high one: on to any_low
 *   any_low    (falling or edge, the line was high) a low sample
 *   pattern8, pattern16, pattern16_half  a sample equal to the value in the
 *              mask's bits (r16 the mask, r17 the value, in each lane)
 *   trg_post   counts @trig_post blocks after the trigger's, then ends
 *
 * "a high sample" is the OR of the 8 words in the channel's lanes (r16),
 * "a low one" the AND: 8 + 4 cycles a block, 13 with the call.  A pattern
 * costs 4 cycles per word of 16-bit samples, 6 per word of 8-bit ones: all
 * 8 words 33 or 49 cycles, pattern16_half's 4 words 17.  With the 13 of
 * the block (bl_store's header) that is 26 cycles for an edge, 31 for
 * pattern16_half, within the 32 a 16-bit block lasts at 100 Msps, and 63
 * for pattern8 within an 8-bit block's 64 (plus 14 at each full buffer,
 * made up over the next blocks).  The driver picks pattern16 (47) only at
 * 50 Msps and below.  Which sample of the block it was, the driver finds.
 */
	.macro	ALL op
	\op	r0, r21, r22
	\op	r0, r0, r23
	\op	r0, r0, r24
	\op	r0, r0, r25
	\op	r0, r0, r26
	\op	r0, r0, r27
	\op	r0, r0, r28
	and	r0, r0, r16
	.endm

	/* r0 = (\reg ^ value) & mask: 0 in each lane that matches */
	.macro	MATCH reg
	xor	r0, \reg, r17
	and	r0, r0, r16
	.endm

	.macro	MATCH16 reg
	MATCH	\reg
	qbeq	trg_fire, r0.w0, 0
	qbeq	trg_fire, r0.w2, 0
	.endm

	.macro	MATCH8 reg
	MATCH	\reg
	qbeq	trg_fire, r0.b0, 0
	qbeq	trg_fire, r0.b1, 0
	qbeq	trg_fire, r0.b2, 0
	qbeq	trg_fire, r0.b3, 0
	.endm

trg_none:
	jmp	r1.w2

trg_arm:
	sub	r20, r20, 1
	qbne	1f, r20, 0
	mov	r15.w0, r18.w0
	qbbs	1f, r28, r17
	mov	r15.w0, r18.w2
1:
	jmp	r1.w2

rise_low:
	ALL	and
	qbeq	1f, r0, r16		/* no low sample */
	qbbs	trg_fire, r28, r17	/* low, then high again: it rose */
	mov	r15.w0, r18.w2
1:
	jmp	r1.w2

any_high:
	ALL	or
	qbne	trg_fire, r0, 0
	jmp	r1.w2

fall_high:
	ALL	or
	qbeq	1f, r0, 0		/* no high sample */
	qbbc	trg_fire, r28, r17	/* high, then low again: it fell */
	mov	r15.w0, r18.w0
1:
	jmp	r1.w2

any_low:
	ALL	and
	qbne	trg_fire, r0, r16
	jmp	r1.w2

pattern8:
	MATCH8	r21
	MATCH8	r22
	MATCH8	r23
	MATCH8	r24
	MATCH8	r25
	MATCH8	r26
	MATCH8	r27
	MATCH8	r28
	jmp	r1.w2

pattern16:
	MATCH16	r22
	MATCH16	r24
	MATCH16	r26
	MATCH16	r28
pattern16_half:
	MATCH16	r21
	MATCH16	r23
	MATCH16	r25
	MATCH16	r27
	jmp	r1.w2

trg_fire:
	ldi	r0, BL_CTRL_TRIG_POST
	add	r0, r0, r14
	lbbo	&r20, r0, 0, 4
	sbbo	&r4, r0, BL_CTRL_TRIG_BLOCK - BL_CTRL_TRIG_POST, 4
	ldi	r15.w0, %pmem(trg_post)
	jmp	r1.w2

trg_post:
	sub	r20, r20, 1
	qbeq	done, r20, 0
	jmp	r1.w2

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
