/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * AM335x PRU-ICSS industrial Ethernet peripheral timer (local 0x2e000,
 * constant table C26).  Offsets and fields from SPRUH73 chapter 4,
 * "PRU_ICSS_IEP Registers".  The 32-bit counter adds DEFAULT_INC per IEP
 * clock (200 MHz by default); with DEFAULT_INC = 5 it counts nanoseconds.
 */
#ifndef _AM335X_PRUSS_IEP_H
#define _AM335X_PRUSS_IEP_H

#include <am335x/pruss.h>

#define PRU_IEP_GLOBAL_CFG	0x00
#define PRU_IEP_GLOBAL_STATUS	0x04
#define PRU_IEP_COMPEN		0x08	/* slow/fast compensation */
#define PRU_IEP_COUNT		0x0c
#define PRU_IEP_CAP_CFG		0x10
#define PRU_IEP_CAP_STATUS	0x14
#define PRU_IEP_CMP_CFG		0x40
#define PRU_IEP_CMP_STATUS	0x44
#define PRU_IEP_CMP(n)		(0x48 + 4 * (n))	/* n = 0..7 */
#define PRU_IEP_NUM_CMP		8

/* GLOBAL_CFG */
#define PRU_IEP_GLOBAL_CFG_CNT_ENABLE		(1u << 0)
#define PRU_IEP_GLOBAL_CFG_DEFAULT_INC_SHIFT	4
#define PRU_IEP_GLOBAL_CFG_DEFAULT_INC_MASK	(0xfu << 4)
#define PRU_IEP_GLOBAL_CFG_CMP_INC_SHIFT	8
#define PRU_IEP_GLOBAL_CFG_CMP_INC_MASK		(0xfffu << 8)

/* GLOBAL_STATUS: counter overflowed (write 1 to clear) */
#define PRU_IEP_GLOBAL_STATUS_CNT_OVF		(1u << 0)

/* COMPEN: compensation counter, bits 23:0 */
#define PRU_IEP_COMPEN_CNT_MASK			0xffffffu

/* CMP_CFG */
#define PRU_IEP_CMP_CFG_CMP0_RST_CNT_EN		(1u << 0)	/* CMP0 hit resets COUNT */
#define PRU_IEP_CMP_CFG_CMP_EN(n)		(1u << ((n) + 1))

/* CMP_STATUS: compare n hit (write 1 to clear) */
#define PRU_IEP_CMP_STATUS_HIT(n)		(1u << (n))

static inline uint32_t pru_iep_read(uint32_t off)
{
	return pruss_readl(PRUSS_LOCAL_IEP + off);
}

static inline void pru_iep_write(uint32_t off, uint32_t val)
{
	pruss_writel(val, PRUSS_LOCAL_IEP + off);
}

/* Stop, zero and start the counter with the given increment (1..15). */
static inline void pru_iep_start(unsigned int inc)
{
	uint32_t cfg = ((inc << PRU_IEP_GLOBAL_CFG_DEFAULT_INC_SHIFT) &
			PRU_IEP_GLOBAL_CFG_DEFAULT_INC_MASK) |
		       ((inc << PRU_IEP_GLOBAL_CFG_CMP_INC_SHIFT) &
			PRU_IEP_GLOBAL_CFG_CMP_INC_MASK);

	pru_iep_write(PRU_IEP_GLOBAL_CFG, cfg);
	pru_iep_write(PRU_IEP_COUNT, 0);
	pru_iep_write(PRU_IEP_GLOBAL_STATUS, PRU_IEP_GLOBAL_STATUS_CNT_OVF);
	pru_iep_write(PRU_IEP_GLOBAL_CFG, cfg | PRU_IEP_GLOBAL_CFG_CNT_ENABLE);
}

static inline uint32_t pru_iep_count(void)
{
	return pru_iep_read(PRU_IEP_COUNT);
}

#endif /* _AM335X_PRUSS_IEP_H */
