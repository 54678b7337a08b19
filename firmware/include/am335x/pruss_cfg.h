/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * AM335x PRU-ICSS CFG module (local 0x26000, constant table C4).
 * Register offsets and fields from SPRUH73 chapter 4, "PRU_ICSS_CFG Registers".
 */
#ifndef _AM335X_PRUSS_CFG_H
#define _AM335X_PRUSS_CFG_H

#include <am335x/pruss.h>

#define PRUSS_CFG_REVID		0x00
#define PRUSS_CFG_SYSCFG	0x04
#define PRUSS_CFG_GPCFG0	0x08	/* PRU0 GPI/GPO configuration */
#define PRUSS_CFG_GPCFG1	0x0c	/* PRU1 GPI/GPO configuration */
#define PRUSS_CFG_GPCFG(core)	(0x08 + 4 * (core))
#define PRUSS_CFG_CGR		0x10	/* clock gating */
#define PRUSS_CFG_ISRP		0x14	/* IRQ status raw (parity) */
#define PRUSS_CFG_ISP		0x18	/* IRQ status (parity) */
#define PRUSS_CFG_IESP		0x1c	/* IRQ enable set (parity) */
#define PRUSS_CFG_IECP		0x20	/* IRQ enable clear (parity) */
#define PRUSS_CFG_SCRP		0x24	/* scratchpad priority */
#define PRUSS_CFG_PMAO		0x28	/* OCP master address offset */
#define PRUSS_CFG_MII_RT	0x2c
#define PRUSS_CFG_IEPCLK	0x30
#define PRUSS_CFG_SPP		0x34	/* scratchpad / pad config */
#define PRUSS_CFG_PIN_MX	0x40

/* SYSCFG */
#define PRUSS_SYSCFG_IDLE_MODE_MASK	(3u << 0)
#define PRUSS_SYSCFG_IDLE_MODE_FORCE	(0u << 0)
#define PRUSS_SYSCFG_IDLE_MODE_NO	(1u << 0)
#define PRUSS_SYSCFG_IDLE_MODE_SMART	(2u << 0)
#define PRUSS_SYSCFG_STANDBY_MODE_MASK	(3u << 2)
#define PRUSS_SYSCFG_STANDBY_MODE_FORCE	(0u << 2)
#define PRUSS_SYSCFG_STANDBY_MODE_NO	(1u << 2)
#define PRUSS_SYSCFG_STANDBY_MODE_SMART	(2u << 2)
/* 1 = request standby; 0 = OCP master port enabled (access to L3/L4/DDR) */
#define PRUSS_SYSCFG_STANDBY_INIT	(1u << 4)
/* 1 = OCP master port not ready yet (read only) */
#define PRUSS_SYSCFG_SUB_MWAIT		(1u << 5)

/* GPCFG0/1 */
#define PRUSS_GPCFG_GPI_MODE_MASK	(3u << 0)
#define PRUSS_GPCFG_GPI_MODE_DIRECT	(0u << 0)
#define PRUSS_GPCFG_GPI_MODE_PARALLEL	(1u << 0)	/* 16-bit capture */
#define PRUSS_GPCFG_GPI_MODE_SHIFT	(2u << 0)	/* 28-bit shift in */
#define PRUSS_GPCFG_GPI_MODE_MII_RT	(3u << 0)
#define PRUSS_GPCFG_GPI_CLK_MODE	(1u << 2)	/* capture on falling edge */
#define PRUSS_GPCFG_GPI_DIV0_SHIFT	3
#define PRUSS_GPCFG_GPI_DIV0_MASK	(0x1fu << 3)
#define PRUSS_GPCFG_GPI_DIV1_SHIFT	8
#define PRUSS_GPCFG_GPI_DIV1_MASK	(0x1fu << 8)
#define PRUSS_GPCFG_GPI_SB		(1u << 13)	/* shift mode start bit */
#define PRUSS_GPCFG_GPO_MODE_SHIFT_OUT	(1u << 14)	/* 0 = direct output */
#define PRUSS_GPCFG_GPO_DIV0_SHIFT	15
#define PRUSS_GPCFG_GPO_DIV0_MASK	(0x1fu << 15)
#define PRUSS_GPCFG_GPO_DIV1_SHIFT	20
#define PRUSS_GPCFG_GPO_DIV1_MASK	(0x1fu << 20)
#define PRUSS_GPCFG_GPO_SH_SEL		(1u << 25)	/* shadow register select */

/* CGR: for module m, STOP_REQ = bit 3m, STOP_ACK = 3m+1, CLK_EN = 3m+2 */
#define PRUSS_CGR_MOD_PRU0		0
#define PRUSS_CGR_MOD_PRU1		1
#define PRUSS_CGR_MOD_INTC		2
#define PRUSS_CGR_MOD_UART		3
#define PRUSS_CGR_MOD_ECAP		4
#define PRUSS_CGR_MOD_IEP		5
#define PRUSS_CGR_STOP_REQ(m)		(1u << (3 * (m)))
#define PRUSS_CGR_STOP_ACK(m)		(1u << (3 * (m) + 1))
#define PRUSS_CGR_CLK_EN(m)		(1u << (3 * (m) + 2))

/* PMAO: subtract 0x80000 from OCP master addresses of this core */
#define PRUSS_PMAO_PRU0			(1u << 0)
#define PRUSS_PMAO_PRU1			(1u << 1)

#define PRUSS_MII_RT_EVENT_EN		(1u << 0)
#define PRUSS_IEPCLK_OCP_EN		(1u << 0)	/* IEP clocked by ocp_clk */
#define PRUSS_SPP_PRU1_PAD_HP_EN	(1u << 0)	/* PRU1 drives PRU0's pads */
#define PRUSS_SPP_XFR_SHIFT_EN		(1u << 1)
#define PRUSS_PIN_MX_PIN_MUX_SEL_MASK	(0xffu << 0)

static inline uint32_t pruss_cfg_read(uint32_t off)
{
	return pruss_readl(PRUSS_LOCAL_CFG + off);
}

static inline void pruss_cfg_write(uint32_t off, uint32_t val)
{
	pruss_writel(val, PRUSS_LOCAL_CFG + off);
}

/*
 * Enable the OCP master port (clear SYSCFG.STANDBY_INIT) so that the core can
 * reach L3/L4 (GPIO modules, DDR).  The kernel's pruss driver normally does
 * this already; doing it again is harmless.  Waits for SUB_MWAIT to clear.
 */
static inline void pruss_ocp_master_enable(void)
{
	pruss_cfg_write(PRUSS_CFG_SYSCFG,
			pruss_cfg_read(PRUSS_CFG_SYSCFG) & ~PRUSS_SYSCFG_STANDBY_INIT);
	while (pruss_cfg_read(PRUSS_CFG_SYSCFG) & PRUSS_SYSCFG_SUB_MWAIT)
		;
}

#endif /* _AM335X_PRUSS_CFG_H */
