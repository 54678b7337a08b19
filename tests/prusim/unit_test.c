// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim unit tests that need the embedding API rather than the CLI: the
 * ELF loader (accepts, rejects, resource table, .pru_irq_map), host access
 * and CTRL semantics, events raised by the embedder, the host interrupt
 * callback and how often the input callback is called.
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

/* A core polling R31 calls the input callback once per announced change. */
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
		free(s);
	}
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
	return failures ? 1 : 0;
}
