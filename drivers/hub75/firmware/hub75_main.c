// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * hub75: PRU firmware of the hub75 (RGB LED matrix) driver.
 *
 * The command loop: START checks the parameters (hub75_proto.h) and runs
 * the refresh loop of hub75_scan.S until the next command; STOP leaves the
 * panel dark.  The loop polls the control block with loads only.
 */
#include <stddef.h>
#include <stdint.h>
#include <am335x/pruss.h>
#include <am335x/pruss_cfg.h>
#include <am335x/pruss_iep.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#include "hub75_fw.h"

PRUKIT_RESOURCE_TABLE_EMPTY();

/* hub75_scan.S reaches the control block at these offsets */
#define CTRL_AT(field, off) \
	static_assert(offsetof(struct hub75_ctrl, field) == (off), "hub75_scan.S: ctrl layout")
CTRL_AT(buf_addr, HUB75_CTRL_BUF_ADDR);
CTRL_AT(gpio_base, HUB75_CTRL_GPIO_BASE);
CTRL_AT(row_bytes, HUB75_CTRL_ROW_BYTES);
CTRL_AT(data_mode, HUB75_CTRL_DATA_MODE);
CTRL_AT(row_addr, HUB75_CTRL_ROW_ADDR);
CTRL_AT(oe_cycles, HUB75_CTRL_OE_CYCLES);
CTRL_AT(show, HUB75_CTRL_SHOW);
CTRL_AT(refreshes, HUB75_CTRL_REFRESHES);
CTRL_AT(refresh_cycles, HUB75_CTRL_REFRESH_CYCLES);
static_assert(sizeof(struct hub75_ctrl) == HUB75_CTRL_SIZE, "hub75_scan.S: ctrl layout");

/* The image initialises the header: the driver checks it right after loading. */
struct hub75_ctrl hub75_ctrl __attribute__((section(".prukit_ctrl"), used)) = {
	.hdr = {
		.magic = HUB75_MAGIC,
		.version = HUB75_VERSION,
		.size = sizeof(struct hub75_ctrl),
	},
};

static const uint32_t gpio_banks[] = { 0x44e07000u, 0x4804c000u, 0x481ac000u, 0x481ae000u };

static void answer(volatile struct hub75_ctrl *c, uint16_t seq, uint32_t result)
{
	c->hdr.status = PRUKIT_CTRL_STATUS(seq, result);
}

static int gpio_bank_ok(uint32_t base)
{
	unsigned int i;

	for (i = 0; i < ARRAY_SIZE(gpio_banks); i++)
		if (base == gpio_banks[i])
			return 1;
	return 0;
}

static uint32_t check_start(volatile struct hub75_ctrl *c)
{
	uint32_t pins = (1u << c->lat_bit) | (1u << c->oe_bit) | (1u << c->clk_bit);

	if (c->planes < 1 || c->planes > HUB75_MAX_PLANES ||
	    c->rows < 1 || c->rows > HUB75_MAX_ROWS ||
	    !c->row_bytes || c->row_bytes % HUB75_CHUNK_BYTES ||
	    c->row_bytes > HUB75_MAX_ROW_BYTES ||
	    c->clk_bit > 31 || c->lat_bit > 31 || c->oe_bit > 31 ||
	    (c->addr_mask & pins))
		return HUB75_EINVAL;
	switch (c->data_mode) {
	case HUB75_DATA_R30:
		/* the data byte is written whole: OE and the address stay out */
		if (c->clk_bit > 7 || c->oe_bit < 8 || (c->addr_mask & 0xffu) ||
		    c->clk_delay < 1)
			return HUB75_EINVAL;
		return HUB75_OK;
	case HUB75_DATA_GPIO:
		if (!gpio_bank_ok(c->gpio_base) || !c->gpio_mask || c->gpio_shift > 31)
			return HUB75_EINVAL;
		return HUB75_OK;
	}
	return HUB75_EINVAL;
}

int main(void)
{
	volatile struct hub75_ctrl *c = &hub75_ctrl;
	uint16_t last = 0;

	/* the IEP counter measures @refresh_cycles */
	if (!(pru_iep_read(PRU_IEP_GLOBAL_CFG) & PRU_IEP_GLOBAL_CFG_CNT_ENABLE))
		pru_iep_start(1);
	answer(c, 0, HUB75_OK);
	for (;;) {
		uint32_t cmd = c->hdr.command;
		uint16_t seq = PRUKIT_CTRL_SEQ(cmd);
		uint32_t result;

		if (seq == last)
			continue;
		last = seq;
		switch (PRUKIT_CTRL_OPCODE(cmd)) {
		case HUB75_CMD_START:
			result = check_start(c);
			if (result != HUB75_OK) {
				answer(c, seq, result);
				break;
			}
			pruss_ocp_master_enable();
			c->refreshes = 0;
			c->refresh_cycles = 0;
			answer(c, seq, HUB75_OK);
			/* returns on the next command, which this loop then takes */
			hub75_scan(c, cmd);
			break;
		case HUB75_CMD_STOP:
			/* R30 is 0 from the core's start: OE low, lit */
			if (c->oe_bit > 31) {
				answer(c, seq, HUB75_EINVAL);
				break;
			}
			write_r30(read_r30() | 1u << c->oe_bit);
			answer(c, seq, HUB75_OK);
			break;
		default:
			answer(c, seq, HUB75_EOPCODE);
		}
	}
}
