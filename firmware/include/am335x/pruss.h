/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * AM335x PRU-ICSS local memory map and register access helpers, for firmware
 * running on a PRU core.  Addresses are the PRU's own view (AM335x TRM
 * SPRUH73, chapter 4 "Programmable Real-Time Unit Subsystem", local memory
 * map); the same blocks are at PRUSS_GLOBAL_BASE + offset from the ARM.
 *
 * The module headers (pruss_cfg.h, pruss_ctrl.h, pruss_intc.h, pruss_iep.h,
 * gpio.h) give register offsets as plain #defines and small static inline
 * helpers built on pruss_readl()/pruss_writel() below.
 */
#ifndef _AM335X_PRUSS_H
#define _AM335X_PRUSS_H

#include <stdint.h>

/* Local addresses, as seen by the PRU core the firmware runs on. */
#define PRUSS_LOCAL_DRAM_OWN	0x00000000u	/* 8 KiB, this core's data RAM */
#define PRUSS_LOCAL_DRAM_OTHER	0x00002000u	/* 8 KiB, the other core's */
#define PRUSS_LOCAL_SHARED_RAM	0x00010000u	/* 12 KiB */
#define PRUSS_LOCAL_INTC	0x00020000u
#define PRUSS_LOCAL_PRU0_CTRL	0x00022000u
#define PRUSS_LOCAL_PRU0_DBG	0x00022400u
#define PRUSS_LOCAL_PRU1_CTRL	0x00024000u
#define PRUSS_LOCAL_PRU1_DBG	0x00024400u
#define PRUSS_LOCAL_CFG		0x00026000u
#define PRUSS_LOCAL_UART0	0x00028000u
#define PRUSS_LOCAL_IEP		0x0002e000u
#define PRUSS_LOCAL_ECAP0	0x00030000u
#define PRUSS_LOCAL_MII_RT	0x00032000u
#define PRUSS_LOCAL_MDIO	0x00032400u

/* Anything at or above this goes out through the OCP master port. */
#define PRUSS_LOCAL_OCP_START	0x00080000u

/* Sizes */
#define PRUSS_DRAM_SIZE		0x2000u
#define PRUSS_SHARED_RAM_SIZE	0x3000u
#define PRUSS_IRAM_SIZE		0x2000u

/* The subsystem on the L4 fast interconnect, as the ARM (and OCP) sees it. */
#define PRUSS_GLOBAL_BASE	0x4a300000u

/* Number of cycles per microsecond at the 200 MHz PRU clock. */
#define PRU_CYCLES_PER_US	200u

/*
 * PRUKIT_PRU_CORE (0 or 1) is set by firmware/Makefile for each build of a
 * firmware; PRUSS_LOCAL_CTRL is then this core's control block.
 */
#if defined(PRUKIT_PRU_CORE) && PRUKIT_PRU_CORE == 1
#define PRUSS_LOCAL_CTRL	PRUSS_LOCAL_PRU1_CTRL
#elif defined(PRUKIT_PRU_CORE) && PRUKIT_PRU_CORE == 0
#define PRUSS_LOCAL_CTRL	PRUSS_LOCAL_PRU0_CTRL
#endif

/*
 * Constant table entries with fixed addresses (SPRUH73 table "PRU0/1 Constants
 * Table").  Telling GCC about them lets it use LBCO/SBCO (no address load) for
 * accesses within 256 bytes of these bases.  The programmable entries (C24,
 * C25, C26-C31 pointers) are left alone because firmware may reprogram them.
 * Define PRUKIT_NO_CTABLE before including this header to turn this off.
 */
#if defined(__GNUC__) && defined(__PRU__) && !defined(PRUKIT_NO_CTABLE)
#pragma ctable_entry 0 0x00020000
#pragma ctable_entry 3 0x00030000
#pragma ctable_entry 4 0x00026000
#pragma ctable_entry 7 0x00028000
#pragma ctable_entry 26 0x0002e000
#endif

/* 32-bit register access.  addr is a PRU local or OCP (L3/L4) address. */
static inline uint32_t pruss_readl(uint32_t addr)
{
	return *(volatile uint32_t *)(uintptr_t)addr;
}

static inline void pruss_writel(uint32_t val, uint32_t addr)
{
	*(volatile uint32_t *)(uintptr_t)addr = val;
}

/* Read-modify-write: clear the bits in clr, then set those in set. */
static inline void pruss_rmw(uint32_t addr, uint32_t clr, uint32_t set)
{
	pruss_writel((pruss_readl(addr) & ~clr) | set, addr);
}

/* Lvalue form, for code that prefers REG |= x. */
#define PRUSS_REG32(addr)	(*(volatile uint32_t *)(uintptr_t)(addr))

#endif /* _AM335X_PRUSS_H */
