// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim - run PRU firmware on the simulated AM335x PRU-ICSS.
 *
 * See Documentation/prusim.rst for the options, the stimulus file format and
 * the JSON output.
 */

#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"
#include "pinlog.h"
#include "prusim.h"
#include "stimulus.h"
#include "trace.h"
#include "vcd.h"

#define ARRAY_SIZE(a)		(sizeof(a) / sizeof((a)[0]))
#define DDR_BASE		0x80000000u
#define DEFAULT_MAX_CYCLES	1000000000ull
#define MAX_EVENTS		64
#define MAX_HOST_IRQS		4096
#define MAX_MEM_OPS		16

#define EXIT_USAGE		1
#define EXIT_NO_HALT		2
#define EXIT_STOPPED		3

/**
 * struct kick - a system event raised from outside at a given cycle
 * @cycle: when
 * @event: system event number
 */
struct kick {
	uint64_t cycle;
	unsigned int event;
};

/**
 * struct mem_op - a --load or --dump of memory
 * @core: the core whose local map @addr is in (-1: the first one loaded)
 * @addr: local address of the core's data memories, or a DDR bus address
 *	(0x80000000.., with --ddr)
 * @len: bytes to dump (--dump; a load takes the file's size)
 * @path: file read (--load) or written (--dump)
 */
struct mem_op {
	int core;
	uint32_t addr;
	uint32_t len;
	const char *path;
};

/**
 * struct host_irq - a recorded change of a host interrupt line (2..9)
 * @cycle: when
 * @host: line
 * @level: new level
 */
struct host_irq {
	uint64_t cycle;
	unsigned int host;
	bool level;
};

/**
 * struct tool - everything the callbacks need
 * @sim: the simulator (large: heap allocated)
 * @input: stimulus of each input port (R31 of each core, GPIO DATAIN)
 * @has_input: a stimulus file was given for the port
 * @log: pin changes, when @record is set
 * @record: keep the pin changes (for --vcd, --events or --trace-out)
 * @vcd_path: VCD output file (--vcd)
 * @events_path: text event list (--events)
 * @trace_out: binary pin trace output file (--trace-out)
 * @trace_in: binary pin trace to convert (--trace-in)
 * @ddr: host memory behind OCP addresses from 0x80000000
 * @ddr_size: its size
 * @irqs: host interrupt changes
 * @nirqs: number of @irqs
 * @pin_changes: number of pin changes
 * @trace: print every instruction
 * @error: a callback failed (out of memory)
 */
struct tool {
	struct prusim *sim;
	struct prusim_stim input[PRUSIM_NUM_PORTS];
	bool has_input[PRUSIM_NUM_PORTS];
	struct pin_log log;
	bool record;
	const char *vcd_path;
	const char *events_path;
	const char *trace_out;
	const char *trace_in;
	uint8_t *ddr;
	uint64_t ddr_size;
	struct host_irq irqs[MAX_HOST_IRQS];
	unsigned int nirqs;
	uint64_t pin_changes;
	bool trace;
	bool error;
};

static void on_pin(void *ctx, u64 cycle, unsigned int pin, bool level)
{
	struct tool *t = ctx;

	t->pin_changes++;
	if (t->record && pin_log_add(&t->log, cycle, pin, level))
		t->error = true;
}

static u32 on_input(void *ctx, unsigned int port, u64 cycle, u64 *next)
{
	struct tool *t = ctx;

	if (port < PRUSIM_NUM_PORTS && t->has_input[port])
		return prusim_stim_value(&t->input[port], cycle, next);
	*next = PRUSIM_NEVER;
	return 0;
}

static void on_host_irq(void *ctx, u64 cycle, unsigned int host, bool level)
{
	struct tool *t = ctx;

	if (t->nirqs < MAX_HOST_IRQS)
		t->irqs[t->nirqs++] = (struct host_irq){ cycle, host, level };
}

static uint8_t *ddr_at(struct tool *t, u32 addr, unsigned int len)
{
	u64 off = (u64)addr - DDR_BASE;

	if (addr < DDR_BASE || off > t->ddr_size || len > t->ddr_size - off)
		return NULL;
	return t->ddr + off;
}

static int on_ocp_read(void *ctx, u32 addr, void *buf, unsigned int len)
{
	uint8_t *p = ddr_at(ctx, addr, len);

	if (!p)
		return -EFAULT;
	memcpy(buf, p, len);
	return 0;
}

static int on_ocp_write(void *ctx, u32 addr, const void *buf, unsigned int len)
{
	uint8_t *p = ddr_at(ctx, addr, len);

	if (!p)
		return -EFAULT;
	memcpy(p, buf, len);
	return 0;
}

/*
 * Host pointer to @len bytes at @addr as core @core sees its data memories
 * (own and other data RAM, shared RAM), or in DDR; NULL if they are not all
 * in one of those memories.
 */
static uint8_t *mem_at(struct tool *t, unsigned int core, uint32_t addr, uint32_t len)
{
	if (addr >= DDR_BASE)
		return ddr_at(t, addr, len);
	return prusim_da_to_va(t->sim, core, addr, len);
}

/* [pruN:]ADDR:FILE (--load) or [pruN:]ADDR:LEN:FILE (--dump) */
static int parse_mem_op(const char *arg, bool with_len, struct mem_op *op)
{
	uint64_t addr, len = 0;
	char *end;

	op->core = -1;
	if (!strncmp(arg, "pru", 3) && (arg[3] == '0' || arg[3] == '1') && arg[4] == ':') {
		op->core = arg[3] - '0';
		arg += 5;
	}
	errno = 0;
	addr = strtoull(arg, &end, 0);
	if (errno || end == arg || *end != ':' || addr > UINT32_MAX)
		return -EINVAL;
	arg = end + 1;
	if (with_len) {
		len = strtoull(arg, &end, 0);
		if (errno || end == arg || *end != ':' || !len || len > UINT32_MAX)
			return -EINVAL;
		arg = end + 1;
	}
	if (!*arg)
		return -EINVAL;
	op->addr = addr;
	op->len = len;
	op->path = arg;
	return 0;
}

/* --load: copy a file into memory before the run */
static int mem_load(struct tool *t, const struct mem_op *op, unsigned int core)
{
	size_t size = 0;
	uint8_t *img = read_file(op->path, &size), *p;

	if (!img) {
		fprintf(stderr, "prusim: %s: %s\n", op->path, strerror(errno));
		return -1;
	}
	p = size > UINT32_MAX ? NULL : mem_at(t, core, op->addr, size);
	if (!p) {
		fprintf(stderr, "prusim: --load %s: %zu bytes at 0x%08x: %s of PRU%u%s\n",
			op->path, size, op->addr, "not in one memory", core,
			op->addr >= DDR_BASE ? " (see --ddr)" : "");
		free(img);
		return -1;
	}
	memcpy(p, img, size);
	free(img);
	prusim_memory_written(t->sim);
	return 0;
}

/* --dump: write memory to a file after the run */
static int mem_dump(struct tool *t, const struct mem_op *op, unsigned int core)
{
	const uint8_t *p = mem_at(t, core, op->addr, op->len);
	FILE *f;
	int ret = 0;

	if (!p) {
		fprintf(stderr, "prusim: --dump %s: %u bytes at 0x%08x: %s of PRU%u%s\n",
			op->path, op->len, op->addr, "not in one memory", core,
			op->addr >= DDR_BASE ? " (see --ddr)" : "");
		return -1;
	}
	f = fopen(op->path, "wb");
	if (!f || fwrite(p, 1, op->len, f) != op->len)
		ret = -1;
	if (f && fclose(f))
		ret = -1;
	if (ret)
		fprintf(stderr, "prusim: %s: cannot write\n", op->path);
	return ret;
}

static void on_trace(void __always_unused *ctx, u64 cycle, unsigned int core, u32 pc, u32 insn)
{
	char text[64];

	prusim_disasm(text, sizeof(text), insn, pc * 4);
	printf("%llu pru%u %04x: %08x  %s\n", (unsigned long long)cycle, core, pc * 4, insn, text);
}

/* Print the executable sections like "pru-objdump -d" (without symbols). */
static int disasm_elf(const char *path)
{
	size_t size = 0, i;
	uint8_t *img = read_file(path, &size);
	uint32_t shoff, shentsize, shnum;
	char text[64];

	if (!img || size < 52 || memcmp(img, "\177ELF", 4) || img[4] != 1 || img[5] != 1) {
		fprintf(stderr, "prusim: %s: not a 32-bit little-endian ELF file\n", path);
		free(img);
		return EXIT_USAGE;
	}
	shoff = prusim_get_le32(img + 32);
	shentsize = prusim_get_le16(img + 46);
	shnum = prusim_get_le16(img + 48);
	for (i = 0; i < shnum; i++) {
		const uint8_t *sh = img + shoff + i * shentsize;
		uint32_t addr, off, len, w;

		if (shoff + (i + 1) * shentsize > size || shentsize < 40)
			break;
		/* SHT_PROGBITS with SHF_EXECINSTR */
		if (prusim_get_le32(sh + 4) != 1 || !(prusim_get_le32(sh + 8) & 4))
			continue;
		addr = prusim_get_le32(sh + 12);
		off = prusim_get_le32(sh + 16);
		len = prusim_get_le32(sh + 20);
		for (w = 0; w + 4 <= len && off + w + 4 <= size; w += 4) {
			uint32_t insn = prusim_get_le32(img + off + w);

			prusim_disasm(text, sizeof(text), insn, addr + w);
			printf("%8x:\t%08x \t%s\n", addr + w, insn, text);
		}
	}
	free(img);
	return 0;
}

static const char *const state_names[] = {
	[PRUSIM_DISABLED] = "disabled",
	[PRUSIM_RUNNING] = "running",
	[PRUSIM_SLEEPING] = "sleeping",
	[PRUSIM_HALTED] = "halted",
	[PRUSIM_STOPPED] = "stopped",
};

static void json_string(const char *s)
{
	putchar('"');
	for (; *s; s++) {
		if (*s == '"' || *s == '\\')
			printf("\\%c", *s);
		else if ((unsigned char)*s < 0x20)
			printf("\\u%04x", *s);
		else
			putchar(*s);
	}
	putchar('"');
}

static void print_json(struct tool *t)
{
	struct prusim *s = t->sim;
	struct prusim_status st;
	unsigned int i, r;

	printf("{\"cycles\": %llu, \"pin_changes\": %llu, \"pru\": [",
	       (unsigned long long)s->now, (unsigned long long)t->pin_changes);
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		prusim_get_status(s, i, &st);
		printf("%s{\"state\": \"%s\", \"halted\": %s, \"reason\": ", i ? ", " : "",
		       state_names[st.state], st.state == PRUSIM_HALTED ? "true" : "false");
		json_string(st.reason);
		printf(", \"pc\": %u, \"instructions\": %llu, \"stalls\": %llu", st.pc,
		       (unsigned long long)st.insns, (unsigned long long)st.stalls);
		printf(", \"cycle_counter\": %u, \"stall_counter\": %u, \"regs\": [",
		       st.cycle_cnt, st.stall_cnt);
		for (r = 0; r < 32; r++)
			printf("%s%u", r ? ", " : "", st.regs[r]);
		printf("]}");
	}
	printf("], \"intc\": {\"raw\": %llu, \"enabled\": %llu, \"pending\": %u}",
	       (unsigned long long)s->intc.raw, (unsigned long long)s->intc.enabled,
	       s->intc.pending);
	printf(", \"host_irq\": [");
	for (i = 0; i < t->nirqs; i++)
		printf("%s{\"cycle\": %llu, \"host\": %u, \"level\": %d}", i ? ", " : "",
		       (unsigned long long)t->irqs[i].cycle, t->irqs[i].host, t->irqs[i].level);
	printf("]}\n");
}

static int parse_size(const char *arg, uint64_t *v)
{
	char *end;

	errno = 0;
	*v = strtoull(arg, &end, 0);
	if (errno || end == arg)
		return -EINVAL;
	if (*end == 'K' || *end == 'k')
		*v <<= 10, end++;
	else if (*end == 'M' || *end == 'm')
		*v <<= 20, end++;
	return *end ? -EINVAL : 0;
}

static const char *const lat_names[PRUSIM_NUM_LAT] = {
	"dram", "shared", "intc", "ctrl", "cfg", "iep",
	"gpio0", "gpio", "ocmc", "ddr", "prcm", "ocp",
};

/* -C NAME=VALUE: change one timing parameter */
static int set_config(struct prusim_config *cfg, const char *arg)
{
	static const struct {
		const char *name;
		size_t offset;
	} fields[] = {
		{ "read_word_cycles", offsetof(struct prusim_config, read_word_cycles) },
		{ "write_cycles", offsetof(struct prusim_config, write_cycles) },
		{ "write_word_cycles", offsetof(struct prusim_config, write_word_cycles) },
		{ "gpio_write_latency", offsetof(struct prusim_config, gpio_write_latency) },
		{ "gpio_write_interval", offsetof(struct prusim_config, gpio_write_interval) },
		{ "r31_sync_delay", offsetof(struct prusim_config, r31_sync_delay) },
		{ "event_latency", offsetof(struct prusim_config, event_latency) },
		{ "ddr_jitter", offsetof(struct prusim_config, ddr_jitter) },
	};
	const char *eq = strchr(arg, '=');
	uint64_t v;
	size_t i, n;

	if (!eq || parse_size(eq + 1, &v) || v > UINT32_MAX)
		return -EINVAL;
	n = eq - arg;
	if (n == strlen("ocp_write_delay") && !strncmp(arg, "ocp_write_delay", n)) {
		cfg->ocp_write_delay = v;
		return 0;
	}
	if (n == strlen("jitter_seed") && !strncmp(arg, "jitter_seed", n)) {
		cfg->jitter_seed = v;
		return 0;
	}
	if (v > UINT16_MAX)
		return -EINVAL;
	for (i = 0; i < PRUSIM_NUM_LAT; i++) {
		if (strlen(lat_names[i]) == n && !strncmp(arg, lat_names[i], n)) {
			cfg->read_latency[i] = v;
			return 0;
		}
	}
	for (i = 0; i < ARRAY_SIZE(fields); i++) {
		if (strlen(fields[i].name) == n && !strncmp(arg, fields[i].name, n)) {
			*(u16 *)((char *)cfg + fields[i].offset) = v;
			return 0;
		}
	}
	return -EINVAL;
}

static int parse_kick(const char *arg, struct kick *k)
{
	unsigned long long cycle;
	unsigned int event;
	char tail;

	if (sscanf(arg, "%llu:%u%c", &cycle, &event, &tail) != 2 || event >= PRUSIM_NUM_EVENTS)
		return -EINVAL;
	k->cycle = cycle;
	k->event = event;
	return 0;
}

/* --gpio-in BANK:FILE: the input port of the bank; *arg is left at FILE */
static int parse_gpio_port(char **arg)
{
	char *p = *arg;

	if (p[0] < '0' || p[0] >= '0' + PRUSIM_GPIO_BANKS || p[1] != ':')
		return -1;
	*arg = p + 2;
	return PRUSIM_PORT_GPIO(p[0] - '0');
}

static int load_firmware(struct prusim *s, unsigned int core, const char *path)
{
	struct prusim_elf_info info;
	size_t size = 0;
	void *img = read_file(path, &size);
	int ret;

	if (!img) {
		fprintf(stderr, "prusim: %s: %s\n", path, strerror(errno));
		return -1;
	}
	ret = prusim_load_elf(s, core, img, size, &info);
	free(img);
	if (ret) {
		fprintf(stderr, "prusim: %s: %s\n", path, info.err);
		return -1;
	}
	prusim_core_enable(s, core, true);
	return 0;
}

static void print_usage(void)
{
	fprintf(stderr,
		"usage: prusim [--pru0 FW.elf] [--pru1 FW.elf] [--max-cycles N] [--until-halt]\n"
		"              [--r31-0 FILE] [--r31-1 FILE] [--gpio-in BANK:FILE]\n"
		"              [--ddr SIZE] [--event CYCLE:EVENT]... [-C NAME=VALUE]...\n"
		"              [--load [pruN:]ADDR:FILE]... [--dump [pruN:]ADDR:LEN:FILE]...\n"
		"              [--vcd FILE] [--events FILE] [--trace-out FILE]\n"
		"              [--no-skip] [--trace] [--json]\n"
		"       prusim --trace-in TRACE [--vcd FILE] [--events FILE]\n");
}

/* Write what was asked for from @t->log; 0 or EXIT_USAGE */
static int write_outputs(struct tool *t)
{
	int ret = 0;

	if (t->vcd_path && vcd_write(&t->log, t->vcd_path)) {
		fprintf(stderr, "prusim: %s: cannot write\n", t->vcd_path);
		ret = EXIT_USAGE;
	}
	if (t->events_path && events_write(&t->log, t->events_path)) {
		fprintf(stderr, "prusim: %s: cannot write\n", t->events_path);
		ret = EXIT_USAGE;
	}
	if (t->trace_out && trace_write(&t->log, t->trace_out)) {
		fprintf(stderr, "prusim: %s: cannot write\n", t->trace_out);
		ret = EXIT_USAGE;
	}
	return ret;
}

/* --trace-in: convert a binary pin trace to VCD and/or an event list */
static int convert_trace(struct tool *t)
{
	char err[256];
	int ret;

	if (trace_read(&t->log, t->trace_in, err, sizeof(err))) {
		fprintf(stderr, "prusim: %s\n", err);
		return EXIT_USAGE;
	}
	if (t->log.dropped)
		fprintf(stderr, "prusim: %s: warning: %llu older pin changes were dropped; %s\n",
			t->trace_in, (unsigned long long)t->log.dropped,
			"levels before the first record are unknown");
	ret = write_outputs(t);
	pin_log_free(&t->log);
	return ret;
}

/* Run to @end, raising the scheduled events on the way. */
static void run(struct tool *t, const struct kick *kicks, unsigned int nkicks, uint64_t end)
{
	struct prusim *s = t->sim;
	unsigned int k;

	for (k = 0; k <= nkicks; k++) {
		uint64_t until = k < nkicks && kicks[k].cycle < end ? kicks[k].cycle : end;

		if (s->now < until)
			prusim_run(s, until - s->now);
		if (s->stop_run || k == nkicks || kicks[k].cycle >= end)
			return;
		/*
		 * prusim_run() returns early when nothing is scheduled; the clock
		 * may then move to the kick without anything else happening.
		 */
		if (s->now < kicks[k].cycle)
			s->now = kicks[k].cycle;
		prusim_raise_event(s, kicks[k].event);
	}
}

static int compare_kicks(const void *a, const void *b)
{
	const struct kick *x = a, *y = b;

	return x->cycle < y->cycle ? -1 : x->cycle > y->cycle;
}

int main(int argc, char **argv)
{
	static const struct option opts[] = {
		{ "pru0", required_argument, NULL, '0' },
		{ "pru1", required_argument, NULL, '1' },
		{ "max-cycles", required_argument, NULL, 'm' },
		{ "until-halt", no_argument, NULL, 'u' },
		{ "vcd", required_argument, NULL, 'v' },
		{ "events", required_argument, NULL, 'E' },
		{ "trace-out", required_argument, NULL, 'o' },
		{ "trace-in", required_argument, NULL, 'i' },
		{ "r31-0", required_argument, NULL, 'a' },
		{ "r31-1", required_argument, NULL, 'b' },
		{ "gpio-in", required_argument, NULL, 'g' },
		{ "ddr", required_argument, NULL, 'd' },
		{ "event", required_argument, NULL, 'e' },
		{ "no-skip", no_argument, NULL, 'n' },
		{ "trace", no_argument, NULL, 't' },
		{ "json", no_argument, NULL, 'j' },
		{ "disasm", required_argument, NULL, 'D' },
		{ "load", required_argument, NULL, 'L' },
		{ "dump", required_argument, NULL, 'P' },
		{ NULL, 0, NULL, 0 },
	};
	static struct tool t;
	const struct prusim_ops ops = {
		.pin = on_pin,
		.input = on_input,
		.host_irq = on_host_irq,
		.ocp_read = on_ocp_read,
		.ocp_write = on_ocp_write,
	};
	const char *fw[PRUSIM_NUM_CORES] = { NULL, NULL };
	struct kick kicks[MAX_EVENTS];
	struct mem_op loads[MAX_MEM_OPS], dumps[MAX_MEM_OPS];
	unsigned int nloads = 0, ndumps = 0, mem_core;
	unsigned int nkicks = 0, i;
	uint64_t max_cycles = DEFAULT_MAX_CYCLES;
	bool until_halt = false, json = false, run_only = false;
	struct prusim_config cfg;
	struct prusim_ops run_ops = ops;
	char err[256];
	int opt, port, ret = 0;

	prusim_default_config(&cfg);
	while ((opt = getopt_long(argc, argv, "C:", opts, NULL)) != -1) {
		/* everything but --vcd, --events and --trace-in needs a run */
		if (opt != 'v' && opt != 'E' && opt != 'i')
			run_only = true;
		switch (opt) {
		case '0':
		case '1':
			fw[opt - '0'] = optarg;
			break;
		case 'm':
			if (parse_size(optarg, &max_cycles))
				goto bad;
			break;
		case 'u':
			until_halt = true;
			break;
		case 'v':
			t.vcd_path = optarg;
			break;
		case 'E':
			t.events_path = optarg;
			break;
		case 'o':
			t.trace_out = optarg;
			break;
		case 'i':
			t.trace_in = optarg;
			break;
		case 'a':
		case 'b':
		case 'g':
			port = opt == 'g' ? parse_gpio_port(&optarg) : PRUSIM_PORT_R31(opt - 'a');
			if (port < 0)
				goto bad;
			if (stimulus_load(&t.input[port], optarg, err, sizeof(err))) {
				fprintf(stderr, "prusim: %s\n", err);
				return EXIT_USAGE;
			}
			t.has_input[port] = true;
			break;
		case 'd':
			if (parse_size(optarg, &t.ddr_size) || !t.ddr_size ||
			    t.ddr_size > 0x40000000)
				goto bad;
			break;
		case 'e':
			if (nkicks == MAX_EVENTS || parse_kick(optarg, &kicks[nkicks++]))
				goto bad;
			break;
		case 'C':
			if (set_config(&cfg, optarg))
				goto bad;
			break;
		case 'n':
			cfg.no_skip = true;
			break;
		case 't':
			t.trace = true;
			break;
		case 'j':
			json = true;
			break;
		case 'D':
			return disasm_elf(optarg);
		case 'L':
			if (nloads == MAX_MEM_OPS || parse_mem_op(optarg, false, &loads[nloads++]))
				goto bad;
			break;
		case 'P':
			if (ndumps == MAX_MEM_OPS || parse_mem_op(optarg, true, &dumps[ndumps++]))
				goto bad;
			break;
		default:
			goto bad;
		}
	}
	if (optind != argc)
		goto bad;
	if (t.trace_in) {
		if (run_only || (!t.vcd_path && !t.events_path)) {
			fprintf(stderr, "prusim: --trace-in converts a trace: %s\n",
				"it takes --vcd and/or --events and nothing else");
			ret = EXIT_USAGE;
		} else {
			ret = convert_trace(&t);
		}
		for (i = 0; i < PRUSIM_NUM_PORTS; i++)
			stimulus_free(&t.input[i]);
		return ret;
	}
	if (!fw[0] && !fw[1])
		goto bad;
	t.record = t.vcd_path || t.events_path || t.trace_out;

	if (t.trace) {
		run_ops.trace = on_trace;
		cfg.no_skip = true;
	}
	t.sim = calloc(1, sizeof(*t.sim));
	if (t.ddr_size)
		t.ddr = calloc(1, t.ddr_size);
	if (!t.sim || (t.ddr_size && !t.ddr)) {
		fprintf(stderr, "prusim: out of memory\n");
		return EXIT_USAGE;
	}
	prusim_init(t.sim, &cfg, &run_ops, &t);
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		if (fw[i] && load_firmware(t.sim, i, fw[i]))
			return EXIT_USAGE;
	}
	/* what the host put in memory before starting the cores */
	mem_core = fw[0] ? 0 : 1;
	for (i = 0; i < nloads; i++) {
		int core = loads[i].core < 0 ? (int)mem_core : loads[i].core;

		if (mem_load(&t, &loads[i], core))
			return EXIT_USAGE;
	}
	qsort(kicks, nkicks, sizeof(kicks[0]), compare_kicks);
	run(&t, kicks, nkicks, max_cycles);

	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		struct prusim_status st;

		prusim_get_status(t.sim, i, &st);
		if (st.state == PRUSIM_STOPPED) {
			fprintf(stderr, "prusim: PRU%u stopped: %s\n", i, st.reason);
			ret = EXIT_STOPPED;
		} else if (until_halt && fw[i] && st.state != PRUSIM_HALTED && !ret) {
			fprintf(stderr, "prusim: PRU%u did not halt within %llu cycles\n",
				i, (unsigned long long)max_cycles);
			ret = EXIT_NO_HALT;
		}
	}
	if (t.error) {
		fprintf(stderr, "prusim: out of memory while tracing\n");
		ret = EXIT_USAGE;
	}
	t.log.origin = 0;
	t.log.end = t.sim->now;
	if (write_outputs(&t))
		ret = EXIT_USAGE;
	for (i = 0; i < ndumps; i++) {
		int core = dumps[i].core < 0 ? (int)mem_core : dumps[i].core;

		if (mem_dump(&t, &dumps[i], core))
			ret = EXIT_USAGE;
	}
	if (json)
		print_json(&t);
	for (i = 0; i < PRUSIM_NUM_PORTS; i++)
		stimulus_free(&t.input[i]);
	pin_log_free(&t.log);
	free(t.ddr);
	free(t.sim);
	return ret;

bad:
	print_usage();
	return EXIT_USAGE;
}
