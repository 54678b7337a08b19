// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * irq-map: route one system event through .pru_irq_map (set per core in
 * fw.mk), strobe it once, halt.  The PRU remoteproc driver maps the route
 * when the core starts and disposes of it when the core stops; a route that
 * conflicts with one in use fails the start.
 */
#include <stdint.h>
#include <prukit/irq_map.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

PRUKIT_RESOURCE_TABLE_EMPTY();
PRUKIT_IRQ_MAP(PRUKIT_IRQ_EVT(IRQ_MAP_EVENT, IRQ_MAP_CHANNEL, IRQ_MAP_HOST));

int main(void)
{
	r31_strobe_event(IRQ_MAP_EVENT);
	pru_halt();
}
