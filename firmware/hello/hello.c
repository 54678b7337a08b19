// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * hello: the smallest prukit firmware.
 *
 * Drives one of the core's direct outputs (R30 bit HELLO_BIT) high for
 * HELLO_HIGH_CYCLES and low for HELLO_LOW_CYCLES, HELLO_PULSES times, then
 * halts.  At 200 MHz the defaults give ten 1 us pulses with a 2 us period.
 *
 *   PRU0, R30 bit 5: pr1_pru0_pru_r30_5 = BeagleBone header P9_27
 *                    (pad mcasp0_fsr, mux mode 5)
 *   PRU1, R30 bit 5: pr1_pru1_pru_r30_5 = BeagleBone header P8_42
 *                    (pad lcd_data5, mux mode 5; the HDMI cape must be off)
 *
 * The bit is set per core in fw.mk.  firmware/check.sh verifies from the
 * disassembly that the pulses are exactly as long as defined here.
 */
#include <stdint.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#ifndef HELLO_BIT
#define HELLO_BIT		5
#endif
#define HELLO_PULSES		10
#define HELLO_HIGH_CYCLES	200	/* 1 us */
#define HELLO_LOW_CYCLES	200	/* 1 us */

/*
 * Cycles each loop iteration spends outside the two write_r30() and the two
 * __delay_cycles(): GCC counts the loop down with "sub; qbne" (2 cycles) at
 * the end of the low phase.  It does not use the zero-overhead LOOP
 * instruction here because __delay_cycles() is itself a loop.  check.sh
 * fails if the generated code ever disagrees with this number.
 */
#define HELLO_LOOP_OVERHEAD	2

PRUKIT_RESOURCE_TABLE_EMPTY();

int main(void)
{
	uint32_t on = read_r30() | (1u << HELLO_BIT);
	uint32_t off = on & ~(1u << HELLO_BIT);
	unsigned int i;

	for (i = 0; i < HELLO_PULSES; i++) {
		/* write_r30() itself takes one cycle: count it in each phase */
		write_r30(on);
		__delay_cycles(HELLO_HIGH_CYCLES - 1);
		write_r30(off);
		__delay_cycles(HELLO_LOW_CYCLES - 1 - HELLO_LOOP_OVERHEAD);
	}

	pru_halt();
}
