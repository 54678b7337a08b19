/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * ws281x firmware: the bit-sending loops (ws281x_proto.h has the protocol).
 *
 *   uint32_t ws281x_send_r30(const struct ws281x_job *job);
 *   uint32_t ws281x_send_gpio(const struct ws281x_job *job);
 *
 * Send job->slots bit slots of struct ws281x_slot, read from DDR at
 * job->frame over the OCP master port, on every string at once, then hold
 * the strings low for job->reset cycles from the end of the last slot.
 * Returns the CYCLE value at which slot 0 started, also stored at
 * job->first_cycle_addr when slot 0 is about to start.  The caller
 * restarts CYCLE before each frame, so it cannot saturate during one
 * (at most 2^20 slots: 262144000 cycles).
 *
 * Schedule of every slot, in cycles of 5 ns from the slot's start S:
 *
 *   S + 0     every string rises
 *   S + 70    strings whose bit is 0 fall        (WS281X_T0H_CYCLES)
 *   S + 140   the others fall                     (WS281X_T1H_CYCLES)
 *   S + 250   the next slot starts                (WS281X_SLOT_CYCLES)
 *
 * Every edge instruction is issued at a deadline taken from the core's
 * CYCLE counter (wait_until below), not after a count of the instructions
 * before it: an OCP read or a GPIO store that stalls the core for a few
 * cycles more or less than the simulator assumes moves no edge, as long as it
 * ends before the deadline.  The slack left before each deadline is the
 * margin (below).
 *
 * Pin kinds and their offset from S (the simulator's defaults):
 *
 *   R30 bits          0 cycles: "mov r30" is the edge, exact on a board too.
 *   GPIO bank b       each edge writes SETDATAOUT (rise: the bank's mask) or
 *                     CLEARDATAOUT (at +70: mask & ~ones, at +140: mask) of
 *                     banks 0, 1, 2, 3 in this order, right after the R30
 *                     edge, whatever the masks (a write of 0 changes nothing),
 *                     so each bank's edges keep one distance from S.  The
 *                     simulator lands a GPIO store gpio_write_latency (17) cycles after
 *                     the bank accepts it and accepts one 32-bit write per
 *                     gpio_write_interval (8) cycles, the core stalling on a
 *                     busy path: bank b's store issues at S+1+8b (the first
 *                     one finds the path free), so bank b's edges land at
 *                     S + 18 + 8b: 18, 26, 34, 42 cycles.
 *
 * Latency and interval are guesses the simulator makes configurable (-C): on a
 * board L4 writes cross the interconnect with a latency that varies with
 * traffic, so the edges of GPIO strings may move by a few cycles (tens of
 * ns, well inside the WS281x's +-150 ns) from one edge to the next; R30
 * edges are exact to the cycle.  The GPIO pins must be outputs (OE), set
 * by whoever muxes them: the firmware only writes SET/CLEARDATAOUT.
 *
 * Cycle budget of a slot, GPIO variant (the simulator's defaults):
 *   S+0..25    R30 edge + 4 stores (the 2nd..4th wait for the path: 25)
 *   S+26..36   the next edges' values (10), next deadline (1)
 *   S+37..69   wait_until: 10 + 23 cycles of slack
 *   S+70..96   R30 edge + 4 CLEARDATAOUT, next deadline
 *   S+97..139  wait_until: 10 + 33 slack
 *   S+140..168 R30 edge + 4 CLEARDATAOUT, slot count, pointer
 *   S+169..215 next slot's 20 bytes from DDR (43 + 4 cycles)
 *   S+216..249 deadline, loop, wait_until: 10 + 22 slack
 * so 22 cycles (110 ns) are left in the tightest window: a DDR read may
 * take up to 69 cycles before an edge moves.  R30 variant: only the
 * slot's r30 word is read (43 cycles); slack 56, 58 and 51 cycles.
 *
 * GCC's PRU ABI: the argument in r14, the result in r14; r0, r1 and
 * r14..r29 are the caller's, r4..r13 are saved here (r4..r11 used); r2
 * is the stack pointer, r3.w2 the return address.
 *
 * The clock: deadlines are values of the counter at job->clock + 0x0c,
 * the core's own CTRL CYCLE, or the IEP counter that both cores share when
 * they run in step (ws281x_proto.h, @sync; the C side chooses, and sets
 * job->wait_fixed to match: see WS281X_WAIT_* in ws281x_fw.h).
 *
 * Registers while sending:
 *   r0  R30 with every string low     r1  reset cycles
 *   r4..r7  &GPIO bank b CLEARDATAOUT (SETDATAOUT is the next word)
 *   r8  the clock's register block    r9  deadline of the slot's start
 *   r10 deadline of the next fall     r15 bus address of the slot read next
 *   r16 slots left                    r17 R30 mask
 *   r18..r21 GPIO bank masks          r22 &first_cycle
 *   r23 slot.r30 (then R30 after the 0s fell)
 *   r24..r27 slot.gpio[b] (then mask & ~ones)
 *   r28 R30 with every string high    r29 scratch
 *   r11 job->wait_fixed
 */

#define SLOT_CYCLES	250		/* WS281X_SLOT_CYCLES */
#define T0H_CYCLES	70		/* WS281X_T0H_CYCLES */
#define T1H_CYCLES	140		/* WS281X_T1H_CYCLES */
#define SLOT_BYTES	20		/* sizeof(struct ws281x_slot) */
#define JOB_BYTES	48		/* sizeof(struct ws281x_job), ws281x_fw.h */
#define SAVE_BYTES	32		/* r4..r11 */

#define CTRL_CYCLE	0x0c		/* CTRL CYCLE, and IEP COUNT */

#define GPIO_CLEAR	0x190		/* CLEARDATAOUT; SETDATAOUT is at +4 */
#define GPIO_SET_OFF	4
#define GPIO0_CLEAR	(0x44e07000 + GPIO_CLEAR)
#define GPIO1_CLEAR	(0x4804c000 + GPIO_CLEAR)
#define GPIO2_CLEAR	(0x481ac000 + GPIO_CLEAR)
#define GPIO3_CLEAR	(0x481ae000 + GPIO_CLEAR)

/* Deadline of slot 0, from the CYCLE read that sets it (slack 16 cycles) */
#define FIRST_LEAD	30

/*
 * wait_until DL: the next instruction issues in the cycle in which the
 * clock reads DL.  r11 (job->wait_fixed) is the number of cycles between
 * the value the clock's "lbbo" returns and the cycle in which the
 * instruction after wait_until issues, besides the wait itself.  Costs
 * 10 + n cycles, n = the cycles left, burnt exactly: one more for odd n,
 * then n / 2 rounds of sub/qbne.  A deadline already
 * passed (n "negative") or further than 255 cycles does not wait: an edge
 * would be late, never lost, and nothing can hang here.
 */
.macro	wait_until dl
	lbbo	&r29, r8, CTRL_CYCLE, 4
	sub	r29, \dl, r29
	sub	r29, r29, r11
	qblt	9f, r29, 255
	qbbc	8f, r29, 0
	nop
8:	lsr	r29, r29, 1
	qbeq	9f, r29, 0
7:	sub	r29, r29, 1
	qbne	7b, r29, 0
9:
.endm

/*
 * Save r4..r11, load the job (r15..r26: frame, slots, r30_mask,
 * gpio_mask[4], reset, &first_cycle, clock, wait_fixed, start), and the
 * R30 values with every string low and high; bits outside the mask keep
 * what R30 holds.
 */
.macro	prologue
	sub	r2, r2, SAVE_BYTES
	sbbo	&r4, r2, 0, SAVE_BYTES
	lbbo	&r15, r14, 0, JOB_BYTES
	mov	r1, r22
	mov	r22, r23
	mov	r8, r24
	mov	r11, r25
	mov	r10, r26
	not	r29, r17
	and	r0, r30, r29
	or	r28, r0, r17
.endm

/*
 * Slot 0's data is in r23.. already: its deadline is the job's start, or
 * (start 0) FIRST_LEAD cycles from now; publish it as first_cycle, and
 * return it.
 */
.macro	first_deadline
	qbne	5f, r10, 0
	lbbo	&r29, r8, CTRL_CYCLE, 4
	add	r10, r29, FIRST_LEAD
5:	mov	r9, r10
	sbbo	&r9, r22, 0, 4
	mov	r14, r9
.endm

/*
 * After the last slot's fall: wait for the end of that slot, then hold
 * every string low for at least r1 cycles, counted (2 per round) rather
 * than read from CYCLE, which a long reset could take to saturation.
 */
.macro	epilogue
	add	r9, r9, SLOT_CYCLES
	wait_until r9
	lsr	r29, r1, 1
	add	r29, r29, 1
6:	sub	r29, r29, 1
	qbne	6b, r29, 0
	lbbo	&r4, r2, 0, SAVE_BYTES
	add	r2, r2, SAVE_BYTES
	ret
.endm

	.section .text.ws281x_send_r30, "ax", @progbits
	.global	ws281x_send_r30
	.type	ws281x_send_r30, @function
ws281x_send_r30:
	prologue
	lbbo	&r23, r15, 0, 4			/* slot 0: only its r30 word */
	first_deadline
.Lr30_slot:
	wait_until r9
	mov	r30, r28			/* S + 0: every string rises */
	and	r23, r23, r17
	or	r23, r23, r0			/* R30 once the 0s fell */
	add	r10, r9, T0H_CYCLES
	wait_until r10
	mov	r30, r23			/* S + 70: the 0s fall */
	add	r10, r9, T1H_CYCLES
	wait_until r10
	mov	r30, r0				/* S + 140: the 1s fall */
	sub	r16, r16, 1
	qbeq	.Lr30_done, r16, 0
	add	r15, r15, SLOT_BYTES
	lbbo	&r23, r15, 0, 4			/* the next slot, in the low part */
	add	r9, r9, SLOT_CYCLES
	qba	.Lr30_slot
.Lr30_done:
	epilogue
	.size	ws281x_send_r30, . - ws281x_send_r30

	.section .text.ws281x_send_gpio, "ax", @progbits
	.global	ws281x_send_gpio
	.type	ws281x_send_gpio, @function
ws281x_send_gpio:
	prologue
	ldi32	r4, GPIO0_CLEAR
	ldi32	r5, GPIO1_CLEAR
	ldi32	r6, GPIO2_CLEAR
	ldi32	r7, GPIO3_CLEAR
	lbbo	&r23, r15, 0, SLOT_BYTES	/* slot 0 */
	first_deadline
.Lgpio_slot:
	wait_until r9
	mov	r30, r28			/* S + 0: every string rises */
	sbbo	&r18, r4, GPIO_SET_OFF, 4
	sbbo	&r19, r5, GPIO_SET_OFF, 4
	sbbo	&r20, r6, GPIO_SET_OFF, 4
	sbbo	&r21, r7, GPIO_SET_OFF, 4
	and	r23, r23, r17
	or	r23, r23, r0			/* R30 once the 0s fell */
	and	r24, r24, r18
	xor	r24, r24, r18			/* bank 0: mask & ~ones */
	and	r25, r25, r19
	xor	r25, r25, r19
	and	r26, r26, r20
	xor	r26, r26, r20
	and	r27, r27, r21
	xor	r27, r27, r21
	add	r10, r9, T0H_CYCLES
	wait_until r10
	mov	r30, r23			/* S + 70: the 0s fall */
	sbbo	&r24, r4, 0, 4
	sbbo	&r25, r5, 0, 4
	sbbo	&r26, r6, 0, 4
	sbbo	&r27, r7, 0, 4
	add	r10, r9, T1H_CYCLES
	wait_until r10
	mov	r30, r0				/* S + 140: the 1s fall */
	sbbo	&r18, r4, 0, 4
	sbbo	&r19, r5, 0, 4
	sbbo	&r20, r6, 0, 4
	sbbo	&r21, r7, 0, 4
	sub	r16, r16, 1
	qbeq	.Lgpio_done, r16, 0
	add	r15, r15, SLOT_BYTES
	lbbo	&r23, r15, 0, SLOT_BYTES	/* the next slot, in the low part */
	add	r9, r9, SLOT_CYCLES
	qba	.Lgpio_slot
.Lgpio_done:
	epilogue
	.size	ws281x_send_gpio, . - ws281x_send_gpio
