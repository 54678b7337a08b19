// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * gpio-set: pulse a GPIO line as the PRU Cookbook's blink examples do:
 * SETDATAOUT and CLEARDATAOUT stores over the OCP master port, ten times,
 * then halt.  It reads nothing and leaves the line's direction to Linux,
 * which must make it an output and keep its bank clocked, e.g.
 *	gpioset -m signal gpiochip1 28=0 &
 *
 *   gpio1_28 (Linux GPIO 60) = BeagleBone header P9_12 (pad gpmc_ben1,
 *   mode 7, GPIO from reset)
 *
 * With no line of the bank requested, PRCM gates the bank's clocks and
 * the stores change no pin (the VM's tests/vm/cases/15-board runs it so);
 * gpio-pulse, which makes the line an output itself, reads the bank.
 */
#include <stdint.h>
#include <am335x/gpio.h>
#include <am335x/pruss_cfg.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#define GPIO_SET_LINE		60	/* gpio1_28, P9_12 */
#define GPIO_SET_COUNT		10
#define GPIO_SET_CYCLES		400	/* each level, about 2 us */

PRUKIT_RESOURCE_TABLE_EMPTY();

int main(void)
{
	uint32_t base = am335x_gpio_base(AM335X_GPIO_BANK(GPIO_SET_LINE));
	uint32_t mask = AM335X_GPIO_MASK(GPIO_SET_LINE);
	unsigned int i;

	pruss_ocp_master_enable();
	for (i = 0; i < GPIO_SET_COUNT; i++) {
		am335x_gpio_set(base, mask);
		__delay_cycles(GPIO_SET_CYCLES);
		am335x_gpio_clear(base, mask);
		__delay_cycles(GPIO_SET_CYCLES);
	}
	pru_halt();
}
