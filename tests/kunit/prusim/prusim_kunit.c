// SPDX-License-Identifier: GPL-2.0-only
/*
 * KUnit suite "prusim_validation": the prusim validation programs (the .S
 * files of tests/prusim/asm and the .c files of tests/prusim/c) run on the
 * simulator core compiled into the kernel, with the checks that
 * tests/prusim/runner.py makes on the host: the expected registers, counts,
 * states and stop reasons, host interrupt changes, pin edges, gaps and
 * periods, and the exit status the prusim tool would have.
 *
 * The firmware and the checks come from prusim_kunit_data.h, which
 * tests/kunit/prusim/gen.sh generates from the validation programs (see
 * gen.py and prusim_kunit.h).  Each program runs three times, as the tool
 * runs it (idle skipping, one prusim_run() call between two events), with
 * skipping off, and skipping in short slices as the QEMU PRU-ICSS runs it; the three
 * results must be identical.  Every check is also made once with its
 * expected value changed, and must then fail: no check passes vacuously.
 */

#include <kunit/resource.h>
#include <kunit/test.h>
#include <linux/sched.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/vmalloc.h>

#include "prusim.h"
#include "prusim_stim.h"
#include "prusim_kunit.h"

#define PK_MAX_PIN_LOG	65536		/* pin changes recorded per run */
#define PK_MAX_IRQS	256		/* host interrupt changes recorded per run */
#define PK_SLICE	997		/* cycles per prusim_run() of the sliced run */
#define PK_DDR_BASE	0x80000000u
#define PK_EXIT_NO_HALT	2
#define PK_EXIT_STOPPED	3

/**
 * struct pk_pin - one recorded pin change
 * @cycle: when
 * @pin: prusim pin id
 * @level: new level
 */
struct pk_pin {
	u64 cycle;
	u16 pin;
	u8 level;
};

/**
 * enum pk_mode - how a program is run
 * @PK_SKIP: idle skipping, one prusim_run() call up to each event (the tool)
 * @PK_STEP: no idle skipping (the tool's --no-skip)
 * @PK_SLICED: idle skipping, prusim_run() calls of %PK_SLICE cycles
 */
enum pk_mode {
	PK_SKIP,
	PK_STEP,
	PK_SLICED,
};

static const char *const pk_mode_names[] = { "skipping", "stepped", "sliced" };

/**
 * struct pk_run - one run of a validation program and its result
 * @s: the simulator
 * @stim: parsed stimulus of each input port
 * @has_stim: a stimulus is given for the port
 * @ddr: memory behind OCP address 0x80000000
 * @ddr_size: its size
 * @pins: pin changes in cycle order
 * @npins: entries in @pins
 * @pin_overflow: more than %PK_MAX_PIN_LOG changes happened
 * @pin_changes: number of pin changes
 * @irqs: host interrupt changes
 * @nirqs: entries in @irqs
 * @irq_overflow: more than %PK_MAX_IRQS changes happened
 * @st: status of each core at the end
 * @reason: copy of each core's reason
 * @cycles: &prusim.now at the end
 * @intc_raw: INTC raw status at the end
 * @intc_enabled: INTC enables at the end
 * @intc_pending: host interrupts pending at the end
 * @exit: the prusim tool's exit status for this result
 */
struct pk_run {
	struct prusim *s;
	struct prusim_stim stim[PRUSIM_NUM_PORTS];
	bool has_stim[PRUSIM_NUM_PORTS];
	u8 *ddr;
	u32 ddr_size;
	struct pk_pin *pins;
	u32 npins;
	bool pin_overflow;
	u64 pin_changes;
	struct prusim_kunit_irq irqs[PK_MAX_IRQS];
	u32 nirqs;
	bool irq_overflow;
	struct prusim_status st[PRUSIM_NUM_CORES];
	char reason[PRUSIM_NUM_CORES][PRUSIM_REASON_LEN];
	u64 cycles;
	u64 intc_raw;
	u64 intc_enabled;
	u32 intc_pending;
	int exit;
};

static int pk_vzalloc_init(struct kunit_resource *res, void *context)
{
	res->data = vzalloc(*(size_t *)context);
	return res->data ? 0 : -ENOMEM;
}

static void pk_vfree(struct kunit_resource *res)
{
	vfree(res->data);
}

/* vzalloc() freed when the test case ends */
static void *pk_vzalloc(struct kunit *test, size_t size)
{
	return kunit_alloc_resource(test, pk_vzalloc_init, pk_vfree, GFP_KERNEL, &size);
}

static void pk_on_pin(void *ctx, u64 cycle, unsigned int pin, bool level)
{
	struct pk_run *r = ctx;

	r->pin_changes++;
	if (r->npins < PK_MAX_PIN_LOG)
		r->pins[r->npins++] = (struct pk_pin){ cycle, pin, level };
	else
		r->pin_overflow = true;
}

static u32 pk_on_input(void *ctx, unsigned int port, u64 cycle, u64 *next)
{
	struct pk_run *r = ctx;

	if (port < PRUSIM_NUM_PORTS && r->has_stim[port])
		return prusim_stim_value(&r->stim[port], cycle, next);
	*next = PRUSIM_NEVER;
	return 0;
}

static void pk_on_host_irq(void *ctx, u64 cycle, unsigned int host, bool level)
{
	struct pk_run *r = ctx;

	if (r->nirqs < PK_MAX_IRQS)
		r->irqs[r->nirqs++] = (struct prusim_kunit_irq){ cycle, host, level };
	else
		r->irq_overflow = true;
}

static u8 *pk_ddr_at(struct pk_run *r, u32 addr, unsigned int len)
{
	u64 off = (u64)addr - PK_DDR_BASE;

	if (addr < PK_DDR_BASE || off > r->ddr_size || len > r->ddr_size - off)
		return NULL;
	return r->ddr + off;
}

static int pk_on_ocp_read(void *ctx, u32 addr, void *buf, unsigned int len)
{
	u8 *p = pk_ddr_at(ctx, addr, len);

	if (!p)
		return -EFAULT;
	memcpy(buf, p, len);
	return 0;
}

static int pk_on_ocp_write(void *ctx, u32 addr, const void *buf, unsigned int len)
{
	u8 *p = pk_ddr_at(ctx, addr, len);

	if (!p)
		return -EFAULT;
	memcpy(p, buf, len);
	return 0;
}

static const struct prusim_ops pk_ops = {
	.pin = pk_on_pin,
	.input = pk_on_input,
	.host_irq = pk_on_host_irq,
	.ocp_read = pk_on_ocp_read,
	.ocp_write = pk_on_ocp_write,
};

static void pk_set_config(struct prusim_config *cfg, const struct prusim_kunit_cfg *c)
{
	switch (c->param) {
	case PK_CFG_READ_WORD_CYCLES:
		cfg->read_word_cycles = c->value;
		break;
	case PK_CFG_WRITE_CYCLES:
		cfg->write_cycles = c->value;
		break;
	case PK_CFG_WRITE_WORD_CYCLES:
		cfg->write_word_cycles = c->value;
		break;
	case PK_CFG_GPIO_WRITE_LATENCY:
		cfg->gpio_write_latency = c->value;
		break;
	case PK_CFG_GPIO_WRITE_INTERVAL:
		cfg->gpio_write_interval = c->value;
		break;
	case PK_CFG_R31_SYNC_DELAY:
		cfg->r31_sync_delay = c->value;
		break;
	case PK_CFG_EVENT_LATENCY:
		cfg->event_latency = c->value;
		break;
	case PK_CFG_OCP_WRITE_DELAY:
		cfg->ocp_write_delay = c->value;
		break;
	case PK_CFG_DDR_JITTER:
		cfg->ddr_jitter = c->value;
		break;
	case PK_CFG_JITTER_SEED:
		cfg->jitter_seed = c->value;
		break;
	default:
		if (c->param < PRUSIM_NUM_LAT)
			cfg->read_latency[c->param] = c->value;
		break;
	}
}

/* Parse the stimulus of @port the way the tool and the QEMU PRU-ICSS do (two passes) */
static int pk_load_stim(struct kunit *test, struct pk_run *r, const struct prusim_kunit_case *c,
			unsigned int port)
{
	struct prusim_stim *st = &r->stim[port];
	char err[96];
	int n;

	n = prusim_stim_parse(c->stim[port], c->stim_len[port], NULL, err, sizeof(err));
	if (n < 0) {
		KUNIT_FAIL(test, "%s: input %u: %s", c->name, port, err);
		return n;
	}
	/* one spare entry: an empty stimulus still gets arrays */
	st->cycle = kunit_kmalloc_array(test, n + 1, sizeof(*st->cycle), GFP_KERNEL);
	st->value = kunit_kmalloc_array(test, n + 1, sizeof(*st->value), GFP_KERNEL);
	KUNIT_ASSERT_NOT_ERR_OR_NULL(test, st->cycle);
	KUNIT_ASSERT_NOT_ERR_OR_NULL(test, st->value);
	st->count = n;
	n = prusim_stim_parse(c->stim[port], c->stim_len[port], st, err, sizeof(err));
	if (n < 0) {
		KUNIT_FAIL(test, "%s: input %u, second pass: %s", c->name, port, err);
		return n;
	}
	r->has_stim[port] = true;
	return 0;
}

/* Advance to @until: one call, or slices of PK_SLICE cycles */
static void pk_advance(struct prusim *s, u64 until, bool sliced)
{
	u64 ask, ran;

	while (s->now < until) {
		ask = until - s->now;
		if (sliced && ask > PK_SLICE)
			ask = PK_SLICE;
		ran = prusim_run(s, ask);
		if (ran < ask || !sliced)
			return;		/* stopped, or nothing can happen any more */
		cond_resched();
	}
}

/*
 * Run @c as the prusim tool runs it: load the cores' firmware and start
 * them, then run to the end, raising the --event kicks on the way.
 */
static struct pk_run *pk_run(struct kunit *test, const struct prusim_kunit_case *c,
			     enum pk_mode mode)
{
	struct prusim_elf_info info;
	struct prusim_config cfg;
	struct pk_run *r;
	unsigned int i;
	u64 until;
	u32 k;

	r = pk_vzalloc(test, sizeof(*r));
	KUNIT_ASSERT_NOT_ERR_OR_NULL(test, r);
	r->s = pk_vzalloc(test, sizeof(*r->s));
	KUNIT_ASSERT_NOT_ERR_OR_NULL(test, r->s);
	r->pins = pk_vzalloc(test, PK_MAX_PIN_LOG * sizeof(*r->pins));
	KUNIT_ASSERT_NOT_ERR_OR_NULL(test, r->pins);
	if (c->ddr_size) {
		r->ddr = pk_vzalloc(test, c->ddr_size);
		KUNIT_ASSERT_NOT_ERR_OR_NULL(test, r->ddr);
		r->ddr_size = c->ddr_size;
	}
	for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
		if (c->stim[i] && pk_load_stim(test, r, c, i))
			return NULL;
	}

	prusim_default_config(&cfg);
	for (k = 0; k < c->ncfg; k++)
		pk_set_config(&cfg, &c->cfg[k]);
	cfg.no_skip = mode == PK_STEP;
	prusim_init(r->s, &cfg, &pk_ops, r);
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		if (!c->fw[i])
			continue;
		if (prusim_load_elf(r->s, i, c->fw[i], c->fw_size[i], &info)) {
			KUNIT_FAIL(test, "%s: PRU%u firmware rejected: %s", c->name, i, info.err);
			return NULL;
		}
		prusim_core_enable(r->s, i, true);
	}

	for (k = 0; k <= c->nkicks; k++) {
		until = k < c->nkicks && c->kicks[k].cycle < c->max_cycles ? c->kicks[k].cycle
									    : c->max_cycles;
		pk_advance(r->s, until, mode == PK_SLICED);
		if (r->s->stop_run || k == c->nkicks || c->kicks[k].cycle >= c->max_cycles)
			break;
		/* prusim_run() returned early if nothing could happen before the kick */
		if (r->s->now < c->kicks[k].cycle)
			r->s->now = c->kicks[k].cycle;
		prusim_raise_event(r->s, c->kicks[k].event);
	}

	r->cycles = r->s->now;
	r->intc_raw = r->s->intc.raw;
	r->intc_enabled = r->s->intc.enabled;
	r->intc_pending = r->s->intc.pending;
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		prusim_get_status(r->s, i, &r->st[i]);
		strscpy(r->reason[i], r->st[i].reason, sizeof(r->reason[i]));
		r->st[i].reason = r->reason[i];
		if (r->st[i].state == PRUSIM_STOPPED)
			r->exit = PK_EXIT_STOPPED;
		else if (c->until_halt && c->fw[i] && r->st[i].state != PRUSIM_HALTED && !r->exit)
			r->exit = PK_EXIT_NO_HALT;
	}
	KUNIT_EXPECT_FALSE_MSG(test, r->pin_overflow || r->irq_overflow,
			       "%s: more pin or interrupt changes than the test records", c->name);
	return r;
}

/* The value of an expectation's field in @r */
static u64 pk_field(const struct pk_run *r, const struct prusim_kunit_expect *e)
{
	const struct prusim_status *st = &r->st[e->core % PRUSIM_NUM_CORES];

	switch (e->field) {
	case PK_CYCLES:
		return r->cycles;
	case PK_PIN_CHANGES:
		return r->pin_changes;
	case PK_STATE:
		return st->state;
	case PK_PC:
		return st->pc;
	case PK_INSNS:
		return st->insns;
	case PK_STALLS:
		return st->stalls;
	case PK_CYCLE_CNT:
		return st->cycle_cnt;
	case PK_STALL_CNT:
		return st->stall_cnt;
	case PK_REG:
		return st->regs[e->reg % 32];
	case PK_INTC_RAW:
		return r->intc_raw;
	case PK_INTC_ENABLED:
		return r->intc_enabled;
	case PK_INTC_PENDING:
		return r->intc_pending;
	}
	return ~0ull;
}

/*
 * Does @r meet expectation @e?  With @mutate the expected value is changed
 * first (a number plus one, another state, a text with '#' appended), so
 * the answer must be no.
 */
static bool pk_expect_ok(const struct pk_run *r, const struct prusim_kunit_expect *e,
			 bool mutate)
{
	const char *reason = r->reason[e->core % PRUSIM_NUM_CORES];
	char text[PRUSIM_REASON_LEN + 2];

	switch (e->field) {
	case PK_REASON_IS:
	case PK_REASON_HAS:
		snprintf(text, sizeof(text), "%s%s", e->text, mutate ? "#" : "");
		return e->field == PK_REASON_IS ? !strcmp(reason, text) : !!strstr(reason, text);
	case PK_STATE:
		return pk_field(r, e) == (mutate ? (e->value + 1) % 5 : e->value);
	}
	return pk_field(r, e) == e->value + mutate;
}

/*
 * The edges of @pin as the VCD shows them: the cycles (after cycle 0) at
 * whose end the level differs from the level before.  Fills up to @max
 * entries of @cycle and @level; returns the number of edges.
 */
static u32 pk_edges(const struct pk_run *r, u16 pin, u64 *cycle, u8 *level, u32 max)
{
	bool now = false, before;
	u32 i = 0, n = 0;
	u64 t;

	while (i < r->npins) {
		t = r->pins[i].cycle;
		before = now;
		for (; i < r->npins && r->pins[i].cycle == t; i++) {
			if (r->pins[i].pin == pin)
				now = r->pins[i].level;
		}
		if (now == before || !t)
			continue;
		if (n < max) {
			cycle[n] = t;
			level[n] = now;
		}
		n++;
	}
	return n;
}

/*
 * Does @r meet the signal check @sig?  @want are the expected values
 * (&prusim_kunit_signal.values or a changed copy).  On failure @why says
 * what was found.
 */
static bool pk_signal_ok(struct kunit *test, const struct pk_run *r,
			 const struct prusim_kunit_signal *sig, const u64 *want, char *why,
			 size_t len)
{
	u32 n = pk_edges(r, sig->pin, NULL, NULL, 0), i, j, rises = 0;
	u64 *cycle = kunit_kmalloc_array(test, n + 1, sizeof(*cycle), GFP_KERNEL);
	u8 *level = kunit_kmalloc_array(test, n + 1, sizeof(*level), GFP_KERNEL);
	u64 last = 0;

	KUNIT_ASSERT_NOT_ERR_OR_NULL(test, cycle);
	KUNIT_ASSERT_NOT_ERR_OR_NULL(test, level);
	pk_edges(r, sig->pin, cycle, level, n);
	switch (sig->kind) {
	case PK_EDGES:
		for (i = 0; i < n && i < sig->count && cycle[i] == want[i]; i++)
			;
		if (n == sig->count && i == n)
			return true;
		if (i < n)
			snprintf(why, len, "%u edges, edge %u at %llu", n, i, cycle[i]);
		else
			snprintf(why, len, "%u edges, edge %u missing", n, i);
		return false;
	case PK_GAPS:
		for (i = 0; i + 1 < n && i < sig->count && cycle[i + 1] - cycle[i] == want[i]; i++)
			;
		if ((n ? n - 1 : 0) == sig->count && i == sig->count)
			return true;
		snprintf(why, len, "%u edges, gap %u is %llu", n, i,
			 i + 1 < n ? cycle[i + 1] - cycle[i] : 0);
		return false;
	case PK_PERIOD:
		for (i = 0; i < n; i++) {
			if (!level[i])
				continue;
			if (rises && cycle[i] - last != want[0]) {
				snprintf(why, len, "period %llu at cycle %llu", cycle[i] - last,
					 last);
				return false;
			}
			for (j = i + 1; j < n && level[j]; j++)
				;
			if (j < n && cycle[j] - cycle[i] != want[1]) {
				snprintf(why, len, "high for %llu cycles at %llu",
					 cycle[j] - cycle[i], cycle[i]);
				return false;
			}
			last = cycle[i];
			rises++;
		}
		if (rises >= 3)
			return true;
		snprintf(why, len, "only %u rising edges", rises);
		return false;
	}
	snprintf(why, len, "unknown check %u", sig->kind);
	return false;
}

/* Does @r show exactly the host interrupt changes @want (@n of them)? */
static bool pk_irqs_ok(const struct pk_run *r, const struct prusim_kunit_irq *want, u32 n)
{
	u32 i;

	if (r->nirqs != n)
		return false;
	for (i = 0; i < n; i++) {
		if (r->irqs[i].cycle != want[i].cycle || r->irqs[i].host != want[i].host ||
		    r->irqs[i].level != want[i].level)
			return false;
	}
	return true;
}

/* Every check of @c on @r, reported; and each must fail once changed. */
static void pk_check(struct kunit *test, const struct prusim_kunit_case *c,
		     const struct pk_run *r)
{
	struct prusim_kunit_irq *irq;
	char why[96];
	u64 *want;
	u32 i, j;

	KUNIT_EXPECT_EQ_MSG(test, r->exit, c->exit, "%s: exit status (PRU0: %s, PRU1: %s)",
			    c->name, r->reason[0], r->reason[1]);
	for (i = 0; i < c->nexpect; i++) {
		const struct prusim_kunit_expect *e = &c->expect[i];

		if (e->field == PK_REASON_IS || e->field == PK_REASON_HAS)
			KUNIT_EXPECT_TRUE_MSG(test, pk_expect_ok(r, e, false),
					      "%s: expect %s: the reason is \"%s\"", c->name,
					      e->line, r->reason[e->core % PRUSIM_NUM_CORES]);
		else
			KUNIT_EXPECT_TRUE_MSG(test, pk_expect_ok(r, e, false),
					      "%s: expect %s: got %llu (0x%llx)", c->name, e->line,
					      pk_field(r, e), pk_field(r, e));
		KUNIT_EXPECT_FALSE_MSG(test, pk_expect_ok(r, e, true),
				       "%s: expect %s: still met with the value changed",
				       c->name, e->line);
	}
	for (i = 0; i < c->nsignals; i++) {
		const struct prusim_kunit_signal *sig = &c->signals[i];

		KUNIT_EXPECT_TRUE_MSG(test, pk_signal_ok(test, r, sig, sig->values, why,
							 sizeof(why)),
				      "%s: %s: %s", c->name, sig->line, why);
		/* changed: every value one more, or one edge expected where none are */
		want = kunit_kmalloc_array(test, sig->count + 1, sizeof(*want), GFP_KERNEL);
		KUNIT_ASSERT_NOT_ERR_OR_NULL(test, want);
		for (j = 0; j < sig->count; j++)
			want[j] = sig->values[j] + 1;
		if (!sig->count) {
			struct prusim_kunit_signal one = *sig;

			one.count = 1;
			want[0] = 1;
			KUNIT_EXPECT_FALSE_MSG(test, pk_signal_ok(test, r, &one, want, why,
								  sizeof(why)),
					       "%s: %s: met with one edge expected", c->name,
					       sig->line);
		} else {
			KUNIT_EXPECT_FALSE_MSG(test, pk_signal_ok(test, r, sig, want, why,
								  sizeof(why)),
					       "%s: %s: still met with the values changed",
					       c->name, sig->line);
		}
	}
	if (c->check_host_irq) {
		const struct prusim_kunit_irq none = { 0 }, *first = r->nirqs ? r->irqs : &none;

		KUNIT_EXPECT_TRUE_MSG(test, pk_irqs_ok(r, c->host_irq, c->nhost_irq),
				      "%s: host_irq: %u changes, the first at %llu (host %u, %u)",
				      c->name, r->nirqs, first->cycle, first->host, first->level);
		irq = kunit_kmalloc_array(test, c->nhost_irq + 1, sizeof(*irq), GFP_KERNEL);
		KUNIT_ASSERT_NOT_ERR_OR_NULL(test, irq);
		for (j = 0; j < c->nhost_irq; j++) {
			irq[j] = c->host_irq[j];
			irq[j].cycle++;
		}
		irq[c->nhost_irq] = (struct prusim_kunit_irq){ 1, 2, 1 };
		KUNIT_EXPECT_FALSE_MSG(test, pk_irqs_ok(r, irq, c->nhost_irq ? c->nhost_irq : 1),
				       "%s: host_irq: still met with the list changed", c->name);
	}
}

/* Idle skipping and slicing must not change anything: @b against @a */
static void pk_compare(struct kunit *test, const struct prusim_kunit_case *c,
		       const struct pk_run *a, const struct pk_run *b, enum pk_mode mode)
{
	const char *how = pk_mode_names[mode];
	unsigned int i;

	KUNIT_EXPECT_EQ_MSG(test, b->cycles, a->cycles, "%s: %s: cycles", c->name, how);
	KUNIT_EXPECT_EQ_MSG(test, b->exit, a->exit, "%s: %s: exit status", c->name, how);
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		const struct prusim_status *x = &a->st[i], *y = &b->st[i];

		KUNIT_EXPECT_EQ_MSG(test, y->insns, x->insns, "%s: %s: PRU%u instructions",
				    c->name, how, i);
		KUNIT_EXPECT_EQ_MSG(test, y->stalls, x->stalls, "%s: %s: PRU%u stalls",
				    c->name, how, i);
		KUNIT_EXPECT_EQ_MSG(test, y->cycle_cnt, x->cycle_cnt, "%s: %s: PRU%u CYCLE",
				    c->name, how, i);
		KUNIT_EXPECT_EQ_MSG(test, y->stall_cnt, x->stall_cnt, "%s: %s: PRU%u STALL",
				    c->name, how, i);
		KUNIT_EXPECT_EQ_MSG(test, y->state, x->state, "%s: %s: PRU%u state",
				    c->name, how, i);
		KUNIT_EXPECT_EQ_MSG(test, y->pc, x->pc, "%s: %s: PRU%u pc", c->name, how, i);
		KUNIT_EXPECT_TRUE_MSG(test, !memcmp(y->regs, x->regs, sizeof(x->regs)),
				      "%s: %s: PRU%u registers", c->name, how, i);
		KUNIT_EXPECT_STREQ_MSG(test, b->reason[i], a->reason[i], "%s: %s: PRU%u reason",
				       c->name, how, i);
	}
	KUNIT_EXPECT_EQ_MSG(test, b->intc_raw, a->intc_raw, "%s: %s: INTC raw", c->name, how);
	KUNIT_EXPECT_EQ_MSG(test, b->intc_enabled, a->intc_enabled, "%s: %s: INTC enabled",
			    c->name, how);
	KUNIT_EXPECT_EQ_MSG(test, b->intc_pending, a->intc_pending, "%s: %s: INTC pending",
			    c->name, how);
	KUNIT_EXPECT_TRUE_MSG(test, pk_irqs_ok(b, a->irqs, a->nirqs),
			      "%s: %s: host interrupt changes", c->name, how);
	KUNIT_EXPECT_EQ_MSG(test, b->pin_changes, a->pin_changes, "%s: %s: pin changes",
			    c->name, how);
	KUNIT_EXPECT_TRUE_MSG(test, b->npins == a->npins &&
			      !memcmp(b->pins, a->pins, a->npins * sizeof(*a->pins)),
			      "%s: %s: the pin change lists differ", c->name, how);
}

/* One validation program: called by the functions prusim_kunit_data.h defines */
static void prusim_kunit_run_case(struct kunit *test, const struct prusim_kunit_case *c)
{
	struct pk_run *skip, *step, *sliced;
	unsigned int i;

	skip = pk_run(test, c, PK_SKIP);
	step = pk_run(test, c, PK_STEP);
	sliced = pk_run(test, c, PK_SLICED);
	if (!skip || !step || !sliced)
		return;
	pk_check(test, c, skip);
	pk_compare(test, c, skip, step, PK_STEP);
	pk_compare(test, c, skip, sliced, PK_SLICED);
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		KUNIT_EXPECT_EQ_MSG(test, step->st[i].skipped_insns, 0,
				    "%s: PRU%u: instructions skipped without skipping", c->name, i);
		KUNIT_EXPECT_LE_MSG(test, skip->st[i].skipped_insns, skip->st[i].insns,
				    "%s: PRU%u: more instructions skipped than run", c->name, i);
	}
}

#if __has_include("prusim_kunit_data.h")
#include "prusim_kunit_data.h"
#else
#error "prusim_kunit_data.h is missing: run tests/kunit/prusim/gen.sh before the kernel build"
#endif

/* The generated data covers the validation programs, each with checks. */
static void prusim_kunit_data(struct kunit *test)
{
	unsigned int i, cores, checks;

	KUNIT_EXPECT_GE(test, ARRAY_SIZE(prusim_kunit_cases), 25);
	for (i = 0; i < ARRAY_SIZE(prusim_kunit_cases); i++) {
		const struct prusim_kunit_case *c = &prusim_kunit_cases[i];

		cores = !!c->fw[0] + !!c->fw[1];
		checks = c->nexpect + c->nsignals + c->check_host_irq;
		KUNIT_EXPECT_GE_MSG(test, cores, 1, "%s: no firmware", c->name);
		KUNIT_EXPECT_GE_MSG(test, checks, 1, "%s: no checks", c->name);
	}
}

static struct kunit_case prusim_validation_cases[] = {
	KUNIT_CASE(prusim_kunit_data),
	PRUSIM_KUNIT_CASE_LIST
	{}
};

static struct kunit_suite prusim_validation_suite = {
	.name = "prusim_validation",
	.test_cases = prusim_validation_cases,
};

kunit_test_suite(prusim_validation_suite);

MODULE_DESCRIPTION("prusim validation programs run in the kernel");
MODULE_LICENSE("GPL");
