// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * gpio-pulse: drive a GPIO line from a PRU as the PRU Cookbook's GPIO
 * examples do: make the line an output (its OE bit 0), then pulse it with
 * SETDATAOUT and CLEARDATAOUT stores over the OCP master port, ten times,
 * then halt.
 *
 *   gpio1_28 (Linux GPIO 60) = BeagleBone header P9_12 (pad gpmc_ben1,
 *   mode 7, GPIO from reset)
 *
 * On a board the bank answers only while Linux keeps it enabled: with no
 * line of the bank requested, PRCM gates its clocks (ti-sysc) and
 * gpio-omap disables it (GPIO_CTRL.DISABLEMODULE).  Hold a line of the
 * bank, e.g.
 *	gpioset -m signal gpiochip1 27=0 &
 * and the pulses show; with nothing held the load of OE fails (the VM
 * stops the core there; tests/vm/cases/15-board runs both).
 */
#include <stdint.h>
#include <am335x/gpio.h>
#include <am335x/pruss_cfg.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#define GPIO_PULSE_LINE		60	/* gpio1_28, P9_12 */
#define GPIO_PULSE_COUNT	10
#define GPIO_PULSE_CYCLES	400	/* each level, about 2 us */

PRUKIT_RESOURCE_TABLE_EMPTY();

int main(void)
{
	uint32_t base = am335x_gpio_base(AM335X_GPIO_BANK(GPIO_PULSE_LINE));
	uint32_t mask = AM335X_GPIO_MASK(GPIO_PULSE_LINE);
	unsigned int i;

	pruss_ocp_master_enable();
	am335x_gpio_clear(base, mask);
	am335x_gpio_direction_output(base, mask);
	for (i = 0; i < GPIO_PULSE_COUNT; i++) {
		am335x_gpio_set(base, mask);
		__delay_cycles(GPIO_PULSE_CYCLES);
		am335x_gpio_clear(base, mask);
		__delay_cycles(GPIO_PULSE_CYCLES);
	}
	pru_halt();
}
