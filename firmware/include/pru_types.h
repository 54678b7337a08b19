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
 *
 * Also the older form, of the support package's releases for TI's 4.x
 * kernels: a TYPE_CUSTOM entry of the resource table (<rsc_types.h>) whose
 * sub type TYPE_PRU_INTS holds struct fw_rsc_custom_ints, which points to
 * the program's struct ch_map array.  No kernel since reads it; prukit_pru
 * turns it into the map above when a firmware has no .pru_irq_map
 * (Documentation/rpmsg-kick.rst), so programs that keep that form run.
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

/* The older form: the sub type of the TYPE_CUSTOM resource */
#define TYPE_PRU_INTS		1

/* A channel the program does not route to a host */
#define HOST_UNUSED		255

/* One system event routed to an INTC channel */
struct ch_map {
	uint8_t evt;		/* system event 0..63 */
	uint8_t ch;		/* channel 0..9 */
};

struct fw_rsc_custom_ints {
	uint16_t version;		/* 0 */
	uint8_t channel_host[10];	/* each channel's host, HOST_UNUSED for none */
	uint32_t num_evts;		/* entries of event_channel */
	struct ch_map *event_channel;	/* the program's array, in its data RAM */
};

#endif /* PRUKIT_COMPAT_PRU_TYPES_H */
