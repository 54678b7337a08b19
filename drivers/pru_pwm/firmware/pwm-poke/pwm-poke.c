// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * pwm-poke: test firmware (PRU0, prusim only).  Its data RAM holds, at
 * PRUKIT_CTRL_DA, a count and then that many (cycle, address, value)
 * triples, preloaded by the test; from its start it writes each value to
 * its address once the core's CYCLE counter reached the triple's cycle
 * (give the triples in cycle order), then halts.  The addresses are
 * PRU0's: the other core's data RAM is at 0x2000.
 */
#include <stdint.h>
#include <am335x/pruss_ctrl.h>
#include <prukit/pru.h>
#include <prukit/pru_ctrl.h>
#include <prukit/resource_table.h>

PRUKIT_RESOURCE_TABLE_EMPTY();

struct poke {
	uint32_t cycle;
	uint32_t addr;
	uint32_t value;
};

struct poke_list {
	uint32_t count;
	struct poke poke[64];
};

struct poke_list poke_list __attribute__((section(".prukit_ctrl"), used));

int main(void)
{
	volatile struct poke_list *l = &poke_list;
	uint32_t i, n = l->count;

	pru_cycle_counter_restart();
	for (i = 0; i < n && i < 64; i++) {
		while (pru_cycle_counter_read() < l->poke[i].cycle)
			;
		*(volatile uint32_t *)(uintptr_t)l->poke[i].addr = l->poke[i].value;
	}
	pru_halt();
}
