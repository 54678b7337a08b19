// SPDX-License-Identifier: GPL-2.0-only
/*
 * rpmsg_fw_test - play Linux's side of rpmsg against prukit's rpmsg firmware
 * running in the prusim core, on the host, without a kernel.
 *
 *   rpmsg_fw_test echo RPMSG_ECHO_PRU0.elf RPMSG_ECHO_PRU1.elf
 *   rpmsg_fw_test rpmsg-neopixel RPMSG_NEOPIXEL_PRU0.elf [TRACE_FILE]
 *
 * The harness does what remoteproc and virtio_rpmsg do: it reads the
 * resource table from the loaded image, writes the vring addresses into the
 * copy in the core's data RAM, lays out the two split rings and their 512-byte
 * buffers in a "DDR" buffer that the core reaches through prusim's OCP
 * callbacks (at DMA address DDR_BASE), sets DRIVER_OK, raises the ARM -> PRU
 * event after adding buffers and takes the PRU -> ARM event out of the INTC as
 * the ARM's interrupt handler would.  Malformed descriptors point into a
 * poisoned part of the DDR buffer (or outside it, or at the core's own shared
 * RAM): any access there is a failure, as is a core stopped by the simulator.
 *
 * Prints PASS:/FAIL: lines (and the measured cycle counts on their PASS
 * lines); exits 1 if anything failed, 2 on usage or file errors.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "prusim.h"
#include "prusim_trace.h"
#include <prukit/rpmsg.h>
#include "../../firmware/rpmsg-neopixel/neopixel.h"

#define DDR_BASE	0x9e000000u	/* a DMA address, as in the VM's window */
#define DDR_SIZE	0x40000u
#define VRING_DA(i)	(DDR_BASE + 0x1000u * (i))
#define RXBUF(i)	(DDR_BASE + 0x4000u + 512u * (i))	/* vring 0: PRU -> ARM */
#define TXBUF(i)	(DDR_BASE + 0x8000u + 512u * (i))	/* vring 1: ARM -> PRU */
#define POISON_START	(DDR_BASE + 0x10000u)
#define POISON_END	(DDR_BASE + 0x20000u)
#define NUM		PRUKIT_VRING_NUM
#define BUF_SIZE	RPMSG_PRU_BUF_SIZE
#define HDR		RPMSG_PRU_HDR_SIZE
#define SLICE		100		/* cycles per prusim_run() call */
#define MAX_EDGES	16384
#define MEAS_LOG	32
#define NO_ADDR		0xffffffffu

/* PRU-ICSS offsets as the ARM sees them */
#define HOST_INTC_SICR	0x20024
#define HOST_CFG_SYSCFG	0x26004
#define SYSCFG_STANDBY_INIT	0x10
#define ARRAY_SIZE(a)		(sizeof(a) / sizeof((a)[0]))

struct vq_host {
	u32 da;
	u16 avail_idx;		/* Linux's next avail->idx */
	u16 last_used;		/* used entries Linux has taken */
	u32 busy;		/* descriptors owned by the PRU */
};

struct msg {
	u32 src;
	u32 dst;
	u32 reserved;
	u16 len;
	u16 flags;
	u32 used_id;
	u32 used_len;
	u8 data[BUF_SIZE];
};

/*
 * Cycles spent in one firmware function: from the cycle its first
 * instruction issues to the cycle the instruction it returns to issues.
 */
struct meas {
	u32 entry;		/* IRAM word address */
	u32 ret_pc;
	u64 start;
	bool active;
	unsigned int n;		/* calls completed since the log was reset */
	u64 cycles[MEAS_LOG];
	u32 ret[MEAS_LOG];	/* return value (r14) */
};

struct harness {
	struct prusim *s;
	unsigned int core;
	char name[32];
	struct prusim_elf_info info;
	u8 *img;
	size_t img_size;
	u8 *ddr;
	u32 port;
	u32 evt_to_arm;
	u32 evt_from_arm;
	u32 vdev;		/* data RAM address of the vdev entry */
	u32 state;		/* data RAM address of struct prukit_rpmsg */
	u64 ocp_accesses;
	u64 poison_hits;
	u32 poison_addr;
	unsigned int kicks;	/* PRU -> ARM events taken */
	unsigned int bad_used;	/* used entries naming a buffer Linux did not give */
	bool no_refill;		/* arm_recv() keeps the buffers */
	struct vq_host vq[2];
	struct meas m_recv;
	struct meas m_send;
	/* R30 pin log */
	u64 edge_cycle[MAX_EDGES];
	u8 edge_level[MAX_EDGES];
	unsigned int edges;
	unsigned int other_pins;
};

static int failures;

static void check(bool ok, const char *name, const char *fmt, ...)
{
	va_list ap;

	if (ok) {
		printf("PASS: %s: ", name);
	} else {
		failures++;
		printf("FAIL: %s: ", name);
	}
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	printf("\n");
	fflush(stdout);
}

static void *xcalloc(size_t n, size_t size)
{
	void *p = calloc(n, size);

	if (!p) {
		perror("calloc");
		exit(2);
	}
	return p;
}

static u8 *read_file(const char *path, size_t *size)
{
	FILE *f = fopen(path, "rb");
	long n = -1;
	u8 *buf;

	if (f && !fseek(f, 0, SEEK_END))
		n = ftell(f);
	if (n <= 0 || fseek(f, 0, SEEK_SET)) {
		perror(path);
		exit(2);
	}
	buf = xcalloc(1, n);
	if (fread(buf, 1, n, f) != (size_t)n) {
		perror(path);
		exit(2);
	}
	fclose(f);
	*size = n;
	return buf;
}

static u16 get16(const u8 *p)
{
	return p[0] | p[1] << 8;
}

static u32 get32(const u8 *p)
{
	return p[0] | p[1] << 8 | p[2] << 16 | (u32)p[3] << 24;
}

static void put16(u8 *p, u16 v)
{
	p[0] = v;
	p[1] = v >> 8;
}

static void put32(u8 *p, u32 v)
{
	put16(p, v);
	put16(p + 2, v >> 16);
}

/* Value of symbol @name in an ELF32 file, or NO_ADDR */
static u32 elf_sym(const u8 *img, size_t size, const char *name)
{
	u32 shoff = get32(img + 32), shentsize = get16(img + 46), shnum = get16(img + 48);
	u32 i, j;

	for (i = 0; i < shnum; i++) {
		const u8 *sh = img + shoff + i * shentsize, *strsh;
		u32 symoff, symsize, stroff;

		if (shoff + (i + 1) * shentsize > size || get32(sh + 4) != 2)	/* SHT_SYMTAB */
			continue;
		symoff = get32(sh + 16);
		symsize = get32(sh + 20);
		strsh = img + shoff + get32(sh + 24) * shentsize;
		stroff = get32(strsh + 16);
		for (j = 0; j + 16 <= symsize && symoff + j + 16 <= size; j += 16) {
			u32 nameoff = stroff + get32(img + symoff + j);

			if (nameoff < size &&
			    !strncmp((const char *)img + nameoff, name, size - nameoff))
				return get32(img + symoff + j + 4);
		}
	}
	return NO_ADDR;
}

/* File offset and size of section @name in an ELF32 file; false if absent */
static bool elf_section(const u8 *img, size_t size, const char *name, u32 *off, u32 *len)
{
	u32 shoff = get32(img + 32), shentsize = get16(img + 46), shnum = get16(img + 48);
	u32 shstrndx = get16(img + 50), stroff, i;

	if (shoff + (u64)shnum * shentsize > size || shstrndx >= shnum)
		return false;
	stroff = get32(img + shoff + shstrndx * shentsize + 16);
	for (i = 0; i < shnum; i++) {
		const u8 *sh = img + shoff + i * shentsize;
		u32 nameoff = stroff + get32(sh);

		if (nameoff >= size || strncmp((const char *)img + nameoff, name, size - nameoff))
			continue;
		*off = get32(sh + 16);
		*len = get32(sh + 20);
		return *off + (u64)*len <= size;
	}
	return false;
}

/* ---------------------------------------------------------------------- */
/* The simulator's view of "DDR", the INTC and the pins                    */

static bool in_poison(u32 addr, u32 len)
{
	return addr < POISON_END && addr + len > POISON_START;
}

static int ocp_access(void *ctx, u32 addr, void *buf, unsigned int len, bool write)
{
	struct harness *h = ctx;

	h->ocp_accesses++;
	if (in_poison(addr, len)) {
		h->poison_hits++;
		h->poison_addr = addr;
	}
	if (addr < DDR_BASE || addr - DDR_BASE + (u64)len > DDR_SIZE)
		return -EFAULT;
	if (write)
		memcpy(h->ddr + (addr - DDR_BASE), buf, len);
	else
		memcpy(buf, h->ddr + (addr - DDR_BASE), len);
	return 0;
}

static int ocp_read(void *ctx, u32 addr, void *buf, unsigned int len)
{
	return ocp_access(ctx, addr, buf, len, false);
}

static int ocp_write(void *ctx, u32 addr, const void *buf, unsigned int len)
{
	return ocp_access(ctx, addr, (void *)buf, len, true);
}

static void pin_cb(void *ctx, u64 cycle, unsigned int pin, bool level)
{
	struct harness *h = ctx;

	if (pin != PRUSIM_PIN_R30(h->core, NEOPIXEL_BIT)) {
		h->other_pins++;
		return;
	}
	if (h->edges < MAX_EDGES) {
		h->edge_cycle[h->edges] = cycle;
		h->edge_level[h->edges] = level;
	}
	h->edges++;
}

static void meas_step(struct harness *h, struct meas *m, u64 cycle, unsigned int core, u32 pc)
{
	if (!m->active && pc == m->entry) {
		m->active = true;
		m->start = cycle;
		m->ret_pc = h->s->core[core].r[3] >> 16;
	} else if (m->active && pc == m->ret_pc) {
		m->active = false;
		if (m->n < MEAS_LOG) {
			m->cycles[m->n] = cycle - m->start;
			m->ret[m->n] = h->s->core[core].r[14];
		}
		m->n++;
	}
}

/* Cycles of the first logged call that returned @ret */
static bool meas_find(const struct meas *m, int ret, u64 *cycles)
{
	unsigned int i;

	for (i = 0; i < m->n && i < MEAS_LOG; i++) {
		if (m->ret[i] == (u32)ret) {
			*cycles = m->cycles[i];
			return true;
		}
	}
	return false;
}

static void trace_cb(void *ctx, u64 cycle, unsigned int core, u32 pc, u32 insn)
{
	struct harness *h = ctx;

	(void)insn;
	if (core != h->core)
		return;
	meas_step(h, &h->m_recv, cycle, core, pc);
	meas_step(h, &h->m_send, cycle, core, pc);
}

static const struct prusim_ops harness_ops = {
	.pin = pin_cb,
	.ocp_read = ocp_read,
	.ocp_write = ocp_write,
};

static u8 *ddr(struct harness *h, u32 addr)
{
	return h->ddr + (addr - DDR_BASE);
}

/* The core's data RAM, as remoteproc's da_to_va gives it */
static u8 *dram(struct harness *h, u32 da, size_t len)
{
	u8 *p = prusim_da_to_va(h->s, h->core, da, len);

	if (!p) {
		fprintf(stderr, "%s: no data RAM at 0x%x+%zu\n", h->name, da, len);
		exit(2);
	}
	return p;
}

/* A write by the ARM into the core's data RAM (the loaded resource table) */
static void dram_write32(struct harness *h, u32 da, u32 val)
{
	u8 buf[4];

	put32(buf, val);
	if (prusim_host_write(h->s, h->core * 0x2000 + da, buf, 4)) {
		fprintf(stderr, "%s: host write at 0x%x failed\n", h->name, da);
		exit(2);
	}
}

static void dram_write8(struct harness *h, u32 da, u8 val)
{
	if (prusim_host_write(h->s, h->core * 0x2000 + da, &val, 1))
		exit(2);
}

static u32 fw_u32(struct harness *h, size_t off)
{
	return get32(dram(h, h->state + off, 4));
}

#define STAT(h, field)	fw_u32(h, offsetof(struct prukit_rpmsg, field))

static bool core_running(struct harness *h)
{
	struct prusim_status st;

	prusim_get_status(h->s, h->core, &st);
	return st.state == PRUSIM_RUNNING;
}

static const char *core_reason(struct harness *h)
{
	struct prusim_status st;

	prusim_get_status(h->s, h->core, &st);
	return st.reason && st.reason[0] ? st.reason : "(no reason)";
}

/* The ARM's interrupt handler: take the PRU -> ARM event out of the INTC. */
static void collect_kicks(struct harness *h)
{
	u8 buf[4];

	if (!((h->s->intc.raw >> h->evt_to_arm) & 1))
		return;
	h->kicks++;
	put32(buf, h->evt_to_arm);
	prusim_host_write(h->s, HOST_INTC_SICR, buf, 4);
}

typedef bool (*cond_fn)(struct harness *h, void *arg);

/* Run in slices until @cond holds, @max cycles pass or the core stops. */
static bool run_until(struct harness *h, cond_fn cond, void *arg, u64 max)
{
	u64 start = h->s->now;

	for (;;) {
		if (cond && cond(h, arg))
			return true;
		if (h->s->now - start >= max || !core_running(h))
			return false;
		if (!prusim_run(h->s, SLICE))
			return false;
		collect_kicks(h);
	}
}

static void run_for(struct harness *h, u64 cycles)
{
	run_until(h, NULL, NULL, cycles);
}

/* ---------------------------------------------------------------------- */
/* Linux's half of the rings                                               */

static u32 vring_off(unsigned int q, u32 off)
{
	return VRING_DA(q) + off;
}

static void set_desc(struct harness *h, unsigned int q, unsigned int i, u64 addr, u32 len,
		     u16 flags)
{
	u8 *d = ddr(h, vring_off(q, PRUKIT_VRING_DESC_OFF + 16 * i));

	put32(d, (u32)addr);
	put32(d + 4, addr >> 32);
	put32(d + 8, len);
	put16(d + 12, flags);
	put16(d + 14, 0);
}

/* Put @head into the avail ring and publish it (no kick). */
static void push_avail(struct harness *h, unsigned int q, u16 head)
{
	struct vq_host *vq = &h->vq[q];

	put16(ddr(h, vring_off(q, PRUKIT_VRING_AVAIL_RING(vq->avail_idx % NUM))), head);
	vq->avail_idx++;
	put16(ddr(h, vring_off(q, PRUKIT_VRING_AVAIL_IDX)), vq->avail_idx);
	if (head < NUM)
		vq->busy |= 1u << head;
}

static void set_avail_flags(struct harness *h, unsigned int q, u16 flags)
{
	put16(ddr(h, vring_off(q, PRUKIT_VRING_AVAIL_FLAGS)), flags);
}

static u16 used_idx(struct harness *h, unsigned int q)
{
	return get16(ddr(h, vring_off(q, PRUKIT_VRING_USED_IDX)));
}

static void kick_pru(struct harness *h)
{
	prusim_raise_event(h->s, h->evt_from_arm);
}

/* Take back the transmit buffers the PRU has finished with. */
static void reclaim_tx(struct harness *h)
{
	struct vq_host *vq = &h->vq[1];

	while (vq->last_used != used_idx(h, 1)) {
		u8 *e = ddr(h, vring_off(1, PRUKIT_VRING_USED_RING(vq->last_used % NUM)));
		u32 id = get32(e);

		if (id >= NUM || !(vq->busy & (1u << id)))
			h->bad_used++;
		else
			vq->busy &= ~(1u << id);
		vq->last_used++;
	}
}

/* A free transmit buffer, or -1 */
static int free_tx(struct harness *h)
{
	unsigned int i;

	reclaim_tx(h);
	for (i = 0; i < NUM; i++)
		if (!(h->vq[1].busy & (1u << i)))
			return i;
	return -1;
}

/* Write a message into transmit buffer @i (not yet published). */
static void fill_tx(struct harness *h, unsigned int i, u32 src, u32 dst, const u8 *data,
		    u16 len, u16 hdr_len)
{
	u8 *b = ddr(h, TXBUF(i));

	put32(b, src);
	put32(b + 4, dst);
	put32(b + 8, 0);
	put16(b + 12, hdr_len);
	put16(b + 14, 0);
	memcpy(b + HDR, data, len);
	set_desc(h, 1, i, TXBUF(i), HDR + len, 0);
}

/* rpmsg_send(): one message in a free buffer, then a kick.  0 or -1. */
static int arm_send(struct harness *h, u32 src, u32 dst, const u8 *data, u16 len, bool kick)
{
	int i = free_tx(h);

	if (i < 0)
		return -1;
	fill_tx(h, i, src, dst, data, len, len);
	push_avail(h, 1, i);
	if (kick)
		kick_pru(h);
	return 0;
}

/*
 * The receive callback: take one message from vring 0 and, unless
 * h->no_refill, give the buffer back at once (no kick: the caller kicks once
 * per batch, as virtio_rpmsg does).  1 if there was one, 0 if not.
 */
static int arm_recv(struct harness *h, struct msg *m)
{
	struct vq_host *vq = &h->vq[0];
	u8 *e, *b;
	u32 id;

	if (vq->last_used == used_idx(h, 0))
		return 0;
	e = ddr(h, vring_off(0, PRUKIT_VRING_USED_RING(vq->last_used % NUM)));
	id = get32(e);
	vq->last_used++;
	memset(m, 0, sizeof(*m));
	m->used_id = id;
	m->used_len = get32(e + 4);
	if (id >= NUM || !(vq->busy & (1u << id))) {
		h->bad_used++;
		m->len = 0xffff;
		return 1;
	}
	vq->busy &= ~(1u << id);
	b = ddr(h, RXBUF(id));
	m->src = get32(b);
	m->dst = get32(b + 4);
	m->reserved = get32(b + 8);
	m->len = get16(b + 12);
	m->flags = get16(b + 14);
	memcpy(m->data, b + HDR, m->len <= BUF_SIZE - HDR ? m->len : BUF_SIZE - HDR);
	if (!h->no_refill) {
		set_desc(h, 0, id, RXBUF(id), BUF_SIZE, PRUKIT_VRING_DESC_F_WRITE);
		push_avail(h, 0, id);
	}
	return 1;
}

static bool cond_used(struct harness *h, void *arg)
{
	const unsigned int *want = arg;

	return used_idx(h, want[0]) == (u16)want[1];
}

/* ---------------------------------------------------------------------- */
/* Boot                                                                    */

static struct harness *harness_new(const char *fw, const char *what, unsigned int core)
{
	struct harness *h = xcalloc(1, sizeof(*h));
	struct prusim_config cfg;
	int ret;

	h->s = xcalloc(1, sizeof(*h->s));
	h->ddr = xcalloc(1, DDR_SIZE);
	h->core = core;
	snprintf(h->name, sizeof(h->name), "%s-pru%u", what, core);
	h->port = core ? RPMSG_PRU1_PORT : RPMSG_PRU0_PORT;
	h->evt_to_arm = core ? RPMSG_PRU1_EVT_TO_ARM : RPMSG_PRU0_EVT_TO_ARM;
	h->evt_from_arm = core ? RPMSG_PRU1_EVT_FROM_ARM : RPMSG_PRU0_EVT_FROM_ARM;
	h->img = read_file(fw, &h->img_size);

	prusim_default_config(&cfg);
	/* RPMSG_FW_NO_SKIP=1: step every cycle (the results must not change) */
	cfg.no_skip = getenv("RPMSG_FW_NO_SKIP") && !strcmp(getenv("RPMSG_FW_NO_SKIP"), "1");
	prusim_init(h->s, &cfg, &harness_ops, h);
	ret = prusim_load_elf(h->s, core, h->img, h->img_size, &h->info);
	if (ret) {
		fprintf(stderr, "%s: %s: %s\n", h->name, fw, h->info.err);
		exit(2);
	}
	h->state = elf_sym(h->img, h->img_size, "rpmsg");
	h->m_recv.entry = (elf_sym(h->img, h->img_size, "prukit_rpmsg_recv") & 0xfffff) / 4;
	h->m_send.entry = (elf_sym(h->img, h->img_size, "prukit_rpmsg_send") & 0xfffff) / 4;
	if (h->state == NO_ADDR) {
		fprintf(stderr, "%s: %s has no symbol 'rpmsg'\n", h->name, fw);
		exit(2);
	}
	return h;
}

static void harness_free(struct harness *h)
{
	free(h->img);
	free(h->ddr);
	free(h->s);
	free(h);
}

/* The resource table as remoteproc parses it; sets h->vdev.  */
static void check_rsc(struct harness *h)
{
	char name[64];
	const u8 *t, *v;
	bool ok;

	snprintf(name, sizeof(name), "%s: resource table", h->name);
	if (h->info.rsc_size != sizeof(struct prukit_rpmsg_rsc_table)) {
		check(false, name, "%u bytes, want %zu", h->info.rsc_size,
		      sizeof(struct prukit_rpmsg_rsc_table));
		h->vdev = h->info.rsc_addr + 20;
		return;
	}
	t = dram(h, h->info.rsc_addr, h->info.rsc_size);
	h->vdev = h->info.rsc_addr + get32(t + 16);
	v = t + get32(t + 16);
	ok = get32(t) == 1 && get32(t + 4) == 1 && !get32(t + 8) && !get32(t + 12) &&
	     get32(t + 16) == 20 &&
	     get32(v) == 3 && get32(v + 4) == 7 && get32(v + 12) == 1 && !get32(v + 16) &&
	     !get32(v + 20) && v[24] == 0 && v[25] == 2 && !v[26] && !v[27];
	for (int i = 0; i < 2; i++) {
		const u8 *r = v + 28 + 20 * i;

		ok = ok && get32(r) == PRUKIT_RSC_ADDR_ANY && get32(r + 4) == 16 &&
		     get32(r + 8) == 16 && !get32(r + 16);
	}
	/* the copy remoteproc parses is the one in the file */
	ok = ok && !memcmp(t, h->img + h->info.rsc_offset, h->info.rsc_size);
	check(ok, name,
	      "ver 1, 1 entry at 20: vdev id 7, dfeatures 1 (NS), config_len 0, 2 vrings {da 0x%08x, align 16, num 16}, status 0",
	      PRUKIT_RSC_ADDR_ANY);
}

static void check_irq_map(struct harness *h)
{
	const struct prusim_intc *in = &h->s->intc;
	u32 ch_to = h->core ? 3 : 2, ch_from = h->core ? 1 : 0;
	u32 off = 0, len = 0;
	char name[96];
	const u8 *m;
	bool ok;

	snprintf(name, sizeof(name), "%s: .pru_irq_map", h->name);
	/* the ARM -> PRU event first: TI's 5.10 kernels kick the first one */
	if (!elf_section(h->img, h->img_size, ".pru_irq_map", &off, &len) || len != 8) {
		check(false, name, "no 8-byte .pru_irq_map section");
		return;
	}
	m = h->img + off;
	ok = h->info.irq_map_events == 2 && m[0] == 0 && m[1] == 2 &&
	     m[2] == h->evt_from_arm && m[3] == ch_from && m[4] == ch_from &&
	     m[5] == h->evt_to_arm && m[6] == ch_to && m[7] == ch_to;
	/* and what the loader made of it */
	ok = ok && in->cmr[h->evt_to_arm] == ch_to && in->hmr[ch_to] == ch_to &&
	     in->cmr[h->evt_from_arm] == ch_from && in->hmr[ch_from] == ch_from &&
	     ((in->enabled >> h->evt_to_arm) & 1) && ((in->enabled >> h->evt_from_arm) & 1) &&
	     (in->hier & (1u << ch_to)) && (in->hier & (1u << ch_from)) && in->ger;
	check(ok, name,
	      "%u events, in this order: %u -> channel %u -> host %u, %u -> channel %u -> host %u",
	      h->info.irq_map_events, h->evt_from_arm, ch_from, ch_from, h->evt_to_arm, ch_to,
	      ch_to);
}

/* What remoteproc does before starting the core: vrings allocated, da written. */
static void arm_setup_vrings(struct harness *h, u32 da0, u32 da1)
{
	unsigned int i;

	memset(h->vq, 0, sizeof(h->vq));
	h->vq[0].da = da0;
	h->vq[1].da = da1;
	dram_write32(h, h->vdev + 28, da0);
	dram_write32(h, h->vdev + 28 + 20, da1);
	dram_write32(h, h->vdev + 28 + 12, 0);
	dram_write32(h, h->vdev + 28 + 20 + 12, 1);
	/* virtio_rpmsg: every receive buffer available, transmit ones idle */
	for (i = 0; i < NUM; i++) {
		set_desc(h, 0, i, RXBUF(i), BUF_SIZE, PRUKIT_VRING_DESC_F_WRITE);
		push_avail(h, 0, i);
	}
	set_avail_flags(h, 1, PRUKIT_VRING_AVAIL_F_NO_INTERRUPT);
}

static void arm_driver_ok(struct harness *h)
{
	dram_write8(h, h->vdev + 24, PRUKIT_VIRTIO_S_ACKNOWLEDGE | PRUKIT_VIRTIO_S_DRIVER |
		    PRUKIT_VIRTIO_S_DRIVER_OK);
	kick_pru(h);
}

/* Boot to the name service announcement; true if it came as it should. */
static bool boot(struct harness *h)
{
	unsigned int want[2] = { 0, 1 };
	struct prukit_rpmsg_ns_msg ns;
	char name[64];
	struct msg m;
	u8 cfg[4];
	bool ok;

	check_rsc(h);
	check_irq_map(h);
	arm_setup_vrings(h, VRING_DA(0), VRING_DA(1));
	prusim_core_enable(h->s, h->core, true);

	/* Before DRIVER_OK the firmware must wait without touching DDR. */
	run_for(h, 200000);
	prusim_host_read(h->s, HOST_CFG_SYSCFG, cfg, 4);
	snprintf(name, sizeof(name), "%s: waits for DRIVER_OK", h->name);
	check(core_running(h) && !h->ocp_accesses && used_idx(h, 0) == 0 &&
	      !(get32(cfg) & SYSCFG_STANDBY_INIT),
	      name, "200000 cycles: running, %llu OCP accesses, SYSCFG 0x%x (STANDBY_INIT clear)",
	      (unsigned long long)h->ocp_accesses, get32(cfg));

	arm_driver_ok(h);
	h->kicks = 0;
	ok = run_until(h, cond_used, want, 100000);
	run_for(h, 1000);
	snprintf(name, sizeof(name), "%s: name service announcement", h->name);
	if (!ok || !arm_recv(h, &m)) {
		check(false, name, "nothing in vring 0 (%s)", core_reason(h));
		return false;
	}
	memset(&ns, 0, sizeof(ns));
	memcpy(&ns, m.data, sizeof(ns));
	ok = m.src == h->port && m.dst == PRUKIT_RPMSG_NS_ADDR && m.len == 40 && !m.flags &&
	     !m.reserved && m.used_len == HDR + 40 &&
	     !memcmp(ns.name, "rpmsg-pru\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0", 32) &&
	     get32((u8 *)&ns.addr) == h->port && get32((u8 *)&ns.flags) == 0 && h->kicks == 1 &&
	     STAT(h, stats.status) == (PRUKIT_RPMSG_ST_READY | PRUKIT_RPMSG_ST_ANNOUNCED) &&
	     STAT(h, stats.tx_msgs) == 1;
	check(ok, name,
	      "src %u dst %u len %u flags %u used.len %u name \"%.32s\" addr %u flags %u, %u kick(s), status 0x%x",
	      m.src, m.dst, m.len, m.flags, m.used_len,
	      ns.name, get32((u8 *)&ns.addr), get32((u8 *)&ns.flags), h->kicks,
	      STAT(h, stats.status));
	return ok;
}

/* ---------------------------------------------------------------------- */
/* Echo                                                                    */

static u32 rnd_state = 12345;

static u8 rnd8(void)
{
	rnd_state = rnd_state * 1103515245u + 12345u;
	return rnd_state >> 16;
}

struct sent {
	u32 src;
	u16 len;
	u8 data[RPMSG_PRU_MAX_PAYLOAD];
};

static bool same_echo(struct harness *h, const struct msg *m, const struct sent *s, char *why,
		      size_t whylen)
{
	if (m->src != h->port || m->dst != s->src || m->len != s->len || m->flags ||
	    m->reserved || m->used_len != (u32)HDR + s->len) {
		snprintf(why, whylen,
			 "header src %u dst %u len %u flags %u used.len %u, want %u/%u/%u/0/%u",
			 m->src, m->dst, m->len, m->flags, m->used_len, h->port,
			 s->src, s->len, HDR + s->len);
		return false;
	}
	if (memcmp(m->data, s->data, s->len)) {
		snprintf(why, whylen, "payload of %u bytes differs", s->len);
		return false;
	}
	return true;
}

static void make_msg(struct sent *s, u32 src, u16 len)
{
	unsigned int i;

	s->src = src;
	s->len = len;
	for (i = 0; i < len; i++)
		s->data[i] = rnd8();
}

static bool cond_rx_count(struct harness *h, void *arg)
{
	const unsigned int *want = arg;

	return (u16)(used_idx(h, 0) - h->vq[0].last_used) >= *want;
}

/*
 * Send @n messages (at most NUM) in one go, wait for their echoes, check
 * them.  Returns true if all came back unchanged and in order.
 */
static bool echo_batch(struct harness *h, struct sent *s, unsigned int n, char *why,
		       size_t whylen)
{
	unsigned int i, want = n;
	struct msg m;

	for (i = 0; i < n; i++) {
		if (arm_send(h, s[i].src, h->port, s[i].data, s[i].len, true)) {
			snprintf(why, whylen, "no free transmit buffer for message %u", i);
			return false;
		}
	}
	if (!run_until(h, cond_rx_count, &want, 200000ull * n)) {
		snprintf(why, whylen, "%u of %u echoes after %llu cycles (%s)",
			 (u16)(used_idx(h, 0) - h->vq[0].last_used), n, 200000ull * n,
			 core_running(h) ? "running" : core_reason(h));
		return false;
	}
	for (i = 0; i < n; i++) {
		if (!arm_recv(h, &m) || !same_echo(h, &m, &s[i], why, whylen))
			return false;
	}
	kick_pru(h);
	/* let the firmware finish (counters) and go back to waiting */
	run_for(h, 5000);
	return true;
}

static void test_echo_lengths(struct harness *h)
{
	static struct sent s[8];
	u32 first_src = 1024 + 7 + 1 % 5;
	unsigned int len = 1, n, i;
	char name[64], why[160] = "";
	bool ok = true;

	while (ok && len <= RPMSG_PRU_MAX_PAYLOAD) {
		n = 0;
		for (i = 0; i < 8 && len <= RPMSG_PRU_MAX_PAYLOAD; i++, len++)
			make_msg(&s[n++], 1024 + 7 + len % 5, len);
		ok = echo_batch(h, s, n, why, sizeof(why));
	}
	snprintf(name, sizeof(name), "%s: echo 1..496 bytes", h->name);
	if (!ok) {
		check(false, name, "%s", why);
		return;
	}
	check(STAT(h, peer) == first_src && STAT(h, stats.rx_msgs) == 496 &&
	      STAT(h, stats.tx_msgs) == 497, name,
	      "496 messages of 1..496 bytes came back unchanged, in order, to their senders; "
	      "peer %u (want %u), rx %u, tx %u", STAT(h, peer), first_src,
	      STAT(h, stats.rx_msgs), STAT(h, stats.tx_msgs));
}

/*
 * More messages than both rings hold, Linux reading its side late: the
 * firmware fills all 16 receive buffers, takes one more message and waits
 * with it until Linux gives buffers back.
 */
static void test_echo_burst(struct harness *h)
{
	enum { TOTAL = 64 };
	static struct sent s[TOTAL];
	unsigned int sent = 0, got = 0, stalls = 0, i, round;
	u32 rx0 = STAT(h, stats.rx_msgs);
	char name[64], why[160] = "";
	bool ok = true;
	struct msg m;

	for (i = 0; i < TOTAL; i++)
		make_msg(&s[i], 2000 + i, 1 + (i * 37) % RPMSG_PRU_MAX_PAYLOAD);
	while (ok && got < TOTAL) {
		/* keep the transmit ring full, one kick per message as Linux */
		for (round = 0; round < 2; round++) {
			while (sent < TOTAL && !arm_send(h, s[sent].src, h->port, s[sent].data,
							 s[sent].len, true))
				sent++;
			run_for(h, 100000);
		}
		if ((u16)(used_idx(h, 0) - h->vq[0].last_used) == NUM &&
		    STAT(h, stats.rx_msgs) - rx0 == got + NUM + 1)
			stalls++;
		while (ok && arm_recv(h, &m)) {
			ok = got < TOTAL && same_echo(h, &m, &s[got], why, sizeof(why));
			got++;
		}
		kick_pru(h);
		if (!core_running(h)) {
			snprintf(why, sizeof(why), "core stopped: %s", core_reason(h));
			ok = false;
		}
	}
	snprintf(name, sizeof(name), "%s: burst of %u messages", h->name, TOTAL);
	if (!ok)
		check(false, name, "message %u: %s", got - 1, why);
	else
		check(stalls >= 2 && STAT(h, stats.rx_msgs) - rx0 == TOTAL && !h->bad_used, name,
		      "all came back in order; %u times the PRU had filled all 16 receive buffers and held one more message until Linux read",
		      stalls);
}

/* Kicks to the ARM follow avail->flags of each ring. */
static void test_kicks(struct harness *h)
{
	static const struct {
		u16 flags0, flags1;
		unsigned int want;
		const char *what;
	} c[] = {
		{ 0, PRUKIT_VRING_AVAIL_F_NO_INTERRUPT, 5, "vring 0 interrupts on: 1 per reply" },
		{ PRUKIT_VRING_AVAIL_F_NO_INTERRUPT, PRUKIT_VRING_AVAIL_F_NO_INTERRUPT, 0,
		  "both off: none" },
		{ PRUKIT_VRING_AVAIL_F_NO_INTERRUPT, 0, 5, "vring 1 on: 1 per buffer taken" },
		{ 0, 0, 10, "both on: 2 per echo" },
	};
	static struct sent s;
	char name[64], why[160];
	unsigned int i, j;
	bool ok;

	for (i = 0; i < ARRAY_SIZE(c); i++) {
		unsigned int kicks = 0;

		set_avail_flags(h, 0, c[i].flags0);
		set_avail_flags(h, 1, c[i].flags1);
		ok = true;
		for (j = 0; j < 5 && ok; j++) {
			make_msg(&s, 3000 + j, 10 + j);
			h->kicks = 0;
			ok = echo_batch(h, &s, 1, why, sizeof(why));
			run_for(h, 2000);
			kicks += h->kicks;
		}
		snprintf(name, sizeof(name), "%s: kicks, %s", h->name, c[i].what);
		check(ok && kicks == c[i].want, name, "%u kicks for 5 echoes, want %u%s%s", kicks,
		      c[i].want, ok ? "" : ": ", ok ? "" : why);
	}
	set_avail_flags(h, 0, 0);
	set_avail_flags(h, 1, PRUKIT_VRING_AVAIL_F_NO_INTERRUPT);
}

/*
 * Cycles per message in prukit_rpmsg_recv() and prukit_rpmsg_send(), the
 * cost of a recv() that finds nothing, and the time from the ARM's kick to
 * the PRU's kick for the reply.  Each is measured three times and must be
 * the same every time (nothing in the path depends on anything else).
 */
static void test_cycles(struct harness *h)
{
	static const u16 lens[] = { 1, 16, 64, 128, 256, 496 };
	enum { N = ARRAY_SIZE(lens), REPS = 4 };
	static struct sent s;
	u64 rc[N], sc[N], lat_min[N], lat_max[N], empty = 0, empty0 = 0, r, t, e;
	unsigned int i, rep, n = 0;
	char name[64], why[160] = "", buf[700];
	bool ok = true, stable = true;
	struct msg m;

	h->s->ops.trace = trace_cb;
	for (i = 0; i < N && ok; i++) {
		for (rep = 0; rep < REPS && ok; rep++) {
			u64 c0;

			make_msg(&s, 4000, lens[i]);
			h->m_recv.n = 0;
			h->m_send.n = 0;
			/* a different phase of the firmware's wait loop each time */
			run_for(h, 1 + rep);
			arm_send(h, s.src, h->port, s.data, s.len, true);
			c0 = h->s->now;
			while (!((h->s->intc.raw >> h->evt_to_arm) & 1) && core_running(h) &&
			       h->s->now - c0 < 100000)
				prusim_run(h->s, 1);
			t = h->s->now - c0;
			collect_kicks(h);
			run_for(h, 3000);
			if (!arm_recv(h, &m) || !same_echo(h, &m, &s, why, sizeof(why))) {
				ok = false;
				break;
			}
			kick_pru(h);
			run_for(h, 3000);
			if (!meas_find(&h->m_recv, 0, &r) || !meas_find(&h->m_send, 0, &e) ||
			    !meas_find(&h->m_recv, -EAGAIN, &empty)) {
				snprintf(why, sizeof(why), "%u recv and %u send calls seen",
					 h->m_recv.n, h->m_send.n);
				ok = false;
				break;
			}
			if (rep) {
				stable &= rc[i] == r && sc[i] == e && empty == empty0;
				lat_min[i] = t < lat_min[i] ? t : lat_min[i];
				lat_max[i] = t > lat_max[i] ? t : lat_max[i];
			} else {
				lat_min[i] = t;
				lat_max[i] = t;
			}
			rc[i] = r;
			sc[i] = e;
			empty0 = empty;
		}
	}
	h->s->ops.trace = NULL;
	snprintf(name, sizeof(name), "%s: cycles per message", h->name);
	if (!ok) {
		check(false, name, "%s", why);
		return;
	}
	for (i = 0; i < N; i++)
		n += snprintf(buf + n, sizeof(buf) - n,
			      "%s%u B: recv %llu send %llu, kick to kick %llu..%llu",
			      i ? "; " : "", lens[i], (unsigned long long)rc[i],
			      (unsigned long long)sc[i], (unsigned long long)lat_min[i],
			      (unsigned long long)lat_max[i]);
	check(stable && rc[N - 1] > rc[0] && sc[N - 1] > sc[0] && rc[N - 1] < 3000 &&
	      sc[N - 1] < 3000 && lat_max[N - 1] < 4000, name, "%s; recv of an empty ring %llu%s",
	      buf, (unsigned long long)empty,
	      stable ? "" : " (recv/send NOT the same every time)");
}

/* ---------------------------------------------------------------------- */
/* Malformed rings                                                         */

struct snap {
	u32 err_ring_idx, err_desc_idx, err_desc, err_msg_len, rx, tx;
	u16 used0, used1;
};

static void take_snap(struct harness *h, struct snap *sn)
{
	sn->err_ring_idx = STAT(h, stats.err_ring_idx);
	sn->err_desc_idx = STAT(h, stats.err_desc_idx);
	sn->err_desc = STAT(h, stats.err_desc);
	sn->err_msg_len = STAT(h, stats.err_msg_len);
	sn->rx = STAT(h, stats.rx_msgs);
	sn->tx = STAT(h, stats.tx_msgs);
	sn->used0 = used_idx(h, 0);
	sn->used1 = used_idx(h, 1);
}

/* After a malformed case: one normal echo must still work. */
static bool still_echoes(struct harness *h, char *why, size_t whylen)
{
	static struct sent s;

	make_msg(&s, 5000, 33);
	return echo_batch(h, &s, 1, why, whylen);
}

static void report_bad(struct harness *h, const char *what, bool ok, const struct snap *a,
		       const char *why)
{
	struct snap b;
	char name[96];

	take_snap(h, &b);
	snprintf(name, sizeof(name), "%s: malformed: %s", h->name, what);
	ok = ok && !h->poison_hits && core_running(h) && !h->bad_used;
	check(ok, name,
	      "refused (errors: ring idx +%u, desc idx +%u, desc +%u, msg len +%u), poison accesses %llu, core %s%s%s",
	      b.err_ring_idx - a->err_ring_idx,
	      b.err_desc_idx - a->err_desc_idx, b.err_desc - a->err_desc,
	      b.err_msg_len - a->err_msg_len, (unsigned long long)h->poison_hits,
	      core_running(h) ? "running" : core_reason(h), why[0] ? "; " : "", why);
}

/* A buffer of the transmit ring set up by hand: desc @i, no kick yet */
static void bad_tx_desc(struct harness *h, unsigned int i, u64 addr, u32 len)
{
	set_desc(h, 1, i, addr, len, 0);
	push_avail(h, 1, i);
}

/* Transmit buffers (Linux -> PRU) the firmware must refuse */
static const struct {
	u64 addr;
	u32 len;
	u16 hdr_len;
	bool msg_len;		/* refused for its header len, not its descriptor */
	const char *what;
} rx_bad[] = {
	{ POISON_START, 8, 0, false, "buffer of 8 bytes (< header)" },
	{ 0x100000000ull | POISON_START, 512, 4, false, "address above 4 GiB" },
	{ 0x10000, 512, 4, false, "address 0x10000 (the PRU's shared RAM)" },
	{ 0x7fff0, 512, 4, false, "address 0x7fff0 (below the OCP port)" },
	{ 0xfffffff8u, 512, 4, false, "address 0xfffffff8 (wraps)" },
	{ POISON_START - HDR, 100, 200, true, "header len 200 > buffer 100 - 16" },
	{ POISON_START - HDR, 1000, 497, true, "header len 497 > 496" },
};

static void test_malformed_rx(struct harness *h)
{
	struct snap a, b;
	char why[160];
	bool ok;
	int i;
	u16 saved;

	/* 1. avail->idx 17 ahead: nothing taken while it is so, then fixed */
	why[0] = 0;
	take_snap(h, &a);
	saved = h->vq[1].avail_idx;
	put16(ddr(h, vring_off(1, PRUKIT_VRING_AVAIL_IDX)), saved + NUM + 1);
	kick_pru(h);
	run_for(h, 20000);
	kick_pru(h);
	run_for(h, 20000);
	take_snap(h, &b);
	ok = b.err_ring_idx - a.err_ring_idx >= 2 && b.used1 == a.used1 && b.rx == a.rx;
	put16(ddr(h, vring_off(1, PRUKIT_VRING_AVAIL_IDX)), saved);
	ok = ok && still_echoes(h, why, sizeof(why));
	take_snap(h, &b);
	ok = ok && b.err_desc_idx == a.err_desc_idx && b.err_desc == a.err_desc;
	report_bad(h, "vring 1 avail idx 17 ahead (counted per kick, then fixed)", ok, &a, why);

	/* 2. descriptor index 16 and 0xffff, then a good message */
	why[0] = 0;
	take_snap(h, &a);
	push_avail(h, 1, NUM);
	push_avail(h, 1, 0xffff);
	ok = still_echoes(h, why, sizeof(why));
	take_snap(h, &b);
	ok = ok && b.err_desc_idx - a.err_desc_idx == 2 && b.used1 - a.used1 == 1;
	report_bad(h, "vring 1 descriptor index 16 and 65535 (skipped, not returned)", ok, &a,
		   why);

	/* 3..: buffers that must not be read */
	for (i = 0; i < (int)ARRAY_SIZE(rx_bad); i++) {
		int t = free_tx(h);
		u8 *b2;

		why[0] = 0;
		take_snap(h, &a);
		if (t < 0) {
			report_bad(h, rx_bad[i].what, false, &a, "no free transmit buffer");
			continue;
		}
		if (rx_bad[i].msg_len) {
			/* a good header right before the poison, payload in it */
			b2 = ddr(h, POISON_START - HDR);
			put32(b2, 6000);
			put32(b2 + 4, h->port);
			put32(b2 + 8, 0);
			put16(b2 + 12, rx_bad[i].hdr_len);
			put16(b2 + 14, 0);
		}
		bad_tx_desc(h, t, rx_bad[i].addr, rx_bad[i].len);
		ok = still_echoes(h, why, sizeof(why));
		reclaim_tx(h);
		take_snap(h, &b);
		ok = ok && b.used1 - a.used1 == 2 && b.rx - a.rx == 1 && b.tx - a.tx == 1;
		if (rx_bad[i].msg_len)
			ok = ok && b.err_msg_len - a.err_msg_len == 1 && b.err_desc == a.err_desc;
		else
			ok = ok && b.err_desc - a.err_desc == 1 && b.err_msg_len == a.err_msg_len;
		report_bad(h, rx_bad[i].what, ok, &a, why);
	}
}

/* Descriptors of the receive ring that Linux holds (not with the PRU) */
static int free_rx(struct harness *h, unsigned int after)
{
	unsigned int i;

	for (i = after; i < NUM; i++)
		if (!(h->vq[0].busy & (1u << i)))
			return i;
	return -1;
}

static u16 fw_u16(struct harness *h, size_t off)
{
	return get16(dram(h, h->state + off, 2));
}

#define FW_LAST_AVAIL(h, q)	fw_u16(h, offsetof(struct prukit_rpmsg, vq[q].last_avail))

/*
 * Reply buffers.  Linux stops refilling its receive ring until the PRU has
 * none left; then each case offers one bad buffer followed by a good one.
 */
static void test_malformed_tx(struct harness *h)
{
	static const struct {
		u64 addr;
		u32 len;
		const char *what;
	} c[] = {
		{ POISON_START, 20, "reply buffer of 20 bytes for 16 + 33" },
		{ 0x10000, 512, "reply buffer at 0x10000 (the PRU's shared RAM)" },
		{ 0x100000000ull | POISON_START, 512, "reply buffer above 4 GiB" },
		{ 0xfffffff0u, 512, "reply buffer at 0xfffffff0 (wraps)" },
		{ 0, 0, "vring 0 descriptor index 19 (skipped)" },
	};
	u8 shared[64], shared2[64];
	struct snap a, b;
	char why[160];
	unsigned int i;
	struct msg m;
	bool ok;
	int bad, good;

	memset(shared, 0xa5, sizeof(shared));
	prusim_host_write(h->s, 0x10000, shared, sizeof(shared));
	h->no_refill = true;
	while ((u16)(h->vq[0].avail_idx - FW_LAST_AVAIL(h, 0)) && still_echoes(h, why, 1))
		;
	for (i = 0; i < ARRAY_SIZE(c); i++) {
		why[0] = 0;
		take_snap(h, &a);
		bad = free_rx(h, 0);
		good = free_rx(h, bad + 1);
		if (bad < 0 || good < 0 || h->vq[0].avail_idx != FW_LAST_AVAIL(h, 0)) {
			report_bad(h, c[i].what, false, &a, "cannot set the case up");
			continue;
		}
		if (c[i].len) {
			set_desc(h, 0, bad, c[i].addr, c[i].len, PRUKIT_VRING_DESC_F_WRITE);
			push_avail(h, 0, bad);
		} else {
			push_avail(h, 0, NUM + 3);
		}
		set_desc(h, 0, good, RXBUF(good), BUF_SIZE, PRUKIT_VRING_DESC_F_WRITE);
		push_avail(h, 0, good);
		ok = still_echoes(h, why, sizeof(why));
		prusim_host_read(h->s, 0x10000, shared2, sizeof(shared2));
		take_snap(h, &b);
		ok = ok && b.tx - a.tx == 1 && !memcmp(shared, shared2, sizeof(shared)) &&
		     (c[i].len ? b.err_desc - a.err_desc : b.err_desc_idx - a.err_desc_idx) == 1 &&
		     h->vq[0].avail_idx == FW_LAST_AVAIL(h, 0);
		/* never given back: Linux would have to reset to get it */
		h->vq[0].busy &= ~(1u << bad);
		report_bad(h, c[i].what, ok, &a, why);
	}

	/* avail->idx of the receive ring 20 ahead: the reply waits until fixed */
	why[0] = 0;
	take_snap(h, &a);
	{
		static struct sent s;
		u16 saved = h->vq[0].avail_idx;
		unsigned int want = 1;

		put16(ddr(h, vring_off(0, PRUKIT_VRING_AVAIL_IDX)), saved + 20);
		make_msg(&s, 7000, 40);
		arm_send(h, s.src, h->port, s.data, s.len, true);
		run_for(h, 30000);
		kick_pru(h);
		run_for(h, 30000);
		take_snap(h, &b);
		ok = b.used0 == a.used0 && b.err_ring_idx - a.err_ring_idx >= 2 &&
		     b.rx - a.rx == 1;
		put16(ddr(h, vring_off(0, PRUKIT_VRING_AVAIL_IDX)), saved);
		good = free_rx(h, 0);
		if (good >= 0) {
			set_desc(h, 0, good, RXBUF(good), BUF_SIZE, PRUKIT_VRING_DESC_F_WRITE);
			push_avail(h, 0, good);
		}
		kick_pru(h);
		ok = ok && good >= 0 && run_until(h, cond_rx_count, &want, 100000) &&
		     arm_recv(h, &m) && same_echo(h, &m, &s, why, sizeof(why));
	}
	report_bad(h, "vring 0 avail idx 20 ahead (the reply waits until fixed)", ok, &a, why);

	/* Linux refills its receive ring again */
	h->no_refill = false;
	for (i = 0; i < NUM; i++) {
		if (!(h->vq[0].busy & (1u << i))) {
			set_desc(h, 0, i, RXBUF(i), BUF_SIZE, PRUKIT_VRING_DESC_F_WRITE);
			push_avail(h, 0, i);
		}
	}
	kick_pru(h);
	run_for(h, 10000);
}

/* A table Linux never filled in, or a ring in the PRU's own memory */
static void test_bad_rsc(const char *fw, unsigned int core)
{
	static const struct {
		u32 da0, da1;
		const char *what;
	} c[] = {
		{ PRUKIT_RSC_ADDR_ANY, PRUKIT_RSC_ADDR_ANY, "vring da left at FW_RSC_ADDR_ANY" },
		{ VRING_DA(0), 0x10000, "vring 1 in the PRU's shared RAM" },
		{ 0xffffff00u, VRING_DA(1), "vring 0 at 0xffffff00 (wraps)" },
	};
	unsigned int i;

	for (i = 0; i < ARRAY_SIZE(c); i++) {
		struct harness *h = harness_new(fw, "echo", core);
		struct prusim_status st;
		char name[96];

		h->vdev = h->info.rsc_addr + 20;
		arm_setup_vrings(h, VRING_DA(0), VRING_DA(1));
		dram_write32(h, h->vdev + 28, c[i].da0);
		dram_write32(h, h->vdev + 28 + 20, c[i].da1);
		prusim_core_enable(h->s, h->core, true);
		run_for(h, 10000);
		arm_driver_ok(h);
		run_for(h, 100000);
		prusim_get_status(h->s, h->core, &st);
		snprintf(name, sizeof(name), "%s: bad resource table: %s", h->name, c[i].what);
		check(st.state == PRUSIM_HALTED && !h->ocp_accesses &&
		      STAT(h, stats.status) == PRUKIT_RPMSG_ST_BAD_RSC, name,
		      "core %s, %llu OCP accesses, status 0x%x",
		      st.state == PRUSIM_HALTED ? "halted" : "not halted",
		      (unsigned long long)h->ocp_accesses, STAT(h, stats.status));
		harness_free(h);
	}
}

static void test_echo(const char *fw, unsigned int core)
{
	struct harness *h = harness_new(fw, "echo", core);
	char name[64], why[160] = "";

	if (boot(h)) {
		test_echo_lengths(h);
		test_echo_burst(h);
		test_kicks(h);
		test_cycles(h);
		test_malformed_rx(h);
		test_malformed_tx(h);
		snprintf(name, sizeof(name), "%s: after everything", h->name);
		check(still_echoes(h, why, sizeof(why)) && core_running(h) && !h->poison_hits &&
		      !h->bad_used, name, "still running and echoing; kicks in %u, out %u%s%s",
		      STAT(h, stats.kicks_in), STAT(h, stats.kicks_out), why[0] ? ": " : "", why);
	}
	harness_free(h);
	test_bad_rsc(fw, core);
}

/* ---------------------------------------------------------------------- */
/* rpmsg-neopixel                                                          */

static u32 np_stat(struct harness *h, u32 sym, size_t off)
{
	return get32(dram(h, sym + off, 4));
}

static bool cond_frames(struct harness *h, void *arg)
{
	const u32 *a = arg;		/* { sym, want } */

	return np_stat(h, a[0], offsetof(struct neopixel_stats, frames)) >= a[1];
}

/* Send one text message and let the firmware take it */
static bool np_send(struct harness *h, const char *text)
{
	u32 len = strlen(text);

	if (len > RPMSG_PRU_MAX_PAYLOAD || arm_send(h, 1025, h->port, (const u8 *)text, len, true))
		return false;
	run_for(h, 20000);
	return true;
}

/*
 * Check the edges logged since @from against the WS2812 encoding of @grb:
 * every bit's high and low time exact, MSB first; the last low at least a
 * reset long (up to @end, the cycle the check is made).
 */
static bool check_frame(struct harness *h, unsigned int from, const u8 *grb, u64 end,
			char *why, size_t whylen, u64 *first_rise)
{
	unsigned int nbits = NEOPIXEL_COUNT * 24, i, e = from;

	if (h->edges - from != 2 * nbits) {
		snprintf(why, whylen, "%u edges, want %u", h->edges - from, 2 * nbits);
		return false;
	}
	*first_rise = h->edge_cycle[from];
	for (i = 0; i < nbits; i++, e += 2) {
		bool one = (grb[i / 8] >> (7 - i % 8)) & 1;
		u64 high, low, want_h = one ? WS2812_T1H : WS2812_T0H;
		u64 want_l = one ? WS2812_T1L : WS2812_T0L;

		if (h->edge_level[e] != 1 || h->edge_level[e + 1] != 0) {
			snprintf(why, whylen, "bit %u: edge levels %u %u", i, h->edge_level[e],
				 h->edge_level[e + 1]);
			return false;
		}
		high = h->edge_cycle[e + 1] - h->edge_cycle[e];
		low = (i + 1 < nbits ? h->edge_cycle[e + 2] : end) - h->edge_cycle[e + 1];
		if (high != want_h || (i + 1 < nbits ? low != want_l : low < WS2812_RESET)) {
			snprintf(why, whylen,
				 "bit %u (pixel %u byte %u, value %u): high %llu low %llu cycles, want %llu/%s%llu",
				 i, i / 24, i / 8 % 3, one,
				 (unsigned long long)high, (unsigned long long)low,
				 (unsigned long long)want_h, i + 1 < nbits ? "" : ">=",
				 (unsigned long long)(i + 1 < nbits ? want_l : WS2812_RESET));
			return false;
		}
	}
	return true;
}

static void put64(u8 *p, u64 v)
{
	put32(p, v);
	put32(p + 4, v >> 32);
}

/*
 * Write the P9_29 edges as a binary pin trace (sim/prusim_trace.h), for
 * "prusim --trace-in FILE --events/--vcd": run.sh checks the tool's own
 * event list with an independent decoder.
 */
static void write_trace(struct harness *h, const char *path)
{
	struct prusim_trace_hdr hdr;
	struct prusim_trace_rec rec;
	unsigned int i, n = h->edges < MAX_EDGES ? h->edges : MAX_EDGES;
	FILE *f = fopen(path, "wb");
	bool ok = f;

	memset(&hdr, 0, sizeof(hdr));
	memcpy(hdr.magic, PRUSIM_TRACE_MAGIC, sizeof(hdr.magic));
	put32((u8 *)&hdr.version, PRUSIM_TRACE_VERSION);
	put32((u8 *)&hdr.rec_size, sizeof(rec));
	put64((u8 *)&hdr.count, n);
	put64((u8 *)&hdr.end, h->s->now);
	ok = ok && fwrite(&hdr, sizeof(hdr), 1, f) == 1;
	for (i = 0; ok && i < n; i++) {
		memset(&rec, 0, sizeof(rec));
		put64((u8 *)&rec.cycle, h->edge_cycle[i]);
		put16((u8 *)&rec.pin, PRUSIM_PIN_R30(h->core, NEOPIXEL_BIT));
		rec.level = h->edge_level[i];
		ok = fwrite(&rec, sizeof(rec), 1, f) == 1;
	}
	if (f && fclose(f))
		ok = false;
	check(ok && n == h->edges, "rpmsg-neopixel-pru0: pin trace written", "%u edges to %s", n,
	      path);
}

static void np_frame_case(struct harness *h, u32 stats, const char *what, const char *text,
			  const u8 *grb, u64 *last_fall)
{
	u32 frames = np_stat(h, stats, offsetof(struct neopixel_stats, frames));
	u32 want[2] = { stats, frames + 1 };
	unsigned int from = h->edges;
	char name[96], why[200] = "";
	u64 rise = 0;
	bool ok;

	ok = np_send(h, text) && run_until(h, cond_frames, want, 400000);
	run_for(h, 1000);
	ok = ok && check_frame(h, from, grb, h->s->now, why, sizeof(why), &rise);
	if (ok && *last_fall && rise - *last_fall < WS2812_RESET) {
		snprintf(why, sizeof(why), "only %llu cycles low before the frame",
			 (unsigned long long)(rise - *last_fall));
		ok = false;
	}
	snprintf(name, sizeof(name), "rpmsg-neopixel-pru0: %s", what);
	if (!ok)
		check(false, name, "%s", why);
	else
		check(!h->other_pins, name,
		      "576 bits, every high/low exact (T0H %u T0L %u T1H %u T1L %u cycles), then low >= %u; low %llu cycles before it; %u other pin changes",
		      WS2812_T0H, WS2812_T0L, WS2812_T1H, WS2812_T1L, WS2812_RESET,
		      (unsigned long long)(rise - *last_fall), h->other_pins);
	if (h->edges > from)
		*last_fall = h->edge_cycle[h->edges - 1];
}

static void test_neopixel(const char *fw, const char *trace)
{
	struct harness *h = harness_new(fw, "rpmsg-neopixel", 0);
	u32 stats = elf_sym(h->img, h->img_size, "neopixel_stats");
	u8 grb[NEOPIXEL_COUNT * 3] = { 0 };
	char line[200], name[96];
	u32 bad0, ok0;
	u64 last_fall = 0;

	if (stats == NO_ADDR) {
		check(false, "rpmsg-neopixel-pru0: symbols", "no neopixel_stats");
		harness_free(h);
		return;
	}
	if (!boot(h)) {
		harness_free(h);
		return;
	}
	check(!h->edges && !(h->s->core[0].r[30] & (1u << NEOPIXEL_BIT)),
	      "rpmsg-neopixel-pru0: line low at start", "%u edges on P9_29 before the first frame",
	      h->edges);

	/* The brief's example: pixel 0 = red 0xff, green 0, blue 127 */
	grb[0] = 0x00;
	grb[1] = 0xff;
	grb[2] = 0x7f;
	last_fall = 0;
	if (!np_send(h, "0 0xff 0 127\n"))
		check(false, "rpmsg-neopixel-pru0: send", "no transmit buffer");
	np_frame_case(h, stats, "\"0 0xff 0 127\" then \"-1\": LED0 GRB 00 ff 7f, 23 off",
		      "-1\n", grb, &last_fall);
	np_frame_case(h, stats, "a second \"-1\": same frame after the reset", "-1", grb,
		      &last_fall);

	/* Malformed lines among good ones, then a frame in the same message */
	bad0 = np_stat(h, stats, offsetof(struct neopixel_stats, lines_bad));
	ok0 = np_stat(h, stats, offsetof(struct neopixel_stats, lines_ok));
	memset(line, ' ', sizeof(line));
	memcpy(line, "9 1 2 3", 7);
	line[NEOPIXEL_LINE_MAX + 1] = '\n';
	line[NEOPIXEL_LINE_MAX + 2] = 0;
	np_send(h, "24 1 2 3\n0 256 0 0\n0 1 2\nabc\n0 1 2 3 4\n0x 1 2 3\n-1 5\n-2\n");
	np_send(h, "0 -1 0 0\n1 2 3 0x1g\n1 0x100 0 0\n99999999999 1 1 1\n-10\n1,2,3,4\n");
	np_send(h, line);		/* 65 characters: one too many */
	np_send(h, "\n\n\t\t\n5 1 2 3\n\t6 0x10 0X20 0x3F\r\n2 1 2 3 # comment\n");
	grb[5 * 3 + 0] = 2;
	grb[5 * 3 + 1] = 1;
	grb[5 * 3 + 2] = 3;
	grb[6 * 3 + 0] = 0x20;
	grb[6 * 3 + 1] = 0x10;
	grb[6 * 3 + 2] = 0x3f;
	grb[7 * 3 + 0] = 255;
	grb[7 * 3 + 1] = 0;
	grb[7 * 3 + 2] = 1;
	np_frame_case(h, stats, "several lines and \"-1\" in one message",
		      "7 0 0xff 1\n-1\n8 1 1 1", grb, &last_fall);
	snprintf(name, sizeof(name), "rpmsg-neopixel-pru0: malformed lines ignored and counted");
	check(np_stat(h, stats, offsetof(struct neopixel_stats, lines_bad)) - bad0 == 16 &&
	      np_stat(h, stats, offsetof(struct neopixel_stats, lines_ok)) - ok0 == 4 &&
	      core_running(h), name, "%u bad (want 16), %u good (want 4: pixels 5, 6, 7, 8)",
	      np_stat(h, stats, offsetof(struct neopixel_stats, lines_bad)) - bad0,
	      np_stat(h, stats, offsetof(struct neopixel_stats, lines_ok)) - ok0);

	/* pixel 8 was set after the frame: it shows in the next one */
	grb[8 * 3 + 0] = 1;
	grb[8 * 3 + 1] = 1;
	grb[8 * 3 + 2] = 1;
	np_frame_case(h, stats, "the line after \"-1\" shows in the next frame", "-1\n", grb,
		      &last_fall);
	check(core_running(h) && !h->poison_hits && !STAT(h, stats.err_desc) &&
	      !STAT(h, stats.err_msg_len) && !STAT(h, stats.err_desc_idx) &&
	      !STAT(h, stats.err_ring_idx),
	      "rpmsg-neopixel-pru0: rpmsg clean", "running, no ring errors, %u messages",
	      np_stat(h, stats, offsetof(struct neopixel_stats, msgs)));
	if (trace)
		write_trace(h, trace);
	harness_free(h);
}

int main(int argc, char **argv)
{
	if (argc == 4 && !strcmp(argv[1], "echo")) {
		test_echo(argv[2], 0);
		test_echo(argv[3], 1);
	} else if ((argc == 3 || argc == 4) && !strcmp(argv[1], "rpmsg-neopixel")) {
		test_neopixel(argv[2], argc == 4 ? argv[3] : NULL);
	} else {
		fprintf(stderr, "usage: %s echo ECHO_PRU0.elf ECHO_PRU1.elf\n"
			"       %s rpmsg-neopixel RPMSG_NEOPIXEL_PRU0.elf [TRACE_FILE]\n",
			argv[0], argv[0]);
		return 2;
	}
	return failures ? 1 : 0;
}
