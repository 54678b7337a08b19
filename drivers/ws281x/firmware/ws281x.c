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
 */
#include <stdint.h>
#include <am335x/pruss_cfg.h>
#include <am335x/pruss_ctrl.h>
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
	*event = c->event;

	if (job->slots < 1 || job->slots > WS281X_MAX_SLOTS ||
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
			continue;	/* only reads: pru_sim sees a waiting core */
		go = take(c, &last, &job, &event, &gpio);
		while (go) {
			/* from 0 each frame: CYCLE stops at 0xffffffff (21 s) */
			pru_cycle_counter_restart();
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
