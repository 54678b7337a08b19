// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * ws281x: PRU firmware of the ws281x (NeoPixel) driver.
 *
 * The control block (ws281x_proto.h) is polled in a loop that only reads
 * its command word.  A SHOW is checked, copied (the driver may post the
 * next frame's parameters as soon as this one is taken), answered, then
 * sent by ws281x_send.S: all strings at once, one bit slot of 250 cycles
 * after the other, edges at fixed offsets from each slot's start (the
 * schedule, each pin kind's offset and the cycle budget are described
 * there).  After the reset the frame is counted, a SHOW posted meanwhile
 * is taken (answered), and then the event is strobed.
 *
 * With two cores that both drive GPIO strings the driver asks them to run
 * in step (@sync, ws281x_proto.h): before each frame the follower (PRU1)
 * says it is ready, the leader (PRU0) waits for that and publishes slot
 * 0's deadline on the IEP counter, and the follower starts
 * WS281X_SYNC_PHASE cycles after it, so that their bank writes interleave.
 */
#include <stdint.h>
#include <am335x/pruss_cfg.h>
#include <am335x/pruss_ctrl.h>
#include <am335x/pruss_iep.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#include "ws281x_fw.h"

PRUKIT_RESOURCE_TABLE_EMPTY();

/* The image initialises the header: the driver checks it right after loading. */
struct ws281x_ctrl ws281x_ctrl __attribute__((section(".prukit_ctrl"), used)) = {
	.hdr = {
		.magic = WS281X_MAGIC,
		.version = WS281X_VERSION,
		.size = sizeof(struct ws281x_ctrl),
	},
};

/* The other core's control block, in its data RAM */
#define OTHER_CTRL ((volatile struct ws281x_ctrl *)(PRUSS_LOCAL_DRAM_OTHER + PRUKIT_CTRL_DA))

/* Cycles before slot 0 at which set_clock() hands over to the send */
#define PRE_WAIT 200
/* The fewest cycles before slot 0 the send needs (setup, slot 0's read) */
#define MIN_AHEAD 120

/* Poll rounds of about 10 cycles each: WS281X_SYNC_WAIT cycles */
#define SYNC_ROUNDS (WS281X_SYNC_WAIT / 10)

/* Copy SHOW's parameters and check them; returns a WS281X_* result. */
static uint32_t take_show(volatile struct ws281x_ctrl *c, struct ws281x_job *job,
			  uint32_t *event, uint32_t *gpio)
{
	uint32_t any, b;

	job->frame = c->frame;
	job->slots = c->slots;
	job->r30_mask = c->r30_mask;
	any = job->r30_mask;
	*gpio = 0;
	for (b = 0; b < WS281X_GPIO_BANKS; b++) {
		job->gpio_mask[b] = c->gpio_mask[b];
		*gpio |= job->gpio_mask[b];
	}
	any |= *gpio;
	job->reset = c->reset;
	job->first_cycle_addr = (uint32_t)(uintptr_t)&c->first_cycle;
	job->sync = c->sync;
	*event = c->event;

	if (job->slots < 1 || job->slots > WS281X_MAX_SLOTS ||
	    job->sync > WS281X_SYNC_FOLLOWER ||
	    (job->sync && !*gpio) ||
	    (job->sync == WS281X_SYNC_LEADER && PRUKIT_PRU_CORE != 0) ||
	    (job->sync == WS281X_SYNC_FOLLOWER && PRUKIT_PRU_CORE != 1) ||
	    job->reset < WS281X_RESET_MIN ||
	    *event < PRU_R31_EVENT_FIRST || *event > PRU_R31_EVENT_LAST ||
	    !job->frame || !any)
		return WS281X_EINVAL;
	return WS281X_OK;
}

/*
 * Answer a new command (*last tells it from the one answered before);
 * returns 1 if it is a SHOW that was taken: its parameters are in *job.
 */
static int take(volatile struct ws281x_ctrl *c, uint16_t *last, struct ws281x_job *job,
		uint32_t *event, uint32_t *gpio)
{
	uint32_t cmd = c->hdr.command, res;
	uint16_t seq = PRUKIT_CTRL_SEQ(cmd);

	if (seq == *last)
		return 0;
	*last = seq;
	if (PRUKIT_CTRL_OPCODE(cmd) != WS281X_CMD_SHOW) {
		c->hdr.status = PRUKIT_CTRL_STATUS(seq, WS281X_EOPCODE);
		return 0;
	}
	res = take_show(c, job, event, gpio);
	c->hdr.status = PRUKIT_CTRL_STATUS(seq, res);	/* taken, or refused */
	return res == WS281X_OK;
}

/* The IEP counter, one count per PRU cycle, running (both cores may ask). */
static void iep_start(void)
{
	uint32_t cfg = (1u << PRU_IEP_GLOBAL_CFG_DEFAULT_INC_SHIFT) |
		       (1u << PRU_IEP_GLOBAL_CFG_CMP_INC_SHIFT) | PRU_IEP_GLOBAL_CFG_CNT_ENABLE;

	if (pru_iep_read(PRU_IEP_GLOBAL_CFG) != cfg)
		pru_iep_write(PRU_IEP_GLOBAL_CFG, cfg);
}

/*
 * Where this frame's deadlines come from, and slot 0's: the core's own
 * CYCLE (restarted: it stops at 0xffffffff, 21 s), or, in step with the
 * other core, the IEP counter.
 */
static void set_clock(volatile struct ws281x_ctrl *c, struct ws281x_job *job)
{
	uint32_t want = c->frames + 1, n;

	if (job->sync == WS281X_SYNC_NONE) {
		pru_cycle_counter_restart();
		job->clock = PRUSS_LOCAL_CTRL;
		job->wait_fixed = WS281X_WAIT_CTRL;
		job->start = 0;
		return;
	}
	iep_start();
	job->clock = PRUSS_LOCAL_IEP;
	job->wait_fixed = WS281X_WAIT_IEP;
	job->start = 0;
	if (job->sync == WS281X_SYNC_LEADER) {
		for (n = 0; OTHER_CTRL->ready != want; n++)
			if (n == SYNC_ROUNDS)
				break;
		job->start = pru_iep_read(PRU_IEP_COUNT) + WS281X_SYNC_LEAD;
		c->start_at = job->start;
		c->started = want;
	} else {
		c->ready = want;
		for (n = 0; OTHER_CTRL->started != want; n++)
			if (n == SYNC_ROUNDS)
				break;
		if (n < SYNC_ROUNDS)
			job->start = OTHER_CTRL->start_at + WS281X_SYNC_PHASE;
		/* a leader that went ahead alone: no deadline in the past */
		if (job->start &&
		    (int32_t)(job->start - pru_iep_read(PRU_IEP_COUNT)) < MIN_AHEAD) {
			job->start = 0;
			n = SYNC_ROUNDS;
		}
	}
	if (n == SYNC_ROUNDS)
		c->unsynced++;
	/*
	 * ws281x_send.S waits at most 255 cycles for a deadline: come within
	 * PRE_WAIT of slot 0 here, which leaves the send's setup and slot 0's
	 * read (about 80 cycles) their time.
	 */
	if (job->start)
		while ((int32_t)(job->start - pru_iep_read(PRU_IEP_COUNT)) > PRE_WAIT)
			;
}

/*
 * Before the first frame: the outputs may be high (R30 keeps what the last
 * program left there), and a string needs a low of at least the reset
 * before its first bit.  GPIO pins are low already: the driver takes them
 * as outputs driven low.
 */
static void first_low(const struct ws281x_job *job)
{
	write_r30(read_r30() & ~job->r30_mask);
	pru_cycle_counter_restart();
	while (pru_cycle_counter_read() < job->reset)
		;
}

int main(void)
{
	volatile struct ws281x_ctrl *c = &ws281x_ctrl;
	struct ws281x_job job;
	uint16_t last = 0;

	pruss_ocp_master_enable();
	pru_cycle_counter_restart();
	c->hdr.status = PRUKIT_CTRL_STATUS(0, WS281X_OK);
	for (;;) {
		uint32_t event, gpio, done_event;
		int go;

		if (PRUKIT_CTRL_SEQ(c->hdr.command) == last)
			continue;	/* only reads: the simulator sees a waiting core */
		go = take(c, &last, &job, &event, &gpio);
		if (go && !c->frames)
			first_low(&job);
		while (go) {
			set_clock(c, &job);
			if (gpio)
				ws281x_send_gpio(&job);
			else
				ws281x_send_r30(&job);
			c->frames++;
			/*
			 * A frame the driver queued meanwhile is taken before
			 * the event: with the event the driver sees it taken,
			 * and may queue the next one.
			 */
			done_event = event;
			go = take(c, &last, &job, &event, &gpio);
			r31_strobe_event(done_event);
		}
	}
}
