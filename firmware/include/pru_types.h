/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: <pru_types.h> for PRU programs written against TI's PRU Software
 * Support Package: the layout of the ".pru_irq_map" ELF section (the INTC
 * map that mainline and TI 5.10+ kernels program before starting the core),
 * under the names the kernel's PRU remoteproc driver gives it.
 *
 * A program's own map, e.g. in its intc_map_0.h:
 *
 *	struct pru_irq_rsc my_irq_rsc
 *	__attribute__((section(".pru_irq_map"), used)) = {
 *		0, 2, { { 17, 0, 0 }, { 16, 2, 2 } },	// {event, channel, host}
 *	};
 *
 * (pru-gcc accepts the initialised flexible array; prukit's own intc_map_0.h
 * and intc_map_1.h use PRUKIT_IRQ_MAP() from <prukit/irq_map.h>.)
 */
#ifndef PRUKIT_COMPAT_PRU_TYPES_H
#define PRUKIT_COMPAT_PRU_TYPES_H

#include <stdint.h>

/* One system event routed to an INTC channel and that channel to a host */
struct pruss_int_map {
	uint8_t event;		/* system event 0..63 */
	uint8_t chnl;		/* channel 0..9 */
	uint8_t host;		/* host 0..9: 0/1 = R31 bit 30/31, 2..9 = to the ARM */
};

struct pru_irq_rsc {
	uint8_t type;		/* 0 */
	uint8_t num_evts;
	struct pruss_int_map pru_intc_map[];
};

#endif /* PRUKIT_COMPAT_PRU_TYPES_H */
