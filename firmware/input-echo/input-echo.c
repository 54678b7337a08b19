// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * input-echo: copy the core's direct inputs (R31 bits 0..15) to its direct
 * outputs (R30 bits 0..15) in a tight loop, forever.  The tests feed the
 * same stimulus to the QEMU PRU-ICSS in a VM and to the prusim tool on the host and
 * compare the output pin traces cycle by cycle.
 */
#include <stdint.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

PRUKIT_RESOURCE_TABLE_EMPTY();

int main(void)
{
	for (;;)
		write_r30(read_r31() & 0xffffu);
}
