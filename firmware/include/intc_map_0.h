/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: intc_map_0.h for PRU0 programs written against TI's PRU Software
 * Support Package's rpmsg API: the .pru_irq_map that routes PRU0's rpmsg
 * events, as the device tree does (rpmsg_pru_proto.h has the conventions):
 *
 *	event 17 (ARM -> PRU0) -> channel 0 -> host 0 = R31 bit 30
 *	event 16 (PRU0 -> ARM) -> channel 2 -> host 2 (PRU_EVTOUT0)
 *
 * ARM -> PRU first: TI's 5.10 kernels kick by raising the first event of the
 * map.  Included by prukit's resource_table_0.h; a program that keeps the
 * support package's copy of this file edits its pragmas instead (see
 * Documentation/firmware-rpmsg.rst).
 */
#ifndef PRUKIT_COMPAT_INTC_MAP_0_H
#define PRUKIT_COMPAT_INTC_MAP_0_H

#include <prukit/irq_map.h>
#include <rpmsg_pru_proto.h>

PRUKIT_IRQ_MAP(PRUKIT_IRQ_EVT(RPMSG_PRU0_EVT_FROM_ARM, 0, 0),
	       PRUKIT_IRQ_EVT(RPMSG_PRU0_EVT_TO_ARM, 2, 2));

#endif /* PRUKIT_COMPAT_INTC_MAP_0_H */
