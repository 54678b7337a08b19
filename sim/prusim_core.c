// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim core: decoding, execution and timing of the two PRU v3 cores of an
 * AM335x PRU-ICSS, stepped in lockstep (TI SPRUIJ2, AM335x TRM SPRUH73).
 *
 * Timing model: an instruction issues in one cycle and occupies its core for
 * "cost" cycles (1, or the latency of a load, or more while a store waits for
 * the GPIO path); the cycles after the first are stall cycles.  Every
 * instruction's effects are applied when it issues.  Within one cycle PRU0
 * issues before PRU1.
 */

#include "prusim_priv.h"

/* Internal operation codes; 0..15 are the format 1 ALU sub-opcodes */
enum prusim_op {
	OP_ADD, OP_ADC, OP_SUB, OP_SUC, OP_LSL, OP_LSR, OP_RSB, OP_RSC,
	OP_AND, OP_OR, OP_XOR, OP_NOT, OP_MIN, OP_MAX, OP_CLR, OP_SET,
	OP_LDI, OP_LMBD,
	OP_JMP, OP_JAL, OP_QB, OP_QBBS, OP_QBBC,
	OP_HALT, OP_SLP, OP_XIN, OP_XOUT, OP_XCHG, OP_LOOP,
	OP_LBBO, OP_SBBO, OP_LBCO, OP_SBCO, OP_ILLEGAL,
	OP_R30,		/* dispatch code of ALU operations writing r30 */
	OP_R30_SET,	/* dispatch code of "set r30, r30, N" */
	OP_R30_CLR,	/* dispatch code of "clr r30, r30, N" */
	OP_R30_MOV,	/* dispatch code of "mov r30, rX" */
	OP_GENERIC,	/* dispatch code of other instructions with IF_* flags */
};

#define IF_R31		BIT(0)	/* reads r31: sample the inputs first */
#define IF_WR_SPECIAL	BIT(1)	/* writes r28..r31 (multiplier, pins, events) */

/* Instruction word fields (see prusim_disasm.c) */
#define F(insn, sh, bits)	(((insn) >> (sh)) & ((1u << (bits)) - 1))
#define SEL_FULL	7
#define BURST_R0	124
#define REGFILE_BYTES	128
#define XFR_BYTES	PRUSIM_SPAD_BYTES	/* XFR reaches r0..r29 */

#define XFR_MAC		0
#define XFR_SPAD0	10
#define XFR_DIRECT	14
#define XFR_FILL	254
#define XFR_ZERO	255

#define IDLE_MAX_INSNS	64		/* longest loop body watched for idleness */
#define IDLE_MAX_PERIOD	BIT(20)	/* longest common period skipped */

#define COUNTER_MAX	0xffffffffu

/* ---------------------------------------------------------------------- */
/* Decoding                                                                */

static const u8 sel_shift[8] = { 0, 8, 16, 24, 0, 8, 16, 0 };
static const u8 sel_width[8] = { 8, 8, 8, 8, 16, 16, 16, 32 };

static u32 width_mask(unsigned int width)
{
	return width == 32 ? ~0u : (1u << width) - 1;
}

static void dec_rd(struct prusim_insn *in, u32 insn)
{
	u32 sel = F(insn, 5, 3);

	in->rd = F(insn, 0, 5);
	in->rd_shift = sel_shift[sel];
	in->rd_width = sel_width[sel];
	in->rd_mask = width_mask(in->rd_width);
	if (in->rd >= 28)
		in->flags |= IF_WR_SPECIAL;
}

static void dec_rs1(struct prusim_insn *in, u32 insn, u32 sel)
{
	in->rs1 = F(insn, 8, 5);
	in->rs1_shift = sel_shift[sel];
	in->rs1_mask = width_mask(sel_width[sel]);
	if (in->rs1 == 31)
		in->flags |= IF_R31;
}

/* Second operand: imm8 (bits 23:16) if IO, else a register field */
static void dec_op2(struct prusim_insn *in, u32 insn, u32 imm)
{
	u32 sel = F(insn, 21, 3);

	if (F(insn, 24, 1)) {
		in->rs2 = 32;
		in->imm = imm;
		return;
	}
	in->rs2 = F(insn, 16, 5);
	in->rs2_shift = sel_shift[sel];
	in->rs2_mask = width_mask(sel_width[sel]);
	if (in->rs2 == 31)
		in->flags |= IF_R31;
}

/* Register-file byte offset and length code of a burst or XFR */
static void dec_burst(struct prusim_insn *in, u32 insn, u32 len)
{
	in->rd = F(insn, 0, 5) * 4 + F(insn, 5, 2);
	in->len = len;
}

static u16 dec_broff(u32 insn, u32 pc)
{
	u32 raw = F(insn, 25, 2) << 8 | F(insn, 0, 8);

	return pc + (raw & 0x200 ? raw - 0x400 : raw);
}

static void dec_format2(struct prusim_insn *in, u32 insn, u32 pc)
{
	switch (F(insn, 25, 4)) {
	case 0:
		in->op = OP_JMP;
		dec_op2(in, insn, F(insn, 8, 16));
		break;
	case 1:
		in->op = OP_JAL;
		dec_rd(in, insn);
		dec_op2(in, insn, F(insn, 8, 16));
		break;
	case 2:
		in->op = OP_LDI;
		dec_rd(in, insn);
		in->imm = F(insn, 8, 16);
		break;
	case 3:
		in->op = OP_LMBD;
		dec_rd(in, insn);
		dec_rs1(in, insn, F(insn, 13, 3));
		dec_op2(in, insn, F(insn, 16, 8));
		break;
	case 5:
		in->op = OP_HALT;
		break;
	case 7:
		/* XIN/XOUT/XCHG; the S (scan/shift) variants are not PRU v3 */
		if (!F(insn, 23, 2) || F(insn, 14, 1))
			break;
		in->op = OP_XIN + F(insn, 23, 2) - 1;
		in->aux = F(insn, 15, 8);
		dec_burst(in, insn, F(insn, 7, 7));
		break;
	case 8:
		in->op = OP_LOOP;
		in->aux = F(insn, 15, 1);
		in->target = pc + F(insn, 0, 8);
		dec_op2(in, insn, F(insn, 16, 8) + 1);
		break;
	case 15:
		in->op = OP_SLP;
		in->aux = F(insn, 23, 1);
		break;
	}
}

static void dec_insn(struct prusim_insn *in, u32 insn, u32 pc)
{
	switch (insn >> 29) {
	case 0:
		if (F(insn, 25, 4) == OP_NOT && !F(insn, 24, 1))
			break;
		in->op = F(insn, 25, 4);
		dec_rd(in, insn);
		dec_rs1(in, insn, F(insn, 13, 3));
		dec_op2(in, insn, F(insn, 16, 8));
		break;
	case 1:
		dec_format2(in, insn, pc);
		break;
	case 2:
	case 3:
		if (!F(insn, 27, 3))
			break;
		in->op = OP_QB;
		in->aux = F(insn, 27, 3);
		in->target = dec_broff(insn, pc);
		dec_rs1(in, insn, F(insn, 13, 3));
		dec_op2(in, insn, F(insn, 16, 8));
		break;
	case 4:
	case 7:
		in->op = (insn >> 29 == 7 ? OP_SBBO : OP_SBCO) - F(insn, 28, 1);
		dec_burst(in, insn, F(insn, 25, 3) << 4 | F(insn, 13, 3) << 1 | F(insn, 7, 1));
		if (insn >> 29 == 7)
			dec_rs1(in, insn, SEL_FULL);
		else
			in->aux = F(insn, 8, 5);
		dec_op2(in, insn, F(insn, 16, 8));
		break;
	case 6:
		if (F(insn, 27, 2) != 1 && F(insn, 27, 2) != 2)
			break;
		in->op = F(insn, 27, 2) == 2 ? OP_QBBS : OP_QBBC;
		in->target = dec_broff(insn, pc);
		dec_rs1(in, insn, F(insn, 13, 3));
		dec_op2(in, insn, F(insn, 16, 8));
		break;
	}
}

/* Dispatch code of an ALU operation on r30: the pin idioms get their own */
static u8 dec_r30(const struct prusim_insn *in)
{
	bool whole = in->rd_mask == ~0u;

	if (whole && in->rs1 == 30 && in->rs1_mask == ~0u && in->rs2 == 32 &&
	    (in->op == OP_SET || in->op == OP_CLR))
		return in->op == OP_SET ? OP_R30_SET : OP_R30_CLR;
	if (whole && in->op == OP_OR && in->rs2 == 32 && !in->imm)
		return OP_R30_MOV;
	return OP_R30;
}

/**
 * prusim_decode() - predecode one instruction word
 * @in: result; OP_ILLEGAL for words the PRU v3 does not execute
 * @insn: instruction word
 * @pc: its IRAM word address (branch targets are stored absolute)
 */
static void prusim_decode(struct prusim_insn *in, u32 insn, u32 pc)
{
	memset(in, 0, sizeof(*in));
	in->op = OP_ILLEGAL;
	in->rs2 = 32;
	dec_insn(in, insn, pc);
	/* only plain instructions are dispatched inline (see step()) */
	in->kind = in->op;
	if (in->flags == IF_WR_SPECIAL && in->rd == 30 && in->op <= OP_LMBD)
		in->op = dec_r30(in);
	else if (in->flags)
		in->op = OP_GENERIC;
}

/* ---------------------------------------------------------------------- */
/* Registers                                                               */

static inline u32 src1(const struct prusim_core *c, const struct prusim_insn *in)
{
	return (c->r[in->rs1] >> in->rs1_shift) & in->rs1_mask;
}

/* An immediate has rs2 = 32 (always 0) and mask 0, so this yields imm */
static inline u32 src2(const struct prusim_core *c, const struct prusim_insn *in)
{
	return ((c->r[in->rs2] >> in->rs2_shift) & in->rs2_mask) | in->imm;
}

static inline void wr_dst(struct prusim_core *c, const struct prusim_insn *in, u32 v)
{
	u32 old = c->r[in->rd];
	u32 val = (old & ~(in->rd_mask << in->rd_shift)) | (v & in->rd_mask) << in->rd_shift;

	c->dirty |= old != val;
	c->r[in->rd] = val;
}

/* Carry/borrow of an add or subtract: the bit above the destination field */
static inline u32 with_carry(struct prusim_core *c, const struct prusim_insn *in, u64 res)
{
	u8 carry = (res >> in->rd_width) & 1;

	c->dirty |= carry != c->carry;
	c->carry = carry;
	return res;
}

/* Sample the R31 inputs of @c as seen at cycle @now. */
static void r31_refresh(struct prusim *s, struct prusim_core *c, u64 now)
{
	u64 delay = s->cfg.r31_sync_delay;
	u64 at = now > delay ? now - delay : 0;
	u64 next = PRUSIM_NEVER;
	u32 v = 0;

	if (s->ops.input)
		v = s->ops.input(s->ctx, PRUSIM_PORT_R31(c->index), at, &next) & 0x3fffffff;
	if (next <= at)
		next = at + 1;
	if (v != c->r31_in)
		s->epoch++;
	c->r31_in = v;
	c->r31_until = next > PRUSIM_NEVER - delay ? PRUSIM_NEVER : next + delay;
}

/**
 * prusim_r31() - the value a core reads from r31 in the current cycle
 * @s: simulator
 * @c: core
 *
 * Return: input pins in bits 0..29, INTC host interrupts 0/1 in bits 30/31.
 */
u32 prusim_r31(struct prusim *s, struct prusim_core *c)
{
	if (s->now >= c->r31_until)
		r31_refresh(s, c, s->now);
	return c->r31_in | (s->intc.pending & 3) << 30;
}

/* Remember the multiplier operands before r28/r29 change (see mpy_product) */
static void mpy_note(struct prusim *s, struct prusim_core *c)
{
	if (c->mpy_written != s->now) {
		c->mpy_prev[0] = c->r[28];
		c->mpy_prev[1] = c->r[29];
	}
	c->mpy_written = s->now;
}

/*
 * The multiplier samples r28/r29 every cycle and needs one cycle, so an
 * instruction at cycle t sees the product of the operands as they were at
 * the start of cycle t - 1.
 */
static u64 mpy_product(const struct prusim *s, const struct prusim_core *c)
{
	bool recent = c->mpy_written + 1 >= s->now;
	u32 a = recent ? c->mpy_prev[0] : c->r[28];
	u32 b = recent ? c->mpy_prev[1] : c->r[29];

	return (u64)a * b;
}

static void r30_changed(struct prusim *s, struct prusim_core *c, u32 old)
{
	u32 diff = old ^ c->r[30];
	unsigned int bit;

	for (bit = 0; diff; bit++, diff >>= 1) {
		if ((diff & 1) && s->ops.pin)
			s->ops.pin(s->ctx, s->now, PRUSIM_PIN_R30(c->index, bit),
				   (c->r[30] >> bit) & 1);
	}
}

/* A write to r31 with bit 5 set strobes system event 16 + bits 3:0. */
static void r31_write(struct prusim *s, struct prusim_core *c, u32 v)
{
	struct prusim_timed t = {
		.cycle = s->now + s->cfg.event_latency,
		.kind = PRUSIM_TIMED_EVENT,
		.value = 16 + (v & 0xf),
	};

	if (!(v & (1u << 5)))
		return;
	c->dirty = true;
	s->epoch++;
	if (!prusim_queue_push(s, &t))
		prusim_intc_event(s, t.value);
}

static u8 regfile_byte(const struct prusim_core *c, u32 off)
{
	return c->r[off / 4] >> (8 * (off & 3));
}

static void regfile_read(const struct prusim_core *c, u32 off, u8 *buf, u32 len)
{
	if (!((off | len) & 3)) {
		for (; len; len -= 4, off += 4, buf += 4)
			prusim_put_le32(buf, c->r[off / 4]);
		return;
	}
	while (len--)
		*buf++ = regfile_byte(c, off++);
}

static bool covers(u32 off, u32 len, unsigned int reg)
{
	return off < reg * 4 + 4 && off + len > reg * 4;
}

/* Write bytes into the register file, with the side effects of r28..r31. */
static void regfile_write(struct prusim *s, struct prusim_core *c, u32 off, const u8 *buf,
			  u32 len)
{
	u32 old30 = c->r[30];
	u32 i;

	if (!((off | len) & 3) && off + len <= 28 * 4) {
		/* whole registers without side effects: the common case */
		for (; len; len -= 4, off += 4, buf += 4) {
			u32 val = prusim_get_le32(buf);

			c->dirty |= c->r[off / 4] != val;
			c->r[off / 4] = val;
		}
		return;
	}
	if (covers(off, len, 28) || covers(off, len, 29))
		mpy_note(s, c);
	for (i = 0; i < len; i++) {
		u32 shift = 8 * ((off + i) & 3);
		u32 old = c->r[(off + i) / 4];
		u32 val = (old & ~(0xffu << shift)) | (u32)buf[i] << shift;

		c->dirty |= old != val;
		c->r[(off + i) / 4] = val;
	}
	if (covers(off, len, 30))
		r30_changed(s, c, old30);
	if (covers(off, len, 31))
		r31_write(s, c, c->r[31]);
}

/* ---------------------------------------------------------------------- */
/* Control                                                                 */

/**
 * prusim_stop() - stop a core because the simulation cannot go on
 * @s: simulator
 * @c: core
 * @fmt: reason, printf style
 */
void prusim_stop(struct prusim *s, struct prusim_core *c, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(c->reason, sizeof(c->reason), fmt, ap);
	va_end(ap);
	c->state = PRUSIM_STOPPED;
	c->next = PRUSIM_NEVER;
	c->xfr_wait = 0;
	s->stop_run = true;
	s->attention = 0;
	s->epoch++;
}

/**
 * prusim_wake() - let sleeping cores re-check their wake-up condition in the
 * next possible cycle (after an INTC or WAKEUP_EN change)
 * @s: simulator
 */
void prusim_wake(struct prusim *s)
{
	unsigned int i;

	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		struct prusim_core *c = &s->core[i];

		if (c->state == PRUSIM_SLEEPING && c->wake_on_status)
			c->next = prusim_min_u64(c->next, s->now + s->in_step);
	}
}

static void count_cycles(struct prusim_core *c, u32 cycles, u32 stalls)
{
	if ((u64)c->cycle_cnt + cycles >= COUNTER_MAX) {
		/* the counter saturates and turns itself off */
		c->cycle_cnt = COUNTER_MAX;
		c->control &= ~PRUSIM_CTRL_CTR_EN;
	} else {
		c->cycle_cnt += cycles;
	}
	c->stall_cnt = (u64)c->stall_cnt + stalls >= COUNTER_MAX ? COUNTER_MAX
								: c->stall_cnt + stalls;
}

/**
 * prusim_count() - count cycles of core @c into CYCLE and STALL
 * @c: core, with CONTROL.CTR_EN set
 * @from: first cycle
 * @stall_from: first of them that is a stall cycle
 * @end: cycle after the last
 *
 * Counts the cycles [@from, @end), of which [@stall_from, @end) are stalls,
 * leaving out those before &prusim_core.ctr_from (the cycles a store to
 * CYCLE overwrites).
 */
void prusim_count(struct prusim_core *c, u64 from, u64 stall_from, u64 end)
{
	if (unlikely(c->ctr_from > from)) {
		from = c->ctr_from;
		if (stall_from < from)
			stall_from = from;
	}
	if (end > from)
		count_cycles(c, end - from, end > stall_from ? end - stall_from : 0);
}

static void single_step_done(struct prusim *s, struct prusim_core *c)
{
	c->state = PRUSIM_DISABLED;
	c->next = PRUSIM_NEVER;
	s->epoch++;
}

/*
 * Complete the instruction that issued at @issue and took @cost cycles;
 * @npc is the sequential next pc (a hardware loop may wrap it).
 */
static inline void retire(struct prusim *s, struct prusim_core *c, u64 issue, u32 npc,
			  u32 cost)
{
	if (unlikely(npc == c->loop_end)) {
		c->dirty = true;
		if (--c->loop_left)
			npc = c->loop_start;
		else
			c->loop_end = PRUSIM_NO_LOOP;
	}
	c->pc = npc;
	c->insns++;
	if (cost > 1)
		c->stalls += cost - 1;
	c->next = issue + cost;
	if (unlikely(c->control & (PRUSIM_CTRL_CTR_EN | PRUSIM_CTRL_SINGLE_STEP))) {
		if (c->control & PRUSIM_CTRL_CTR_EN)
			prusim_count(c, issue, issue + 1, issue + cost);
		if (c->control & PRUSIM_CTRL_SINGLE_STEP)
			single_step_done(s, c);
	}
}

/* The instruction could not issue this cycle: a stall, try again next cycle. */
static void stall_retry(struct prusim *s, struct prusim_core *c)
{
	c->stalls++;
	c->next = s->now + 1;
	if (c->control & PRUSIM_CTRL_CTR_EN)
		prusim_count(c, s->now, s->now, s->now + 1);
}

/* ---------------------------------------------------------------------- */
/* Idle loops                                                              */

static void watch_arm(struct prusim *s, struct prusim_core *c, u32 pc)
{
	c->watch.pc = pc;
	c->watch.cycle = c->next;
	c->watch.insns = c->insns;
	c->watch.stalls = c->stalls;
	c->watch.epoch = s->epoch;
	c->dirty = false;
}

/*
 * Called after a taken backward branch to @target.  A loop whose iteration
 * from @target back to @target changed no register, had no side effect and
 * saw no change of anything it could read (the epoch did not move) will
 * repeat identically until an input changes: the core is idle.
 */
static void idle_watch(struct prusim *s, struct prusim_core *c, u32 target)
{
	struct prusim_watch *w = &c->watch;
	u64 period = c->next - w->cycle;

	if (target == w->pc) {
		if (!c->dirty && w->epoch == s->epoch && period < IDLE_MAX_PERIOD) {
			c->idle.epoch = s->epoch;
			c->idle.period = period;
			c->idle.insns = c->insns - w->insns;
			c->idle.stalls = c->stalls - w->stalls;
			s->skip_pending = true;
			s->attention = 0;
		}
	} else if (w->pc != PRUSIM_NO_LOOP && !c->dirty &&
		   c->insns - w->insns < IDLE_MAX_INSNS) {
		return;		/* an inner branch (a call, say) of the watched loop */
	}
	watch_arm(s, c, target);
}

static u32 gcd_u32(u32 a, u32 b)
{
	while (b) {
		u32 t = a % b;

		a = b;
		b = t;
	}
	return a;
}

/*
 * Limit of a skip for core @c, or 0 if @c is busy.  @lcm accumulates the
 * common period of the idle loops.
 */
static u64 skip_limit(struct prusim *s, struct prusim_core *c, u64 from, u32 *lcm)
{
	u64 limit = PRUSIM_NEVER, period;

	switch (c->state) {
	case PRUSIM_RUNNING:
		if (c->xfr_wait)
			return limit;	/* nothing happens until the other core joins */
		if (c->idle.epoch != s->epoch)
			return 0;
		period = (u64)*lcm / gcd_u32(*lcm, c->idle.period) * c->idle.period;
		if (period > IDLE_MAX_PERIOD)
			return 0;
		*lcm = period;
		if (c->control & PRUSIM_CTRL_CTR_EN)
			limit = from + (COUNTER_MAX - 1 - c->cycle_cnt);
		break;
	case PRUSIM_SLEEPING:
		limit = c->next;
		break;
	default:
		return limit;
	}
	/* the loop (or the wake-up) may depend on the R31 inputs */
	if (from >= c->r31_until) {
		u64 epoch = s->epoch;

		r31_refresh(s, c, from);
		if (s->epoch != epoch)
			return 0;
	}
	return prusim_min_u64(limit, c->r31_until);
}

/*
 * Move an idle core @cycles (a whole number of its loop periods) forward, as
 * if it had stepped through them.  The watch moves too: its cycle and counts
 * are the baseline of the next idle_watch(), which must measure one
 * iteration, not the iteration plus the skipped ones.
 */
static void skip_core(struct prusim_core *c, u64 cycles)
{
	u64 n, insns, stalls;

	if (c->state != PRUSIM_RUNNING || c->xfr_wait)
		return;
	n = prusim_div_u64(cycles, c->idle.period);
	insns = n * c->idle.insns;
	stalls = n * c->idle.stalls;
	c->insns += insns;
	c->stalls += stalls;
	c->skipped_insns += insns;
	if (c->control & PRUSIM_CTRL_CTR_EN) {
		/*
		 * skip_limit() keeps CYCLE below saturation; a store to CYCLE
		 * ends the idle observation, so &prusim_core.ctr_from is past
		 */
		c->cycle_cnt += cycles;
		c->stall_cnt = (u64)c->stall_cnt + stalls >= COUNTER_MAX ?
			       COUNTER_MAX : c->stall_cnt + stalls;
	}
	c->next += cycles;
	c->watch.cycle += cycles;
	c->watch.insns += insns;
	c->watch.stalls += stalls;
}

/*
 * Every core is idle, asleep or stopped from cycle @from on: jump over whole
 * common periods up to the first cycle at which anything could change.
 */
static void try_skip(struct prusim *s, u64 from, u64 end)
{
	u64 limit = prusim_min_u64(end, s->next_event);
	u32 lcm = 1;
	u64 cycles;
	unsigned int i;

	u64 inside = s->next_event;

	if (s->cfg.no_skip || from >= limit)
		return;
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		u64 l = skip_limit(s, &s->core[i], from, &lcm);

		if (!l)
			return;
		limit = prusim_min_u64(limit, l);
		inside = prusim_min_u64(inside, l);
	}
	if (inside == PRUSIM_NEVER && s->cfg.stop_when_idle) {
		/* nothing inside will ever end the wait: leave the rest of the budget */
		s->waiting = true;
		prusim_yield(s);
		return;
	}
	if (limit <= from)
		return;
	cycles = prusim_div_u64(limit - from, lcm) * lcm;
	for (i = 0; i < PRUSIM_NUM_CORES && cycles; i++)
		skip_core(&s->core[i], cycles);
}

/* ---------------------------------------------------------------------- */
/* Loads, stores, transfers                                                */

static u32 burst_len(const struct prusim_core *c, u8 code)
{
	return code < BURST_R0 ? code + 1u : (c->r[0] >> (8 * (code - BURST_R0))) & 0xff;
}

/* Cost of the instruction, or 0 if it did not complete */
static noinline u32 exec_load(struct prusim *s, struct prusim_core *c,
			      const struct prusim_insn *in, u32 base)
{
	u32 len = burst_len(c, in->len), addr = base + src2(c, in);
	struct prusim_access acc;
	u8 buf[REGFILE_BYTES];
	enum prusim_lat lat;
	const u8 *ram;

	if (in->rd + len > REGFILE_BYTES) {
		prusim_stop(s, c, "load of %u bytes into r%u.b%u runs past r31", len,
			    in->rd / 4, in->rd & 3);
		return 0;
	}
	if (!len)
		return 1;
	ram = prusim_ram(s, c, addr, len, &lat);
	if (likely(ram)) {
		regfile_write(s, c, in->rd, ram, len);
		return prusim_read_cycles(s, lat, len);
	}
	if (prusim_mem_read(s, c, addr, buf, len, &acc))
		return 0;
	c->dirty |= acc.volatile_data;
	regfile_write(s, c, in->rd, buf, len);
	return acc.cycles;
}

static noinline u32 exec_store(struct prusim *s, struct prusim_core *c,
			       const struct prusim_insn *in, u32 base)
{
	u32 len = burst_len(c, in->len), addr = base + src2(c, in);
	struct prusim_access acc;
	u8 buf[REGFILE_BYTES];
	enum prusim_lat lat;
	u8 *ram;

	if (in->rd + len > REGFILE_BYTES) {
		prusim_stop(s, c, "store of %u bytes from r%u.b%u runs past r31", len,
			    in->rd / 4, in->rd & 3);
		return 0;
	}
	if (!len)
		return 1;
	if (covers(in->rd, len, 31))
		c->r[31] = prusim_r31(s, c);
	c->dirty = true;
	ram = prusim_ram(s, c, addr, len, &lat);
	if (likely(ram)) {
		regfile_read(c, in->rd, ram, len);
		s->epoch++;
		return prusim_write_cycles(s, len);
	}
	regfile_read(c, in->rd, buf, len);
	if (prusim_mem_write(s, c, addr, buf, len, &acc))
		return 0;
	if (acc.retry) {
		stall_retry(s, c);
		return 0;
	}
	return acc.cycles;
}

/* XFR with a scratchpad bank: exchange the bytes of r0..r29 register-wise */
static u32 xfr_spad(struct prusim *s, struct prusim_core *c, const struct prusim_insn *in,
		    u32 len)
{
	unsigned int bank = in->aux - XFR_SPAD0;
	bool shifting = s->cfg_regs[PRUSIM_CFG_REG(PRUSIM_CFG_SPP)] & PRUSIM_SPP_XFR_SHIFT_EN;
	u32 shift = shifting ? c->r[0] & 0x1f : 0;
	u8 regs[XFR_BYTES];
	u32 i;

	if (in->kind != OP_XIN) {
		/* simultaneous writes to one bank: PRU0 wins, PRU1 stalls */
		if (c->index && s->spad_xout[bank] == s->now) {
			stall_retry(s, c);
			return 0;
		}
		if (!c->index)
			s->spad_xout[bank] = s->now;
		s->epoch++;
		c->dirty = true;
	}
	regfile_read(c, in->rd, regs, len);
	for (i = 0; i < len; i++) {
		u32 off = in->rd + i;
		u32 sp = ((off / 4 + shift) % 30) * 4 + (off & 3);
		u8 reg = regs[i];

		if (in->kind != OP_XOUT)
			regs[i] = s->spad[bank][sp];
		if (in->kind != OP_XIN)
			s->spad[bank][sp] = reg;
	}
	if (in->kind != OP_XOUT)
		regfile_write(s, c, in->rd, regs, len);
	return 1;
}

/*
 * XFR device 14 connects the register files of the two cores: an XOUT on
 * one core and an XIN on the other complete together; the first to arrive
 * stalls.  The XIN's byte range is copied from the XOUT core's registers.
 */
static u32 xfr_direct(struct prusim *s, struct prusim_core *c, const struct prusim_insn *in)
{
	struct prusim_core *o = &s->core[!c->index];
	u8 mine = in->kind == OP_XIN ? 1 : 2;
	struct prusim_core *dst = mine == 1 ? c : o;
	const struct prusim_insn *xin;
	u8 regs[XFR_BYTES];
	u32 len;

	if (in->kind == OP_XCHG) {
		prusim_stop(s, c, "XCHG with the other PRU (XFR device 14) is not supported");
		return 0;
	}
	if (o->state != PRUSIM_RUNNING || o->xfr_wait != 3 - mine) {
		c->xfr_wait = mine;
		c->xfr_since = s->now;
		c->next = PRUSIM_NEVER;
		return 0;
	}
	/* the other core waits at its XFR, so its pc is valid */
	xin = mine == 1 ? in : &o->code[o->pc];
	len = burst_len(dst, xin->len);
	if (xin->rd + len > XFR_BYTES) {
		prusim_stop(s, dst, "XIN of %u bytes past r29", len);
		return 0;
	}
	regfile_read(dst == c ? o : c, xin->rd, regs, len);
	regfile_write(s, dst, xin->rd, regs, len);
	o->xfr_wait = 0;
	retire(s, o, o->xfr_since, o->pc + 1, s->now - o->xfr_since + 1);
	s->epoch++;
	c->dirty = true;
	return 1;
}

/* XFR device 0: the multiplier / multiply-accumulate unit on r25..r29 */
static u32 xfr_mac(struct prusim *s, struct prusim_core *c, const struct prusim_insn *in,
		   u32 len)
{
	u8 regs[XFR_BYTES];
	u32 v, i;

	if (in->rd < 25 * 4 || in->kind == OP_XCHG) {
		prusim_stop(s, c, "XFR with the multiplier must use r25..r29 and XIN or XOUT");
		return 0;
	}
	if (in->kind == OP_XOUT) {
		if (covers(in->rd, len, 25)) {
			v = c->r[25];
			if (v & 2) {
				c->mac_acc = 0;
				c->mac_carry = false;
			} else if (c->mac_mode && (v & 1)) {
				u64 acc = c->mac_acc + mpy_product(s, c);

				c->mac_carry |= acc < c->mac_acc;
				c->mac_acc = acc;
			}
			c->mac_mode = v & 1;
			s->epoch++;
			c->dirty = true;
		}
		return 1;
	}
	for (i = 0; i < len; i++) {
		u32 off = in->rd + i;
		u64 prod = c->mac_mode ? c->mac_acc : mpy_product(s, c);

		switch (off / 4) {
		case 25:
			v = c->mac_mode | c->mac_carry << 1;
			break;
		case 26:
			v = prod;
			break;
		case 27:
			v = prod >> 32;
			break;
		default:
			v = c->r[off / 4];
			break;
		}
		regs[i] = v >> (8 * (off & 3));
	}
	regfile_write(s, c, in->rd, regs, len);
	return 1;
}

static u32 exec_xfr(struct prusim *s, struct prusim_core *c, const struct prusim_insn *in)
{
	u32 len = burst_len(c, in->len);
	u8 regs[XFR_BYTES];

	if (in->aux == XFR_DIRECT)
		return xfr_direct(s, c, in);
	if (in->rd + len > XFR_BYTES) {
		prusim_stop(s, c, "XFR of %u bytes from r%u.b%u runs past r29", len,
			    in->rd / 4, in->rd & 3);
		return 0;
	}
	switch (in->aux) {
	case XFR_MAC:
		return xfr_mac(s, c, in, len);
	case XFR_SPAD0:
	case XFR_SPAD0 + 1:
	case XFR_SPAD0 + 2:
		return xfr_spad(s, c, in, len);
	case XFR_FILL:
	case XFR_ZERO:
		if (in->kind != OP_XIN)
			break;
		memset(regs, in->aux == XFR_FILL ? 0xff : 0, len);
		regfile_write(s, c, in->rd, regs, len);
		return 1;
	}
	prusim_stop(s, c, "XFR device %u is not modelled", in->aux);
	return 0;
}

/* ---------------------------------------------------------------------- */
/* Execution                                                               */

static u32 lmbd(const struct prusim_insn *in, u32 v, u32 bit)
{
	int i = in->rs1_mask == 0xff ? 7 : in->rs1_mask == 0xffff ? 15 : 31;

	for (; i >= 0; i--) {
		if (((v >> i) & 1) == (bit & 1))
			return i;
	}
	return 32;
}

/*
 * ALU, LDI and LMBD.  Called with a constant @op from the fast dispatch,
 * where the switch folds away, and with the decoded op from exec().
 */
static __always_inline void alu(struct prusim_core *c, const struct prusim_insn *in, u8 op)
{
	u32 a = src1(c, in), b = src2(c, in);

	switch (op) {
	case OP_ADD:
		wr_dst(c, in, with_carry(c, in, (u64)a + b));
		break;
	case OP_ADC:
		wr_dst(c, in, with_carry(c, in, (u64)a + b + c->carry));
		break;
	case OP_SUB:
		wr_dst(c, in, with_carry(c, in, (u64)a - b));
		break;
	case OP_SUC:
		wr_dst(c, in, with_carry(c, in, (u64)a - b - c->carry));
		break;
	case OP_RSB:
		wr_dst(c, in, with_carry(c, in, (u64)b - a));
		break;
	case OP_RSC:
		wr_dst(c, in, with_carry(c, in, (u64)b - a - c->carry));
		break;
	case OP_LSL:
		wr_dst(c, in, a << (b & 31));
		break;
	case OP_LSR:
		wr_dst(c, in, a >> (b & 31));
		break;
	case OP_AND:
		wr_dst(c, in, a & b);
		break;
	case OP_OR:
		wr_dst(c, in, a | b);
		break;
	case OP_XOR:
		wr_dst(c, in, a ^ b);
		break;
	case OP_NOT:
		wr_dst(c, in, ~a);
		break;
	case OP_MIN:
		wr_dst(c, in, a < b ? a : b);
		break;
	case OP_MAX:
		wr_dst(c, in, a > b ? a : b);
		break;
	case OP_CLR:
		wr_dst(c, in, a & ~(1u << (b & 31)));
		break;
	case OP_SET:
		wr_dst(c, in, a | 1u << (b & 31));
		break;
	case OP_LDI:
		wr_dst(c, in, b);
		break;
	case OP_LMBD:
		wr_dst(c, in, lmbd(in, a, b));
		break;
	}
}

/*
 * Branches and jumps: true if taken, with the word address in @target.
 * Folds like alu() for a constant @op.
 */
static __always_inline bool jump(struct prusim_core *c, const struct prusim_insn *in, u8 op,
				 u32 *target)
{
	u32 a = src1(c, in), b = src2(c, in);

	*target = in->target;
	switch (op) {
	case OP_QB:
		/* condition bits: 4 = branch if b > a, 2 = if b == a, 1 = if b < a */
		return in->aux & (b > a ? 4 : b == a ? 2 : 1);
	case OP_QBBS:
		return (a >> (b & 31)) & 1;
	case OP_QBBC:
		return !((a >> (b & 31)) & 1);
	case OP_JAL:
		wr_dst(c, in, c->pc + 1);
		fallthrough;
	case OP_JMP:
		*target = b;
		return true;
	}
	return false;
}

/* Retire a taken branch or jump of one cycle. */
static void branch(struct prusim *s, struct prusim_core *c, u32 pc, u32 target)
{
	/* a taken branch out of a hardware loop body ends the loop */
	if (target < c->loop_start || target >= c->loop_end)
		c->loop_end = PRUSIM_NO_LOOP;
	retire(s, c, s->now, target, 1);
	if (target <= pc)
		idle_watch(s, c, target);
}

static void exec_loop(struct prusim_core *c, const struct prusim_insn *in, u32 *npc)
{
	u32 count = src2(c, in) & 0xffff;

	c->dirty = true;
	if (!count) {
		*npc = in->target;
		return;
	}
	if (in->target <= c->pc + 1)
		return;		/* empty body */
	c->loop_start = c->pc + 1;
	c->loop_end = in->target;
	c->loop_left = count;
}

static void exec_sleep(struct prusim *s, struct prusim_core *c, bool wake_on_status)
{
	if (c->state != PRUSIM_RUNNING)
		return;		/* single-stepped: stays disabled */
	c->wake_on_status = wake_on_status;
	if (wake_on_status && (prusim_r31(s, c) & c->wakeup_en))
		return;
	c->state = PRUSIM_SLEEPING;
	c->next = wake_on_status ? c->r31_until : PRUSIM_NEVER;
	s->epoch++;
}

/* A sleeping core polls its wake-up condition; true if it runs again. */
static bool sleep_poll(struct prusim *s, struct prusim_core *c)
{
	if (c->wake_on_status && (prusim_r31(s, c) & c->wakeup_en)) {
		c->state = PRUSIM_RUNNING;
		s->epoch++;
		return true;
	}
	c->next = c->r31_until;
	return false;
}

static void exec_halt(struct prusim *s, struct prusim_core *c)
{
	c->insns++;
	if (c->control & PRUSIM_CTRL_CTR_EN)
		prusim_count(c, s->now, s->now + 1, s->now + 1);
	c->state = PRUSIM_HALTED;
	c->next = PRUSIM_NEVER;
	snprintf(c->reason, sizeof(c->reason), "HALT at 0x%04x", c->pc * 4);
	s->epoch++;
}

static void special_post(struct prusim *s, struct prusim_core *c, const struct prusim_insn *in,
			 u32 old30)
{
	if (in->rd == 30)
		r30_changed(s, c, old30);
	else if (in->rd == 31)
		r31_write(s, c, (c->r[31] >> in->rd_shift & in->rd_mask) << in->rd_shift);
}

/* Cost of a memory, transfer or control instruction; 0 if it did not retire */
static u32 exec_slow(struct prusim *s, struct prusim_core *c, const struct prusim_insn *in,
		     u32 *npc)
{
	switch (in->kind) {
	case OP_LBBO:
		return exec_load(s, c, in, src1(c, in));
	case OP_LBCO:
		return exec_load(s, c, in, c->ctable[in->aux]);
	case OP_SBBO:
		return exec_store(s, c, in, src1(c, in));
	case OP_SBCO:
		return exec_store(s, c, in, c->ctable[in->aux]);
	case OP_XIN:
	case OP_XOUT:
	case OP_XCHG:
		return exec_xfr(s, c, in);
	case OP_LOOP:
		exec_loop(c, in, npc);
		return 1;
	case OP_HALT:
		exec_halt(s, c);
		return 0;
	}
	prusim_stop(s, c, "illegal instruction 0x%08x at 0x%04x", c->iram[c->pc], c->pc * 4);
	return 0;
}

/*
 * Execute any instruction: the path for operands and destinations with side
 * effects (r28..r31), memory, transfers and control.
 */
static noinline void exec(struct prusim *s, struct prusim_core *c, const struct prusim_insn *in)
{
	u32 pc = c->pc, npc = pc + 1, cost, old30 = c->r[30], target;

	if (in->flags & IF_R31)
		c->r[31] = prusim_r31(s, c);
	if ((in->flags & IF_WR_SPECIAL) && (in->rd == 28 || in->rd == 29))
		mpy_note(s, c);
	switch (in->kind) {
	case OP_ADD ... OP_LMBD:
		alu(c, in, in->kind);
		break;
	case OP_JMP ... OP_QBBC:
		if (jump(c, in, in->kind, &target)) {
			if (in->flags & IF_WR_SPECIAL)
				special_post(s, c, in, old30);
			branch(s, c, pc, target);
			return;
		}
		break;
	case OP_SLP:
		retire(s, c, s->now, npc, 1);
		exec_sleep(s, c, in->aux);
		return;
	default:
		cost = exec_slow(s, c, in, &npc);
		if (cost)
			retire(s, c, s->now, npc, cost);
		return;
	}
	if (in->flags & IF_WR_SPECIAL)
		special_post(s, c, in, old30);
	retire(s, c, s->now, npc, 1);
}

/* Retire a load or store that took @cost cycles (0: it did not complete) */
static __always_inline void memory(struct prusim *s, struct prusim_core *c, u32 cost)
{
	if (cost)
		retire(s, c, s->now, c->pc + 1, cost);
}

/* Write the whole of r30 and report the pins that changed */
static __always_inline void r30_write(struct prusim *s, struct prusim_core *c, u32 v)
{
	u32 old = c->r[30];

	if (old != v) {
		c->r[30] = v;
		c->dirty = true;
		r30_changed(s, c, old);
	}
}

/* An ALU operation on r30 (no r31 operand): report the pins that changed */
static noinline void alu_r30(struct prusim *s, struct prusim_core *c,
			     const struct prusim_insn *in)
{
	u32 old = c->r[30];

	alu(c, in, in->kind);
	r30_changed(s, c, old);
	retire(s, c, s->now, c->pc + 1, 1);
}

/* The cases step() does not take inline: not running, pc out of range, trace */
static noinline void step_checked(struct prusim *s, struct prusim_core *c)
{
	if (c->state != PRUSIM_RUNNING && (c->state != PRUSIM_SLEEPING || !sleep_poll(s, c)))
		return;
	if (c->pc >= PRUSIM_IRAM_WORDS) {
		prusim_stop(s, c, "program counter 0x%04x is outside IRAM", c->pc * 4);
		return;
	}
	if (s->ops.trace)
		s->ops.trace(s->ctx, s->now, c->index, c->pc, c->iram[c->pc]);
	exec(s, c, &c->code[c->pc]);
}

/*
 * Execute the instruction at the pc of @c in cycle &prusim.now.  Plain
 * one-cycle instructions are dispatched here; everything else in exec().
 */
static __always_inline void step(struct prusim *s, struct prusim_core *c)
{
	const struct prusim_insn *in;
	u32 pc = c->pc, target;

	if (unlikely(pc >= PRUSIM_IRAM_WORDS || c->state != PRUSIM_RUNNING || s->ops.trace)) {
		step_checked(s, c);
		return;
	}
	in = &c->code[pc];
	switch (in->op) {
	case OP_ADD:
		alu(c, in, OP_ADD);
		break;
	case OP_ADC:
		alu(c, in, OP_ADC);
		break;
	case OP_SUB:
		alu(c, in, OP_SUB);
		break;
	case OP_SUC:
		alu(c, in, OP_SUC);
		break;
	case OP_LSL:
		alu(c, in, OP_LSL);
		break;
	case OP_LSR:
		alu(c, in, OP_LSR);
		break;
	case OP_RSB:
		alu(c, in, OP_RSB);
		break;
	case OP_RSC:
		alu(c, in, OP_RSC);
		break;
	case OP_AND:
		alu(c, in, OP_AND);
		break;
	case OP_OR:
		alu(c, in, OP_OR);
		break;
	case OP_XOR:
		alu(c, in, OP_XOR);
		break;
	case OP_NOT:
		alu(c, in, OP_NOT);
		break;
	case OP_MIN:
		alu(c, in, OP_MIN);
		break;
	case OP_MAX:
		alu(c, in, OP_MAX);
		break;
	case OP_CLR:
		alu(c, in, OP_CLR);
		break;
	case OP_SET:
		alu(c, in, OP_SET);
		break;
	case OP_LDI:
		alu(c, in, OP_LDI);
		break;
	case OP_QB:
		if (!jump(c, in, OP_QB, &target))
			break;
		branch(s, c, pc, target);
		return;
	case OP_QBBS:
		if (!jump(c, in, OP_QBBS, &target))
			break;
		branch(s, c, pc, target);
		return;
	case OP_QBBC:
		if (!jump(c, in, OP_QBBC, &target))
			break;
		branch(s, c, pc, target);
		return;
	case OP_JMP:
		jump(c, in, OP_JMP, &target);
		branch(s, c, pc, target);
		return;
	case OP_JAL:
		jump(c, in, OP_JAL, &target);
		branch(s, c, pc, target);
		return;
	case OP_LBBO:
		memory(s, c, exec_load(s, c, in, src1(c, in)));
		return;
	case OP_LBCO:
		memory(s, c, exec_load(s, c, in, c->ctable[in->aux]));
		return;
	case OP_SBBO:
		memory(s, c, exec_store(s, c, in, src1(c, in)));
		return;
	case OP_SBCO:
		memory(s, c, exec_store(s, c, in, c->ctable[in->aux]));
		return;
	case OP_R30:
		alu_r30(s, c, in);
		return;
	case OP_R30_SET:
		r30_write(s, c, c->r[30] | 1u << (in->imm & 31));
		break;
	case OP_R30_CLR:
		r30_write(s, c, c->r[30] & ~(1u << (in->imm & 31)));
		break;
	case OP_R30_MOV:
		r30_write(s, c, src1(c, in));
		break;
	default:
		exec(s, c, in);
		return;
	}
	retire(s, c, s->now, pc + 1, 1);
}

/**
 * prusim_run() - simulate up to @max_cycles cycles
 * @s: simulator
 * @max_cycles: cycle budget
 *
 * Both cores advance in lockstep.  Returns early when a core is stopped by
 * the simulator (see prusim_get_status()) or when nothing can happen any
 * more: no core runs, no sleeping core can be woken by an input, and no
 * posted write or event is in flight, or when a callback called
 * prusim_yield().  Idle cycles (only waiting loops,
 * sleeping or halted cores) are skipped without changing the result.  It
 * neither sleeps nor yields: a kernel embedder calls it in slices.
 *
 * Return: number of cycles simulated; &prusim.now advanced by as much.
 */
u64 prusim_run(struct prusim *s, u64 max_cycles)
{
	u64 start = s->now, done = s->now;
	u64 end = max_cycles > PRUSIM_NEVER - start ? PRUSIM_NEVER : start + max_cycles;
	struct prusim_core *c0 = &s->core[0], *c1 = &s->core[1];

	s->stop_run = false;
	s->waiting = false;
	s->attention = 0;
	s->in_step = true;
	for (;;) {
		u64 t = prusim_min_u64(c0->next, c1->next);

		if (unlikely(t >= s->attention)) {
			if (s->stop_run)
				break;
			if (s->skip_pending) {
				s->skip_pending = false;
				try_skip(s, prusim_min_u64(t, s->next_event), end);
				t = prusim_min_u64(c0->next, c1->next);
			}
			t = prusim_min_u64(t, s->next_event);
			if (t >= end) {
				if (t != PRUSIM_NEVER)
					done = end;
				break;
			}
			if (t >= s->next_event) {
				s->now = t;
				s->in_step = false;
				prusim_queue_run(s);
				s->in_step = true;
			}
			/* a callback of the queued action may have asked to return */
			s->attention = s->stop_run ? 0 : prusim_min_u64(end, s->next_event);
		}
		s->now = t;
		if (c0->next == t)
			step(s, c0);
		if (c1->next == t)
			step(s, c1);
		done = t + 1;
	}
	s->in_step = false;
	s->now = done;
	return done - start;
}

/* ---------------------------------------------------------------------- */
/* Setup and state                                                         */

/**
 * prusim_default_config() - the documented AM335x timing
 * @cfg: filled in
 *
 * Read latencies are the best-case figures of TI's "AM335x PRU Read
 * Latencies" and the PRU cookbook; see Documentation/prusim.rst.
 */
void prusim_default_config(struct prusim_config *cfg)
{
	static const u16 lat[PRUSIM_NUM_LAT] = {
		[PRUSIM_LAT_DRAM] = 3,
		[PRUSIM_LAT_SHARED] = 3,
		[PRUSIM_LAT_INTC] = 3,
		[PRUSIM_LAT_CTRL] = 4,
		[PRUSIM_LAT_CFG] = 3,
		[PRUSIM_LAT_IEP] = 4,
		[PRUSIM_LAT_GPIO0] = 38,
		[PRUSIM_LAT_GPIO] = 34,
		[PRUSIM_LAT_OCMC] = 27,
		[PRUSIM_LAT_DDR] = 43,
		[PRUSIM_LAT_PRCM] = 88,
		[PRUSIM_LAT_OCP] = 34,
	};

	memset(cfg, 0, sizeof(*cfg));
	memcpy(cfg->read_latency, lat, sizeof(lat));
	cfg->read_word_cycles = 1;
	cfg->write_cycles = 1;
	cfg->write_word_cycles = 1;
	cfg->gpio_write_latency = 17;
	cfg->gpio_write_interval = 8;
	cfg->r31_sync_delay = 0;
	cfg->event_latency = 1;
}

static void core_init(struct prusim *s, unsigned int index)
{
	struct prusim_core *c = &s->core[index];
	u32 pc;

	c->index = index;
	c->state = PRUSIM_DISABLED;
	c->next = PRUSIM_NEVER;
	c->loop_end = PRUSIM_NO_LOOP;
	c->watch.pc = PRUSIM_NO_LOOP;
	prusim_ctrl_update_ctable(c);
	for (pc = 0; pc < PRUSIM_IRAM_WORDS; pc++)
		prusim_decode(&c->code[pc], 0, pc);
}

/**
 * prusim_init() - reset the whole subsystem
 * @s: simulator memory, owned by the caller
 * @cfg: timing, or NULL for prusim_default_config()
 * @ops: callbacks (copied), or NULL for none
 * @ctx: first argument of every callback
 *
 * All memories are cleared, both cores are disabled at pc 0 and the cycle
 * counter starts at 0.  The event latency is clamped to 1..16 cycles.
 */
void prusim_init(struct prusim *s, const struct prusim_config *cfg,
		 const struct prusim_ops *ops, void *ctx)
{
	unsigned int i;

	memset(s, 0, sizeof(*s));
	if (cfg)
		s->cfg = *cfg;
	else
		prusim_default_config(&s->cfg);
	if (ops)
		s->ops = *ops;
	s->ctx = ctx;
	if (s->cfg.event_latency < 1)
		s->cfg.event_latency = 1;
	if (s->cfg.event_latency > PRUSIM_MAX_EVENT_LATENCY)
		s->cfg.event_latency = PRUSIM_MAX_EVENT_LATENCY;
	s->epoch = 1;
	for (i = 0; i < PRUSIM_SPAD_BANKS; i++)
		s->spad_xout[i] = PRUSIM_NEVER;
	for (i = 0; i < PRUSIM_NUM_CORES; i++)
		core_init(s, i);
	prusim_mem_reset(s);
}

/**
 * prusim_icss_reset() - the PRU-ICSS's local reset (PRCM's PRU_ICSS_LRST)
 * @s: simulator
 *
 * The subsystem goes back to the state prusim_init() leaves it in: both
 * cores disabled at pc 0 with their registers, instruction and data RAMs
 * cleared, shared RAM, the scratchpad, the INTC, the IEP and CFG at their
 * reset values, and the events on their way to the INTC dropped.  What
 * lies outside the subsystem is kept: the time, the configuration and
 * callbacks, the GPIO banks, and the GPIO writes and OCP stores already
 * on the interconnect (they land when they are due).
 */
void prusim_icss_reset(struct prusim *s)
{
	unsigned int i, n = 0;

	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		memset(&s->core[i], 0, sizeof(s->core[i]));
		core_init(s, i);
	}
	memset(s->shared, 0, sizeof(s->shared));
	memset(s->spad, 0, sizeof(s->spad));
	for (i = 0; i < PRUSIM_SPAD_BANKS; i++)
		s->spad_xout[i] = PRUSIM_NEVER;
	prusim_icss_regs_reset(s);
	for (i = 0; i < s->queued; i++) {
		if (s->queue[i].kind != PRUSIM_TIMED_EVENT)
			s->queue[n++] = s->queue[i];
	}
	s->queued = n;
	s->next_event = n ? s->queue[0].cycle : PRUSIM_NEVER;
	s->skip_pending = false;
	s->waiting = false;
	s->stop_run = true;
	s->attention = 0;
	s->epoch++;
}

/**
 * prusim_core_reset() - soft reset of one core (CONTROL.SOFT_RST_N = 0)
 * @s: simulator
 * @core: 0 or 1
 * @pc: program counter after reset (word address), also PCOUNTER_RST_VAL
 *
 * The core is left disabled; registers and memories keep their contents.
 */
void prusim_core_reset(struct prusim *s, unsigned int core, u32 pc)
{
	struct prusim_core *c = &s->core[core];

	c->pc = pc & 0xffff;
	c->control = (c->control & 0xffff) | c->pc << PRUSIM_CTRL_RST_VAL_SHIFT;
	c->state = PRUSIM_DISABLED;
	c->next = PRUSIM_NEVER;
	c->loop_end = PRUSIM_NO_LOOP;
	c->xfr_wait = 0;
	c->reason[0] = '\0';
	s->epoch++;
}

/**
 * prusim_core_enable() - set or clear CONTROL.EN of one core
 * @s: simulator
 * @core: 0 or 1
 * @enable: run (from the current pc) or stop after the current instruction
 *
 * A stopped core must be reset first.  An enabled core issues its next
 * instruction at &prusim.now (the next cycle when called by a PRU store).
 */
void prusim_core_enable(struct prusim *s, unsigned int core, bool enable)
{
	struct prusim_core *c = &s->core[core];

	if (enable && (c->state == PRUSIM_DISABLED || c->state == PRUSIM_HALTED)) {
		c->state = PRUSIM_RUNNING;
		c->next = s->now + s->in_step;
		c->reason[0] = '\0';
	} else if (!enable && (c->state == PRUSIM_RUNNING || c->state == PRUSIM_SLEEPING)) {
		c->state = PRUSIM_DISABLED;
		c->next = PRUSIM_NEVER;
		c->xfr_wait = 0;
	}
	s->epoch++;
}

/**
 * prusim_write_iram() - write instruction RAM of a core (and predecode it)
 * @s: simulator
 * @core: 0 or 1
 * @offset: byte offset in IRAM
 * @buf: data, instruction words little endian
 * @len: bytes
 *
 * Return: 0, or -EINVAL if the range is outside the 8 KiB IRAM.
 */
int prusim_write_iram(struct prusim *s, unsigned int core, u32 offset, const void *buf,
		      size_t len)
{
	struct prusim_core *c = &s->core[core];
	const u8 *p = buf;
	size_t i;

	if (core >= PRUSIM_NUM_CORES || offset > PRUSIM_IRAM_SIZE ||
	    len > PRUSIM_IRAM_SIZE - offset)
		return -EINVAL;
	for (i = 0; i < len; i++, offset++) {
		u32 pc = offset / 4, shift = 8 * (offset & 3);

		c->iram[pc] = (c->iram[pc] & ~(0xffu << shift)) | (u32)p[i] << shift;
		if ((offset & 3) == 3 || i == len - 1)
			prusim_decode(&c->code[pc], c->iram[pc], pc);
	}
	s->epoch++;
	return 0;
}

/**
 * prusim_set_ocp_write_delay() - change &prusim_config.ocp_write_delay
 * @s: simulator
 * @cycles: the new delay
 *
 * Stores on their way land when they were due to; later ones land after
 * them, however short the new delay.
 */
void prusim_set_ocp_write_delay(struct prusim *s, u32 cycles)
{
	s->cfg.ocp_write_delay = cycles;
}

/**
 * prusim_set_ddr_jitter() - change &prusim_config.ddr_jitter and its seed
 * @s: simulator
 * @cycles: the most a DDR access may take longer
 * @seed: the seed
 */
void prusim_set_ddr_jitter(struct prusim *s, u16 cycles, u32 seed)
{
	s->cfg.ddr_jitter = cycles;
	s->cfg.jitter_seed = seed;
}

/**
 * prusim_active() - can anything still happen?
 * @s: simulator
 *
 * Return: true if a core runs or sleeps, or a posted write or event is in
 * flight.
 */
bool prusim_active(const struct prusim *s)
{
	unsigned int i;

	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		if (s->core[i].state == PRUSIM_RUNNING || s->core[i].state == PRUSIM_SLEEPING)
			return true;
	}
	return s->queued;
}

/**
 * prusim_get_status() - snapshot of a core
 * @s: simulator
 * @core: 0 or 1
 * @st: filled in; @st->reason points into @s
 */
void prusim_get_status(const struct prusim *s, unsigned int core, struct prusim_status *st)
{
	const struct prusim_core *c = &s->core[core];

	st->state = c->state;
	st->pc = c->pc;
	st->insns = c->insns;
	st->stalls = c->stalls;
	st->skipped_insns = c->skipped_insns;
	st->cycle_cnt = c->cycle_cnt;
	st->stall_cnt = c->stall_cnt;
	memcpy(st->regs, c->r, sizeof(st->regs));
	st->reason = c->reason;
}

/**
 * prusim_input_changed() - an input source changed its pattern
 * @s: simulator
 * @port: PRUSIM_PORT_R31() or PRUSIM_PORT_GPIO() number
 *
 * The simulator caches input values until the change their source announced
 * (&prusim_ops.input's next_change).  An embedder whose source changes
 * otherwise (new stimulus) calls this between prusim_run() calls: the next
 * read asks the source again, and sleeping or idle cores look again.
 */
void prusim_input_changed(struct prusim *s, unsigned int port)
{
	unsigned int i;

	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		struct prusim_core *c = &s->core[i];

		if (port != PRUSIM_PORT_R31(i))
			continue;
		c->r31_until = s->now;
		if (c->state == PRUSIM_SLEEPING && c->wake_on_status)
			c->next = s->now;
	}
	s->epoch++;
}

/**
 * prusim_memory_written() - the embedder wrote memory that a core may poll
 * @s: simulator
 *
 * Writes through prusim_da_to_va() pointers (or to the RAM behind the OCP
 * port) are invisible to the idle detector: a core found spinning on a
 * control word would be skipped over forever.  Call this between
 * prusim_run() calls whenever such a write may have happened; idle loops
 * are examined afresh (costing one iteration each), nothing else changes.
 */
void prusim_memory_written(struct prusim *s)
{
	s->epoch++;
}

/**
 * prusim_yield() - make prusim_run() return at the end of the current cycle
 * @s: simulator
 *
 * For callbacks: an embedder that must act on what just happened (a host
 * interrupt for the ARM, say) ends the slice here instead of at its budget.
 * The cycles not run are simply run by the next prusim_run() call; the
 * simulated result does not change.
 */
void prusim_yield(struct prusim *s)
{
	s->stop_run = true;
	s->attention = 0;
}
