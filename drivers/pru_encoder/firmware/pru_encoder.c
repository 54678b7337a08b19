// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * pru_encoder: PRU0 firmware of the pru_encoder (quadrature counter) driver.
 *
 * Here: the control block, the transition table built from the pin
 * assignment, and the commands; the sampling loop is pru_encoder_loop.S,
 * which returns whenever a new command word appears.  While counting, a
 * command blinds the decoder for the time it takes here (some 70 cycles,
 * traced in prusim): edges in that time are seen as one change when the
 * loop resumes (one step, or a skipped state).
 */
#include <stddef.h>
#include <stdint.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#include "pru_encoder_fw.h"

PRUKIT_RESOURCE_TABLE_EMPTY();

#define CHECK_OFF(field, off) \
	static_assert(offsetof(struct pru_enc_ctrl, field) == (off), "pru_encoder_loop.S: layout")
CHECK_OFF(hdr.command, PRU_ENC_OFF_COMMAND);
CHECK_OFF(count, PRU_ENC_OFF_COUNT);
CHECK_OFF(direction, PRU_ENC_OFF_DIRECTION);
CHECK_OFF(inputs, PRU_ENC_OFF_INPUTS);
CHECK_OFF(overflows, PRU_ENC_OFF_OVERFLOWS);
CHECK_OFF(underflows, PRU_ENC_OFF_UNDERFLOWS);
CHECK_OFF(indexes, PRU_ENC_OFF_INDEXES);
CHECK_OFF(reversals, PRU_ENC_OFF_REVERSALS);
CHECK_OFF(skips, PRU_ENC_OFF_SKIPS);
CHECK_OFF(irq_armed, PRU_ENC_OFF_IRQ_ARMED);
CHECK_OFF(ceiling, PRU_ENC_OFF_CEILING);
CHECK_OFF(floor, PRU_ENC_OFF_FLOOR);

/* The image initialises the header: the driver checks it right after loading. */
struct pru_enc_ctrl pru_enc_ctrl __attribute__((section(".prukit_ctrl"), used)) = {
	.hdr = {
		.magic = PRU_ENC_MAGIC,
		.version = PRU_ENC_VERSION,
		.size = sizeof(struct pru_enc_ctrl),
	},
	.pins = PRU_ENC_PINS(14, 15, PRU_ENC_PIN_NONE),
	.ceiling = 0xffffffffu,
};

/* (previous window << 3 | window): what the change means, PRU_ENC_T_* */
static uint32_t table[1 << (2 * PRU_ENC_WIN_BITS)];

static uint32_t window(void)
{
	return (read_r31() >> PRU_ENC_WIN_SHIFT) & ((1u << PRU_ENC_WIN_BITS) - 1);
}

/*
 * Position of (A, B) in the x4 cycle 00, 10, 11, 01 (A leads: forward):
 * A ^ 3B, without a branch (see build_table()).
 */
static uint32_t phase(uint32_t w, uint32_t a, uint32_t b)
{
	uint32_t va = (w >> a) & 1, vb = (w >> b) & 1;

	return va ^ (vb | vb << 1);
}

static int build_table(uint32_t pins)
{
	uint32_t a = PRU_ENC_PIN_A(pins), b = PRU_ENC_PIN_B(pins), i = PRU_ENC_PIN_I(pins);
	static const uint8_t kind[4] = { 0, PRU_ENC_T_UP, PRU_ENC_T_SKIP, PRU_ENC_T_DOWN };
	uint32_t prev, cur, imask;

	if (a < PRU_ENC_WIN_FIRST || a > PRU_ENC_WIN_LAST ||
	    b < PRU_ENC_WIN_FIRST || b > PRU_ENC_WIN_LAST || a == b)
		return -1;
	if (i != PRU_ENC_PIN_NONE &&
	    (i < PRU_ENC_WIN_FIRST || i > PRU_ENC_WIN_LAST || i == a || i == b))
		return -1;
	a -= PRU_ENC_WIN_FIRST;
	b -= PRU_ENC_WIN_FIRST;
	imask = i == PRU_ENC_PIN_NONE ? 0 : 1u << (i - PRU_ENC_WIN_FIRST);
	/*
	 * Branch-free body: pru-gcc makes the inner loop a hardware LOOP, and
	 * with branches in its body it jumps out of the body and back in,
	 * which prusim (Documentation/prusim.rst) takes as the loop's end.
	 */
	for (prev = 0; prev < 8; prev++) {
		for (cur = 0; cur < 8; cur++) {
			uint32_t d = (phase(cur, a, b) - phase(prev, a, b)) & 3;

			table[prev << 3 | cur] = kind[d] |
				(uint32_t)((~prev & cur & imask) != 0) * PRU_ENC_T_INDEX;
		}
	}
	return 0;
}

/* What R31 is written to strobe system event @event (0: nothing) */
static uint32_t strobe(uint32_t event)
{
	if (!event)
		return 0;
	return PRU_R31_VEC_VALID | ((event - PRU_R31_EVENT_FIRST) & PRU_R31_VEC_MASK);
}

static void answer(volatile struct pru_enc_ctrl *c, uint16_t seq, uint32_t result)
{
	c->hdr.status = PRUKIT_CTRL_STATUS(seq, result);
}

static uint32_t handle(volatile struct pru_enc_ctrl *c, uint32_t cmd)
{
	uint32_t v, ceiling, floor;

	switch (PRUKIT_CTRL_OPCODE(cmd)) {
	case PRU_ENC_CMD_CONFIG:
		v = c->event;
		if ((v && (v < PRU_R31_EVENT_FIRST || v > PRU_R31_EVENT_LAST)) ||
		    build_table(c->pins))
			return PRU_ENC_EINVAL;
		c->state = PRU_ENC_STATE_IDLE;
		return PRU_ENC_OK;
	case PRU_ENC_CMD_ENABLE:
		c->inputs = window();
		c->state = PRU_ENC_STATE_COUNTING;
		return PRU_ENC_OK;
	case PRU_ENC_CMD_DISABLE:
		c->state = PRU_ENC_STATE_IDLE;
		return PRU_ENC_OK;
	case PRU_ENC_CMD_SET_COUNT:
		v = c->value;
		if (v < c->floor || v > c->ceiling)
			return PRU_ENC_EINVAL;
		c->count = v;
		return PRU_ENC_OK;
	case PRU_ENC_CMD_SET_LIMITS:
		ceiling = c->set_ceiling;
		floor = c->set_floor;
		v = c->count;
		if (floor > ceiling || v < floor || v > ceiling)
			return PRU_ENC_EINVAL;
		c->ceiling = ceiling;
		c->floor = floor;
		return PRU_ENC_OK;
	default:
		return PRU_ENC_EOPCODE;
	}
}

int main(void)
{
	volatile struct pru_enc_ctrl *c = &pru_enc_ctrl;
	uint32_t last = 0, cmd;

	build_table(c->pins);
	c->state = PRU_ENC_STATE_IDLE;
	c->inputs = window();
	answer(c, 0, PRU_ENC_OK);
	for (;;) {
		cmd = c->hdr.command;
		if (cmd == last) {
			if (c->state != PRU_ENC_STATE_COUNTING) {
				c->inputs = window();	/* the signals' levels */
				continue;
			}
			/* count until the next command word */
			cmd = pru_enc_loop(c, table, last, strobe(c->event));
		}
		last = cmd;
		answer(c, PRUKIT_CTRL_SEQ(cmd), handle(c, cmd));
	}
}
