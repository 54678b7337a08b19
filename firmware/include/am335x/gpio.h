/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * AM335x GPIO modules as reached from a PRU through the OCP master port
 * (SPRUH73 chapter 25 "General-Purpose Input/Output", chapter 2 memory map).
 * The port must be enabled first: pruss_ocp_master_enable() in pruss_cfg.h.
 *
 * Timing: reads take ~34 cycles (GPIO1-3) or ~38 (GPIO0); writes are posted,
 * but the L4 accepts about one per 8 cycles, so back-to-back writes stall.
 * The pins must be muxed to GPIO (mode 7) and the bank's clock enabled, which
 * Linux does for banks it has claimed pins from.
 */
#ifndef _AM335X_GPIO_H
#define _AM335X_GPIO_H

#include <am335x/pruss.h>

#define AM335X_GPIO0_BASE	0x44e07000u	/* L4_WKUP */
#define AM335X_GPIO1_BASE	0x4804c000u	/* L4_PER */
#define AM335X_GPIO2_BASE	0x481ac000u
#define AM335X_GPIO3_BASE	0x481ae000u
#define AM335X_GPIO_NUM_BANKS	4

static inline uint32_t am335x_gpio_base(unsigned int bank)
{
	static const uint32_t base[AM335X_GPIO_NUM_BANKS] = {
		AM335X_GPIO0_BASE, AM335X_GPIO1_BASE, AM335X_GPIO2_BASE, AM335X_GPIO3_BASE,
	};

	return base[bank & 3];
}

#define AM335X_GPIO_REVISION		0x000
#define AM335X_GPIO_SYSCONFIG		0x010
#define AM335X_GPIO_OE			0x134	/* 1 = input, 0 = output */
#define AM335X_GPIO_DATAIN		0x138
#define AM335X_GPIO_DATAOUT		0x13c
#define AM335X_GPIO_CLEARDATAOUT	0x190	/* write 1s to drive low */
#define AM335X_GPIO_SETDATAOUT		0x194	/* write 1s to drive high */

/* Linux GPIO number n is bank n / 32, bit n % 32. */
#define AM335X_GPIO_BANK(n)	((n) >> 5)
#define AM335X_GPIO_MASK(n)	(1u << ((n) & 31))

static inline void am335x_gpio_set(uint32_t base, uint32_t mask)
{
	pruss_writel(mask, base + AM335X_GPIO_SETDATAOUT);
}

static inline void am335x_gpio_clear(uint32_t base, uint32_t mask)
{
	pruss_writel(mask, base + AM335X_GPIO_CLEARDATAOUT);
}

static inline uint32_t am335x_gpio_read(uint32_t base)
{
	return pruss_readl(base + AM335X_GPIO_DATAIN);
}

/* Make the pins in mask outputs (OE bit 0) or inputs (OE bit 1). */
static inline void am335x_gpio_direction_output(uint32_t base, uint32_t mask)
{
	pruss_rmw(base + AM335X_GPIO_OE, mask, 0);
}

static inline void am335x_gpio_direction_input(uint32_t base, uint32_t mask)
{
	pruss_rmw(base + AM335X_GPIO_OE, 0, mask);
}

#endif /* _AM335X_GPIO_H */
