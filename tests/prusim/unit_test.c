// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim unit tests that need the embedding API rather than the CLI: the
 * ELF loader (accepts, rejects, resource table, .pru_irq_map), host access
 * and CTRL semantics, events raised by the embedder, the host interrupt
 * callback, how often the input callback is called and the shared stimulus
 * parser and lookup (sim/prusim_stim.c), posted OCP stores, the PRU-ICSS's
 * local reset.
 *
 * usage: unit_test FW.elf RSC_OFFSET RSC_SIZE
 *   FW.elf is a firmware with a .resource_table and a two-entry
 *   .pru_irq_map (17 -> channel 1 -> host 1, 18 -> channel 2 -> host 2);
 *   RSC_OFFSET/RSC_SIZE are what pru-readelf says about its resource table.
 */

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "prusim.h"
#include "prusim_stim.h"

/* Instruction words (checked against pru-objdump by the disassembler test) */
#define LDI_R1(v)	(0x240000e1u | (v) << 8)	/* ldi r1, v */
#define LDI_R2(v)	(0x240000e2u | (v) << 8)	/* ldi sp, v */
#define ADD_R1_1	0x0101e1e1u			/* add r1, r1, 1 */
#define LDI_R31(v)	(0x240000ffu | (v) << 8)	/* ldi r31, v */
#define LDI_R2_W2(v)	(0x240000c2u | (v) << 8)	/* ldi sp.w2, v */
#define HALT		0x2a000000u
#define SLP_1		0x3e800000u
#define WBS_R31_3	0xc903ff00u			/* wbs r31, 3 */
#define SBBO_R2_R3_8	0xe1082382u			/* sbbo sp.b0, ra, 8, 4 */
#define LDI_R3_2400	0x242400e3u			/* ldi ra, 0x2400 */
#define LSL_R3_4	0x0904e3e3u			/* lsl ra, ra, 4 */

static int failures;

static void check(bool ok, const char *name, const char *fmt, ...)
{
	va_list ap;

	if (ok) {
		printf("PASS: unit/%s\n", name);
		return;
	}
	failures++;
	printf("FAIL: unit/%s: ", name);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	printf("\n");
}

static struct prusim *new_sim(const struct prusim_ops *ops, void *ctx)
{
	struct prusim *s = calloc(1, sizeof(*s));

	if (!s) {
		perror("calloc");
		exit(2);
	}
	prusim_init(s, NULL, ops, ctx);
	return s;
}

static void put_words(struct prusim *s, unsigned int core, const u32 *words, size_t n)
{
	u8 buf[4];
	size_t i;

	for (i = 0; i < n; i++) {
		prusim_put_le32(buf, words[i]);
		prusim_write_iram(s, core, i * 4, buf, 4);
	}
}

static u8 *read_file(const char *path, size_t *size)
{
	FILE *f = fopen(path, "rb");
	long n = -1;
	u8 *buf;

	if (f && !fseek(f, 0, SEEK_END))
		n = ftell(f);
	if (n < 0 || fseek(f, 0, SEEK_SET)) {
		perror(path);
		exit(2);
	}
	buf = malloc(n);
	if (!buf || fread(buf, 1, n, f) != (size_t)n) {
		perror(path);
		exit(2);
	}
	fclose(f);
	*size = n;
	return buf;
}

/* Offset of the first program header with p_paddr >= @min, for mutations */
static u32 find_phdr(const u8 *img, u32 min)
{
	u32 phoff = prusim_get_le32(img + 28), i;

	for (i = 0; i < prusim_get_le16(img + 44); i++) {
		u32 ph = phoff + i * prusim_get_le16(img + 42);

		if (prusim_get_le32(img + ph) == 1 && prusim_get_le32(img + ph + 12) >= min &&
		    prusim_get_le32(img + ph + 20))
			return ph;
	}
	return 0;
}

/* File offset of the contents of section @name */
static u32 find_section(const u8 *img, const char *name)
{
	u32 shoff = prusim_get_le32(img + 32), esz = prusim_get_le16(img + 46);
	u32 str = prusim_get_le32(img + shoff + prusim_get_le16(img + 50) * esz + 16), i;

	for (i = 0; i < prusim_get_le16(img + 48); i++) {
		const u8 *sh = img + shoff + i * esz;

		if (!strcmp((const char *)img + str + prusim_get_le32(sh), name))
			return prusim_get_le32(sh + 16);
	}
	return 0;
}

/* Load a mutated copy of @img; check it is rejected with @msg and no IRAM change */
static void expect_reject(const char *name, const u8 *img, size_t size, size_t load_size,
			  void (*mutate)(u8 *img), const char *msg)
{
	struct prusim *s = new_sim(NULL, NULL);
	struct prusim_elf_info info;
	u8 *copy = malloc(size);
	int ret;

	memcpy(copy, img, size);
	if (mutate)
		mutate(copy);
	s->core[0].iram[0] = 0x12345678;
	ret = prusim_load_elf(s, 0, copy, load_size, &info);
	check(ret < 0 && strstr(info.err, msg) && s->core[0].iram[0] == 0x12345678, name,
	      "ret %d, error \"%s\", expected \"%s\"", ret, info.err, msg);
	free(copy);
	free(s);
}

static void mut_magic(u8 *img) { img[1] = 'X'; }
static void mut_class(u8 *img) { img[4] = 2; }
static void mut_endian(u8 *img) { img[5] = 2; }
static void mut_machine(u8 *img) { img[18] = 40; }
static void mut_type(u8 *img) { img[16] = 1; }

static void mut_iram_size(u8 *img)
{
	u32 ph = find_phdr(img, PRUSIM_ELF_IRAM_TAG);

	prusim_put_le32(img + ph + 12, PRUSIM_ELF_IRAM_TAG + PRUSIM_IRAM_SIZE - 4);
}

static void mut_data_addr(u8 *img)
{
	u32 ph = find_phdr(img, 0);

	prusim_put_le32(img + ph + 12, 0x5000);
}

static void mut_phoff(u8 *img) { prusim_put_le32(img + 28, 0x7ffffff0); }

static void mut_irq_type(u8 *img) { img[find_section(img, ".pru_irq_map")] = 1; }

static void mut_irq_event(u8 *img) { img[find_section(img, ".pru_irq_map") + 2] = 64; }

static void mut_irq_count(u8 *img) { img[find_section(img, ".pru_irq_map") + 1] = 200; }

static void test_elf(const char *path, u32 rsc_offset, u32 rsc_size)
{
	struct prusim *s = new_sim(NULL, NULL);
	struct prusim_elf_info info;
	size_t size;
	u8 *img = read_file(path, &size);
	int ret = prusim_load_elf(s, 1, img, size, &info);

	check(!ret && info.entry == 0 && s->core[1].pc == 0, "elf-load",
	      "ret %d (%s), entry 0x%x", ret, info.err, info.entry);
	check(info.rsc_offset == rsc_offset && info.rsc_size == rsc_size, "elf-resource-table",
	      "offset 0x%x size %u, expected 0x%x %u", info.rsc_offset, info.rsc_size,
	      rsc_offset, rsc_size);
	check(info.irq_map_events == 2 && s->intc.cmr[17] == 1 && s->intc.hmr[1] == 1 &&
	      s->intc.cmr[18] == 2 && s->intc.hmr[2] == 2 &&
	      s->intc.enabled == (3ull << 17) && s->intc.hier == 6 && s->intc.ger == 1,
	      "elf-irq-map", "events %u cmr %u/%u hmr %u/%u enabled 0x%llx hier 0x%x ger %u",
	      info.irq_map_events, s->intc.cmr[17], s->intc.cmr[18], s->intc.hmr[1],
	      s->intc.hmr[2], (unsigned long long)s->intc.enabled, s->intc.hier, s->intc.ger);
	check(s->core[1].state == PRUSIM_DISABLED && s->core[0].iram[0] == 0 &&
	      s->core[1].iram[0] == prusim_get_le32(img + find_section(img, ".text")),
	      "elf-load-target", "loaded into the wrong core or started");
	prusim_core_enable(s, 1, true);
	ret = prusim_load_elf(s, 1, img, size, &info);
	check(ret == -EBUSY, "elf-busy", "loading a running core returned %d", ret);
	free(s);

	expect_reject("elf-not-elf", img, size, size, mut_magic, "not an ELF file");
	expect_reject("elf-class", img, size, size, mut_class, "not a 32-bit ELF");
	expect_reject("elf-endian", img, size, size, mut_endian, "not a little-endian");
	expect_reject("elf-machine", img, size, size, mut_machine, "is not TI PRU");
	expect_reject("elf-type", img, size, size, mut_type, "not an executable");
	expect_reject("elf-truncated", img, size, size / 2, NULL, "truncated");
	expect_reject("elf-header-short", img, size, 40, NULL, "not an ELF file");
	expect_reject("elf-phdr-outside", img, size, size, mut_phoff, "truncated");
	expect_reject("elf-iram-overflow", img, size, size, mut_iram_size,
		      "outside the 8 KiB IRAM");
	expect_reject("elf-data-outside", img, size, size, mut_data_addr,
		      "outside DRAM and shared RAM");
	expect_reject("elf-irq-map-type", img, size, size, mut_irq_type,
		      ".pru_irq_map type 1 is not supported");
	expect_reject("elf-irq-map-event", img, size, size, mut_irq_event, "out of range");
	expect_reject("elf-irq-map-count", img, size, size, mut_irq_count, "too few for 200");
	free(img);
}

/* Program IRAM and start it through the CTRL registers, as a host would */
static void test_host_access(void)
{
	static const u32 prog[] = { LDI_R1(7), ADD_R1_1, LDI_R2(0xabc), HALT };
	struct prusim *s = new_sim(NULL, NULL);
	struct prusim_status st;
	u32 control = 0x2 | (0 << 16), gpreg1 = 0, v = 0;
	u8 *dram1, word[4];
	u64 n;

	put_words(s, 1, prog, 4);
	prusim_host_read(s, 0x38004, word, 4);
	check(prusim_get_le32(word) == ADD_R1_1, "host-iram-read", "read 0x%08x",
	      prusim_get_le32(word));
	prusim_host_write(s, 0x24000, &control, 4);		/* PRU1 CONTROL: EN */
	n = prusim_run(s, 100);
	prusim_get_status(s, 1, &st);
	prusim_host_read(s, 0x24404, &gpreg1, 4);		/* PRU1 debug GPREG1 */
	check(st.state == PRUSIM_HALTED && st.regs[1] == 8 && st.regs[2] == 0xabc &&
	      gpreg1 == 8 && n == 4 && st.pc == 3, "host-start",
	      "state %d r1 %u r2 0x%x gpreg1 %u cycles %llu pc %u", st.state, st.regs[1],
	      st.regs[2], gpreg1, (unsigned long long)n, st.pc);

	dram1 = prusim_da_to_va(s, 0, 0x2000, 16);
	v = 0xfeedbeef;
	prusim_host_write(s, 0x2004, &v, 4);
	check(dram1 == s->core[1].dram && prusim_get_le32(dram1 + 4) == 0xfeedbeef &&
	      prusim_da_to_va(s, 1, 0, 16) == s->core[1].dram &&
	      prusim_da_to_va(s, 0, 0x10000, 0x3000) == s->shared &&
	      !prusim_da_to_va(s, 0, 0x1ff0, 0x20) && !prusim_da_to_va(s, 0, 0x20000, 4),
	      "da-to-va", "pointers into the wrong memory");
	check(prusim_host_read(s, 0x28000, &v, 4) == -EINVAL &&
	      prusim_host_write(s, 0x1ffe, &v, 4) == -EINVAL, "host-unmapped",
	      "unmodelled or straddling ranges were accepted");

	/* soft reset to PCOUNTER_RST_VAL 1, then single step one instruction */
	control = 0x0 | (1 << 16);
	prusim_host_write(s, 0x24000, &control, 4);
	control = 0x1 | 0x2 | 0x100 | (1 << 16);
	prusim_host_write(s, 0x24000, &control, 4);
	prusim_run(s, 100);
	prusim_get_status(s, 1, &st);
	prusim_host_read(s, 0x24000, &control, 4);
	check(st.state == PRUSIM_DISABLED && st.pc == 2 && st.regs[1] == 9 &&
	      control == (0x1 | 0x100 | 1 << 16), "ctrl-reset-single-step",
	      "state %d pc %u r1 %u CONTROL 0x%x", st.state, st.pc, st.regs[1], control);
	free(s);
}

struct irq_log {
	unsigned int count;
	u64 cycle[8];
	unsigned int host[8];
	bool level[8];
};

static void log_irq(void *ctx, u64 cycle, unsigned int host, bool level)
{
	struct irq_log *log = ctx;

	if (log->count < 8) {
		log->cycle[log->count] = cycle;
		log->host[log->count] = host;
		log->level[log->count++] = level;
	}
}

#define ARRAY_SIZE(a)	(sizeof(a) / sizeof((a)[0]))

/* Route system event @ev to @channel and host @host through INTC registers */
static void intc_route(struct prusim *s, u8 ev, u8 channel, u8 host)
{
	u32 v;

	prusim_host_write(s, 0x20400 + ev, &channel, 1);	/* CMR byte */
	prusim_host_write(s, 0x20800 + channel, &host, 1);	/* HMR byte */
	v = ev;
	prusim_host_write(s, 0x20028, &v, 4);			/* EISR */
	v = host;
	prusim_host_write(s, 0x20034, &v, 4);			/* HIEISR */
	v = 1;
	prusim_host_write(s, 0x20010, &v, 4);			/* GER */
}

/*
 * PRU0 strobes event 20 (routed to host 5) in cycle 2; the embedder sees the
 * line rise one cycle later.  PRU1 sleeps on host 0 until the embedder
 * raises event 21 between two runs.
 */
static void test_events(void)
{
	static const u32 prog0[] = { LDI_R1(0), LDI_R1(1), LDI_R31(32 | 4), HALT };
	static const u32 prog1[] = {
		LDI_R3_2400, LSL_R3_4, LDI_R2(0), LDI_R2_W2(0x4000),	/* r2 = 1 << 30 */
		SBBO_R2_R3_8, SLP_1, LDI_R1(5), HALT			/* WAKEUP_EN */
	};
	const struct prusim_ops ops = { .host_irq = log_irq };
	struct irq_log log = { 0 };
	struct prusim *s = new_sim(&ops, &log);
	struct prusim_status st;

	put_words(s, 0, prog0, 4);
	put_words(s, 1, prog1, 8);
	intc_route(s, 20, 3, 5);
	intc_route(s, 21, 0, 0);
	prusim_core_enable(s, 0, true);
	prusim_core_enable(s, 1, true);
	prusim_run(s, 500);
	check(log.count == 1 && log.cycle[0] == 3 && log.host[0] == 5 && log.level[0] &&
	      prusim_host_pending(s, 5), "host-irq-callback",
	      "%u calls, first at %llu host %u level %d", log.count,
	      (unsigned long long)log.cycle[0], log.host[0], log.level[0]);
	prusim_get_status(s, 1, &st);
	check(st.state == PRUSIM_SLEEPING && s->now == 6, "sleep-idle",
	      "PRU1 state %d, run ended at %llu", st.state, (unsigned long long)s->now);
	s->now = 1000;
	prusim_raise_event(s, 21);
	prusim_run(s, 500);
	prusim_get_status(s, 1, &st);
	check(st.state == PRUSIM_HALTED && st.regs[1] == 5 && s->now == 1002 &&
	      st.insns == 8, "raise-event-wake", "state %d r1 %u end %llu insns %llu",
	      st.state, st.regs[1], (unsigned long long)s->now, (unsigned long long)st.insns);
	free(s);
}

struct input_log {
	unsigned int calls;
};

/* R31 of PRU0: bit 3 rises at cycle 1000000 */
static u32 steady_input(void *ctx, unsigned int port, u64 cycle, u64 *next)
{
	struct input_log *log = ctx;

	log->calls++;
	if (port != PRUSIM_PORT_R31(0) || cycle >= 1000000) {
		*next = PRUSIM_NEVER;
		return port == PRUSIM_PORT_R31(0) ? 1u << 3 : 0;
	}
	*next = 1000000;
	return 0;
}

/*
 * A core polling R31 calls the input callback once per announced change, and
 * almost all of its instructions are accounted for by idle skipping.
 */
static void test_input_calls(void)
{
	static const u32 prog[] = { WBS_R31_3, HALT };
	const struct prusim_ops ops = { .input = steady_input };
	struct input_log log = { 0 };
	struct prusim_config cfg;
	struct prusim_status st;
	struct prusim *s;
	unsigned int skip;

	for (skip = 0; skip < 2; skip++) {
		prusim_default_config(&cfg);
		cfg.no_skip = !skip;
		s = calloc(1, sizeof(*s));
		prusim_init(s, &cfg, &ops, &log);
		log.calls = 0;
		put_words(s, 0, prog, 2);
		prusim_core_enable(s, 0, true);
		prusim_run(s, 2000000);
		prusim_get_status(s, 0, &st);
		check(st.state == PRUSIM_HALTED && st.insns == 1000002 && log.calls <= 3,
		      skip ? "input-calls-skip" : "input-calls-step",
		      "state %d, %llu instructions, %u input callbacks", st.state,
		      (unsigned long long)st.insns, log.calls);
		/* executed: the waits that found the loop idle, and the rest */
		check(skip ? st.insns - st.skipped_insns <= 4 : !st.skipped_insns,
		      skip ? "skipped-insns-skip" : "skipped-insns-step",
		      "%llu of %llu instructions skipped", (unsigned long long)st.skipped_insns,
		      (unsigned long long)st.insns);
		free(s);
	}
}

/* An input source that changes without announcing it (next_change: never) */
struct silent_input {
	u32 value;
	unsigned int calls;
};

static u32 silent_input(void *ctx, unsigned int port, u64 cycle __always_unused, u64 *next)
{
	struct silent_input *in = ctx;

	*next = PRUSIM_NEVER;
	if (port != PRUSIM_PORT_R31(0))
		return 0;
	in->calls++;
	return in->value;
}

/*
 * prusim_input_changed(): PRU0 waits for R31 bit 3 with WBS (round 0) or
 * sleeps in SLP 1 with WAKEUP_EN bit 3 (round 1).  The source sets the bit
 * at cycle 1000 without announcing it: the cached value hides it, and so
 * does prusim_input_changed() for PRU1's port; after prusim_input_changed()
 * for PRU0's port the core sees it in the next cycle simulated (2000).
 * Both with and without idle skipping.
 */
static void run_to(struct prusim *s, u64 until)
{
	if (s->now < until && prusim_run(s, until - s->now) < until - s->now)
		s->now = until;		/* returned early: nothing can happen before */
}

static void input_changed_case(bool slp, bool skip)
{
	static const u32 wbs_prog[] = { WBS_R31_3, LDI_R1(5), HALT };
	static const u32 slp_prog[] = { SLP_1, LDI_R1(5), HALT };
	const struct prusim_ops ops = { .input = silent_input };
	struct silent_input in = { 0 };
	struct prusim_config cfg;
	struct prusim_status st;
	u32 wake = 1u << 3;
	unsigned int calls;
	struct prusim *s;
	char name[48];
	u64 ran;

	snprintf(name, sizeof(name), "input-changed-%s-%s", slp ? "slp" : "wbs",
		 skip ? "skip" : "step");
	prusim_default_config(&cfg);
	cfg.no_skip = !skip;
	s = calloc(1, sizeof(*s));
	prusim_init(s, &cfg, &ops, &in);
	put_words(s, 0, slp ? slp_prog : wbs_prog, 3);
	prusim_host_write(s, 0x22008, &wake, 4);		/* WAKEUP_EN */
	prusim_core_enable(s, 0, true);
	run_to(s, 1000);
	in.value = 1u << 3;
	run_to(s, 1500);
	prusim_input_changed(s, PRUSIM_PORT_R31(1));
	run_to(s, 2000);
	prusim_get_status(s, 0, &st);
	calls = in.calls;
	if (st.state != (slp ? PRUSIM_SLEEPING : PRUSIM_RUNNING) || st.pc != slp ||
	    s->now != 2000) {
		check(false, name, "before the call: state %d pc %u at %llu, %u calls", st.state,
		      st.pc, (unsigned long long)s->now, calls);
		free(s);
		return;
	}
	/* WBS passes in 2000, then ldi, halt; SLP wakes in 2000: ldi, halt */
	prusim_input_changed(s, PRUSIM_PORT_R31(0));
	ran = prusim_run(s, 1000);
	prusim_get_status(s, 0, &st);
	check(st.state == PRUSIM_HALTED && st.regs[1] == 5 && ran == (slp ? 2 : 3) &&
	      st.insns == (slp ? 3 : 2003) && in.calls == calls + 1, name,
	      "state %d r1 %u, %llu cycles, %llu instructions, %u calls after", st.state,
	      st.regs[1], (unsigned long long)ran, (unsigned long long)st.insns,
	      in.calls - calls);
	free(s);
}

static void test_input_changed(void)
{
	input_changed_case(false, false);
	input_changed_case(false, true);
	input_changed_case(true, false);
	input_changed_case(true, true);
}

/*
 * Idle skipping against stepping on random waits.  The image holds seven
 * small programs that wait in different ways; every round picks one per
 * core, random R31 stimuli (with entries that change nothing, sometimes
 * periodic), the cycle counter (sometimes near saturation), timing
 * parameters, events raised between runs (one routed to R31 bit 30) and
 * prusim_input_changed() calls.  One run steps every cycle in one
 * prusim_run() call per segment; the other skips, in random slices as a
 * kernel thread would run it.  Counts, registers, CYCLE/STALL, memories and
 * every pin change must agree.
 */
static const u32 fuzz_image[] = {
	/* 0 echo: R31 & 0xffff -> R30, 4 cycles */
	0x24ffffe1, 0x1300ffe0, 0x10e1e0e0, 0x1300e0fe, 0x21000100,
	/* 5 wbs r31, 3; set r30.0; wbc r31, 3; clr r30.0: 1-cycle waits */
	0xc903ff00, 0x1f00fefe, 0xd103ff00, 0x1d00fefe, 0x21000500,
	/* 10 poll a shared RAM word for a change: lbbo (3) + qbeq, toggle r30.1 */
	0x240001c4, 0x24000084, 0xf1002485, 0x56e6e5ff, 0x1300e5e6, 0x1502fefe, 0x21000c00,
	/* 17 store R31 to that word when it changes */
	0x240001c4, 0x24000084, 0x1300ffe0, 0x56e7e0ff, 0x1300e0e7, 0xe1002480, 0x21001300,
	/* 24 call a subroutine reading R31 until bit 2 (an inner branch) */
	0x23001dc3, 0xcf02e8ff, 0x1300e8fe, 0x240000e8, 0x21001800,
	/* 29 the subroutine: r8 = r31 & 0xc; ret */
	0x1300ffe8, 0x110ce8e8, 0x20c30000,
	/* 32 slp 1; mov r30, r31 */
	0x3e800000, 0x1300fffe, 0x21002000,
	/* 35 wait for bit 2, then count in DRAM until it falls */
	0x1300ffe0, 0x1104e0e0, 0x5700e0fe, 0xf1002489, 0x0101e9e9, 0xe1042489, 0x6f00e0fa,
};

static const u32 fuzz_entry[] = { 0, 5, 10, 17, 24, 32, 35 };

#define FUZZ_ENTRIES	24
#define FUZZ_KICKS	4

struct fuzz_round {
	unsigned int prog[2];
	bool ctr_en[2];
	u32 cycle_preset[2];
	u32 wakeup_en[2];
	struct prusim_config cfg;
	u64 cycle[2][FUZZ_ENTRIES];
	u32 value[2][FUZZ_ENTRIES];
	struct prusim_stim st[2];
	unsigned int kicks;
	u64 kick_cycle[FUZZ_KICKS];
	unsigned int kick_event[FUZZ_KICKS];
	bool kick_input[FUZZ_KICKS];
	u64 end;
};

struct fuzz_result {
	struct prusim_status st[2];
	char reason[2][PRUSIM_REASON_LEN];
	u64 now;
	u64 pins;
	u64 pin_hash;
	u8 mem_hash[3];
	unsigned int idle_seen;
};

struct fuzz_ctx {
	const struct fuzz_round *r;
	struct fuzz_result *res;
};

static u64 fuzz_rng;

static u64 fuzz_rand(void)
{
	fuzz_rng ^= fuzz_rng << 13;
	fuzz_rng ^= fuzz_rng >> 7;
	fuzz_rng ^= fuzz_rng << 17;
	return fuzz_rng;
}

static u32 fuzz_input(void *ctx, unsigned int port, u64 cycle, u64 *next)
{
	const struct fuzz_ctx *f = ctx;

	if (port >= 2) {
		*next = PRUSIM_NEVER;
		return 0;
	}
	return prusim_stim_value(&f->r->st[port], cycle, next);
}

static void fuzz_pin(void *ctx, u64 cycle, unsigned int pin, bool level)
{
	struct fuzz_result *res = ((struct fuzz_ctx *)ctx)->res;

	res->pins++;
	res->pin_hash = (res->pin_hash ^ (cycle << 9 | pin << 1 | level)) * 0x100000001b3ull;
}

static void fuzz_make(struct fuzz_round *r)
{
	unsigned int core, i, n;

	memset(r, 0, sizeof(*r));
	prusim_default_config(&r->cfg);
	if (!(fuzz_rand() % 4))
		r->cfg.r31_sync_delay = fuzz_rand() % 5;
	r->cfg.event_latency = 1 + fuzz_rand() % 3;
	for (core = 0; core < 2; core++) {
		u64 t = 0;

		r->prog[core] = fuzz_rand() % ARRAY_SIZE(fuzz_entry);
		r->ctr_en[core] = fuzz_rand() % 2;
		if (!(fuzz_rand() % 3))
			r->cycle_preset[core] = 0xffffffffu - fuzz_rand() % 200000;
		r->wakeup_en[core] = (fuzz_rand() % 2 ? 1u << 3 : 1u << 2) |
				     (fuzz_rand() % 2 ? 1u << 30 : 0);
		n = 1 + fuzz_rand() % FUZZ_ENTRIES;
		for (i = 0; i < n; i++) {
			u32 v = (fuzz_rand() & 0xd) | (fuzz_rand() % 4 ? 0 : 0x8000);

			if (i) {
				u64 span = fuzz_rand() % 2 ? 400 : 6000;

				t += 1 + (fuzz_rand() % 8 ? fuzz_rand() % span : fuzz_rand() % 3);
				if (fuzz_rand() % 5 < 2)
					v = r->value[core][i - 1];
			}
			r->cycle[core][i] = t;
			r->value[core][i] = v;
		}
		r->st[core].cycle = r->cycle[core];
		r->st[core].value = r->value[core];
		r->st[core].count = n;
		if (!(fuzz_rand() % 3))
			r->st[core].period = t + 1 + fuzz_rand() % 2000;
	}
	r->end = 20000 + fuzz_rand() % 150000;
	r->kicks = fuzz_rand() % (FUZZ_KICKS + 1);
	for (i = 0; i < r->kicks; i++) {
		/* increasing cycles, before the end */
		r->kick_cycle[i] = (i ? r->kick_cycle[i - 1] : 0) + 1 +
				   fuzz_rand() % (r->end / FUZZ_KICKS);
		r->kick_event[i] = fuzz_rand() % 2 ? 17 : 40;
		r->kick_input[i] = fuzz_rand() % 2;
	}
}

static u8 fuzz_mem_hash(const u8 *p, size_t n)
{
	u8 h = 0;

	while (n--)
		h = (h << 1 | h >> 7) ^ *p++;
	return h;
}

/* Run round @r; @slices: random prusim_run() budgets, else one per segment */
static void fuzz_run(const struct fuzz_round *r, bool skip, bool slices, struct fuzz_result *res)
{
	struct fuzz_ctx f = { .r = r, .res = res };
	const struct prusim_ops ops = { .input = fuzz_input, .pin = fuzz_pin };
	struct prusim_config cfg = r->cfg;
	struct prusim *s = calloc(1, sizeof(*s));
	unsigned int core, k;

	memset(res, 0, sizeof(*res));
	cfg.no_skip = !skip;
	prusim_init(s, &cfg, &ops, &f);
	intc_route(s, 17, 0, 0);			/* event 17 -> R31 bit 30 */
	for (core = 0; core < 2; core++) {
		u32 pc = fuzz_entry[r->prog[core]], base = 0x22000 + 0x2000 * core;
		u32 control = 0x3 | (r->ctr_en[core] ? 0x8 : 0) | pc << 16;

		put_words(s, core, fuzz_image, ARRAY_SIZE(fuzz_image));
		prusim_core_reset(s, core, pc);
		prusim_host_write(s, base + 0x08, &r->wakeup_en[core], 4);
		if (r->cycle_preset[core])
			prusim_host_write(s, base + 0x0c, &r->cycle_preset[core], 4);
		prusim_host_write(s, base, &control, 4);
	}
	for (k = 0; k <= r->kicks; k++) {
		u64 until = k < r->kicks ? r->kick_cycle[k] : r->end;

		while (s->now < until) {
			u64 ask = until - s->now, ran;

			if (slices)
				ask = prusim_min_u64(ask, 1 + fuzz_rand() %
						     (fuzz_rand() % 2 ? 50 : 20000));
			ran = prusim_run(s, ask);
			for (core = 0; core < 2; core++)
				res->idle_seen += s->core[core].state == PRUSIM_RUNNING &&
						  s->core[core].idle.epoch == s->epoch;
			if (ran < ask)
				s->now = until;		/* nothing can happen before */
		}
		if (k < r->kicks) {
			prusim_raise_event(s, r->kick_event[k]);
			if (r->kick_input[k])
				prusim_input_changed(s, PRUSIM_PORT_R31(k % 2));
		}
	}
	for (core = 0; core < 2; core++) {
		prusim_get_status(s, core, &res->st[core]);
		snprintf(res->reason[core], PRUSIM_REASON_LEN, "%s", res->st[core].reason);
		res->st[core].reason = NULL;		/* points into *s */
	}
	res->now = s->now;
	res->mem_hash[0] = fuzz_mem_hash(s->core[0].dram, PRUSIM_DRAM_SIZE);
	res->mem_hash[1] = fuzz_mem_hash(s->core[1].dram, PRUSIM_DRAM_SIZE);
	res->mem_hash[2] = fuzz_mem_hash(s->shared, PRUSIM_SHARED_SIZE);
	free(s);
}

/* "" if @a and @b agree, else what differs */
static const char *fuzz_diff(const struct fuzz_result *a, const struct fuzz_result *b)
{
	unsigned int core;

	for (core = 0; core < 2; core++) {
		const struct prusim_status *x = &a->st[core], *y = &b->st[core];

		if (x->insns != y->insns)
			return "instructions differ";
		if (x->stalls != y->stalls)
			return "stalls differ";
		if (x->cycle_cnt != y->cycle_cnt || x->stall_cnt != y->stall_cnt)
			return "CYCLE/STALL differ";
		if (x->state != y->state || x->pc != y->pc ||
		    memcmp(x->regs, y->regs, sizeof(x->regs)) ||
		    strcmp(a->reason[core], b->reason[core]))
			return "state, pc or registers differ";
	}
	if (a->now != b->now)
		return "end cycles differ";
	if (a->pins != b->pins || a->pin_hash != b->pin_hash)
		return "pin changes differ";
	if (memcmp(a->mem_hash, b->mem_hash, sizeof(a->mem_hash)))
		return "memories differ";
	return "";
}

static void test_skip_fuzz(unsigned int rounds)
{
	unsigned int round, bad = 0, skipped_rounds = 0, counted = 0;
	struct fuzz_result step, skip, sliced;
	struct fuzz_round r;
	char why[160] = "";
	const char *d;

	fuzz_rng = 0x2545f4914f6cdd1dull;
	for (round = 0; round < rounds; round++) {
		fuzz_make(&r);
		fuzz_run(&r, false, false, &step);
		fuzz_run(&r, true, false, &skip);
		fuzz_run(&r, true, true, &sliced);
		d = fuzz_diff(&step, &skip);
		if (!*d)
			d = fuzz_diff(&step, &sliced);
		if (!*d && (step.st[0].skipped_insns || step.st[1].skipped_insns ||
			    sliced.st[0].skipped_insns > sliced.st[0].insns ||
			    sliced.st[1].skipped_insns > sliced.st[1].insns))
			d = "skipped instruction counts are off";
		if (*d && !bad++)
			snprintf(why, sizeof(why), "round %u (programs %u/%u, %llu cycles): %s",
				 round, r.prog[0], r.prog[1], (unsigned long long)r.end, d);
		/* rounds in which a running core was found idle after a slice */
		skipped_rounds += sliced.idle_seen > 0;
		counted += r.ctr_en[0] || r.ctr_en[1];
	}
	check(!bad && skipped_rounds > rounds / 4 && counted > rounds / 4, "skip-fuzz",
	      "%u of %u rounds differ; first: %s (idle loops in %u rounds, %u with CTR_EN)",
	      bad, rounds, why, skipped_rounds, counted);
}

#define STIM_CAP	64

/* Both passes of prusim_stim_parse(); the passes must agree. */
static int stim_parse2(const char *text, size_t len, struct prusim_stim *st, u64 *cycles,
		       u32 *values, char *err, size_t errlen)
{
	int n = prusim_stim_parse(text, len, NULL, err, errlen), m;

	if (n < 0 || n > STIM_CAP)
		return n < 0 ? n : -E2BIG;
	st->cycle = cycles;
	st->value = values;
	st->count = n;
	st->period = 12345;
	m = prusim_stim_parse(text, len, st, err, errlen);
	if (m != n)
		return -EPROTO;
	return n;
}

/* Values and next changes at the given cycles, compared with @want */
static void stim_expect(const char *name, const struct prusim_stim *st, size_t n,
			const u64 *at, const u32 *want, const u64 *want_next)
{
	char why[256] = "";
	size_t i;
	u64 next;
	u32 v;

	for (i = 0; i < n && !why[0]; i++) {
		next = 0;
		v = prusim_stim_value(st, at[i], &next);
		if (v != want[i] || next != want_next[i])
			snprintf(why, sizeof(why), "at %llu: %u next %llu, expected %u next %llu",
				 (unsigned long long)at[i], v, (unsigned long long)next, want[i],
				 (unsigned long long)want_next[i]);
	}
	check(!why[0], name, "%s", why);
}

static void test_stim_lookup(void)
{
	static const char text[] = "# comment line\n0 0\n4\t1  # trailing comment\n\n"
		"0x10 0xFF\r\n  20 007";		/* CRLF, leading zeros, no final newline */
	static const u64 at[] = { 0, 3, 4, 15, 16, 19, 20, 1000000000000ull };
	static const u32 want[] = { 0, 0, 1, 1, 255, 255, 7, 7 };
	static const u64 next[] = { 4, 4, 16, 16, 20, 20, PRUSIM_NEVER, PRUSIM_NEVER };
	static const char clock[] = "0 0\n4 1\nrepeat 8\n# end\n";
	static const u64 cat[] = { 0, 3, 4, 7, 8, 12, 8000029, (1ull << 40) + 4 };
	static const u32 cwant[] = { 0, 0, 1, 1, 0, 1, 1, 1 };
	static const u64 cnext[] = { 4, 4, 8, 8, 12, 16, 8000032, (1ull << 40) + 8 };
	static const char slow[] = "0 1\n0x100000000 2\nrepeat 0x200000000\n";
	static const u64 sat[] = { 0x300000001ull, 0x2ffffffffull, 0xfffffffffull };
	static const u32 swant[] = { 2, 1, 2 };
	static const u64 snext[] = { 0x400000000ull, 0x300000000ull, 0x1000000000ull };
	static const char late[] = "10 5";
	static const u64 lat[] = { 0, 9, 10, 11 };
	static const u32 lwant[] = { 0, 0, 5, 5 };
	static const u64 lnext[] = { 10, 10, PRUSIM_NEVER, PRUSIM_NEVER };
	u64 cycles[STIM_CAP];
	u32 values[STIM_CAP];
	struct prusim_stim st;
	char err[96];
	int n;

	n = stim_parse2(text, strlen(text), &st, cycles, values, err, sizeof(err));
	check(n == 4 && st.count == 4 && st.period == 0 && !err[0] && cycles[2] == 16 &&
	      values[2] == 255 && cycles[3] == 20 && values[3] == 7, "stim-parse",
	      "returned %d, count %zu, period %llu, err '%s'", n, st.count,
	      (unsigned long long)st.period, err);
	if (n == 4)
		stim_expect("stim-value", &st, 8, at, want, next);

	n = stim_parse2(clock, strlen(clock), &st, cycles, values, err, sizeof(err));
	check(n == 2 && st.period == 8, "stim-parse-repeat", "returned %d, period %llu, err '%s'",
	      n, (unsigned long long)st.period, err);
	if (n == 2)
		stim_expect("stim-value-repeat", &st, 8, cat, cwant, cnext);

	n = stim_parse2(slow, strlen(slow), &st, cycles, values, err, sizeof(err));
	check(n == 2 && st.period == 0x200000000ull, "stim-parse-period-64bit",
	      "returned %d, period %llu, err '%s'", n, (unsigned long long)st.period, err);
	if (n == 2)
		stim_expect("stim-value-period-64bit", &st, 3, sat, swant, snext);

	n = stim_parse2(late, strlen(late), &st, cycles, values, err, sizeof(err));
	check(n == 1, "stim-parse-late", "returned %d, err '%s'", n, err);
	if (n == 1)
		stim_expect("stim-value-before-first", &st, 4, lat, lwant, lnext);

	n = stim_parse2(NULL, 0, &st, cycles, values, err, sizeof(err));
	check(n == 0 && st.count == 0 && st.period == 0 &&
	      prusim_stim_value(&st, 5, &cycles[0]) == 0 && cycles[0] == PRUSIM_NEVER,
	      "stim-empty", "returned %d, count %zu", n, st.count);
	n = prusim_stim_parse("# only a comment\n\n", 18, NULL, NULL, 0);
	check(n == 0, "stim-comments-only", "returned %d", n);
	n = prusim_stim_parse("18446744073709551615 1\n", 23, NULL, err, sizeof(err));
	check(n == 1, "stim-max-cycle", "returned %d, err '%s'", n, err);
}

/**
 * struct stim_bad - a malformed stimulus text and what the parser must say
 * @text: the text
 * @ret: expected return value
 * @msg: expected error text
 */
struct stim_bad {
	const char *text;
	int ret;
	const char *msg;
};

static void test_stim_errors(void)
{
	static const struct stim_bad bad[] = {
		{ "0 1\n10 2\n5 3\n", -EINVAL, "line 3: cycles must increase" },
		{ "# x\r\n\r\n0 1\r\n0 2\r\n", -EINVAL, "line 4: cycles must increase" },
		{ "0 1 2\n", -EINVAL, "line 1: expected \"CYCLE VALUE\" or \"repeat PERIOD\"" },
		{ "\n\n5\n", -EINVAL, "line 3: expected \"CYCLE VALUE\" or \"repeat PERIOD\"" },
		{ "0 0x100000000", -EINVAL, "line 1: bad value \"0x100000000\" (32 bits at most)" },
		{ "0 4294967296", -EINVAL, "line 1: bad value \"4294967296\" (32 bits at most)" },
		{ "18446744073709551616 1", -EINVAL, "line 1: bad cycle \"18446744073709551616\"" },
		{ "0x10000000000000000 1", -EINVAL, "line 1: bad cycle \"0x10000000000000000\"" },
		{ "0x 1", -EINVAL, "line 1: bad cycle \"0x\"" },
		{ "-1 5", -EINVAL, "line 1: bad cycle \"-1\"" },
		{ "1e3 5", -EINVAL, "line 1: bad cycle \"1e3\"" },
		{ "12 0x1g", -EINVAL, "line 1: bad value \"0x1g\" (32 bits at most)" },
		{ "0 1\nrepeat 0\n", -EINVAL, "line 2: bad period \"0\"" },
		{ "0 1\nrepeat x\n", -EINVAL, "line 2: bad period \"x\"" },
		{ "1 1\nrepeat 8\n", -EINVAL,
		  "line 2: a repeated pattern must start at cycle 0 and end before its period" },
		{ "0 1\n8 0\nrepeat 8\n", -EINVAL,
		  "line 3: a repeated pattern must start at cycle 0 and end before its period" },
		{ "repeat 8\n", -EINVAL,
		  "line 1: a repeated pattern must start at cycle 0 and end before its period" },
		{ "0 1\nrepeat 8\n# fine\n4 2\n", -EINVAL,
		  "line 4: nothing may follow \"repeat\"" },
		{ "0 1\nrepeat 8\nrepeat 8\n", -EINVAL, "line 3: nothing may follow \"repeat\"" },
	};
	char err[96], why[256] = "";
	u64 cycles[2];
	u32 values[2];
	struct prusim_stim st = { cycles, values, 2, 0 };
	size_t i;
	int n;

	for (i = 0; i < ARRAY_SIZE(bad) && !why[0]; i++) {
		n = prusim_stim_parse(bad[i].text, strlen(bad[i].text), NULL, err, sizeof(err));
		if (n != bad[i].ret || strcmp(err, bad[i].msg))
			snprintf(why, sizeof(why), "text %zu: returned %d '%s', expected %d '%s'",
				 i, n, err, bad[i].ret, bad[i].msg);
	}
	check(!why[0], "stim-errors", "%s", why);

	/* the fill pass finds more entries than there is room for */
	n = prusim_stim_parse("0 1\n1 2\n2 3\n", 12, &st, err, sizeof(err));
	check(n == -ENOSPC && !strcmp(err, "line 3: more entries than the 2 counted") &&
	      st.count == 2 && cycles[1] == 1, "stim-enospc", "returned %d '%s'", n, err);

	/* a short error buffer is truncated, not overrun */
	memset(err, 'x', sizeof(err));
	n = prusim_stim_parse("0 1\n0 2\n", 8, NULL, err, 6);
	check(n == -EINVAL && !strcmp(err, "line ") && err[6] == 'x', "stim-short-err",
	      "returned %d '%.8s'", n, err);
	n = prusim_stim_parse("0 1\n0 2\n", 8, NULL, NULL, 0);
	check(n == -EINVAL, "stim-no-err-buffer", "returned %d", n);
}

/* Random texts: both passes agree, accepted texts are well formed, no crash */
static void test_stim_fuzz(void)
{
	static const char alphabet[] = "0123456789xXaAfFgG \t\r\n\n\n#-repeat\v\0";
	u64 cycles[STIM_CAP];
	u32 values[STIM_CAP];
	struct prusim_stim st;
	char text[80], err[96], why[256] = "";
	unsigned int seed = 12345, round, accepted = 0, rejected = 0;
	size_t len, i, j;
	int n;

	for (round = 0; round < 200000 && !why[0]; round++) {
		seed = seed * 1103515245 + 12345;
		len = (seed >> 16) % sizeof(text);
		for (i = 0; i < len; i++) {
			seed = seed * 1103515245 + 12345;
			text[i] = alphabet[(seed >> 16) % (sizeof(alphabet) - 1)];
		}
		/* make valid lines likely too */
		if (round & 1)
			memcpy(text, "0 1\n", len < 4 ? len : 4);
		n = stim_parse2(text, len, &st, cycles, values, err, sizeof(err));
		if (n == -EPROTO) {
			snprintf(why, sizeof(why), "round %u: the passes disagree", round);
		} else if (n >= 0) {
			const char *bad = NULL;

			accepted++;
			for (j = 1; j < (size_t)n; j++) {
				if (cycles[j] <= cycles[j - 1])
					bad = "cycles not increasing";
			}
			if (st.period && (cycles[0] || cycles[n - 1] >= st.period))
				bad = "bad period accepted";
			if (err[0])
				bad = "error text on success";
			if (bad)
				snprintf(why, sizeof(why), "round %u: %s", round, bad);
		} else {
			rejected++;
			if (strncmp(err, "line ", 5))
				snprintf(why, sizeof(why), "round %u: error '%s'", round, err);
		}
	}
	check(!why[0] && accepted > 1000 && rejected > 1000, "stim-fuzz",
	      "%s (%u accepted, %u rejected)", why, accepted, rejected);
}

struct oe_log {
	unsigned int count;
	unsigned int bank;
	u32 oe;
};

static void log_oe(void *ctx, u64 cycle __always_unused, unsigned int bank, u32 oe)
{
	struct oe_log *log = ctx;

	log->count++;
	log->bank = bank;
	log->oe = oe;
}

/*
 * What the model does not do is refused, not silently ignored: settings it
 * has one value for, the IEP's compare block (a core's store to CMP0 stops
 * it); and OE changes reach the embedder, from the TRM's reset value on.
 */
static void test_unmodelled(void)
{
	static const u32 prog[] = { 0x242e04e3u /* ldi ra, 0x2e04 */, LSL_R3_4,
				    SBBO_R2_R3_8 /* to 0x2e048, CMP0 */, HALT };
	const struct prusim_ops ops = { .gpio_oe = log_oe };
	u32 ones[2] = { 0xffffffffu, 0xffffffffu }, zero = 0, one = 1, nest = 0x4;
	struct oe_log log = { 0 };
	struct prusim *s = new_sim(&ops, &log);
	struct prusim_status st;
	u32 control = 0x2;

	check(prusim_store_modelled(0x20d00, ones, 4) &&
	      prusim_store_modelled(0x20d00, ones, 8) &&
	      prusim_store_modelled(0x20d80, &zero, 4) &&
	      prusim_store_modelled(0x20004, &zero, 4) &&
	      prusim_store_modelled(0x2e008, &zero, 4) &&
	      prusim_store_modelled(0x20028, &one, 4),
	      "store-modelled", "a modelled setting was refused");
	check(!prusim_store_modelled(0x20d00, &zero, 4) &&
	      !prusim_store_modelled(0x20d82, &zero, 2) &&
	      !prusim_store_modelled(0x20d84, &one, 4) &&
	      !prusim_store_modelled(0x20004, &nest, 4) &&
	      !prusim_store_modelled(0x2e008, &one, 4),
	      "store-unmodelled",
	      "polarity low, a partial SITR, type 1, nesting or compensation taken");
	check(prusim_host_modelled(0x2e00c, 4, false) &&
	      !prusim_host_modelled(0x2e040, 4, true) &&
	      !prusim_host_modelled(0x2e044, 4, false) &&
	      !prusim_host_modelled(0x2e048, 4, false),
	      "iep-compare-unmodelled", "the IEP compare block counts as modelled");

	check(prusim_gpio_read(s, 1, PRUSIM_GPIO_OE) == 0xffffffffu && log.count == 0,
	      "gpio-oe-reset", "OE 0x%08x, %u calls", prusim_gpio_read(s, 1, PRUSIM_GPIO_OE),
	      log.count);
	prusim_gpio_write(s, 2, PRUSIM_GPIO_OE, 0xfffffffeu);
	prusim_gpio_write(s, 2, PRUSIM_GPIO_OE, 0xfffffffeu);
	check(log.count == 1 && log.bank == 2 && log.oe == 0xfffffffeu, "gpio-oe-callback",
	      "%u calls, bank %u, OE 0x%08x", log.count, log.bank, log.oe);

	put_words(s, 0, prog, ARRAY_SIZE(prog));
	prusim_host_write(s, 0x22000, &control, 4);		/* PRU0 CONTROL: EN */
	prusim_run(s, 100);
	prusim_get_status(s, 0, &st);
	check(st.state == PRUSIM_STOPPED && strstr(st.reason, "0x2e048, a register not modelled"),
	      "iep-compare-stops-core", "state %d reason \"%s\"", st.state, st.reason);
	free(s);
}

struct posted_log {
	u8 ddr[16];
	unsigned int writes;
	u64 cycle[4];
	u64 irq_cycle;
	struct prusim *s;
};

static int posted_read(void *ctx, u32 addr, void *buf, unsigned int len)
{
	struct posted_log *log = ctx;

	if (addr < 0x80000000u || addr - 0x80000000u + len > sizeof(log->ddr))
		return -EFAULT;
	memcpy(buf, log->ddr + (addr - 0x80000000u), len);
	return 0;
}

static int posted_write(void *ctx, u32 addr, const void *buf, unsigned int len)
{
	struct posted_log *log = ctx;

	if (addr < 0x80000000u || addr - 0x80000000u + len > sizeof(log->ddr))
		return -EFAULT;
	memcpy(log->ddr + (addr - 0x80000000u), buf, len);
	if (log->writes < ARRAY_SIZE(log->cycle))
		log->cycle[log->writes] = log->s->now;
	log->writes++;
	return 0;
}

static void posted_irq(void *ctx, u64 cycle, unsigned int host __always_unused, bool level)
{
	struct posted_log *log = ctx;

	if (level && !log->irq_cycle)
		log->irq_cycle = cycle;
}

/*
 * The PRU-ICSS's local reset: PRU1 runs, the INTC routes an event, the
 * RAMs and CFG hold values and a GPIO bank drives a line; after
 * prusim_icss_reset() the subsystem is as prusim_init() leaves it and the
 * GPIO bank, outside it, keeps its state.
 */
static void test_icss_reset(void)
{
	static const u32 prog[] = { SLP_1, HALT };
	struct prusim *s = new_sim(NULL, NULL);
	struct prusim_status st;
	u32 control = 0x2, v = 0xfeedbeef, cmr = 0, syscfg = 0, gpio, oe;
	unsigned int i;
	bool ram_clear = true;
	u8 b = 0;

	put_words(s, 1, prog, 2);
	prusim_host_write(s, 0x24000, &control, 4);		/* PRU1 CONTROL: EN */
	prusim_run(s, 10);
	prusim_host_write(s, 0x2004, &v, 4);			/* PRU1 data RAM */
	prusim_host_write(s, 0x10100, &v, 4);			/* shared RAM */
	v = 0;
	prusim_host_write(s, 0x26004, &v, 4);			/* SYSCFG */
	intc_route(s, 21, 3, 1);
	prusim_gpio_write(s, 1, PRUSIM_GPIO_OE, 0xefffffff);
	prusim_gpio_write(s, 1, PRUSIM_GPIO_SETDATAOUT, 1u << 28);
	prusim_raise_event(s, 21);
	prusim_run(s, 10);
	check(prusim_host_pending(s, 1), "icss-reset-before", "host 1 not pending");

	prusim_icss_reset(s);
	prusim_get_status(s, 1, &st);
	prusim_host_read(s, 0x20400 + 21, &b, 1);			/* CMR byte */
	cmr = b;
	prusim_host_read(s, 0x26004, &syscfg, 4);
	for (i = 0; i < PRUSIM_IRAM_WORDS && ram_clear; i++)
		ram_clear = !s->core[1].iram[i];
	ram_clear = ram_clear && !prusim_get_le32(s->core[1].dram + 4) &&
		    !prusim_get_le32(s->shared + 0x100);
	gpio = prusim_gpio_read(s, 1, PRUSIM_GPIO_DATAOUT);
	oe = prusim_gpio_read(s, 1, PRUSIM_GPIO_OE);
	check(st.state == PRUSIM_DISABLED && st.pc == 0 && !prusim_host_pending(s, 1) &&
	      !cmr && syscfg == 0x1a && ram_clear, "icss-reset",
	      "state %d pc %u pending %d CMR 0x%x SYSCFG 0x%x RAMs %s", st.state, st.pc,
	      prusim_host_pending(s, 1), cmr, syscfg, ram_clear ? "clear" : "kept");
	check(gpio == 1u << 28 && oe == 0xefffffff, "icss-reset-keeps-gpio",
	      "DATAOUT 0x%08x OE 0x%08x", gpio, oe);
	control = 0x2;
	put_words(s, 1, prog + 1, 1);
	prusim_host_write(s, 0x24000, &control, 4);
	prusim_run(s, 10);
	prusim_get_status(s, 1, &st);
	check(st.state == PRUSIM_HALTED, "icss-reset-runs-again", "state %d", st.state);
	free(s);
}

/*
 * A load from a GPIO bank whose clocks PRCM gated (the embedder's
 * prusim_gpio_set_gated()) stops the core with the reason; clocked again,
 * the same load reads the bank.  A reset of the PRU-ICSS keeps the gating,
 * which is PRCM's.
 */
static void test_gpio_gated(void)
{
	static const u32 prog[] = {
		0x244804e3u,	/* ldi ra, 0x4804 */
		0x0910e3e3u,	/* lsl ra, ra, 16 */
		0x24c13883u,	/* ldi ra.w0, 0xc138: GPIO1 DATAIN */
		0xf1002384u,	/* lbbo &r4, ra, 0, 4 */
		HALT,
	};
	struct prusim *s = new_sim(NULL, NULL);
	struct prusim_status st;
	u32 syscfg = 0x0a, control = 0x2;	/* STANDBY_INIT off; EN */

	prusim_gpio_set_gated(s, 1, true);
	put_words(s, 0, prog, ARRAY_SIZE(prog));
	prusim_host_write(s, 0x26004, &syscfg, 4);
	prusim_host_write(s, 0x22000, &control, 4);
	prusim_run(s, 100);
	prusim_get_status(s, 0, &st);
	check(st.state == PRUSIM_STOPPED && st.pc == 3 &&
	      strstr(st.reason, "GPIO bank 1 at 0x4804c138 while its clocks are gated"),
	      "gpio-gated-load-stops-core", "state %d pc %u reason \"%s\"", st.state, st.pc,
	      st.reason);

	prusim_icss_reset(s);
	check(s->gpio[1].gated, "gpio-gated-kept-by-icss-reset", "the bank's gating was lost");
	prusim_gpio_set_gated(s, 1, false);
	put_words(s, 0, prog, ARRAY_SIZE(prog));
	prusim_host_write(s, 0x26004, &syscfg, 4);
	prusim_host_write(s, 0x22000, &control, 4);
	prusim_run(s, 100);
	prusim_get_status(s, 0, &st);
	check(st.state == PRUSIM_HALTED && st.regs[4] == 0, "gpio-clocked-load-reads",
	      "state %d r4 0x%x reason \"%s\"", st.state, st.regs[4], st.reason);
	free(s);
}

/*
 * With ocp_write_delay 200 a store to DDR issued in cycle 3 lands in 203 and
 * the next (cycle 5) in 205; the event strobed between them reaches the ARM
 * in cycle 5, long before its data.  A load issued in cycle 6 sees the
 * second store and completes in cycle 206 (the halt's).
 */
static void test_posted(void)
{
	static const u32 prog[] = {
		0x248000e3u,	/* ldi ra, 0x8000 */
		0x0910e3e3u,	/* lsl ra, ra, 16 */
		0x241234e1u,	/* ldi r1, 0x1234 */
		0xe1002381u,	/* sbbo &r1, ra, 0, 4 */
		LDI_R31(32 | 4),	/* event 20 */
		0xe1042381u,	/* sbbo &r1, ra, 4, 4 */
		0xf1042384u,	/* lbbo &r4, ra, 4, 4 */
		HALT,
	};
	const struct prusim_ops ops = {
		.ocp_read = posted_read, .ocp_write = posted_write, .host_irq = posted_irq,
	};
	struct prusim *s = calloc(1, sizeof(*s));
	struct posted_log log;
	struct prusim_config cfg;
	struct prusim_status st;
	u32 control = 0x2, word;

	if (!s) {
		perror("calloc");
		exit(2);
	}
	memset(&log, 0, sizeof(log));
	log.s = s;
	prusim_default_config(&cfg);
	cfg.ocp_write_delay = 200;
	prusim_init(s, &cfg, &ops, &log);
	put_words(s, 0, prog, ARRAY_SIZE(prog));
	intc_route(s, 20, 3, 5);
	control = 0x0a;					/* SYSCFG: STANDBY_INIT off */
	prusim_host_write(s, 0x26004, &control, 4);
	control = 0x2;
	prusim_host_write(s, 0x22000, &control, 4);		/* PRU0 CONTROL: EN */
	prusim_run(s, 100);
	memcpy(&word, log.ddr, 4);
	check(log.irq_cycle == 5 && log.writes == 0 && word == 0, "posted-event-beats-data",
	      "interrupt at %llu, %u stores landed, DDR word 0x%x at cycle 100",
	      (unsigned long long)log.irq_cycle, log.writes, word);
	prusim_run(s, 200);
	prusim_get_status(s, 0, &st);
	memcpy(&word, log.ddr + 4, 4);
	check(log.writes == 2 && log.cycle[0] == 203 && log.cycle[1] == 205 && word == 0x1234,
	      "posted-lands-in-order", "%u stores, at %llu and %llu, second word 0x%x",
	      log.writes, (unsigned long long)log.cycle[0], (unsigned long long)log.cycle[1],
	      word);
	check(st.state == PRUSIM_HALTED && st.regs[4] == 0x1234 && st.pc == 7 &&
	      st.insns == 8 && st.stalls == 199, "posted-load-behind",
	      "state %d r4 0x%x pc %u, %llu instructions, %llu stall cycles", st.state,
	      st.regs[4], st.pc, (unsigned long long)st.insns, (unsigned long long)st.stalls);

	/* the embedder lands both at once (the ARM stops a core), in order */
	memset(&log, 0, sizeof(log));
	log.s = s;
	prusim_init(s, &cfg, &ops, &log);
	put_words(s, 0, prog, ARRAY_SIZE(prog));
	control = 0x0a;
	prusim_host_write(s, 0x26004, &control, 4);
	control = 0x2;
	prusim_host_write(s, 0x22000, &control, 4);
	prusim_run(s, 10);
	prusim_ocp_drain(s);
	check(log.writes == 2 && log.cycle[0] == 10 && log.cycle[1] == 10, "posted-drain",
	      "%u stores landed, at %llu and %llu", log.writes,
	      (unsigned long long)log.cycle[0], (unsigned long long)log.cycle[1]);
	prusim_run(s, 300);
	prusim_get_status(s, 0, &st);
	check(log.writes == 2 && st.state == PRUSIM_HALTED && st.regs[4] == 0x1234,
	      "posted-drain-once", "%u stores landed, state %d r4 0x%x", log.writes, st.state,
	      st.regs[4]);
	free(s);
}

int main(int argc, char **argv)
{
	if (argc != 4) {
		fprintf(stderr, "usage: %s FW.elf RSC_OFFSET RSC_SIZE\n", argv[0]);
		return 2;
	}
	test_elf(argv[1], strtoul(argv[2], NULL, 0), strtoul(argv[3], NULL, 0));
	test_host_access();
	test_events();
	test_input_calls();
	test_input_changed();
	test_skip_fuzz(150);
	test_stim_lookup();
	test_stim_errors();
	test_stim_fuzz();
	test_unmodelled();
	test_posted();
	test_icss_reset();
	test_gpio_gated();
	return failures ? 1 : 0;
}
