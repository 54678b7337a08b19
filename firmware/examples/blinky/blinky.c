// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * blinky: count in binary on R30 bits 0..7, one step every BLINKY_STEP
 * cycles, forever.  Bit 0 is a square wave of 2 * BLINKY_STEP cycles, bit 1
 * of twice that, and so on: on a scope (or in the simulator's pin trace) the eight
 * outputs form the familiar counter staircase.
 *
 *   PRU0 R30 bits 0..7: P9_31 P9_29 P9_30 P9_28 P9_42 P9_27 P9_41 P9_25
 *   PRU1 R30 bits 0..7: P8_45 P8_46 P8_43 P8_44 P8_41 P8_42 P8_39 P8_40
 *
 * The PRU Cookbook's way to run it (PRU0; remoteproc numbering varies):
 *	echo stop > /sys/class/remoteproc/remoteproc1/state
 *	cp blinky-pru0.elf /lib/firmware/am335x-pru0-fw
 *	echo start > /sys/class/remoteproc/remoteproc1/state
 */
#include <stdint.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#define BLINKY_STEP	100	/* cycles: 500 ns */

PRUKIT_RESOURCE_TABLE_EMPTY();

int main(void)
{
	uint32_t r30 = read_r30() & ~0xffu;
	uint32_t count = 0;

	for (;;) {
		write_r30(r30 | (count & 0xff));
		count++;
		/* the rest of the loop (write, mask, increment, branch): 4 cycles */
		__delay_cycles(BLINKY_STEP - 4);
	}
}
