// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * beaglelogic: PRU firmware of the beaglelogic (logic analyzer) driver.
 *
 * One source, two roles (beaglelogic_proto.h): built for PRU1 it is the
 * sampler (the loops are in bl_sample.S), built for PRU0 the storer
 * (bl_store.S).  Here: the command loop of each, and the checks of START's
 * parameters.  Both poll their control block with loads only, so that an
 * idle core costs the simulator nothing.
 */
#include <stddef.h>
#include <stdint.h>
#include <am335x/pruss.h>
#include <am335x/pruss_cfg.h>
#include <am335x/pruss_iep.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#include "bl_fw.h"

PRUKIT_RESOURCE_TABLE_EMPTY();

static_assert(offsetof(struct bl_ctrl, unit) == BL_CTRL_UNIT, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, divisor) == BL_CTRL_DIVISOR, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, state) == BL_CTRL_STATE, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, error) == BL_CTRL_ERROR, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, filled) == BL_CTRL_FILLED, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, first_iep) == BL_CTRL_FIRST_IEP, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, bufs) == BL_CTRL_BUFS, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, trig_mode) == BL_CTRL_TRIG_MODE, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, trig_post) == BL_CTRL_TRIG_POST, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, trig_block) == BL_CTRL_TRIG_BLOCK, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, ping) == BL_CTRL_PING, "bl_*.S: ctrl layout");
static_assert(offsetof(struct bl_ctrl, pong) == BL_CTRL_PING + 2, "bl_*.S: ctrl layout");

/* The image initialises the header: the driver checks it right after loading. */
struct bl_ctrl bl_ctrl __attribute__((section(".prukit_ctrl"), used)) = {
	.hdr = {
		.magic = BL_MAGIC,
		.version = BL_VERSION,
		.size = sizeof(struct bl_ctrl),
	},
};

/* The other core's control block, in its data RAM */
#define OTHER_CTRL ((volatile struct bl_ctrl *)(PRUSS_LOCAL_DRAM_OTHER + PRUKIT_CTRL_DA))

/* Poll rounds (about 10 cycles each) a core waits for the other one */
#define STOP_ROUNDS 10000000u

static void answer(volatile struct bl_ctrl *c, uint16_t seq, uint32_t result)
{
	c->hdr.status = PRUKIT_CTRL_STATUS(seq, result);
}

#if PRUKIT_PRU_CORE == 1

/* The storer takes blocks (bounded: a stopped PRU0 stalls nothing). */
static int storer_running(void)
{
	uint32_t n;

	for (n = 0; n < STOP_ROUNDS; n++)
		if (OTHER_CTRL->state == BL_FW_RUNNING)
			return 1;
	return 0;
}

/*
 * bl_sample.S's delay between samples, 2 * divisor - 2 cycles: for divisor
 * 2 or 3, @pad 0 or 1 (2 or 4 cycles); from 4 on, 3 + @pad's bits 0 and 1
 * + 3 * -@rounds cycles.
 */
static void delay_params(uint32_t divisor, uint32_t *pad, int32_t *rounds)
{
	uint32_t rest = 2 * divisor - 5;

	*pad = divisor == 3;
	*rounds = 0;
	if (divisor < 4)
		return;
	*rounds = -(int32_t)(rest / 3);
	*pad = (rest % 3 == 0) ? 0 : (rest % 3 == 1) ? 1 : 3;
}

/* The sampler: START samples until the storer raises the stop flag. */
int main(void)
{
	volatile struct bl_ctrl *c = &bl_ctrl;
	uint16_t last = 0;
	uint32_t pad;
	int32_t rounds;

	/* The IEP counter: one count per cycle, for @first_iep. */
	if (!(pru_iep_read(PRU_IEP_GLOBAL_CFG) & PRU_IEP_GLOBAL_CFG_CNT_ENABLE))
		pru_iep_start(1);
	c->state = BL_FW_IDLE;
	answer(c, 0, BL_OK);
	for (;;) {
		uint32_t cmd = c->hdr.command;
		uint16_t seq = PRUKIT_CTRL_SEQ(cmd);

		if (seq == last)
			continue;
		last = seq;
		switch (PRUKIT_CTRL_OPCODE(cmd)) {
		case BL_CMD_START:
			if (c->unit > BL_UNIT_8 || c->divisor < 1 || c->divisor > BL_MAX_DIVISOR) {
				answer(c, seq, BL_EINVAL);
				break;
			}
			/* the storer first: else blocks would go nowhere */
			if (!storer_running()) {
				answer(c, seq, BL_ENOSTORER);
				break;
			}
			delay_params(c->divisor, &pad, &rounds);
			c->state = BL_FW_RUNNING;
			answer(c, seq, BL_OK);
			bl_sample(c, pad, rounds);
			c->state = BL_FW_IDLE;
			break;
		case BL_CMD_STOP:
			answer(c, seq, BL_OK);
			break;
		default:
			answer(c, seq, BL_EOPCODE);
		}
	}
}

#else

static uint32_t check_start(volatile struct bl_ctrl *c)
{
	uint32_t i;

	if (c->unit > BL_UNIT_8 || c->mode > BL_MODE_CONTINUOUS ||
	    c->nbufs < 1 || c->nbufs > BL_MAX_BUFS ||
	    !c->bufsize || c->bufsize % BL_BLOCK_BYTES ||
	    c->event < PRU_R31_EVENT_FIRST || c->event > PRU_R31_EVENT_LAST)
		return BL_EINVAL;
	for (i = 0; i < c->nbufs; i++)
		if (!c->bufs[i] || c->bufs[i] % BL_BLOCK_BYTES)
			return BL_EINVAL;
	/* a trigger: a ring that keeps what comes before it and after it */
	if (c->trig_mode > BL_TRIG_MAX ||
	    (c->trig_mode != BL_TRIG_NONE &&
	     (c->mode != BL_MODE_CONTINUOUS || !c->trig_pre || !c->trig_post ||
	      c->trig_pre + c->trig_post + 1 != c->nbufs * (c->bufsize / BL_BLOCK_BYTES))))
		return BL_EINVAL;
	return BL_OK;
}

/* The sampler stopped (or never ran): bounded, a stopped PRU1 stalls nothing. */
static void wait_sampler(void)
{
	uint32_t n;

	for (n = 0; n < STOP_ROUNDS; n++)
		if (OTHER_CTRL->state != BL_FW_RUNNING)
			return;
}

/*
 * The storer.  A capture ends by itself (one-shot done, or an error) or
 * because a new command came: bl_store() has then raised the stop flag,
 * and that command is handled like any other once the sampler stopped.
 */
int main(void)
{
	volatile struct bl_ctrl *c = &bl_ctrl;
	uint16_t last = 0;

	pruss_ocp_master_enable();
	c->state = BL_FW_IDLE;
	answer(c, 0, BL_OK);
	for (;;) {
		uint32_t cmd = c->hdr.command, res;
		uint16_t seq = PRUKIT_CTRL_SEQ(cmd);

		if (seq == last)
			continue;
		last = seq;
		switch (PRUKIT_CTRL_OPCODE(cmd)) {
		case BL_CMD_START:
			res = check_start(c);
			if (res != BL_OK) {
				answer(c, seq, res);
				break;
			}
			c->filled = 0;
			c->error = BL_ERR_NONE;
			c->trig_block = 0;
			/* bl_store() sets @state and answers once the banks are clear */
			res = bl_store(c, PRUKIT_CTRL_STATUS(seq, BL_OK));
			/* the capture ends for the driver once the sampler stopped */
			wait_sampler();
			c->state = res == BL_STORE_DONE ? BL_FW_DONE :
				   res == BL_STORE_MISSED ? BL_FW_ERROR : BL_FW_IDLE;
			if (res != BL_STORE_COMMAND)
				break;
			/* the command that ended the capture */
			cmd = c->hdr.command;
			seq = PRUKIT_CTRL_SEQ(cmd);
			last = seq;
			answer(c, seq, PRUKIT_CTRL_OPCODE(cmd) == BL_CMD_STOP ? BL_OK :
				       PRUKIT_CTRL_OPCODE(cmd) == BL_CMD_START ? BL_EBUSY :
				       BL_EOPCODE);
			break;
		case BL_CMD_STOP:
			answer(c, seq, BL_OK);
			break;
		default:
			answer(c, seq, BL_EOPCODE);
		}
	}
}

#endif
