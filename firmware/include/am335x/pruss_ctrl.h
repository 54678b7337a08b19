/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * AM335x PRU core control registers (PRU0 at local 0x22000, PRU1 at 0x24000).
 * Offsets and fields from SPRUH73 chapter 4, "PRU_ICSS_PRU_CTRL Registers".
 */
#ifndef _AM335X_PRUSS_CTRL_H
#define _AM335X_PRUSS_CTRL_H

#include <am335x/pruss.h>

#define PRU_CTRL_CONTROL	0x00
#define PRU_CTRL_STATUS		0x04	/* current program counter (words) */
#define PRU_CTRL_WAKEUP_EN	0x08	/* R31 status bits that end SLP */
#define PRU_CTRL_CYCLE		0x0c	/* cycle counter, runs while CTR_EN */
#define PRU_CTRL_STALL		0x10	/* stall counter, runs while CTR_EN */
#define PRU_CTRL_CTBIR0		0x20	/* C24/C25 block index */
#define PRU_CTRL_CTBIR1		0x24	/* C26/C27 block index */
#define PRU_CTRL_CTPPR0		0x28	/* C28/C29 pointer */
#define PRU_CTRL_CTPPR1		0x2c	/* C30/C31 pointer */

/* CONTROL */
#define PRU_CTRL_CONTROL_SOFT_RST_N	(1u << 0)	/* write 0: reset core */
#define PRU_CTRL_CONTROL_EN		(1u << 1)	/* core runs */
#define PRU_CTRL_CONTROL_SLEEPING	(1u << 2)	/* in SLP */
#define PRU_CTRL_CONTROL_CTR_EN		(1u << 3)	/* CYCLE/STALL count */
#define PRU_CTRL_CONTROL_SINGLE_STEP	(1u << 8)
#define PRU_CTRL_CONTROL_RUNSTATE	(1u << 15)	/* read only */
#define PRU_CTRL_CONTROL_PCTR_RST_SHIFT	16		/* PC after reset (words) */
#define PRU_CTRL_CONTROL_PCTR_RST_MASK	(0xffffu << 16)

/* STATUS */
#define PRU_CTRL_STATUS_PCOUNTER_MASK	0xffffu

/* CTBIR0/1: 8-bit block indices, low half and high half */
#define PRU_CTRL_CTBIR0_C24_SHIFT	0
#define PRU_CTRL_CTBIR0_C25_SHIFT	16
#define PRU_CTRL_CTBIR1_C26_SHIFT	0
#define PRU_CTRL_CTBIR1_C27_SHIFT	16
#define PRU_CTRL_CTBIR_BLK_MASK		0xffu

/* CTPPR0/1: 16-bit pointers, address bits 23:8 of the entry */
#define PRU_CTRL_CTPPR0_C28_SHIFT	0
#define PRU_CTRL_CTPPR0_C29_SHIFT	16
#define PRU_CTRL_CTPPR1_C30_SHIFT	0
#define PRU_CTRL_CTPPR1_C31_SHIFT	16
#define PRU_CTRL_CTPPR_PTR_MASK		0xffffu

/* Base of a core's control block from the PRU's local view. */
#define PRU_CTRL_BASE(core)	((core) ? PRUSS_LOCAL_PRU1_CTRL : PRUSS_LOCAL_PRU0_CTRL)

static inline uint32_t pru_ctrl_read(unsigned int core, uint32_t off)
{
	return pruss_readl(PRU_CTRL_BASE(core) + off);
}

static inline void pru_ctrl_write(unsigned int core, uint32_t off, uint32_t val)
{
	pruss_writel(val, PRU_CTRL_BASE(core) + off);
}

#ifdef PRUSS_LOCAL_CTRL
/*
 * Cycle counter of this core.  CYCLE does not wrap: at 0xffffffff it stops
 * and CTR_EN clears, so restart it like this (which also works while it
 * counts: a store to CYCLE sets it and clears STALL, taking effect a cycle
 * later - the PRU Cookbook's section 7.3 measurement, modelled by prusim).
 */
static inline void pru_cycle_counter_restart(void)
{
	uint32_t ctl = pruss_readl(PRUSS_LOCAL_CTRL + PRU_CTRL_CONTROL);

	pruss_writel(ctl & ~PRU_CTRL_CONTROL_CTR_EN, PRUSS_LOCAL_CTRL + PRU_CTRL_CONTROL);
	pruss_writel(0, PRUSS_LOCAL_CTRL + PRU_CTRL_CYCLE);
	pruss_writel(ctl | PRU_CTRL_CONTROL_CTR_EN, PRUSS_LOCAL_CTRL + PRU_CTRL_CONTROL);
}

static inline uint32_t pru_cycle_counter_read(void)
{
	return pruss_readl(PRUSS_LOCAL_CTRL + PRU_CTRL_CYCLE);
}

/* Set C28 to addr (bits 23:8 kept); 0x10000 points it at shared RAM. */
static inline void pru_ctrl_set_c28(uint32_t addr)
{
	pruss_rmw(PRUSS_LOCAL_CTRL + PRU_CTRL_CTPPR0,
		  PRU_CTRL_CTPPR_PTR_MASK << PRU_CTRL_CTPPR0_C28_SHIFT,
		  ((addr >> 8) & PRU_CTRL_CTPPR_PTR_MASK) << PRU_CTRL_CTPPR0_C28_SHIFT);
}
#endif

#endif /* _AM335X_PRUSS_CTRL_H */
