// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * hub75: PRU firmware of the hub75 (RGB LED matrix) driver.
 *
 * The command loop: START checks the parameters (hub75_proto.h), clocks in
 * the panel's register words if it has any, and runs the refresh loop of
 * hub75_scan.S until the next command; STOP leaves the panel dark.  The
 * loop polls the control block with loads only.
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
CTRL_AT(init, HUB75_CTRL_INIT);
CTRL_AT(bank_addr, HUB75_CTRL_BANK_ADDR);
CTRL_AT(bank_mask, HUB75_CTRL_BANK_MASK);
CTRL_AT(bank_used, HUB75_CTRL_BANK_USED);
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

/* Clocks in a row, as the refresh does: the bytes of an entry */
static uint32_t row_clocks(volatile struct hub75_ctrl *c)
{
	switch (c->data_mode) {
	case HUB75_DATA_GPIO:
		return c->row_bytes / 2u;
	case HUB75_DATA_BANKS:
		return c->row_bytes / (4u * HUB75_BANK_SLOTS);
	}
	return c->row_bytes;
}

/*
 * HUB75_DATA_BANKS: known banks, slot 3 the control bank with the clock in
 * its mask, the control lines in none of the masks but the clock, rows of
 * whole chunks (four entries), the row addresses within the address lines.
 */
static uint32_t check_banks(volatile struct hub75_ctrl *c)
{
	uint32_t ctrl = 1u << c->lat_bit | 1u << c->oe_bit | c->addr_mask;
	uint32_t clk = 1u << c->clk_bit;
	unsigned int k;

	if (!(c->bank_used & 1u << HUB75_BANK_CTRL_SLOT) || c->bank_used >> HUB75_BANK_SLOTS ||
	    c->bank_addr[HUB75_BANK_CTRL_SLOT] != c->gpio_base || !gpio_bank_ok(c->gpio_base) ||
	    !(c->bank_mask[HUB75_BANK_CTRL_SLOT] & clk) ||
	    c->row_bytes % (16u * HUB75_BANK_SLOTS) || (ctrl & clk))
		return HUB75_EINVAL;
	for (k = 0; k < HUB75_BANK_SLOTS; k++) {
		uint32_t mine = k == HUB75_BANK_CTRL_SLOT ? clk : 0;

		if (!(c->bank_used & 1u << k))
			continue;
		if (!gpio_bank_ok(c->bank_addr[k]) || !c->bank_mask[k] ||
		    (c->bank_addr[k] == c->gpio_base && (c->bank_mask[k] & ~mine & (ctrl | clk))))
			return HUB75_EINVAL;
	}
	for (k = 0; k < c->rows; k++)
		if (c->row_addr[k] & ~c->addr_mask)
			return HUB75_EINVAL;
	return HUB75_OK;
}

static uint32_t check_init(volatile struct hub75_ctrl *c)
{
	unsigned int i;

	for (i = 0; i < HUB75_MAX_INIT && c->init[i]; i++) {
		uint32_t latch = HUB75_INIT_LATCH(c->init[i]);

		if (c->init[i] >> 24 || latch < HUB75_INIT_MIN_LATCH ||
		    latch > HUB75_INIT_MAX_LATCH || latch > row_clocks(c))
			return HUB75_EINVAL;
	}
	return HUB75_OK;
}

static uint32_t check_start(volatile struct hub75_ctrl *c)
{
	uint32_t pins = (1u << c->lat_bit) | (1u << c->oe_bit) | (1u << c->clk_bit);

	if (c->planes < 1 || c->planes > HUB75_MAX_PLANES ||
	    c->rows < 1 || c->rows > HUB75_MAX_ROWS ||
	    !c->row_bytes || c->row_bytes % HUB75_CHUNK_BYTES ||
	    c->row_bytes > HUB75_MAX_ROW_BYTES ||
	    c->clk_bit > 31 || c->lat_bit > 31 || c->oe_bit > 31 ||
	    (c->addr_mask & pins) || check_init(c) != HUB75_OK)
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
	case HUB75_DATA_BANKS:
		return check_banks(c);
	}
	return HUB75_EINVAL;
}

/*
 * The data lines at @one: R30's low byte but the clock and the latch, or
 * the bank's data pins.  A GPIO write lands 17 cycles after the bank took
 * it, and the bank takes one every 8: the wait puts both well before the
 * clock's rising edge.
 */
static void init_data(volatile struct hub75_ctrl *c, uint32_t r30, int one)
{
	uint32_t lines = 0xffu & ~(1u << c->clk_bit | 1u << c->lat_bit);

	if (c->data_mode == HUB75_DATA_GPIO) {
		volatile uint32_t *bank = (volatile uint32_t *)c->gpio_base;

		bank[(one ? HUB75_GPIO_SETDATAOUT : HUB75_GPIO_CLEARDATAOUT) / 4] = c->gpio_mask;
		write_r30(r30);
		__delay_cycles(40);
		return;
	}
	write_r30((r30 & ~lines) | (one ? lines : 0));
	__delay_cycles(4);
}

/*
 * The register words of @init (hub75_proto.h): per word a row of clocks,
 * bit 15 - (clock % 16) on every data line (so each 16-clock driver chip
 * of the chain takes the word), the latch high for the last LATCH clocks,
 * which is how an FM6126A-class chip tells a register write from a data
 * latch.  Dark throughout; the clock and the latch end low.
 */
static void send_init(volatile struct hub75_ctrl *c)
{
	uint32_t clk = 1u << c->clk_bit, lat = 1u << c->lat_bit;
	uint32_t n = row_clocks(c), r30, i;
	unsigned int k;

	r30 = (read_r30() | 1u << c->oe_bit) & ~(clk | lat);
	r30 = (r30 & ~c->addr_mask) | (c->row_addr[1 % c->rows] & c->addr_mask);
	write_r30(r30);
	for (k = 0; k < HUB75_MAX_INIT && c->init[k]; k++) {
		uint32_t word = HUB75_INIT_WORD(c->init[k]);
		uint32_t from = n - HUB75_INIT_LATCH(c->init[k]);

		for (i = 0; i < n; i++) {
			if (i == from)
				r30 |= lat;
			init_data(c, r30, word >> (15 - i % 16) & 1);
			write_r30(read_r30() | clk);
			__delay_cycles(4);
			write_r30(read_r30() & ~clk);
		}
		r30 &= ~lat;
		write_r30(read_r30() & ~lat);
		__delay_cycles(4);
	}
}

/* HUB75_DATA_BANKS: @bits of bank @base high or low */
static void bank_write(uint32_t base, uint32_t bits, int high)
{
	volatile uint32_t *bank = (volatile uint32_t *)base;

	bank[(high ? HUB75_GPIO_SETDATAOUT : HUB75_GPIO_CLEARDATAOUT) / 4] = bits;
}

/*
 * send_init() with every line on GPIO banks: the same words, the data
 * lines of every used slot (but the clock) together.  The L4 path keeps
 * the writes in order, each landing after the one before.
 */
static void send_init_banks(volatile struct hub75_ctrl *c)
{
	uint32_t clk = 1u << c->clk_bit, lat = 1u << c->lat_bit, base = c->gpio_base;
	uint32_t n = row_clocks(c), i;
	unsigned int k, s;

	bank_write(base, 1u << c->oe_bit, 1);
	bank_write(base, clk | lat | (c->addr_mask & ~c->row_addr[1 % c->rows]), 0);
	bank_write(base, c->row_addr[1 % c->rows] & c->addr_mask, 1);
	for (k = 0; k < HUB75_MAX_INIT && c->init[k]; k++) {
		uint32_t word = HUB75_INIT_WORD(c->init[k]);
		uint32_t from = n - HUB75_INIT_LATCH(c->init[k]);

		for (i = 0; i < n; i++) {
			if (i == from)
				bank_write(base, lat, 1);
			for (s = 0; s < HUB75_BANK_SLOTS; s++)
				if (c->bank_used & 1u << s)
					bank_write(c->bank_addr[s], c->bank_mask[s] & ~clk,
						   word >> (15 - i % 16) & 1);
			bank_write(base, clk, 1);
			bank_write(base, clk, 0);
		}
		bank_write(base, lat, 0);
	}
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
			if (c->data_mode == HUB75_DATA_BANKS) {
				send_init_banks(c);
				hub75_scan_banks(c, cmd);
			} else {
				send_init(c);
				hub75_scan(c, cmd);
			}
			break;
		case HUB75_CMD_STOP:
			/* R30 is 0 from the core's start: OE low, lit */
			if (c->oe_bit > 31) {
				answer(c, seq, HUB75_EINVAL);
				break;
			}
			if (c->data_mode == HUB75_DATA_BANKS && gpio_bank_ok(c->gpio_base))
				bank_write(c->gpio_base, 1u << c->oe_bit, 1);
			else
				write_r30(read_r30() | 1u << c->oe_bit);
			answer(c, seq, HUB75_OK);
			break;
		default:
			answer(c, seq, HUB75_EOPCODE);
		}
	}
}
