/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * pru_pwm firmware: the table-playing loop (pru_pwm_proto.h has the
 * protocol).
 *
 *   void pru_pwm_run(volatile struct pru_pwm_ctrl *c);   (never returns)
 *
 * Until the first SET only the command word is read (the simulator sees a
 * waiting core).  Then, for every period starting at deadline S on the
 * IEP counter (one count per PRU cycle), for each step k of the table:
 * wait until the counter reads S + step[k].at and write step[k].r30 to
 * R30 in that very cycle.  After the last step: S += period, count the
 * period, look at the command word, take a SET (which may change the
 * table from this period on), and go on.
 *
 * Cycle budget (the simulator's costs: 4 cycles for an lbbo of up to 8
 * bytes from data RAM, 1 for everything else here; wait_until below costs
 * 14 cycles plus the wait), from the R30 write E of a step:
 *
 *   next step:    E+1 count, E+2 pointer, E+3 qblt, E+4..7 load the step,
 *                 E+8 its deadline, E+9 wait_until's read: the next write
 *                 comes at E+23 at the earliest: PRU_PWM_MIN_GAP.
 *   period end:   E+4 S += period, E+5.. store the counts, read the
 *                 command, and without one, the next period's first write
 *                 at E+36 at the earliest; taking a SET, at E+71
 *                 (measured in the simulator: drivers/pru_pwm/tests);
 *                 PRU_PWM_END_GAP is 80.
 *
 * The deadlines are absolute: a step that is late (a table that breaks
 * these gaps) does not move the next ones, and nothing can hang here.  The
 * IEP counter is the PRU-ICSS's, shared with the other core: firmware
 * there that restarts it (beaglelogic's and hub75's do, at each capture or
 * frame) makes the counter jump back, which a wait sees as a deadline
 * further away than any step can be (r6: the period, or the longer of the
 * two periods while the first period of a new table waits for the end of
 * the last one of the old); the period is then restarted from the step
 * that waits (one period's timing broken, counted in @late).
 *
 * Registers:
 *   r6  the furthest a deadline can be r7  PRU_PWM_MIN_PERIOD
 *   r8  the IEP's registers
 *   r9  S, this period's start         r10 the table played
 *   r11 its period                     r12 its steps
 *   r13 steps written this period      r15 step.at (scratch in take)
 *   r16 step.r30 (scratch in take)     r17 the step's deadline
 *   r18 the control block              r19 sequence of the last command
 *   r20 the step read next             r21..r24 scratch
 *   r25 periods                        r26 late (r25, r26: one store)
 *   r27 &table[0]                      r28 &table[1]
 *   r29 scratch of wait_until          r3.w2 return address of take
 */

#define IEP		0x2e000		/* PRUSS_LOCAL_IEP */
#define IEP_COUNT	0x0c

#define CMD_OFF		8		/* offsets in struct pru_pwm_ctrl */
#define STATUS_OFF	12
#define NEXT_OFF	16
#define ACTIVE_OFF	20
#define PERIODS_OFF	24		/* and late after it */
#define STARTED_OFF	32
#define TABLE0_OFF	36
#define TABLE_BYTES	176		/* sizeof(struct pru_pwm_table) */
#define STEP0_OFF	8
#define STEP_BYTES	8

#define MAX_STEPS	9		/* PRU_PWM_MAX_STEPS */
#define MIN_PERIOD	264		/* PRU_PWM_MIN_PERIOD */
#define LEAD		64		/* PRU_PWM_LEAD */
#define CMD_SET		1		/* PRU_PWM_CMD_SET */
#define RES_OK		0		/* PRU_PWM_OK */
#define RES_EINVAL	1		/* PRU_PWM_EINVAL */
#define RES_EOPCODE	2		/* PRU_PWM_EOPCODE */

/*
 * Cycles from the cycle in which wait_until's "lbbo" issues (the IEP
 * counter is sampled then) to the instruction after it, besides the wait:
 * lbbo 4, sub, sub, qbbs, qblt, qbbc, lsr, add, qba (the nop of an odd wait
 * and the rounds of sub/qbne are the wait; one round more than the wait's
 * half, so that the count never starts at 0).
 */
#define WAIT_FIXED	14
/* Further than this, wait_until reads the counter again */
#define WAIT_FAR	255

/*
 * wait_until DL: the next instruction issues in the cycle in which the
 * IEP counter reads DL.  A deadline already passed does not wait (counted
 * in r26); one further than any can be (r6) means the counter jumped back:
 * S is moved so that this step's deadline is now (counted too).
 */
.macro	wait_until dl
1:	lbbo	&r29, r8, IEP_COUNT, 4
	sub	r29, \dl, r29
	sub	r29, r29, WAIT_FIXED
	qbbs	5f, r29, 31
	qblt	4f, r29, WAIT_FAR
	qbbc	2f, r29, 0
	nop
2:	lsr	r29, r29, 1
	add	r29, r29, 1
3:	sub	r29, r29, 1
	qbne	3b, r29, 0
	qba	6f
4:	qbge	1b, r29, r6			/* r29 <= r6: wait on */
	lbbo	&r29, r8, IEP_COUNT, 4		/* the counter jumped back */
	sub	r9, r29, r15
	mov	\dl, r29
5:	add	r26, r26, 1
6:
.endm

	.section .text.pru_pwm_run, "ax", @progbits
	.global	pru_pwm_run
	.type	pru_pwm_run, @function
pru_pwm_run:
	mov	r18, r14
	ldi32	r8, IEP
	ldi	r7, MIN_PERIOD
	add	r27, r18, TABLE0_OFF
	add	r28, r18, TABLE0_OFF + TABLE_BYTES
	ldi	r19, 0
	ldi	r25, 0
	ldi	r26, 0
	ldi	r11, 0

	/* No table yet: only the command word is read. */
.Lidle:
	lbbo	&r21, r18, CMD_OFF, 4
	lsr	r22, r21, 16
	qbeq	.Lidle, r22, r19
	jal	r3.w2, take
	qbeq	.Lidle, r24, 0
	lbbo	&r9, r8, IEP_COUNT, 4
	add	r9, r9, LEAD
	sbbo	&r9, r18, STARTED_OFF, 4

.Lperiod:
	add	r25, r25, 1
	ldi	r13, 0
	add	r20, r10, STEP0_OFF
.Lstep:
	lbbo	&r15, r20, 0, 8			/* at, r30 */
	add	r17, r9, r15
	wait_until r17
	mov	r30, r16			/* the step's write, at its deadline */
	add	r13, r13, 1
	add	r20, r20, STEP_BYTES
	qblt	.Lstep, r12, r13		/* r13 < steps */

	add	r9, r9, r11			/* the next period's start */
	mov	r6, r11
	sbbo	&r25, r18, PERIODS_OFF, 8
	lbbo	&r21, r18, CMD_OFF, 4
	lsr	r22, r21, 16
	qbeq	.Lperiod, r22, r19
	jal	r3.w2, take
	qbeq	.Lperiod, r24, 0
	sbbo	&r9, r18, STARTED_OFF, 4
	qba	.Lperiod

/*
 * take: answer the new command in r21 (sequence in r22).  A SET of a
 * table whose header is in range makes it the one played (r10, with its
 * period and steps in r11, r12) and returns r24 = 1; anything else leaves
 * the table as it is and returns r24 = 0.  @active is written before
 * @status, so the driver that sees the answer sees the table too.
 */
take:
	mov	r19, r22
	ldi	r24, 0
	ldi	r23, RES_EOPCODE
	qbne	.Lanswer, r21.w0, CMD_SET
	ldi	r23, RES_EINVAL
	lbbo	&r21, r18, NEXT_OFF, 4
	mov	r22, r27
	qbeq	1f, r21, 0
	mov	r22, r28
	qbne	.Lanswer, r21, 1
1:	lbbo	&r15, r22, 0, 8			/* period, steps */
	qbeq	.Lanswer, r16, 0
	qblt	.Lanswer, r16, MAX_STEPS	/* steps > MAX_STEPS */
	qblt	.Lanswer, r7, r15		/* period < MIN_PERIOD */
	qbbs	.Lanswer, r15, 31		/* period > MAX_PERIOD */
	mov	r10, r22
	max	r6, r11, r15			/* the old period ends first */
	mov	r11, r15
	mov	r12, r16
	ldi	r24, 1
	sbbo	&r21, r18, ACTIVE_OFF, 4
	ldi	r23, RES_OK
.Lanswer:
	lsl	r21, r19, 16
	or	r21, r21, r23
	set	r21, r21, 15			/* PRUKIT_CTRL_READY */
	sbbo	&r21, r18, STATUS_OFF, 4
	jmp	r3.w2
	.size	pru_pwm_run, . - pru_pwm_run
