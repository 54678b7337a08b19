// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * irq-test: strobe INTC system event IRQ_TEST_EVENT through R31
 * IRQ_TEST_COUNT times, IRQ_TEST_GAP cycles apart, then halt.  The host
 * side maps the event to an ARM host interrupt (the VM tests do it
 * from the device tree of a test consumer) and counts what arrives.  Each
 * strobe also toggles R30 bit 0, so the pin trace shows when it happened.
 */
#include <stdint.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#define IRQ_TEST_COUNT	5
#define IRQ_TEST_GAP	2000000		/* 10 ms: the ARM handles each one */

PRUKIT_RESOURCE_TABLE_EMPTY();

int main(void)
{
	uint32_t r30 = read_r30();
	unsigned int i;

	for (i = 0; i < IRQ_TEST_COUNT; i++) {
		r30 ^= 1;
		write_r30(r30);
		r31_strobe_event(IRQ_TEST_EVENT);
		__delay_cycles(IRQ_TEST_GAP);
	}
	pru_halt();
}
