/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: intc_map_1.h for PRU1 programs written against TI's PRU Software
 * Support Package's rpmsg API: the .pru_irq_map that routes PRU1's rpmsg
 * events, as the device tree does (rpmsg_pru_proto.h has the conventions):
 *
 *	event 19 (ARM -> PRU1) -> channel 1 -> host 1 = R31 bit 31
 *	event 18 (PRU1 -> ARM) -> channel 3 -> host 3 (PRU_EVTOUT1)
 *
 * ARM -> PRU first: TI's 5.10 kernels kick by raising the first event of the
 * map.  Included by prukit's resource_table_1.h; a program that keeps the
 * support package's copy of this file edits its pragmas instead (see
 * Documentation/firmware-rpmsg.rst).
 */
#ifndef PRUKIT_COMPAT_INTC_MAP_1_H
#define PRUKIT_COMPAT_INTC_MAP_1_H

#include <prukit/irq_map.h>
#include <rpmsg_pru_proto.h>

PRUKIT_IRQ_MAP(PRUKIT_IRQ_EVT(RPMSG_PRU1_EVT_FROM_ARM, 1, 1),
	       PRUKIT_IRQ_EVT(RPMSG_PRU1_EVT_TO_ARM, 3, 3));

#endif /* PRUKIT_COMPAT_INTC_MAP_1_H */
