/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * ws281x firmware: what ws281x.c hands to the sending loops of
 * ws281x_send.S (whose header comment has the schedule and timing).
 */
#ifndef _WS281X_FW_H
#define _WS281X_FW_H

#include <assert.h>
#include <stddef.h>
#include <stdint.h>

#include "ws281x_proto.h"

/*
 * A frame's parameters, copied from the control block; ws281x_send.S loads
 * it with one burst, in this order (JOB_BYTES there).
 */
struct ws281x_job {
	uint32_t frame;
	uint32_t slots;
	uint32_t r30_mask;
	uint32_t gpio_mask[WS281X_GPIO_BANKS];
	uint32_t reset;
	uint32_t first_cycle_addr;	/* where slot 0's CYCLE goes */
	uint32_t clock;			/* the deadlines' counter: CTRL or IEP base */
	uint32_t wait_fixed;		/* WS281X_WAIT_CTRL or WS281X_WAIT_IEP */
	uint32_t start;			/* slot 0's deadline, 0: from now */
	uint32_t sync;			/* not read by ws281x_send.S */
};

/*
 * Cycles between the value a 4-cycle "lbbo" of the clock returns and the
 * cycle in which the instruction after wait_until issues, besides the
 * wait itself: sub, sub, qblt, qbbc, lsr, qbeq after the load, plus the
 * load's cycles after it sampled the counter.  The core's own CYCLE is
 * sampled in the load's last cycle (3 after its issue); the IEP counter
 * when the load issues, 3 cycles earlier.
 */
#define WS281X_WAIT_CTRL	7
#define WS281X_WAIT_IEP		10

static_assert(offsetof(struct ws281x_job, sync) == 48, "ws281x_send.S: JOB_BYTES");
static_assert(offsetof(struct ws281x_job, reset) == 28, "ws281x_send.S: job layout");
static_assert(sizeof(struct ws281x_slot) == 20, "ws281x_send.S: SLOT_BYTES");
static_assert(WS281X_SLOT_CYCLES == 250 && WS281X_T0H_CYCLES == 70 &&
	      WS281X_T1H_CYCLES == 140, "ws281x_send.S: the schedule");

/*
 * Send the frame (R30 strings only, or R30 and GPIO strings), then hold
 * the strings low for job->reset cycles; return slot 0's CYCLE.
 */
uint32_t ws281x_send_r30(const struct ws281x_job *job);
uint32_t ws281x_send_gpio(const struct ws281x_job *job);

#endif /* _WS281X_FW_H */
