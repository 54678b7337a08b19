/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prusim internals shared by the core, memory map and loader.
 */
#ifndef _PRUSIM_PRIV_H
#define _PRUSIM_PRIV_H

#include "prusim.h"

/* CTRL CONTROL bits */
#define PRUSIM_CTRL_SOFT_RST_N	BIT(0)
#define PRUSIM_CTRL_EN		BIT(1)
#define PRUSIM_CTRL_SLEEPING	BIT(2)
#define PRUSIM_CTRL_CTR_EN	BIT(3)
#define PRUSIM_CTRL_SINGLE_STEP	BIT(8)
#define PRUSIM_CTRL_RUNSTATE	BIT(15)
#define PRUSIM_CTRL_RST_VAL_SHIFT	16

/* CFG registers from CGR on are kept in &prusim.cfg_regs */
#define PRUSIM_CFG_CGR			0x10u
#define PRUSIM_CFG_PMAO			0x28u
#define PRUSIM_CFG_MII_RT		0x2cu
#define PRUSIM_CFG_SPP			0x34u
#define PRUSIM_CFG_END			0x44u
#define PRUSIM_CFG_REG(off)		(((off) - PRUSIM_CFG_CGR) / 4)

#define PRUSIM_SYSCFG_RESET		0x1a
#define PRUSIM_SYSCFG_STANDBY_INIT	BIT(4)
#define PRUSIM_SPP_XFR_SHIFT_EN		BIT(1)

/* R31 event strobes keep this many queue entries free of GPIO writes */
#define PRUSIM_QUEUE_EVENT_RESERVE	32
#define PRUSIM_MAX_EVENT_LATENCY	16

/* Kinds of &struct prusim_timed */
#define PRUSIM_TIMED_EVENT	0
#define PRUSIM_TIMED_GPIO	1
#define PRUSIM_TIMED_OCP	2

/* &struct prusim_core.loop_end when no hardware loop is active */
#define PRUSIM_NO_LOOP		0xffffffffu

/*
 * Local PRU-ICSS regions as seen by PRU0.  The same offsets are the ARM's
 * view of the subsystem (prusim_host_read()/prusim_host_write()).
 */
#define PRUSIM_DRAM0		0x00000u
#define PRUSIM_DRAM1		0x02000u
#define PRUSIM_SHARED		0x10000u
#define PRUSIM_INTC		0x20000u
#define PRUSIM_CTRL0		0x22000u
#define PRUSIM_CTRL1		0x24000u
#define PRUSIM_CFG		0x26000u
#define PRUSIM_IEP		0x2e000u
#define PRUSIM_BLOCK_SIZE	0x2000u
#define PRUSIM_HOST_IRAM0	0x34000u
#define PRUSIM_HOST_IRAM1	0x38000u

/**
 * struct prusim_access - result of a memory access by a core
 * @cycles: cycles the instruction takes
 * @volatile_data: the value read may change without a store (counters,
 *	inputs, devices behind the OCP port); an idle loop may not depend on it
 * @retry: the access could not be issued in this cycle; retry in the next
 */
struct prusim_access {
	u32 cycles;
	bool volatile_data;
	bool retry;
};

static inline u32 prusim_words(u32 len)
{
	return len ? (len + 3) / 4 : 1;
}

/* Cycles of a load of @len bytes from a region of latency class @lat */
static inline u32 prusim_read_cycles(const struct prusim *s, enum prusim_lat lat, u32 len)
{
	return s->cfg.read_latency[lat] + (prusim_words(len) - 1) * s->cfg.read_word_cycles;
}

/* Cycles of a (posted) store of @len bytes */
static inline u32 prusim_write_cycles(const struct prusim *s, u32 len)
{
	return s->cfg.write_cycles + (prusim_words(len) - 1) * s->cfg.write_word_cycles;
}

/*
 * The data RAM that holds local address range [@addr, @addr + @len) of core
 * @c (own or other DRAM, shared RAM), or NULL; the fast path of loads and
 * stores.
 */
static inline u8 *prusim_ram(struct prusim *s, const struct prusim_core *c, u32 addr,
			     u32 len, enum prusim_lat *lat)
{
	u32 off;

	if (addr < PRUSIM_DRAM1 + PRUSIM_DRAM_SIZE) {
		off = addr & (PRUSIM_DRAM_SIZE - 1);
		*lat = PRUSIM_LAT_DRAM;
		return off + len <= PRUSIM_DRAM_SIZE ?
		       s->core[c->index ^ (addr >= PRUSIM_DRAM1)].dram + off : NULL;
	}
	off = addr - PRUSIM_SHARED;
	*lat = PRUSIM_LAT_SHARED;
	return off < PRUSIM_SHARED_SIZE && len <= PRUSIM_SHARED_SIZE - off ? s->shared + off : NULL;
}

__printf(3, 4) void prusim_stop(struct prusim *s, struct prusim_core *c,
				const char *fmt, ...);
u32 prusim_r31(struct prusim *s, struct prusim_core *c);
void prusim_wake(struct prusim *s);
void prusim_count(struct prusim_core *c, u64 from, u64 stall_from, u64 end);

int prusim_mem_read(struct prusim *s, struct prusim_core *c, u32 addr, u8 *buf,
		    u32 len, struct prusim_access *acc);
int prusim_mem_write(struct prusim *s, struct prusim_core *c, u32 addr,
		     const u8 *buf, u32 len, struct prusim_access *acc);
void prusim_mem_reset(struct prusim *s);
void prusim_icss_regs_reset(struct prusim *s);
void prusim_ctrl_update_ctable(struct prusim_core *c);
void prusim_intc_event(struct prusim *s, unsigned int event);
void prusim_intc_map(struct prusim *s, unsigned int event, unsigned int channel,
		     unsigned int host);
bool prusim_queue_push(struct prusim *s, const struct prusim_timed *t);
void prusim_queue_run(struct prusim *s);

#endif /* _PRUSIM_PRIV_H */
