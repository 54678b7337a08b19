// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * consumer-test: firmware of prukit's test consumer (tests/kmod), the
 * smallest program that uses the whole driver contract of prukit_pru:
 *
 *  - a control block (tests/kmod/pru_test_consumer.h) at PRUKIT_CTRL_DA,
 *    polled in a tight loop that only reads it: no interrupt from the ARM;
 *  - COPY: the driver's DMA buffers, read and written over the OCP master
 *    port at their bus addresses;
 *  - EVENTS: system event PRU_TEST_EVENT strobed through R31, which the
 *    consumer's own device tree node maps to a Linux interrupt.
 */
#include <stdint.h>
#include <am335x/pruss_cfg.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>
#include <prukit/ocp.h>

#include "pru_test_consumer.h"

PRUKIT_RESOURCE_TABLE_EMPTY();

/* The image initialises the header: the driver checks it right after loading. */
struct pru_test_ctrl pru_test_ctrl __attribute__((section(".prukit_ctrl"), used)) = {
	.hdr = {
		.magic = PRU_TEST_MAGIC,
		.version = PRU_TEST_VERSION,
		.size = sizeof(struct pru_test_ctrl),
	},
};

#define CHUNK	64

static uint32_t copy(volatile struct pru_test_ctrl *c)
{
	uint32_t src = c->src, dst = c->dst, len = c->len, x = c->xor;
	uint32_t buf[CHUNK / 4];

	if (len % 4 || len > PRU_TEST_MAX_COPY)
		return PRU_TEST_EINVAL;
	while (len) {
		uint32_t n = len < CHUNK ? len : CHUNK, i;

		prukit_ocp_read(buf, src, n);
		for (i = 0; i < n / 4; i++)
			buf[i] ^= x;
		prukit_ocp_write(dst, buf, n);
		src += n;
		dst += n;
		len -= n;
	}
	/* the answer (in data RAM) must not overtake the copy */
	if (c->len)
		prukit_ocp_flush(dst - 4);
	return PRU_TEST_OK;
}

static uint32_t events(volatile struct pru_test_ctrl *c)
{
	uint32_t n = c->count, i;

	if (n > PRU_TEST_MAX_EVENTS)
		return PRU_TEST_EINVAL;
	for (i = 0; i < n; i++) {
		r31_strobe_event(PRU_TEST_EVENT);
		__delay_cycles(PRU_TEST_EVENT_GAP);
	}
	return PRU_TEST_OK;
}

int main(void)
{
	volatile struct pru_test_ctrl *c = &pru_test_ctrl;
	uint16_t last = 0;

	pruss_ocp_master_enable();
	c->hdr.status = PRUKIT_CTRL_STATUS(0, PRU_TEST_OK);
	for (;;) {
		uint32_t cmd = c->hdr.command;
		uint16_t seq = PRUKIT_CTRL_SEQ(cmd);
		uint32_t res;

		if (seq == last)
			continue;	/* only reads: the simulator sees a waiting core */
		last = seq;
		switch (PRUKIT_CTRL_OPCODE(cmd)) {
		case PRU_TEST_CMD_PING:
			c->pings++;
			res = PRU_TEST_OK;
			break;
		case PRU_TEST_CMD_COPY:
			res = copy(c);
			break;
		case PRU_TEST_CMD_EVENTS:
			res = events(c);
			break;
		default:
			res = PRU_TEST_EINVAL;
			break;
		}
		c->hdr.status = PRUKIT_CTRL_STATUS(seq, res);
	}
}
