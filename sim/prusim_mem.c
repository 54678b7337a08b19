// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim memory map: data RAMs, INTC, CTRL, CFG, IEP and the OCP master port
 * with the AM335x GPIO banks (AM335x TRM SPRUH73 chapter 4, GPIO chapter 25).
 */

#include "prusim_priv.h"

#define INTC_REVID		0x4e82a900u
#define CFG_REVID		0x47000000u
#define CFG_CGR_RESET		0x24924u	/* CLK_EN of all six modules */
#define CFG_CGR_STOP_REQ	0x09249u	/* STOP_REQ of all six modules */
#define CFG_MII_RT_RESET	0x1u
#define CFG_SYSCFG_RW		0x1fu

#define INTC_NONE		BIT(31)	/* GPIR/HIPIR: nothing pending */

#define IEP_CNT_ENABLE		BIT(0)
#define IEP_DEFAULT_INC(cfg)	(((cfg) >> 4) & 0xf)

#define GPIO_WINDOW		0x1000u
#define GPIO_OE			PRUSIM_GPIO_OE
#define GPIO_DATAIN		PRUSIM_GPIO_DATAIN
#define GPIO_DATAOUT		PRUSIM_GPIO_DATAOUT
#define GPIO_CLEARDATAOUT	PRUSIM_GPIO_CLEARDATAOUT
#define GPIO_SETDATAOUT		PRUSIM_GPIO_SETDATAOUT
#define GPIO_OE_RESET		0xffffffffu	/* every line an input */

static const u32 prusim_gpio_base[PRUSIM_GPIO_BANKS] = {
	0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000
};

/* Fixed constant table entries C0..C23 of the AM335x PRU (TRM, constants table) */
static const u32 prusim_ctable_fixed[24] = {
	0x00020000, 0x48040000, 0x4802a000, 0x00030000,
	0x00026000, 0x48060000, 0x48030000, 0x00028000,
	0x46000000, 0x4a100000, 0x48318000, 0x48022000,
	0x48024000, 0x48310000, 0x481cc000, 0x481d0000,
	0x481a0000, 0x4819c000, 0x48300000, 0x48302000,
	0x48304000, 0x00032400, 0x480c8000, 0x480ca000,
};

/**
 * prusim_ctrl_update_ctable() - recompute the programmable entries C24..C31
 * @c: core whose CTBIR0/1 or CTPPR0/1 changed
 */
void prusim_ctrl_update_ctable(struct prusim_core *c)
{
	memcpy(c->ctable, prusim_ctable_fixed, sizeof(prusim_ctable_fixed));
	c->ctable[24] = 0x00000000 | (c->ctbir[0] & 0xff) << 8;
	c->ctable[25] = 0x00002000 | ((c->ctbir[0] >> 16) & 0xff) << 8;
	c->ctable[26] = 0x0002e000 | (c->ctbir[1] & 0xff) << 8;
	c->ctable[27] = 0x00032000 | ((c->ctbir[1] >> 16) & 0xff) << 8;
	c->ctable[28] = 0x00000000 | (c->ctppr[0] & 0xffff) << 8;
	c->ctable[29] = 0x49000000 | (c->ctppr[0] >> 16) << 8;
	c->ctable[30] = 0x40000000 | (c->ctppr[1] & 0xffff) << 8;
	c->ctable[31] = 0x80000000 | (c->ctppr[1] >> 16) << 8;
}

/**
 * prusim_icss_regs_reset() - put the INTC, the IEP and CFG in their reset state
 * @s: simulator
 */
void prusim_icss_regs_reset(struct prusim *s)
{
	memset(&s->intc, 0, sizeof(s->intc));
	memset(&s->iep, 0, sizeof(s->iep));
	memset(s->cfg_regs, 0, sizeof(s->cfg_regs));
	s->syscfg = PRUSIM_SYSCFG_RESET;
	s->gpcfg[0] = 0;
	s->gpcfg[1] = 0;
	s->cfg_regs[PRUSIM_CFG_REG(PRUSIM_CFG_CGR)] = CFG_CGR_RESET;
	s->cfg_regs[PRUSIM_CFG_REG(PRUSIM_CFG_MII_RT)] = CFG_MII_RT_RESET;
	s->iep.since = s->now;
}

/**
 * prusim_mem_reset() - put the subsystem peripherals in their reset state
 * @s: simulator
 */
void prusim_mem_reset(struct prusim *s)
{
	unsigned int i;

	prusim_icss_regs_reset(s);
	memset(s->gpio, 0, sizeof(s->gpio));
	for (i = 0; i < PRUSIM_GPIO_BANKS; i++)
		s->gpio[i].oe = GPIO_OE_RESET;
	s->gpio_free = 0;
	s->queued = 0;
	s->next_event = PRUSIM_NEVER;
	s->posted_head = 0;
	s->posted_n = 0;
	s->posted_due = 0;
}

/* ---------------------------------------------------------------------- */
/* Timed actions                                                           */

/**
 * prusim_queue_push() - schedule an action
 * @s: simulator
 * @t: the action; entries for the same cycle keep their order
 *
 * Return: false if the queue is full.
 */
bool prusim_queue_push(struct prusim *s, const struct prusim_timed *t)
{
	unsigned int i = s->queued;

	if (i == PRUSIM_QUEUE_LEN)
		return false;
	while (i && s->queue[i - 1].cycle > t->cycle) {
		s->queue[i] = s->queue[i - 1];
		i--;
	}
	s->queue[i] = *t;
	s->queued++;
	s->next_event = s->queue[0].cycle;
	s->attention = prusim_min_u64(s->attention, t->cycle);
	return true;
}

static void gpio_set_dataout(struct prusim *s, unsigned int bank, u32 out)
{
	u32 diff = s->gpio[bank].dataout ^ out;
	unsigned int bit;

	s->gpio[bank].dataout = out;
	for (bit = 0; diff; bit++, diff >>= 1) {
		if ((diff & 1) && s->ops.pin)
			s->ops.pin(s->ctx, s->now, PRUSIM_PIN_GPIO(bank, bit), (out >> bit) & 1);
	}
}

static void gpio_land(struct prusim *s, const struct prusim_timed *t)
{
	struct prusim_gpio *g = &s->gpio[t->bank];
	u32 v = t->value & t->mask;

	switch (t->reg) {
	case GPIO_OE:
		if (g->oe == ((g->oe & ~t->mask) | v))
			break;
		g->oe = (g->oe & ~t->mask) | v;
		if (s->ops.gpio_oe)
			s->ops.gpio_oe(s->ctx, s->now, t->bank, g->oe);
		break;
	case GPIO_DATAOUT:
		gpio_set_dataout(s, t->bank, (g->dataout & ~t->mask) | v);
		break;
	case GPIO_CLEARDATAOUT:
		gpio_set_dataout(s, t->bank, g->dataout & ~v);
		break;
	case GPIO_SETDATAOUT:
		gpio_set_dataout(s, t->bank, g->dataout | v);
		break;
	}
}

/**
 * prusim_gpio_write() - a store by the ARM to a GPIO bank register
 * @s: simulator
 * @bank: GPIO bank 0..3
 * @reg: register offset: OE, DATAOUT, CLEARDATAOUT or SETDATAOUT (others
 *	are ignored)
 * @value: the value stored
 *
 * The ARM's store takes effect at &prusim.now (call it between prusim_run()
 * calls), after the PRU stores that have landed by then and before those
 * still on their way; pin changes are reported through &prusim_ops.pin as
 * for the PRU's stores.
 */
void prusim_gpio_write(struct prusim *s, unsigned int bank, u32 reg, u32 value)
{
	struct prusim_timed t = {
		.kind = PRUSIM_TIMED_GPIO, .bank = bank, .reg = reg,
		.value = value, .mask = ~0u,
	};

	if (bank >= PRUSIM_GPIO_BANKS)
		return;
	prusim_queue_run(s);
	gpio_land(s, &t);
	s->epoch++;
}

/**
 * prusim_gpio_set_gated() - gate or clock a GPIO bank, as PRCM does
 * @s: simulator
 * @bank: GPIO bank 0..3
 * @gated: true while the bank's clocks are off
 *
 * A core's load from a gated bank stops the core with the reason (on a
 * board the interconnect answers it with an error).  Its stores are taken
 * as before and reported through &prusim_ops.pin: the embedder, which
 * gates the bank, decides what a store that reaches a gated bank does.
 */
void prusim_gpio_set_gated(struct prusim *s, unsigned int bank, bool gated)
{
	if (bank < PRUSIM_GPIO_BANKS)
		s->gpio[bank].gated = gated;
}

static int ocp_failed(struct prusim *s, struct prusim_core *c, const char *what, u32 addr,
		      u32 len, int ret)
{
	prusim_stop(s, c, "OCP %s of %u bytes at 0x%08x failed (%d)", what, len, addr, ret);
	return ret;
}

/* The oldest posted OCP store lands (a PRUSIM_TIMED_OCP action) */
static void posted_land(struct prusim *s)
{
	struct prusim_posted *p = &s->posted[s->posted_head];
	int ret;

	s->posted_head = (s->posted_head + 1) % PRUSIM_POSTED_LEN;
	s->posted_n--;
	ret = s->ops.ocp_write ? s->ops.ocp_write(s->ctx, p->addr, p->data, p->len) : -ENODEV;
	if (ret)
		ocp_failed(s, &s->core[p->core], "write (posted)", p->addr, p->len, ret);
	s->epoch++;
}

/**
 * prusim_ocp_drain() - land every store on its way over the OCP master port
 * @s: simulator
 *
 * For an embedder whose outside world must see them before it goes on (the
 * ARM stopping a core and then freeing the memory the core wrote to: on a
 * board a stop takes longer than any store's way there).  They land in
 * order, through &prusim_ops.ocp_write, at &prusim.now.
 *
 * Return: how many landed.
 */
unsigned int prusim_ocp_drain(struct prusim *s)
{
	unsigned int i = 0, landed = 0;

	while (i < s->queued) {
		if (s->queue[i].kind != PRUSIM_TIMED_OCP) {
			i++;
			continue;
		}
		s->queued--;
		memmove(&s->queue[i], &s->queue[i + 1], (s->queued - i) * sizeof(s->queue[0]));
		posted_land(s);
		landed++;
	}
	s->next_event = s->queued ? s->queue[0].cycle : PRUSIM_NEVER;
	return landed;
}

/**
 * prusim_queue_run() - apply every action that is due at &prusim.now
 * @s: simulator
 */
void prusim_queue_run(struct prusim *s)
{
	while (s->queued && s->queue[0].cycle <= s->now) {
		struct prusim_timed t = s->queue[0];

		s->queued--;
		memmove(&s->queue[0], &s->queue[1], s->queued * sizeof(s->queue[0]));
		if (t.kind == PRUSIM_TIMED_EVENT)
			prusim_intc_event(s, t.value);
		else if (t.kind == PRUSIM_TIMED_OCP)
			posted_land(s);
		else
			gpio_land(s, &t);
	}
	s->next_event = s->queued ? s->queue[0].cycle : PRUSIM_NEVER;
}

/* ---------------------------------------------------------------------- */
/* INTC                                                                    */

/* Highest priority active event routed to @host (all hosts if @host < 0) */
static u32 intc_prioritized(const struct prusim_intc *ic, int host)
{
	u64 active = ic->raw & ic->enabled;
	unsigned int ch, ev;

	for (ch = 0; ch < PRUSIM_NUM_CHANNELS; ch++) {
		if (host >= 0 && ic->hmr[ch] != host)
			continue;
		for (ev = 0; ev < PRUSIM_NUM_EVENTS; ev++) {
			if ((active >> ev) & 1 && ic->cmr[ev] == ch)
				return ev;
		}
	}
	return INTC_NONE;
}

static u32 intc_compute_pending(const struct prusim_intc *ic)
{
	u64 active = ic->raw & ic->enabled;
	u32 pending = 0;
	unsigned int ev;

	if (!(ic->ger & 1))
		return 0;
	for (ev = 0; active; ev++, active >>= 1) {
		unsigned int ch = ic->cmr[ev];

		if ((active & 1) && ch < PRUSIM_NUM_CHANNELS && ic->hmr[ch] < PRUSIM_NUM_HOSTS)
			pending |= 1u << ic->hmr[ch];
	}
	return pending & ic->hier;
}

/* Recompute the host interrupt lines after any INTC change. */
static void intc_update(struct prusim *s)
{
	u32 pending = intc_compute_pending(&s->intc);
	u32 changed = pending ^ s->intc.pending;
	unsigned int host;

	s->epoch++;
	s->intc.pending = pending;
	for (host = 2; host < PRUSIM_NUM_HOSTS; host++) {
		if (((changed >> host) & 1) && s->ops.host_irq)
			s->ops.host_irq(s->ctx, s->now, host, (pending >> host) & 1);
	}
	if (changed & 3)
		prusim_wake(s);
}

/**
 * prusim_intc_event() - a system event fires (its raw status bit is set)
 * @s: simulator
 * @event: system event 0..63
 */
void prusim_intc_event(struct prusim *s, unsigned int event)
{
	s->intc.raw |= 1ull << (event & 63);
	intc_update(s);
}

/**
 * prusim_intc_map() - route @event to @channel and @channel to @host, enable
 * the event, the host interrupt and the INTC (as a .pru_irq_map entry asks)
 * @s: simulator
 * @event: system event 0..63
 * @channel: channel 0..9
 * @host: host interrupt 0..9
 */
void prusim_intc_map(struct prusim *s, unsigned int event, unsigned int channel,
		     unsigned int host)
{
	s->intc.cmr[event] = channel;
	s->intc.hmr[channel] = host;
	s->intc.enabled |= 1ull << event;
	s->intc.hier |= 1u << host;
	s->intc.ger = 1;
	intc_update(s);
}

static u32 intc_read32(struct prusim *s, unsigned int __always_unused unit, u32 off)
{
	const struct prusim_intc *ic = &s->intc;
	unsigned int n = (off & 0xff) / 4;

	switch (off) {
	case 0x000:
		return INTC_REVID;
	case 0x004:
		return ic->cr;
	case 0x010:
		return ic->ger;
	case 0x01c:
		return ic->gnlr;
	case 0x080:
		return intc_prioritized(ic, -1);
	case 0x200:
		return ic->raw;
	case 0x204:
		return ic->raw >> 32;
	case 0x280:
		return ic->raw & ic->enabled;
	case 0x284:
		return (ic->raw & ic->enabled) >> 32;
	case 0x300:
	case 0x380:
		return ic->enabled;
	case 0x304:
	case 0x384:
		return ic->enabled >> 32;
	case 0xd00:
	case 0xd04:
		return ic->sipr[n & 1];
	case 0xd80:
	case 0xd84:
		return ic->sitr[n & 1];
	case 0x1500:
		return ic->hier;
	}
	if (off >= 0x400 && off < 0x440)
		return prusim_get_le32(&ic->cmr[off - 0x400]);
	if (off >= 0x800 && off < 0x808)
		return prusim_get_le32(&ic->hmr[off - 0x800]);
	if (off == 0x808)
		return prusim_get_le16(&ic->hmr[8]);
	if (off >= 0x900 && off < 0x928)
		return intc_prioritized(ic, n);
	if (off >= 0x1100 && off < 0x1128)
		return ic->hinlr[n];
	return 0;
}

static void intc_write_map(u8 *map, unsigned int count, u32 first, u32 val, u32 mask)
{
	unsigned int i;

	for (i = 0; i < 4 && first + i < count; i++) {
		if ((mask >> (8 * i)) & 0xff)
			map[first + i] = (val >> (8 * i)) & 0xf;
	}
}

static void intc_write32(struct prusim *s, unsigned int __always_unused unit,
			 u32 off, u32 val, u32 mask)
{
	struct prusim_intc *ic = &s->intc;
	u32 index = val & mask & 0x3ff;
	u64 bits = val & mask;
	unsigned int n = (off & 0xff) / 4;

	switch (off) {
	case 0x004:
		ic->cr = (ic->cr & ~mask) | (val & mask);
		break;
	case 0x010:
		ic->ger = (ic->ger & ~mask) | (val & mask & 1);
		break;
	case 0x01c:
		ic->gnlr = (ic->gnlr & ~mask) | (val & mask);
		break;
	case 0x020:
		if (index < PRUSIM_NUM_EVENTS)
			ic->raw |= 1ull << index;
		break;
	case 0x024:
		if (index < PRUSIM_NUM_EVENTS)
			ic->raw &= ~(1ull << index);
		break;
	case 0x028:
		if (index < PRUSIM_NUM_EVENTS)
			ic->enabled |= 1ull << index;
		break;
	case 0x02c:
		if (index < PRUSIM_NUM_EVENTS)
			ic->enabled &= ~(1ull << index);
		break;
	case 0x034:
		if (index < PRUSIM_NUM_HOSTS)
			ic->hier |= 1u << index;
		break;
	case 0x038:
		if (index < PRUSIM_NUM_HOSTS)
			ic->hier &= ~(1u << index);
		break;
	case 0x200:
		ic->raw |= bits;
		break;
	case 0x204:
		ic->raw |= bits << 32;
		break;
	case 0x280:
		ic->raw &= ~bits;
		break;
	case 0x284:
		ic->raw &= ~(bits << 32);
		break;
	case 0x300:
		ic->enabled |= bits;
		break;
	case 0x304:
		ic->enabled |= bits << 32;
		break;
	case 0x380:
		ic->enabled &= ~bits;
		break;
	case 0x384:
		ic->enabled &= ~(bits << 32);
		break;
	case 0xd00:
	case 0xd04:
		ic->sipr[n & 1] = (ic->sipr[n & 1] & ~mask) | (val & mask);
		break;
	case 0xd80:
	case 0xd84:
		ic->sitr[n & 1] = (ic->sitr[n & 1] & ~mask) | (val & mask);
		break;
	case 0x1500:
		ic->hier = (ic->hier & ~mask) | (val & mask & 0x3ff);
		break;
	default:
		if (off >= 0x400 && off < 0x440)
			intc_write_map(ic->cmr, PRUSIM_NUM_EVENTS, off - 0x400, val, mask);
		else if (off >= 0x800 && off < 0x80c)
			intc_write_map(ic->hmr, PRUSIM_NUM_CHANNELS, off - 0x800, val, mask);
		else if (off >= 0x1100 && off < 0x1128)
			ic->hinlr[n] = (ic->hinlr[n] & ~mask) | (val & mask);
		break;
	}
	intc_update(s);
}

/* ---------------------------------------------------------------------- */
/* CTRL (one block per core)                                               */

static u32 ctrl_control(const struct prusim_core *c)
{
	u32 v = (c->control & ~(PRUSIM_CTRL_EN | PRUSIM_CTRL_SLEEPING)) | PRUSIM_CTRL_SOFT_RST_N;

	if (c->state == PRUSIM_RUNNING || c->state == PRUSIM_SLEEPING)
		v |= PRUSIM_CTRL_EN | PRUSIM_CTRL_RUNSTATE;
	if (c->state == PRUSIM_SLEEPING)
		v |= PRUSIM_CTRL_SLEEPING;
	return v;
}

static u32 ctrl_read32(struct prusim *s, unsigned int unit, u32 off)
{
	const struct prusim_core *c = &s->core[unit];

	switch (off) {
	case 0x00:
		return ctrl_control(c);
	case 0x04:
		return c->pc;
	case 0x08:
		return c->wakeup_en;
	case 0x0c:
		return c->cycle_cnt;
	case 0x10:
		return c->stall_cnt;
	case 0x20:
		return c->ctbir[0];
	case 0x24:
		return c->ctbir[1];
	case 0x28:
		return c->ctppr[0];
	case 0x2c:
		return c->ctppr[1];
	}
	if (off >= 0x400 && off < 0x480)
		return c->r[(off - 0x400) / 4];
	if (off >= 0x480 && off < 0x500)
		return c->ctable[(off - 0x480) / 4];
	return 0;
}

static void ctrl_write_control(struct prusim *s, struct prusim_core *c, u32 v)
{
	if (!(v & PRUSIM_CTRL_SOFT_RST_N))
		prusim_core_reset(s, c->index, v >> PRUSIM_CTRL_RST_VAL_SHIFT);
	c->control = v & (0xffff0000u | PRUSIM_CTRL_CTR_EN | PRUSIM_CTRL_SINGLE_STEP);
	if (c->state == PRUSIM_SLEEPING && !(v & PRUSIM_CTRL_SLEEPING)) {
		c->state = PRUSIM_RUNNING;
		c->next = s->now + s->in_step;
	}
	prusim_core_enable(s, c->index, v & PRUSIM_CTRL_EN);
}

static void ctrl_write32(struct prusim *s, unsigned int unit, u32 off, u32 val, u32 mask)
{
	struct prusim_core *c = &s->core[unit];
	u32 v = (ctrl_read32(s, unit, off) & ~mask) | (val & mask);

	switch (off) {
	case 0x00:
		ctrl_write_control(s, c, v);
		return;
	case 0x08:
		c->wakeup_en = v;
		prusim_wake(s);
		return;
	case 0x0c:
		/*
		 * Writing CYCLE sets it and clears STALL, also while they count
		 * (the PRU Cookbook's measurement).  A PRU store issued in cycle
		 * t lands at the end of cycle t + 1: the counters hold the value
		 * then and count again from t + 2.  The ARM writes between
		 * cycles.
		 */
		c->cycle_cnt = v;
		c->stall_cnt = 0;
		c->ctr_from = s->in_step ? s->now + 2 : 0;
		return;
	case 0x20:
	case 0x24:
		c->ctbir[(off - 0x20) / 4] = v;
		break;
	case 0x28:
	case 0x2c:
		c->ctppr[(off - 0x28) / 4] = v;
		break;
	default:
		if (off >= 0x400 && off < 0x480)
			c->r[(off - 0x400) / 4] = v;
		return;
	}
	prusim_ctrl_update_ctable(c);
}

/* ---------------------------------------------------------------------- */
/* CFG                                                                     */

static u32 *cfg_reg(struct prusim *s, u32 off)
{
	if (off >= PRUSIM_CFG_CGR && off < PRUSIM_CFG_END)
		return &s->cfg_regs[PRUSIM_CFG_REG(off)];
	return NULL;
}

/* CGR: a requested clock stop (STOP_REQ) is acknowledged (STOP_ACK) at once */
static u32 cfg_cgr(u32 cgr)
{
	return (cgr & ~(CFG_CGR_STOP_REQ << 1)) | (cgr & CFG_CGR_STOP_REQ) << 1;
}

static u32 cfg_read32(struct prusim *s, unsigned int __always_unused unit, u32 off)
{
	u32 *reg;

	switch (off) {
	case 0x00:
		return CFG_REVID;
	case 0x04:
		return s->syscfg;	/* SUB_MWAIT reads 0: the port is always ready */
	case 0x08:
		return s->gpcfg[0];
	case 0x0c:
		return s->gpcfg[1];
	case PRUSIM_CFG_CGR:
		return cfg_cgr(s->cfg_regs[PRUSIM_CFG_REG(PRUSIM_CFG_CGR)]);
	}
	reg = cfg_reg(s, off);
	return reg ? *reg : 0;
}

static void cfg_write32(struct prusim *s, unsigned int __always_unused unit,
			u32 off, u32 val, u32 mask)
{
	u32 v = (cfg_read32(s, 0, off) & ~mask) | (val & mask);
	u32 *reg;

	switch (off) {
	case 0x04:
		s->syscfg = v & CFG_SYSCFG_RW;
		return;
	case 0x08:
	case 0x0c:
		s->gpcfg[(off - 0x08) / 4] = v;
		return;
	}
	reg = cfg_reg(s, off);
	if (reg)
		*reg = v;
}

/* ---------------------------------------------------------------------- */
/* IEP: only the free running counter; the compare block (CMP_CFG,        */
/* CMP_STATUS, CMP0-7) is not modelled, and an access to it stops a core    */
/* or is reported by prusim_host_modelled() (a compare event never comes)  */

static void iep_sync(struct prusim *s)
{
	struct prusim_iep *iep = &s->iep;
	u64 count = iep->count;

	if (iep->global_cfg & IEP_CNT_ENABLE)
		count += (u64)IEP_DEFAULT_INC(iep->global_cfg) * (s->now - iep->since);
	if (count >> 32)
		iep->overflow = true;
	iep->count = count;
	iep->since = s->now;
}

static u32 iep_read32(struct prusim *s, unsigned int __always_unused unit, u32 off)
{
	struct prusim_iep *iep = &s->iep;

	iep_sync(s);
	switch (off) {
	case 0x00:
		return iep->global_cfg;
	case 0x04:
		return iep->overflow;
	case 0x08:
		return iep->compen;
	case 0x0c:
		return iep->count;
	}
	return 0;
}

static void iep_write32(struct prusim *s, unsigned int __always_unused unit,
			u32 off, u32 val, u32 mask)
{
	struct prusim_iep *iep = &s->iep;
	u32 v = (iep_read32(s, 0, off) & ~mask) | (val & mask);

	switch (off) {
	case 0x00:
		iep->global_cfg = v;
		break;
	case 0x04:
		if (val & mask & 1)
			iep->overflow = false;
		break;
	case 0x08:
		iep->compen = v;
		break;
	case 0x0c:
		iep->count &= ~(val & mask);	/* write 1 to clear */
		break;
	}
}

/* ---------------------------------------------------------------------- */
/* Register blocks accessed with any length                                */

typedef u32 (*prusim_rd32)(struct prusim *s, unsigned int unit, u32 off);
typedef void (*prusim_wr32)(struct prusim *s, unsigned int unit, u32 off, u32 val, u32 mask);

static void regs_read(struct prusim *s, prusim_rd32 rd, unsigned int unit, u32 off,
		      u8 *buf, u32 len)
{
	while (len) {
		u32 b = off & 3, v = rd(s, unit, off - b);

		for (; b < 4 && len; b++, len--, off++)
			*buf++ = v >> (8 * b);
	}
}

static void regs_write(struct prusim *s, prusim_wr32 wr, unsigned int unit, u32 off,
		       const u8 *buf, u32 len)
{
	while (len) {
		u32 word = off & ~3u, val = 0, mask = 0;

		for (; (off & ~3u) == word && len; off++, len--) {
			val |= (u32)*buf++ << (8 * (off & 3));
			mask |= 0xffu << (8 * (off & 3));
		}
		wr(s, unit, word, val, mask);
	}
}

/* ---------------------------------------------------------------------- */
/* Local address map                                                       */

/**
 * struct prusim_region - where a local address lands
 * @ram: memory, or NULL for a register block
 * @rd: register block read function
 * @wr: register block write function
 * @unit: register block instance (core of a CTRL block)
 * @off: offset inside the region
 * @lat: read latency class
 * @volatile_data: reads may change without a store
 */
struct prusim_region {
	u8 *ram;
	prusim_rd32 rd;
	prusim_wr32 wr;
	unsigned int unit;
	u32 off;
	enum prusim_lat lat;
	bool volatile_data;
};

/* Find the region of [addr, addr + len) in the local map of core @view. */
static bool local_region(struct prusim *s, unsigned int view, u32 addr, u32 len,
			 struct prusim_region *r)
{
	u32 base, size;

	memset(r, 0, sizeof(*r));
	if (addr < PRUSIM_DRAM1 + PRUSIM_DRAM_SIZE) {
		base = addr < PRUSIM_DRAM1 ? PRUSIM_DRAM0 : PRUSIM_DRAM1;
		size = PRUSIM_DRAM_SIZE;
		r->ram = s->core[view ^ (base == PRUSIM_DRAM1)].dram;
		r->lat = PRUSIM_LAT_DRAM;
	} else if (addr >= PRUSIM_SHARED && addr < PRUSIM_SHARED + PRUSIM_SHARED_SIZE) {
		base = PRUSIM_SHARED;
		size = PRUSIM_SHARED_SIZE;
		r->ram = s->shared;
		r->lat = PRUSIM_LAT_SHARED;
	} else {
		base = addr & ~(PRUSIM_BLOCK_SIZE - 1);
		size = PRUSIM_BLOCK_SIZE;
		switch (base) {
		case PRUSIM_INTC:
			r->rd = intc_read32;
			r->wr = intc_write32;
			r->lat = PRUSIM_LAT_INTC;
			break;
		case PRUSIM_CTRL0:
		case PRUSIM_CTRL1:
			r->rd = ctrl_read32;
			r->wr = ctrl_write32;
			r->unit = base == PRUSIM_CTRL1;
			r->lat = PRUSIM_LAT_CTRL;
			r->volatile_data = true;
			break;
		case PRUSIM_CFG:
			r->rd = cfg_read32;
			r->wr = cfg_write32;
			r->lat = PRUSIM_LAT_CFG;
			break;
		case PRUSIM_IEP:
			r->rd = iep_read32;
			r->wr = iep_write32;
			r->lat = PRUSIM_LAT_IEP;
			r->volatile_data = true;
			break;
		default:
			return false;
		}
	}
	r->off = addr - base;
	return (u64)r->off + len <= size;
}

static void region_read(struct prusim *s, const struct prusim_region *r, u8 *buf, u32 len)
{
	if (r->ram)
		memcpy(buf, r->ram + r->off, len);
	else
		regs_read(s, r->rd, r->unit, r->off, buf, len);
}

static void region_write(struct prusim *s, const struct prusim_region *r, const u8 *buf,
			 u32 len)
{
	if (r->ram)
		memcpy(r->ram + r->off, buf, len);
	else
		regs_write(s, r->wr, r->unit, r->off, buf, len);
}

/* ---------------------------------------------------------------------- */
/* OCP master port                                                         */

/**
 * prusim_gpio_bank() - which GPIO bank an address belongs to
 * @addr: an AM335x (OCP) address
 *
 * Return: the bank 0..3 whose register window holds @addr, or -1.
 */
int prusim_gpio_bank(u32 addr)
{
	int bank;

	for (bank = 0; bank < PRUSIM_GPIO_BANKS; bank++) {
		if (addr - prusim_gpio_base[bank] < GPIO_WINDOW)
			return bank;
	}
	return -1;
}

static enum prusim_lat ocp_lat(u32 addr)
{
	if (addr >= 0x80000000u && addr < 0xc0000000u)
		return PRUSIM_LAT_DDR;
	if (addr >= 0x40300000u && addr < 0x40310000u)
		return PRUSIM_LAT_OCMC;
	if (addr >= 0x44e00000u && addr < 0x44e04000u)
		return PRUSIM_LAT_PRCM;
	return PRUSIM_LAT_OCP;
}

/*
 * A GPIO register as a read issued now sees it: the read travels behind any
 * write the bank has accepted, so queued writes to OE and DATAOUT count.
 */
static u32 gpio_reg(const struct prusim *s, unsigned int bank, u32 reg)
{
	u32 v = reg == GPIO_OE ? s->gpio[bank].oe : s->gpio[bank].dataout;
	unsigned int i;

	for (i = 0; i < s->queued; i++) {
		const struct prusim_timed *t = &s->queue[i];
		u32 bits = t->value & t->mask;

		if (t->kind != PRUSIM_TIMED_GPIO || t->bank != bank)
			continue;
		if (t->reg == reg)
			v = (v & ~t->mask) | bits;
		else if (reg == GPIO_DATAOUT && t->reg == GPIO_CLEARDATAOUT)
			v &= ~bits;
		else if (reg == GPIO_DATAOUT && t->reg == GPIO_SETDATAOUT)
			v |= bits;
	}
	return v;
}

static u32 gpio_read32(struct prusim *s, unsigned int bank, u32 off)
{
	u64 next;

	switch (off) {
	case GPIO_OE:
		return gpio_reg(s, bank, GPIO_OE);
	case GPIO_DATAIN:
		if (!s->ops.input)
			return 0;
		return s->ops.input(s->ctx, PRUSIM_PORT_GPIO(bank), s->now, &next);
	case GPIO_DATAOUT:
	case GPIO_CLEARDATAOUT:
	case GPIO_SETDATAOUT:
		return gpio_reg(s, bank, GPIO_DATAOUT);
	}
	return 0;
}

/**
 * prusim_gpio_read() - a load by the ARM from a GPIO bank register
 * @s: simulator
 * @bank: GPIO bank 0..3
 * @reg: register offset: OE, DATAIN or DATAOUT (others read 0)
 *
 * Return: the register as a load issued at &prusim.now sees it.
 */
u32 prusim_gpio_read(struct prusim *s, unsigned int bank, u32 reg)
{
	if (bank >= PRUSIM_GPIO_BANKS)
		return 0;
	return gpio_read32(s, bank, reg);
}

/*
 * A store to a GPIO bank is accepted when the L4 path is free, then lands
 * gpio_write_latency cycles later.  Each 32-bit word keeps the path busy
 * for gpio_write_interval cycles; the core stalls until its store is
 * accepted.
 */
static void gpio_write(struct prusim *s, unsigned int bank, u32 off, const u8 *buf, u32 len,
		       struct prusim_access *acc)
{
	struct prusim_timed t = { .kind = PRUSIM_TIMED_GPIO, .bank = bank };
	u64 accept = s->now > s->gpio_free ? s->now : s->gpio_free;
	u32 n = len ? (off + len - 1) / 4 - off / 4 + 1 : 0;

	if (s->queued + n > PRUSIM_QUEUE_LEN - PRUSIM_QUEUE_EVENT_RESERVE) {
		acc->retry = true;
		return;
	}
	t.cycle = accept + s->cfg.gpio_write_latency;
	acc->cycles = (accept - s->now) + prusim_write_cycles(s, len);
	s->gpio_free = accept + (u64)n * s->cfg.gpio_write_interval;
	while (len) {
		u32 word = off & ~3u;

		t.value = 0;
		t.mask = 0;
		for (; (off & ~3u) == word && len; off++, len--) {
			t.value |= (u32)*buf++ << (8 * (off & 3));
			t.mask |= 0xffu << (8 * (off & 3));
		}
		t.reg = word;
		prusim_queue_push(s, &t);
	}
}

/*
 * Check that the OCP master port may be used and translate @addr; returns
 * the GPIO bank at the address, -1 for another device, or -EIO after
 * stopping the core.
 */
static int ocp_route(struct prusim *s, struct prusim_core *c, u32 *addr, u32 len, bool write,
		     struct prusim_access *acc)
{
	int bank;

	if (s->syscfg & PRUSIM_SYSCFG_STANDBY_INIT) {
		prusim_stop(s, c, "OCP master %s at 0x%08x while CFG SYSCFG.STANDBY_INIT is set",
			    write ? "write" : "read", *addr);
		return -EIO;
	}
	if ((s->cfg_regs[PRUSIM_CFG_REG(PRUSIM_CFG_PMAO)] >> c->index) & 1)
		*addr -= PRUSIM_OCP_BASE;
	acc->volatile_data = true;
	bank = prusim_gpio_bank(*addr);
	if (bank >= 0 && *addr - prusim_gpio_base[bank] + len > GPIO_WINDOW) {
		prusim_stop(s, c, "access at 0x%08x+%u crosses the end of GPIO bank %d",
			    *addr, len, bank);
		return -EIO;
	}
	return bank;
}

/*
 * Extra cycles of a DDR access at @addr issued now (&prusim_config.ddr_jitter):
 * a hash of the seed, the cycle and the address, so that a run gives the
 * same figures whether or not idle loops were skipped.
 */
static u32 ddr_jitter(const struct prusim *s, u32 addr)
{
	u64 x = s->now ^ ((u64)addr << 32) ^ ((u64)s->cfg.jitter_seed * 0x9e3779b97f4a7c15ull);

	if (!s->cfg.ddr_jitter || addr < 0x80000000u || addr >= 0xc0000000u)
		return 0;
	/* splitmix64's finaliser */
	x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
	x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
	x ^= x >> 31;
	return ((u32)x ^ (u32)(x >> 32)) % ((u32)s->cfg.ddr_jitter + 1);
}

/*
 * A load over the OCP master port travels behind the stores on their way:
 * it sees their bytes (they land before it is served) and completes no
 * earlier than the cycle after the last one landed.  Each still lands at its
 * own cycle for everyone else.
 */
static void posted_behind(struct prusim *s, u32 addr, u8 *buf, u32 len,
			  struct prusim_access *acc)
{
	unsigned int i;

	for (i = 0; i < s->posted_n; i++) {
		const struct prusim_posted *p =
			&s->posted[(s->posted_head + i) % PRUSIM_POSTED_LEN];
		u32 lo = p->addr > addr ? p->addr : addr;
		u32 hi = prusim_min_u64((u64)p->addr + p->len, (u64)addr + len);

		if (lo < hi)
			memcpy(buf + (lo - addr), p->data + (lo - p->addr), hi - lo);
	}
	if (s->posted_due + 1 > s->now + acc->cycles)
		acc->cycles = s->posted_due + 1 - s->now;
}

/*
 * A store over the OCP master port (not to a GPIO bank) is posted: it lands
 * &prusim_config.ocp_write_delay cycles after it issued, after the stores
 * before it.  With %PRUSIM_POSTED_LEN on their way the core stalls.
 */
static int ocp_post(struct prusim *s, struct prusim_core *c, u32 addr, const u8 *buf,
		    u32 len, struct prusim_access *acc)
{
	struct prusim_timed t = { .kind = PRUSIM_TIMED_OCP };
	struct prusim_posted *p;

	if (s->posted_n == PRUSIM_POSTED_LEN ||
	    s->queued >= PRUSIM_QUEUE_LEN - PRUSIM_QUEUE_EVENT_RESERVE) {
		acc->retry = true;
		return 0;
	}
	p = &s->posted[(s->posted_head + s->posted_n) % PRUSIM_POSTED_LEN];
	p->addr = addr;
	p->len = len;
	p->core = c->index;
	memcpy(p->data, buf, len);
	s->posted_n++;
	t.cycle = s->now + s->cfg.ocp_write_delay + ddr_jitter(s, addr);
	if (t.cycle < s->posted_due)
		t.cycle = s->posted_due;
	s->posted_due = t.cycle;
	prusim_queue_push(s, &t);
	acc->cycles = prusim_write_cycles(s, len);
	return 0;
}

static int ocp_read(struct prusim *s, struct prusim_core *c, u32 addr, u8 *buf, u32 len,
		    struct prusim_access *acc)
{
	int bank = ocp_route(s, c, &addr, len, false, acc);
	int ret;

	if (bank == -EIO)
		return bank;
	if (bank >= 0 && s->gpio[bank].gated) {
		prusim_stop(s, c, "OCP read of GPIO bank %d at 0x%08x while its clocks are gated",
			    bank, addr);
		return -EIO;
	}
	if (bank >= 0) {
		regs_read(s, gpio_read32, bank, addr - prusim_gpio_base[bank], buf, len);
		acc->cycles = prusim_read_cycles(s, bank ? PRUSIM_LAT_GPIO : PRUSIM_LAT_GPIO0, len);
		return 0;
	}
	acc->cycles = prusim_read_cycles(s, ocp_lat(addr), len) + ddr_jitter(s, addr);
	ret = s->ops.ocp_read ? s->ops.ocp_read(s->ctx, addr, buf, len) : -ENODEV;
	if (ret)
		return ocp_failed(s, c, "read", addr, len, ret);
	if (s->posted_n)
		posted_behind(s, addr, buf, len, acc);
	return 0;
}

static int ocp_write(struct prusim *s, struct prusim_core *c, u32 addr, const u8 *buf, u32 len,
		     struct prusim_access *acc)
{
	int bank = ocp_route(s, c, &addr, len, true, acc);
	int ret;

	if (bank == -EIO)
		return bank;
	if (bank >= 0) {
		gpio_write(s, bank, addr - prusim_gpio_base[bank], buf, len, acc);
		return 0;
	}
	if (s->cfg.ocp_write_delay || s->posted_n)
		return ocp_post(s, c, addr, buf, len, acc);
	acc->cycles = prusim_write_cycles(s, len);
	ret = s->ops.ocp_write ? s->ops.ocp_write(s->ctx, addr, buf, len) : -ENODEV;
	return ret ? ocp_failed(s, c, "write", addr, len, ret) : 0;
}

/*
 * A load by core @c of its own CTRL block while its counters run: the load
 * issued in this cycle and takes @cycles cycles; it samples CYCLE and STALL
 * at the start of its last cycle, so they include its other cycles (the
 * first one and all stall cycles but the last).  The counters themselves
 * advance when the load retires.
 */
static void ctrl_read_own(struct prusim *s, struct prusim_core *c,
			  const struct prusim_region *r, u8 *buf, u32 len, u32 cycles)
{
	u32 cycle_cnt = c->cycle_cnt, stall_cnt = c->stall_cnt, control = c->control;

	if (cycles > 1)
		prusim_count(c, s->now, s->now + 1, s->now + cycles - 1);
	region_read(s, r, buf, len);
	c->cycle_cnt = cycle_cnt;
	c->stall_cnt = stall_cnt;
	c->control = control;
}

/*
 * The region of a core's load (@store NULL) or store (the bytes stored) in
 * its local map, or -EFAULT after stopping the core: an unmapped address, a
 * register its block does not model, or a setting modelled for other
 * values only (prusim_host_modelled(), prusim_store_modelled()).
 */
static int local_access(struct prusim *s, struct prusim_core *c, u32 addr, const u8 *store,
			u32 len, struct prusim_region *r)
{
	const char *what = store ? "store" : "load";

	if (!local_region(s, c->index, addr, len, r)) {
		prusim_stop(s, c, "%s of %u bytes at unmapped or unmodelled address 0x%05x",
			    what, len, addr);
		return -EFAULT;
	}
	if (r->rd && !prusim_host_modelled(addr, len, !!store)) {
		prusim_stop(s, c, "%s of %u bytes at 0x%05x, a register not modelled",
			    what, len, addr);
		return -EFAULT;
	}
	if (r->rd && store && !prusim_store_modelled(addr, store, len)) {
		prusim_stop(s, c, "%s of %u bytes at 0x%05x, a setting not modelled",
			    what, len, addr);
		return -EFAULT;
	}
	return 0;
}

/**
 * prusim_mem_read() - a load by core @c from its local address map
 * @s: simulator
 * @c: core
 * @addr: local address
 * @buf: destination
 * @len: bytes
 * @acc: timing of the access
 *
 * Return: 0, or a negative errno after stopping @c with a reason.
 */
int prusim_mem_read(struct prusim *s, struct prusim_core *c, u32 addr, u8 *buf, u32 len,
		    struct prusim_access *acc)
{
	struct prusim_region r;

	memset(acc, 0, sizeof(*acc));
	if (addr >= PRUSIM_OCP_BASE)
		return ocp_read(s, c, addr, buf, len, acc);
	if (local_access(s, c, addr, NULL, len, &r))
		return -EFAULT;
	acc->cycles = prusim_read_cycles(s, r.lat, len);
	if (r.rd == ctrl_read32 && r.unit == c->index && (c->control & PRUSIM_CTRL_CTR_EN))
		ctrl_read_own(s, c, &r, buf, len, acc->cycles);
	else
		region_read(s, &r, buf, len);
	acc->volatile_data = r.volatile_data;
	return 0;
}

/**
 * prusim_mem_write() - a store by core @c to its local address map
 * @s: simulator
 * @c: core
 * @addr: local address
 * @buf: source
 * @len: bytes
 * @acc: timing of the access; @acc->retry if it must be reissued
 *
 * Return: 0, or a negative errno after stopping @c with a reason.
 */
int prusim_mem_write(struct prusim *s, struct prusim_core *c, u32 addr, const u8 *buf,
		     u32 len, struct prusim_access *acc)
{
	struct prusim_region r;

	memset(acc, 0, sizeof(*acc));
	s->epoch++;
	if (addr >= PRUSIM_OCP_BASE)
		return ocp_write(s, c, addr, buf, len, acc);
	if (local_access(s, c, addr, buf, len, &r))
		return -EFAULT;
	region_write(s, &r, buf, len);
	acc->cycles = prusim_write_cycles(s, len);
	return 0;
}

/* ---------------------------------------------------------------------- */
/* Access from outside the subsystem                                       */

/**
 * prusim_raise_event() - fire a system event from outside (host to PRU kick)
 * @s: simulator
 * @event: system event 0..63
 *
 * The event is seen by the cores from &prusim.now on.
 */
void prusim_raise_event(struct prusim *s, unsigned int event)
{
	if (event < PRUSIM_NUM_EVENTS)
		prusim_intc_event(s, event);
}

/**
 * prusim_host_pending() - level of a host interrupt line
 * @s: simulator
 * @host: host interrupt 0..9
 *
 * Return: true while the INTC asserts @host.
 */
bool prusim_host_pending(const struct prusim *s, unsigned int host)
{
	return host < PRUSIM_NUM_HOSTS && ((s->intc.pending >> host) & 1);
}

/* IRAM of a core in the ARM's view: the core index, or -1 */
static int host_iram_core(u32 offset, size_t len)
{
	if (len > PRUSIM_IRAM_SIZE)
		return -1;
	if (offset >= PRUSIM_HOST_IRAM0 && offset + len <= PRUSIM_HOST_IRAM0 + PRUSIM_IRAM_SIZE)
		return 0;
	if (offset >= PRUSIM_HOST_IRAM1 && offset + len <= PRUSIM_HOST_IRAM1 + PRUSIM_IRAM_SIZE)
		return 1;
	return -1;
}

static bool host_region(struct prusim *s, u32 offset, size_t len, struct prusim_region *r)
{
	return len <= PRUSIM_SHARED_SIZE && local_region(s, 0, offset, len, r);
}

/**
 * prusim_host_read() - read the subsystem as the ARM sees it (offsets from
 * the PRU-ICSS base: DRAM0 0x0, DRAM1 0x2000, shared RAM 0x10000, INTC
 * 0x20000, PRU0/1 CTRL 0x22000/0x24000, CFG 0x26000, IEP 0x2e000, PRU0/1
 * IRAM 0x34000/0x38000)
 * @s: simulator
 * @offset: offset from the subsystem base
 * @buf: destination
 * @len: bytes
 *
 * Return: 0, or -EINVAL if the range is not one modelled region.
 */
int prusim_host_read(struct prusim *s, u32 offset, void *buf, size_t len)
{
	int core = host_iram_core(offset, len);
	struct prusim_region r;
	u8 *p = buf;
	size_t i;

	if (core >= 0) {
		offset -= core ? PRUSIM_HOST_IRAM1 : PRUSIM_HOST_IRAM0;
		for (i = 0; i < len; i++, offset++)
			p[i] = s->core[core].iram[offset / 4] >> (8 * (offset & 3));
		return 0;
	}
	if (!host_region(s, offset, len, &r))
		return -EINVAL;
	region_read(s, &r, buf, len);
	return 0;
}

/**
 * prusim_host_write() - write the subsystem as the ARM sees it
 * @s: simulator
 * @offset: offset from the subsystem base (see prusim_host_read())
 * @buf: source
 * @len: bytes
 *
 * Register writes take effect at &prusim.now, like a write by a core.
 *
 * Return: 0, or -EINVAL if the range is not one modelled region.
 */
int prusim_host_write(struct prusim *s, u32 offset, const void *buf, size_t len)
{
	int core = host_iram_core(offset, len);
	struct prusim_region r;

	if (core >= 0)
		return prusim_write_iram(s, core,
					 offset - (core ? PRUSIM_HOST_IRAM1 : PRUSIM_HOST_IRAM0),
					 buf, len);
	if (!host_region(s, offset, len, &r))
		return -EINVAL;
	s->epoch++;
	region_write(s, &r, buf, len);
	return 0;
}

/*
 * Registers the ARM's view models, per block: offsets [start, end) and
 * whether they may be read and/or written.  Everything else in a block
 * reads 0 and ignores stores (prusim_host_read()/prusim_host_write()), which
 * is what an embedder that must flag unmodelled accesses asks about.
 */
struct prusim_reg_range {
	u32 start;
	u32 end;
	u8 rw;
};

#define PRUSIM_RD	1
#define PRUSIM_WR	2
#define PRUSIM_RW	(PRUSIM_RD | PRUSIM_WR)

static const struct prusim_reg_range prusim_intc_regs[] = {
	{ 0x000, 0x004, PRUSIM_RD },	/* REVID */
	{ 0x004, 0x008, PRUSIM_RW },	/* CR */
	{ 0x010, 0x014, PRUSIM_RW },	/* GER */
	{ 0x01c, 0x020, PRUSIM_RW },	/* GNLR */
	{ 0x020, 0x030, PRUSIM_WR },	/* SISR, SICR, EISR, EICR */
	{ 0x034, 0x03c, PRUSIM_WR },	/* HIEISR, HIDISR */
	{ 0x080, 0x084, PRUSIM_RD },	/* GPIR */
	{ 0x200, 0x208, PRUSIM_RW },	/* SRSR0/1 */
	{ 0x280, 0x288, PRUSIM_RW },	/* SECR0/1 */
	{ 0x300, 0x308, PRUSIM_RW },	/* ESR0/1 */
	{ 0x380, 0x388, PRUSIM_RW },	/* ECR0/1 */
	{ 0x400, 0x440, PRUSIM_RW },	/* CMR0-15 */
	{ 0x800, 0x80c, PRUSIM_RW },	/* HMR0-2 */
	{ 0x900, 0x928, PRUSIM_RD },	/* HIPIR0-9 */
	{ 0xd00, 0xd08, PRUSIM_RW },	/* SIPR0/1 */
	{ 0xd80, 0xd88, PRUSIM_RW },	/* SITR0/1 */
	{ 0x1100, 0x1128, PRUSIM_RW },	/* HINLR0-9 */
	{ 0x1500, 0x1504, PRUSIM_RW },	/* HIER */
};

static const struct prusim_reg_range prusim_ctrl_regs[] = {
	{ 0x00, 0x04, PRUSIM_RW },	/* CONTROL */
	{ 0x04, 0x08, PRUSIM_RD },	/* STATUS (pc) */
	{ 0x08, 0x14, PRUSIM_RW },	/* WAKEUP_EN, CYCLE, STALL */
	{ 0x20, 0x30, PRUSIM_RW },	/* CTBIR0/1, CTPPR0/1 */
	{ 0x400, 0x500, PRUSIM_RW },	/* debug: GPREG0-31, CT_REG0-31 */
};

static const struct prusim_reg_range prusim_cfg_regs[] = {
	{ 0x00, 0x04, PRUSIM_RD },	/* REVID */
	{ 0x04, PRUSIM_CFG_END, PRUSIM_RW },	/* SYSCFG .. PIN_MX */
};

static const struct prusim_reg_range prusim_iep_regs[] = {
	{ 0x00, 0x10, PRUSIM_RW },	/* GLOBAL_CFG, GLOBAL_STATUS, COMPEN, COUNT */
};

static bool prusim_regs_cover(const struct prusim_reg_range *r, unsigned int n, u32 off,
			      size_t len, u8 rw)
{
	u32 end = off + len;
	unsigned int i;

	/* every byte must lie in a range that allows the access */
	while (off < end) {
		for (i = 0; i < n; i++) {
			if (off >= r[i].start && off < r[i].end && (r[i].rw & rw))
				break;
		}
		if (i == n)
			return false;
		off = r[i].end < end ? r[i].end : end;
	}
	return true;
}

/**
 * prusim_store_modelled() - does the model do what this store asks for?
 * @offset: offset from the subsystem base (see prusim_host_read()); a
 *	core's local address of the same register is the same number
 * @buf: the bytes stored
 * @len: bytes
 *
 * Some registers are modelled for one value only, the one every Linux
 * driver writes: the INTC's polarity (SIPR: active high) and type (SITR:
 * 0, as pruss_intc sets them), no nesting (CR's NEST_MODE 0), and the IEP
 * without compensation (COMPEN 0).  Another value, or a store to part of
 * one of them, asks for behaviour the model does not have.
 *
 * Return: false for such a store; true otherwise.
 */
bool prusim_store_modelled(u32 offset, const void *buf, size_t len)
{
	static const struct {
		u32 offset;
		u32 mask;
		u32 value;
	} fixed[] = {
		{ PRUSIM_INTC + 0x004, 0x0000000c, 0 },		/* CR: NEST_MODE */
		{ PRUSIM_INTC + 0xd00, 0xffffffff, 0xffffffff },	/* SIPR0 */
		{ PRUSIM_INTC + 0xd04, 0xffffffff, 0xffffffff },	/* SIPR1 */
		{ PRUSIM_INTC + 0xd80, 0xffffffff, 0 },		/* SITR0 */
		{ PRUSIM_INTC + 0xd84, 0xffffffff, 0 },		/* SITR1 */
		{ PRUSIM_IEP + 0x008, 0xffffffff, 0 },		/* COMPEN */
	};
	unsigned int i;
	u32 v;

	for (i = 0; i < ARRAY_SIZE(fixed); i++) {
		if (offset + len <= fixed[i].offset || offset >= fixed[i].offset + 4)
			continue;
		if (offset > fixed[i].offset || offset + len < fixed[i].offset + 4)
			return false;
		memcpy(&v, (const u8 *)buf + (fixed[i].offset - offset), 4);
		if ((v & fixed[i].mask) != fixed[i].value)
			return false;
	}
	return true;
}

/**
 * prusim_host_modelled() - does the ARM's view model this access?
 * @offset: offset from the subsystem base (see prusim_host_read())
 * @len: bytes, 1..4 for registers
 * @write: a store rather than a load
 *
 * The memories are modelled throughout; the register blocks register by
 * register.  prusim_host_read() and prusim_host_write() accept an access
 * this refuses (it reads 0, a store is ignored): an embedder uses this to
 * report, and to fail a test on, what the model does not know.
 *
 * Return: true if every byte of the access is modelled.
 */
bool prusim_host_modelled(u32 offset, size_t len, bool write)
{
	u8 rw = write ? PRUSIM_WR : PRUSIM_RD;
	u32 base = offset & ~(PRUSIM_BLOCK_SIZE - 1), off = offset - base;

	if (!len || len > PRUSIM_SHARED_SIZE)
		return false;
	if (host_iram_core(offset, len) >= 0)
		return true;
	if ((u64)offset + len <= PRUSIM_DRAM1 + PRUSIM_DRAM_SIZE)
		return (offset < PRUSIM_DRAM1) == (offset + len <= PRUSIM_DRAM1);
	if (offset >= PRUSIM_SHARED && (u64)offset + len <= PRUSIM_SHARED + PRUSIM_SHARED_SIZE)
		return true;
	if ((u64)off + len > PRUSIM_BLOCK_SIZE)
		return false;
	switch (base) {
	case PRUSIM_INTC:
		return prusim_regs_cover(prusim_intc_regs, ARRAY_SIZE(prusim_intc_regs),
					 off, len, rw);
	case PRUSIM_CTRL0:
	case PRUSIM_CTRL1:
		return prusim_regs_cover(prusim_ctrl_regs, ARRAY_SIZE(prusim_ctrl_regs),
					 off, len, rw);
	case PRUSIM_CFG:
		return prusim_regs_cover(prusim_cfg_regs, ARRAY_SIZE(prusim_cfg_regs),
					 off, len, rw);
	case PRUSIM_IEP:
		return prusim_regs_cover(prusim_iep_regs, ARRAY_SIZE(prusim_iep_regs),
					 off, len, rw);
	}
	return false;
}

/**
 * prusim_da_to_va() - host pointer to data memory of a core
 * @s: simulator
 * @core: 0 or 1; selects which DRAM is at device address 0
 * @da: device (PRU local) address of own DRAM, other DRAM or shared RAM
 * @len: bytes that must be inside the same memory
 *
 * IRAM is not reachable this way because it is predecoded; use
 * prusim_write_iram().
 *
 * Return: pointer, or NULL if [@da, @da + @len) is not one data memory.
 */
void *prusim_da_to_va(struct prusim *s, unsigned int core, u32 da, size_t len)
{
	struct prusim_region r;

	if (core >= PRUSIM_NUM_CORES || len > PRUSIM_SHARED_SIZE ||
	    !local_region(s, core, da, len, &r) || !r.ram)
		return NULL;
	return r.ram + r.off;
}
