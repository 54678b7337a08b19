/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * AM335x PRU-ICSS interrupt controller (local 0x20000, constant table C0).
 * Offsets and fields from SPRUH73 chapter 4, "PRU_ICSS_INTC Registers".
 *
 * 64 system events -> (CMR) 10 channels -> (HMR) 10 host interrupts.
 * Hosts 0 and 1 show up in R31 bits 30 and 31 of both cores; hosts 2..9 are
 * the pr1_host_intr[0..7] lines to the ARM (PRU_EVTOUT0..7).
 */
#ifndef _AM335X_PRUSS_INTC_H
#define _AM335X_PRUSS_INTC_H

#include <am335x/pruss.h>

#define PRU_INTC_NUM_EVENTS	64
#define PRU_INTC_NUM_CHANNELS	10
#define PRU_INTC_NUM_HOSTS	10

#define PRU_INTC_REVID		0x0000
#define PRU_INTC_CR		0x0004	/* control (nesting mode) */
#define PRU_INTC_GER		0x0010	/* global enable */
#define PRU_INTC_GNLR		0x001c	/* global nesting level */
#define PRU_INTC_SISR		0x0020	/* system event status set (index) */
#define PRU_INTC_SICR		0x0024	/* system event status clear (index) */
#define PRU_INTC_EISR		0x0028	/* system event enable set (index) */
#define PRU_INTC_EICR		0x002c	/* system event enable clear (index) */
#define PRU_INTC_HIEISR		0x0034	/* host interrupt enable set (index) */
#define PRU_INTC_HIDISR		0x0038	/* host interrupt enable clear (index) */
#define PRU_INTC_GPIR		0x0080	/* global prioritized index */
#define PRU_INTC_SRSR0		0x0200	/* raw status, events 0..31 */
#define PRU_INTC_SRSR1		0x0204	/* raw status, events 32..63 */
#define PRU_INTC_SECR0		0x0280	/* enabled status / clear, 0..31 */
#define PRU_INTC_SECR1		0x0284	/* enabled status / clear, 32..63 */
#define PRU_INTC_ESR0		0x0300	/* enable set, 0..31 */
#define PRU_INTC_ESR1		0x0304	/* enable set, 32..63 */
#define PRU_INTC_ECR0		0x0380	/* enable clear, 0..31 */
#define PRU_INTC_ECR1		0x0384	/* enable clear, 32..63 */
#define PRU_INTC_CMR(n)		(0x0400 + 4 * (n))	/* n = 0..15, 4 events each */
#define PRU_INTC_HMR(n)		(0x0800 + 4 * (n))	/* n = 0..2, 4 channels each */
#define PRU_INTC_HIPIR(h)	(0x0900 + 4 * (h))	/* host h prioritized index */
#define PRU_INTC_SIPR0		0x0d00	/* polarity, 0..31 (must be 1: high) */
#define PRU_INTC_SIPR1		0x0d04
#define PRU_INTC_SITR0		0x0d80	/* type, 0..31 (must be 0: pulse) */
#define PRU_INTC_SITR1		0x0d84
#define PRU_INTC_HINLR(h)	(0x1100 + 4 * (h))	/* host nesting level */
#define PRU_INTC_HIER		0x1500	/* host interrupt enable bits 9:0 */

#define PRU_INTC_GER_EN_HINT_ANY	(1u << 0)
#define PRU_INTC_GPIR_NONE		(1u << 31)
#define PRU_INTC_HIPIR_NONE		(1u << 31)
#define PRU_INTC_INDEX_MASK		0x3ffu	/* GPIR/HIPIR bits 9:0 */

/* Bank registers: event ev lives in register 0 or 1, bit ev % 32. */
#define PRU_INTC_BANK(reg0, ev)	((reg0) + 4 * ((ev) >> 5))
#define PRU_INTC_BIT(ev)	(1u << ((ev) & 31))

/* CMR(n): 4-bit channel for event ev in byte ev % 4 of CMR(ev / 4). */
#define PRU_INTC_CMR_SHIFT(ev)	(8 * ((ev) & 3))
/* HMR(n): 4-bit host for channel ch in byte ch % 4 of HMR(ch / 4). */
#define PRU_INTC_HMR_SHIFT(ch)	(8 * ((ch) & 3))
#define PRU_INTC_MAP_MASK	0xfu

/* R31 bits that show host interrupts 0 and 1 to both cores */
#define PRU_R31_HOST0_PENDING	(1u << 30)
#define PRU_R31_HOST1_PENDING	(1u << 31)

static inline uint32_t pru_intc_read(uint32_t off)
{
	return pruss_readl(PRUSS_LOCAL_INTC + off);
}

static inline void pru_intc_write(uint32_t off, uint32_t val)
{
	pruss_writel(val, PRUSS_LOCAL_INTC + off);
}

/* Clear a latched system event (after handling it). */
static inline void pru_intc_clear_event(unsigned int ev)
{
	pru_intc_write(PRU_INTC_SICR, ev);
}

/* Set a system event from software (any event 0..63). */
static inline void pru_intc_set_event(unsigned int ev)
{
	pru_intc_write(PRU_INTC_SISR, ev);
}

static inline void pru_intc_enable_event(unsigned int ev)
{
	pru_intc_write(PRU_INTC_EISR, ev);
}

static inline void pru_intc_disable_event(unsigned int ev)
{
	pru_intc_write(PRU_INTC_EICR, ev);
}

static inline void pru_intc_enable_host(unsigned int host)
{
	pru_intc_write(PRU_INTC_HIEISR, host);
}

static inline void pru_intc_disable_host(unsigned int host)
{
	pru_intc_write(PRU_INTC_HIDISR, host);
}

/* Raw (unmasked) status of a system event. */
static inline int pru_intc_event_raw(unsigned int ev)
{
	return !!(pru_intc_read(PRU_INTC_BANK(PRU_INTC_SRSR0, ev)) & PRU_INTC_BIT(ev));
}

/* Enabled status of a system event (raw status AND enable). */
static inline int pru_intc_event_pending(unsigned int ev)
{
	return !!(pru_intc_read(PRU_INTC_BANK(PRU_INTC_SECR0, ev)) & PRU_INTC_BIT(ev));
}

/* Map system event ev to channel ch (read-modify-write of CMR). */
static inline void pru_intc_map_event(unsigned int ev, unsigned int ch)
{
	pruss_rmw(PRUSS_LOCAL_INTC + PRU_INTC_CMR(ev >> 2),
		  PRU_INTC_MAP_MASK << PRU_INTC_CMR_SHIFT(ev),
		  (ch & PRU_INTC_MAP_MASK) << PRU_INTC_CMR_SHIFT(ev));
}

/* Map channel ch to host interrupt host (read-modify-write of HMR). */
static inline void pru_intc_map_channel(unsigned int ch, unsigned int host)
{
	pruss_rmw(PRUSS_LOCAL_INTC + PRU_INTC_HMR(ch >> 2),
		  PRU_INTC_MAP_MASK << PRU_INTC_HMR_SHIFT(ch),
		  (host & PRU_INTC_MAP_MASK) << PRU_INTC_HMR_SHIFT(ch));
}

#endif /* _AM335X_PRUSS_INTC_H */
