/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * pru_pwm_proto.h - the pru_pwm driver's control block, shared verbatim by
 * the driver (drivers/pru_pwm/pru_pwm.c) and its PRU firmware
 * (firmware/pru_pwm.c, firmware/pru_pwm_run.S).
 *
 * The firmware plays a table: one period of every channel at once, as a
 * list of steps, each a time from the period's start and the value R30
 * takes then.  The driver computes the table from the channels' states
 * (pru_pwm_table_build() in the driver: every channel rises, or falls for
 * inversed polarity, at step 0 and changes back at its duty cycle; edges
 * in the same cycle are one step), and the firmware writes each step's
 * value to R30 in the cycle its deadline names on the IEP counter, then
 * starts the next period exactly @period cycles after the last one.
 *
 * Two tables: the firmware plays one, the driver fills the other and asks
 * for it with SET.  The firmware looks for a command only at the end of a
 * period, so a new table starts at a period's start: no period is cut
 * short and no pulse is split (no runt).  It answers SET in that cycle
 * (status READY | result | seq << 16) and says which table it plays in
 * @active.  Before the first SET it plays nothing and R30 stays as it is.
 *
 * Timing, in PRU cycles of 5 ns, guaranteed by the firmware's loop
 * (pru_pwm_run.S counts it; the driver's tables respect it):
 *  - a step's R30 write lands exactly at its deadline when it comes at
 *    least PRU_PWM_MIN_GAP cycles after the step before it, and the first
 *    step of a period at least PRU_PWM_END_GAP cycles after the last step
 *    of the one before (the end of a period is where commands are taken);
 *  - a deadline that comes earlier is late, never lost: its write comes
 *    as soon as the loop gets there, it is counted in @late, and later
 *    deadlines keep their time.  The driver never builds such a table.
 */
#ifndef _PRU_PWM_PROTO_H
#define _PRU_PWM_PROTO_H

#ifdef __KERNEL__
#include "prukit/pru_ctrl.h"
#else
#include <prukit/pru_ctrl.h>
#endif

#define PRU_PWM_MAGIC		0x4d575072u	/* "rPWM" */
#define PRU_PWM_VERSION		1

#define PRU_PWM_CHANNELS	8
/* step 0 and one step per channel's second edge */
#define PRU_PWM_MAX_STEPS	(PRU_PWM_CHANNELS + 1)

/* The loop's timing, in PRU cycles (pru_pwm_run.S) */
#define PRU_PWM_MIN_GAP		23	/* between two steps of a period */
/*
 * From a period's last step to its end: the loop needs 71 cycles when it
 * takes a SET there (pru_pwm_run.S), 9 more leave room for a board's
 * memory accesses being slower than the simulator's
 */
#define PRU_PWM_END_GAP		80
/* The shortest period: every step apart, and room at the end */
#define PRU_PWM_MIN_PERIOD	(PRU_PWM_CHANNELS * PRU_PWM_MIN_GAP + PRU_PWM_END_GAP)
/* The longest period: 2^31 - 1 cycles, 10.7 s (deadlines compare signed) */
#define PRU_PWM_MAX_PERIOD	0x7fffffffu
/* The first period starts this long after the first SET is taken */
#define PRU_PWM_LEAD		64

/* Opcodes */
#define PRU_PWM_CMD_SET		1	/* play table @next from the next period */

/* Results */
#define PRU_PWM_OK		0
#define PRU_PWM_EINVAL		1	/* @next or the table's header out of range */
#define PRU_PWM_EOPCODE		2	/* unknown opcode */

/* @active before the first SET */
#define PRU_PWM_NONE		0xffffffffu

/* struct pru_pwm_chan @flags */
#define PRU_PWM_CHAN_ENABLED	0x1u
#define PRU_PWM_CHAN_INVERSED	0x2u

/**
 * struct pru_pwm_step - one R30 write of a period
 * @at: cycles from the period's start (step 0: 0; increasing)
 * @r30: the value R30 takes in that cycle
 */
struct pru_pwm_step {
	__u32 at;
	__u32 r30;
} __packed __aligned(4);

/**
 * struct pru_pwm_chan - what a table does on one channel
 * @duty: cycles the channel is active in each period
 * @flags: PRU_PWM_CHAN_ENABLED, PRU_PWM_CHAN_INVERSED
 * @period: cycles of the channel's period: the table's while enabled, the
 *	one last asked for while disabled
 *
 * The firmware does not read this; the driver keeps it beside the table
 * it describes, so that what it reports (get_state) is what the table the
 * firmware plays does.
 */
struct pru_pwm_chan {
	__u32 duty;
	__u32 flags;
	__u32 period;
} __packed __aligned(4);

/**
 * struct pru_pwm_table - one period of every channel
 * @period: cycles, PRU_PWM_MIN_PERIOD..PRU_PWM_MAX_PERIOD
 * @steps: steps used, 1..PRU_PWM_MAX_STEPS
 * @step: the steps, @step[0].at == 0
 * @chan: the driver's description of each channel (not read by the firmware)
 */
struct pru_pwm_table {
	__u32 period;
	__u32 steps;
	struct pru_pwm_step step[PRU_PWM_MAX_STEPS];
	struct pru_pwm_chan chan[PRU_PWM_CHANNELS];
} __packed __aligned(4);

/**
 * struct pru_pwm_ctrl - the control block, at PRUKIT_CTRL_DA in the core's RAM
 * @hdr: magic PRU_PWM_MAGIC, version PRU_PWM_VERSION, command and status
 * @next: SET: the table to play, 0 or 1
 * @active: the table played (0 or 1), PRU_PWM_NONE before the first SET
 * @periods: periods started since the first SET
 * @late: steps written after their deadline (0 unless a table broke the
 *	rules above)
 * @started_at: the IEP count at the start of the first period of the
 *	table played, for tests
 * @table: the two tables
 */
struct pru_pwm_ctrl {
	struct prukit_ctrl_hdr hdr;
	__u32 next;
	__u32 active;
	__u32 periods;
	__u32 late;
	__u32 started_at;
	struct pru_pwm_table table[2];
} __packed __aligned(4);

#endif /* _PRU_PWM_PROTO_H */
