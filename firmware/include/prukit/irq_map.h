/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: the ".pru_irq_map" ELF section.
 *
 * The PRU remoteproc driver of mainline Linux (5.11+) and of TI's 5.10+
 * kernels reads this section from the firmware file and programs the PRU-ICSS
 * INTC accordingly before starting the core (and undoes it on stop):
 *
 *	struct { u8 type; u8 num_evts; struct { u8 event, chnl, host; } evts[]; }
 *
 * packed, type 0.  event: system event 0..63; chnl: INTC channel 0..9; host:
 * INTC host interrupt 0..9 (0/1 = R31 bits 30/31 of the PRUs, 2..9 =
 * PRU_EVTOUT0..7 to the ARM).  The linker script keeps the section out of
 * every loadable segment: the core never sees it.
 *
 * Usage, once per firmware, at file scope:
 *
 *	PRUKIT_IRQ_MAP(PRUKIT_IRQ_EVT(16, 2, 2),	// to ARM: EVTOUT0
 *		       PRUKIT_IRQ_EVT(17, 0, 0));	// from ARM: R31 bit 30
 */
#ifndef _PRUKIT_IRQ_MAP_H
#define _PRUKIT_IRQ_MAP_H

#include <assert.h>
#include <stdint.h>

#define PRUKIT_IRQ_MAP_TYPE	0

struct prukit_irq_evt {
	uint8_t event;
	uint8_t chnl;
	uint8_t host;
} __attribute__((packed));

struct prukit_irq_map_hdr {
	uint8_t type;
	uint8_t num_evts;
} __attribute__((packed));

static_assert(sizeof(struct prukit_irq_evt) == 3, "pru_irq_map entry must be 3 bytes");

#define PRUKIT_IRQ_EVT(ev, ch, h)	{ .event = (ev), .chnl = (ch), .host = (h) }

#define PRUKIT_IRQ_NUM(...)						\
	(sizeof((const struct prukit_irq_evt[]){ __VA_ARGS__ }) /	\
	 sizeof(struct prukit_irq_evt))

/* Each macro argument is one PRUKIT_IRQ_EVT(event, channel, host). */
#define PRUKIT_IRQ_MAP(...)						\
	static const struct {						\
		struct prukit_irq_map_hdr hdr;				\
		struct prukit_irq_evt evts[PRUKIT_IRQ_NUM(__VA_ARGS__)]; \
	} __attribute__((packed)) prukit_irq_map			\
	__attribute__((section(".pru_irq_map"), used)) = {		\
		.hdr = {						\
			.type = PRUKIT_IRQ_MAP_TYPE,			\
			.num_evts = PRUKIT_IRQ_NUM(__VA_ARGS__),	\
		},							\
		.evts = { __VA_ARGS__ },				\
	}

#endif /* _PRUKIT_IRQ_MAP_H */
