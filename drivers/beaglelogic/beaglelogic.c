// SPDX-License-Identifier: GPL-2.0-only
/*
 * beaglelogic - a logic analyzer on the BeagleBone's PRUs, compatible with
 * the original BeagleLogic's /dev/beaglelogic
 *
 * One "prukit,beaglelogic" node: the storer's and the sampler's PRU in
 * "ti,prus" (PRU0 and PRU1 on a BeagleBone Black, PRU1 and PRU0 on a
 * PocketBeagle), running the beaglelogic firmware (beaglelogic_proto.h),
 * and the storer's event in "interrupts-extended".  The sampler samples
 * its R31 bits 0..15 (8-bit units: 0..7) at 100 MHz / n, the storer writes
 * the samples into a ring of buffers in DDR and raises an event per full
 * buffer; with a trigger (prukit's) the storer runs the ring until it came.
 *
 * Users see what the original offered, names, numbers and quirks included
 * (Documentation/beaglelogic.rst), so that libsigrok's beaglelogic driver
 * and dd work unchanged:
 *  - the misc device "beaglelogic", with no parent: its attributes are in
 *    /sys/devices/virtual/misc/beaglelogic/, where libsigrok looks;
 *  - /dev/beaglelogic: the first read() starts a capture; a read never
 *    crosses a buffer; one-shot captures end with EOF, continuous ones wrap;
 *    lseek(0, SEEK_SET) stops and rewinds, lseek(n, SEEK_CUR) skips; poll()
 *    says when the reader's buffer is full; mmap() maps every buffer back
 *    to back; ioctls (uapi/prukit/beaglelogic.h).
 *
 * The buffers are the driver's own lowmem pages, mapped for streaming DMA
 * (not one coherent allocation: Debian's kernels reserve only 16 MiB of
 * CMA); each full buffer is synced for the CPU before a reader sees it,
 * and in a continuous capture handed back to the device once the reader
 * has left it, before the storer refills it.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/atomic.h>
#include <linux/device.h>
#include <linux/dma-mapping.h>
#include <linux/fs.h>
#include <linux/gfp.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/kref.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/poll.h>
#include <linux/remoteproc.h>
#include <linux/slab.h>
#include <linux/uaccess.h>
#include <linux/wait.h>

#include "compat.h"
#include "prukit_pru.h"
#include "uapi/prukit/beaglelogic.h"
#include "beaglelogic_proto.h"

#define BL_STORER		0	/* "ti,prus" entry 0 (Black: PRU0) */
#define BL_SAMPLER		1	/* entry 1 (Black: PRU1) */
#define BL_CORES		2

#define BL_MAX_RATE		100000000u
/* A buffer is one allocation of contiguous pages: at most order 10. */
#define BL_MAX_BUFUNIT		(4u << 20)
#define BL_DEFAULT_BUFUNIT	(4u << 20)
#define BL_DEFAULT_BUFS		2
/* prukit's own version number of the interface, for IOCTL_BL_GET_VERSION */
#define BL_DRV_VERSION		0x00010002u
/* The smallest buffer a trigger at 100 Msps keeps up with (bl_trig_setup()) */
#define BL_TRIG_MIN_BUFUNIT	4096u
/* R31 bits a 16-bit sample holds: what a trigger may look at */
#define BL_CHANNELS		16
/* lasterror when a continuous reader fell a whole ring behind */
#define BL_ERR_OVERRUN		0x10000u

/* The trigger attribute's kinds (the firmware picks how to look for them) */
enum bl_trig_kind {
	BL_TRIGGER_NONE,
	BL_TRIGGER_RISING,
	BL_TRIGGER_FALLING,
	BL_TRIGGER_EDGE,
	BL_TRIGGER_PATTERN,
};

static const char * const bl_trig_names[] = {
	[BL_TRIGGER_NONE] = "none",
	[BL_TRIGGER_RISING] = "rising",
	[BL_TRIGGER_FALLING] = "falling",
	[BL_TRIGGER_EDGE] = "edge",
	[BL_TRIGGER_PATTERN] = "pattern",
};

/**
 * struct bl_buf - one capture buffer
 * @va: its pages (alloc_pages_exact())
 * @dma: their bus address while @mapped
 * @mapped: mapped for DMA (until the platform device goes)
 */
struct bl_buf {
	void *va;
	dma_addr_t dma;
	bool mapped;
};

/**
 * struct beaglelogic - the logic analyzer
 * @dev: the platform device (its DMA and PRUs)
 * @kref: the last reference (device, open file, mapping) frees it
 * @lock: serialises settings, captures and readers
 * @buf_lock: serialises the buffer set against mmap() (taken inside @lock,
 *	and by mmap() alone: a reader holds @lock while it faults)
 * @wq: woken by the storer's event and when @gone is set
 * @pru: the cores, BL_STORER and BL_SAMPLER
 * @ctrl: their control blocks while the firmware runs
 * @event: the storer's system event
 * @gone: the platform device was unbound: every call fails with -ENODEV
 * @stopped: a core crashed or restarted behind the driver's back: -EPIPE
 * @samplerate: samples per second, 100 MHz / an integer
 * @unit: BL_SAMPLEUNIT_*
 * @flags: BL_TRIGGERFLAGS_*
 * @bufunitsize: bytes of each buffer, a multiple of BL_BLOCK_BYTES
 * @bufs: the buffers
 * @nbufs: how many
 * @maps: mappings of the buffers (they stay while any exists)
 * @opens: open files (the last close stops a capture)
 * @running: a capture runs
 * @started: a capture was started since the last rewind
 * @fw_done: the one-shot capture filled every buffer
 * @fw_error: the storer stopped on an error (lasterror says which)
 * @filled: buffers the storer filled since the capture started
 * @synced: of those, the ones synced for the CPU
 * @rpos: the reader's position, bytes since the capture's start
 * @lasterror: the last error, as the original reports it
 * @trig_kind: the trigger (prukit's), enum bl_trig_kind
 * @trig_chan: its channel (edges)
 * @trig_mask: its mask (patterns)
 * @trig_value: its value (patterns)
 * @pretrigger: samples to keep from before the trigger, at least
 * @trig_on: the capture runs until the trigger (one-shot and a trigger set)
 * @trig_pre: blocks the storer keeps from before the trigger's block
 * @trig_start: the sample (counted from the capture's first) read() begins
 *	with, once the trigger came
 * @trig_sample: the trigger's sample in what read() returns, -1 if none
 * @cap_div: the capture's divisor (100 MHz / samplerate)
 * @misc: /dev/beaglelogic
 */
struct beaglelogic {
	struct device *dev;
	struct kref kref;
	struct mutex lock;	/* protects everything below */
	struct mutex buf_lock;	/* protects @bufs, @nbufs, @maps against mmap() */
	wait_queue_head_t wq;
	struct prukit_pru *pru[BL_CORES];
	void __iomem *ctrl[BL_CORES];
	u32 event;
	bool gone;
	bool stopped;
	u32 samplerate;
	u32 unit;
	u32 flags;
	u32 bufunitsize;
	struct bl_buf bufs[BL_MAX_BUFS];
	unsigned int nbufs;
	unsigned int maps;
	unsigned int opens;
	bool running;
	bool started;
	bool fw_done;
	bool fw_error;
	u32 filled;
	u32 synced;
	u64 rpos;
	u32 lasterror;
	u32 trig_kind;
	u32 trig_chan;
	u32 trig_mask;
	u32 trig_value;
	u32 pretrigger;
	bool trig_on;
	u32 trig_pre;
	u64 trig_start;
	s64 trig_sample;
	u32 cap_div;
	struct miscdevice misc;
};

/* libsigrok knows one analyzer, at one sysfs path: one instance. */
static atomic_t bl_taken = ATOMIC_INIT(0);

/*
 * Capture memory is lowmem the rest of the system cannot use while it is
 * allocated: 128 buffers of 4 MiB would be all of a Black's 512 MiB.
 */
static unsigned int max_memalloc_mib;
module_param(max_memalloc_mib, uint, 0644);
MODULE_PARM_DESC(max_memalloc_mib,
		 "Most capture memory memalloc may allocate, in MiB (default 0: a quarter of the RAM)");

/* The cap on memalloc, in bytes */
static u64 bl_memalloc_cap(void)
{
	unsigned int mib = READ_ONCE(max_memalloc_mib);

	if (mib)
		return (u64)mib << 20;
	return ((u64)totalram_pages() << PAGE_SHIFT) / 4;
}

static void bl_free_pages(struct beaglelogic *bl, struct bl_buf *bufs, unsigned int n, u32 size)
{
	unsigned int i;

	for (i = 0; i < n; i++) {
		if (bufs[i].mapped)
			dma_unmap_single(bl->dev, bufs[i].dma, size, DMA_FROM_DEVICE);
		free_pages_exact(bufs[i].va, size);
		bufs[i].va = NULL;
		bufs[i].mapped = false;
	}
}

static void bl_free(struct kref *kref)
{
	struct beaglelogic *bl = container_of(kref, struct beaglelogic, kref);

	bl_free_pages(bl, bl->bufs, bl->nbufs, bl->bufunitsize);
	kfree(bl);
}

static void bl_put(struct beaglelogic *bl)
{
	kref_put(&bl->kref, bl_free);
}

static void bl_put_action(void *data)
{
	bl_put(data);
}

/* --- the cores ----------------------------------------------------------- */

static u32 bl_read_ctrl(struct beaglelogic *bl, unsigned int core, size_t off)
{
	return readl(bl->ctrl[core] + off);
}

static void bl_write_ctrl(struct beaglelogic *bl, unsigned int core, size_t off, u32 val)
{
	writel(val, bl->ctrl[core] + off);
}

/* An error of the calls that need the PRUs, or 0 while they run. */
static int bl_dead(struct beaglelogic *bl)
{
	if (bl->gone)
		return -ENODEV;
	if (bl->stopped)
		return -EPIPE;
	return 0;
}

/* The firmware's answer to a command: 0, or an errno. */
static int bl_command(struct beaglelogic *bl, unsigned int core, u16 opcode)
{
	int ret = prukit_pru_ctrl_command(bl->pru[core], bl->ctrl[core], opcode,
					  PRUKIT_PRU_TIMEOUT_MS);

	if (ret < 0) {
		bl->stopped = true;
		return ret;
	}
	switch (ret) {
	case BL_OK:
		return 0;
	case BL_EINVAL:
		return -EINVAL;
	case BL_EBUSY:
		return -EBUSY;
	case BL_ENOSTORER:
		return -EIO;
	default:
		return -EPROTO;
	}
}

/* --- triggers ------------------------------------------------------------ */

static u32 bl_sample_bytes(struct beaglelogic *bl)
{
	return bl->unit == BL_SAMPLEUNIT_8_BITS ? 1 : 2;
}

/* Sample @n of the capture (counted from its first), still in the ring */
static u32 bl_sample_at(struct beaglelogic *bl, u64 n)
{
	u32 ring = bl->nbufs * bl->bufunitsize, off;
	const void *p;

	div_u64_rem(n * bl_sample_bytes(bl), ring, &off);
	p = bl->bufs[off / bl->bufunitsize].va + off % bl->bufunitsize;
	return bl_sample_bytes(bl) == 1 ? *(const u8 *)p : le16_to_cpup(p);
}

/* Sample @cur, after @prev, is the trigger's */
static bool bl_trig_hit(struct beaglelogic *bl, u32 prev, u32 cur)
{
	u32 bit = BIT(bl->trig_chan);

	switch (bl->trig_kind) {
	case BL_TRIGGER_RISING:
		return !(prev & bit) && (cur & bit);
	case BL_TRIGGER_FALLING:
		return (prev & bit) && !(cur & bit);
	case BL_TRIGGER_EDGE:
		return (prev ^ cur) & bit;
	default:
		return (cur & bl->trig_mask) == bl->trig_value;
	}
}

/*
 * A triggered capture ended: the storer says which block held the trigger,
 * the samples say which sample (an edge's first sample after it; the first
 * sample of a pattern's run, which may begin before the samples the storer
 * looks at: bl_store.S).  With @lock held.
 */
static void bl_trig_done(struct beaglelogic *bl)
{
	u32 spb = BL_BLOCK_BYTES / bl_sample_bytes(bl), block, i;
	u64 first, start, n;

	block = bl_read_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, trig_block));
	if (block <= bl->trig_pre) {
		dev_err(bl->dev, "the storer ended without a trigger (block %u)\n", block);
		bl->fw_done = false;
		bl->fw_error = true;
		return;
	}
	/* the last buffer is not a full one: sync every buffer */
	for (i = 0; i < bl->nbufs; i++)
		dma_sync_single_for_cpu(bl->dev, bl->bufs[i].dma, bl->bufunitsize,
					DMA_FROM_DEVICE);
	first = (u64)(block - 1) * spb;
	start = first - (u64)bl->trig_pre * spb;
	for (n = first; n < first + spb; n++)
		if (bl_trig_hit(bl, bl_sample_at(bl, n - 1), bl_sample_at(bl, n)))
			break;
	if (n == first + spb) {
		dev_warn(bl->dev, "no trigger in the block the storer named (%u)\n", block);
		n = first;
	}
	if (bl->trig_kind == BL_TRIGGER_PATTERN)
		while (n > start && bl_trig_hit(bl, 0, bl_sample_at(bl, n - 1)))
			n--;
	bl->trig_start = start;
	bl->trig_sample = n - start;
}

/*
 * The storer's trigger parameters for this capture (beaglelogic_proto.h);
 * with @lock held.  -EINVAL when the ring cannot hold the samples asked for
 * before the trigger and one block after it, or the trigger's channel or
 * pattern does not fit the sample unit.
 */
static int bl_trig_setup(struct beaglelogic *bl)
{
	u32 bits = 8 * bl_sample_bytes(bl), spb = BL_BLOCK_BYTES / bl_sample_bytes(bl);
	u32 blocks = bl->nbufs * (bl->bufunitsize / BL_BLOCK_BYTES);
	u32 rep = bits == 8 ? 0x01010101 : 0x00010001;
	u32 mode, lanes, bit;

	/*
	 * Whole blocks; a pattern's run may begin a few samples before the
	 * block it was seen in (bl_trig_done()): one block more.
	 */
	bl->trig_pre = max_t(u32, DIV_ROUND_UP_ULL((u64)bl->pretrigger, spb), 1) +
		       (bl->trig_kind == BL_TRIGGER_PATTERN);
	if (bl->trig_pre + 2 > blocks)
		return -EINVAL;
	/*
	 * At 100 Msps the storer makes up a full buffer's 14 cycles over the
	 * next blocks' few spare ones (bl_store.S): in prusim an 8-bit pattern
	 * needs buffers of 512 bytes, a 16-bit one 448, an edge 64.
	 */
	if (bl->cap_div == 1 && bl->bufunitsize < BL_TRIG_MIN_BUFUNIT)
		return -EINVAL;
	if (bl->trig_kind == BL_TRIGGER_PATTERN) {
		if (bl->trig_mask >> bits)
			return -EINVAL;
		mode = bits == 8 ? BL_TRIG_PATTERN8 :
		       bl->cap_div == 1 ? BL_TRIG_PATTERN16_HALF : BL_TRIG_PATTERN16;
		lanes = bl->trig_mask * rep;
		bit = bl->trig_value * rep;
	} else {
		if (bl->trig_chan >= bits)
			return -EINVAL;
		mode = bl->trig_kind == BL_TRIGGER_RISING ? BL_TRIG_RISING :
		       bl->trig_kind == BL_TRIGGER_FALLING ? BL_TRIG_FALLING : BL_TRIG_EDGE;
		lanes = BIT(bl->trig_chan) * rep;
		bit = bl->trig_chan + 32 - bits;
	}
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, trig_mode), mode);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, trig_lanes), lanes);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, trig_bit), bit);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, trig_pre), bl->trig_pre);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, trig_post),
		      blocks - bl->trig_pre - 1);
	return 0;
}

/*
 * Look at the capture's progress: buffers filled (each synced for the CPU
 * once), the end of a one-shot capture, errors, a core stopped behind the
 * driver's back.  Called with @lock held.
 */
static void bl_update(struct beaglelogic *bl)
{
	u32 filled, state, first;

	if (!bl->running)
		return;
	if (!prukit_pru_running(bl->pru[BL_STORER]) || !prukit_pru_running(bl->pru[BL_SAMPLER])) {
		bl->stopped = true;
		bl->running = false;
		return;
	}
	/* @state first: the storer counts its last buffer before it is DONE */
	state = bl_read_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, state));
	filled = bl_read_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, filled));
	/* Only the last nbufs buffers filled still hold their data. */
	first = filled - bl->synced > bl->nbufs ? filled - bl->nbufs : bl->synced;
	for (; first != filled; first++) {
		struct bl_buf *b = &bl->bufs[first % bl->nbufs];

		dma_sync_single_for_cpu(bl->dev, b->dma, bl->bufunitsize, DMA_FROM_DEVICE);
	}
	bl->synced = filled;
	bl->filled = filled;
	if (state == BL_FW_DONE) {
		bl->running = false;
		bl->fw_done = true;
		if (bl->trig_on)
			bl_trig_done(bl);
	} else if (state == BL_FW_ERROR) {
		bl->running = false;
		bl->fw_error = true;
		bl->lasterror = bl_read_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, error));
		dev_err(bl->dev, "capture stopped: the storer fell behind (error %u)\n",
			bl->lasterror);
	}
}

static irqreturn_t bl_irq(int irq, void *data)
{
	struct beaglelogic *bl = data;

	mutex_lock(&bl->lock);
	bl_update(bl);
	mutex_unlock(&bl->lock);
	wake_up_interruptible(&bl->wq);
	return IRQ_HANDLED;
}

/* Stop a capture; with @lock held.  Leaves the data where it is. */
static void bl_stop(struct beaglelogic *bl)
{
	bool was_running;

	bl_update(bl);
	was_running = bl->running;
	bl->running = false;
	if (!was_running || bl_dead(bl))
		return;
	if (bl_command(bl, BL_STORER, BL_CMD_STOP))
		dev_warn(bl->dev, "the storer did not stop\n");
	wake_up_interruptible(&bl->wq);
}

/* Start a capture into every buffer, reader at 0; with @lock held. */
static int bl_start(struct beaglelogic *bl)
{
	unsigned int i;
	int ret;

	ret = bl_dead(bl);
	if (ret)
		return ret;
	if (bl->running)
		return -EBUSY;
	if (!bl->nbufs)
		return -ENOMEM;
	bl->cap_div = BL_MAX_RATE / bl->samplerate;
	/* a trigger: the ring runs until it came (beaglelogic_proto.h) */
	bl->trig_on = bl->trig_kind != BL_TRIGGER_NONE && bl->flags == BL_TRIGGERFLAGS_ONESHOT;
	bl->trig_sample = -1;
	if (bl->trig_on) {
		ret = bl_trig_setup(bl);
		if (ret)
			return ret;
	} else {
		bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, trig_mode), BL_TRIG_NONE);
	}
	for (i = 0; i < bl->nbufs; i++)
		dma_sync_single_for_device(bl->dev, bl->bufs[i].dma, bl->bufunitsize,
					   DMA_FROM_DEVICE);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, unit), bl->unit);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, mode),
		      bl->trig_on ? BL_MODE_CONTINUOUS : bl->flags);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, nbufs), bl->nbufs);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, bufsize), bl->bufunitsize);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, event), bl->event);
	for (i = 0; i < bl->nbufs; i++)
		bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, bufs) + 4 * i,
			      bl->bufs[i].dma);
	ret = bl_command(bl, BL_STORER, BL_CMD_START);
	if (ret)
		return ret;
	bl_write_ctrl(bl, BL_SAMPLER, offsetof(struct bl_ctrl, unit), bl->unit);
	bl_write_ctrl(bl, BL_SAMPLER, offsetof(struct bl_ctrl, divisor), bl->cap_div);
	ret = bl_command(bl, BL_SAMPLER, BL_CMD_START);
	if (ret) {
		bl_command(bl, BL_STORER, BL_CMD_STOP);
		return ret;
	}
	bl->running = true;
	bl->started = true;
	bl->fw_done = false;
	bl->fw_error = false;
	bl->filled = 0;
	bl->synced = 0;
	bl->rpos = 0;
	bl->lasterror = 0;
	return 0;
}

/* Back to before the first read: stop, reader at 0; with @lock held. */
static void bl_rewind(struct beaglelogic *bl)
{
	bl_stop(bl);
	bl->started = false;
	bl->fw_done = false;
	bl->fw_error = false;
	bl->filled = 0;
	bl->synced = 0;
	bl->rpos = 0;
}

/* --- buffers ------------------------------------------------------------- */

/*
 * Replace the buffers by @n of @unit bytes (0: none); with @lock held and
 * no capture running.  On failure the old ones stay.
 */
static int bl_set_buffers(struct beaglelogic *bl, unsigned int n, u32 unit)
{
	struct bl_buf *bufs;
	unsigned int i;
	int ret = 0;

	bufs = kcalloc(BL_MAX_BUFS, sizeof(*bufs), GFP_KERNEL);
	if (!bufs)
		return -ENOMEM;
	for (i = 0; i < n; i++) {
		bufs[i].va = alloc_pages_exact(unit, GFP_KERNEL | __GFP_NOWARN);
		if (!bufs[i].va) {
			ret = -ENOMEM;
			break;
		}
		bufs[i].dma = dma_map_single(bl->dev, bufs[i].va, unit, DMA_FROM_DEVICE);
		if (dma_mapping_error(bl->dev, bufs[i].dma)) {
			free_pages_exact(bufs[i].va, unit);
			bufs[i].va = NULL;
			ret = -ENOMEM;
			break;
		}
		bufs[i].mapped = true;
	}

	mutex_lock(&bl->buf_lock);
	if (!ret && bl->maps)
		ret = -EBUSY;
	if (ret) {
		mutex_unlock(&bl->buf_lock);
		bl_free_pages(bl, bufs, i, unit);
		kfree(bufs);
		return ret;
	}
	bl_free_pages(bl, bl->bufs, bl->nbufs, bl->bufunitsize);
	memcpy(bl->bufs, bufs, sizeof(bl->bufs));
	bl->nbufs = n;
	bl->bufunitsize = unit;
	mutex_unlock(&bl->buf_lock);
	kfree(bufs);
	bl_rewind(bl);
	return 0;
}

/* Buffers of the current size for @bytes (rounded up); with @lock held. */
static int bl_memalloc(struct beaglelogic *bl, u32 bytes)
{
	u64 n = DIV_ROUND_UP_ULL((u64)bytes, bl->bufunitsize);
	u64 cap = bl_memalloc_cap();

	if (n > BL_MAX_BUFS)
		return -EINVAL;
	if (n * bl->bufunitsize > cap) {
		dev_info_ratelimited(bl->dev,
				     "memalloc %llu bytes: more than max_memalloc_mib allows (%llu MiB)\n",
				     n * bl->bufunitsize, cap >> 20);
		return -ENOMEM;
	}
	return bl_set_buffers(bl, n, bl->bufunitsize);
}

/*
 * The original's test pattern: incrementing 32-bit words over every buffer.
 * No capture runs (bl_settable()): the CPU takes each buffer before it
 * writes, and keeps it until the next capture hands every buffer to the
 * device (bl_start()), which discards nothing the reader wanted.
 */
static void bl_fill_test_pattern(struct beaglelogic *bl)
{
	u32 word = 0;
	unsigned int i, j;

	for (i = 0; i < bl->nbufs; i++) {
		u32 *p = bl->bufs[i].va;

		dma_sync_single_for_cpu(bl->dev, bl->bufs[i].dma, bl->bufunitsize,
					DMA_FROM_DEVICE);
		for (j = 0; j < bl->bufunitsize / 4; j++)
			p[j] = word++;
	}
}

/* --- settings, shared by the ioctls and sysfs; with @lock held ------------ */

static int bl_set_rate(struct beaglelogic *bl, u32 rate)
{
	if (!rate || rate > BL_MAX_RATE)
		return -EINVAL;
	bl->samplerate = BL_MAX_RATE / (BL_MAX_RATE / rate);
	return 0;
}

static int bl_set_unit(struct beaglelogic *bl, u32 unit)
{
	if (unit > BL_SAMPLEUNIT_8_BITS)
		return -EINVAL;
	bl->unit = unit;
	return 0;
}

static int bl_set_flags(struct beaglelogic *bl, u32 flags)
{
	if (flags > BL_TRIGGERFLAGS_CONTINUOUS)
		return -EINVAL;
	bl->flags = flags;
	return 0;
}

/* The original's rule: at least 32, rounded up to 32; the buffers go. */
static int bl_set_bufunit(struct beaglelogic *bl, u32 size)
{
	if (!size || size > BL_MAX_BUFUNIT)
		return -EINVAL;
	size = max_t(u32, round_up(size, BL_BLOCK_BYTES), BL_BLOCK_BYTES);
	return bl_set_buffers(bl, 0, size);
}

/* What the setters may not change: a running capture, a gone device. */
static int bl_settable(struct beaglelogic *bl)
{
	if (bl->gone)
		return -ENODEV;
	bl_update(bl);
	return bl->running ? -EBUSY : 0;
}

/* The original's state numbers */
static u32 bl_state(struct beaglelogic *bl)
{
	if (bl->running)
		return BL_STATE_RUNNING;
	if (bl->fw_error || bl->stopped)
		return BL_STATE_ERROR;
	if (bl->nbufs)
		return BL_STATE_ARMED;
	return BL_STATE_INITIALIZED;
}

/* --- /dev/beaglelogic ---------------------------------------------------- */

static struct beaglelogic *bl_from_misc(struct miscdevice *misc)
{
	return container_of(misc, struct beaglelogic, misc);
}

static int bl_open(struct inode *inode, struct file *file)
{
	/* misc_open() set private_data, and holds misc_mtx: no removal now */
	struct beaglelogic *bl = bl_from_misc(file->private_data);

	mutex_lock(&bl->lock);
	if (bl->gone) {
		mutex_unlock(&bl->lock);
		return -ENODEV;
	}
	kref_get(&bl->kref);
	/* the first opener's first read() starts a new capture */
	if (!bl->opens++)
		bl_rewind(bl);
	mutex_unlock(&bl->lock);
	file->private_data = bl;
	return 0;
}

static int bl_release(struct inode *inode, struct file *file)
{
	struct beaglelogic *bl = file->private_data;

	mutex_lock(&bl->lock);
	if (!--bl->opens && !bl->gone)
		bl_stop(bl);
	mutex_unlock(&bl->lock);
	bl_put(bl);
	return 0;
}

/* The reader's buffer (counted from the capture's start), and @off in it */
static u32 bl_index(struct beaglelogic *bl, u32 *off)
{
	u32 rem;
	u64 index = div_u64_rem(bl->rpos, bl->bufunitsize, &rem);

	if (off)
		*off = rem;
	return index;
}

/* How long a reader waits for the storer to answer a ping (bl_wait()) */
#define BL_PING_MS	2000

/*
 * A continuous capture's reader is done with the buffers from @from up to
 * @index: hand those the storer filled (bl_update() took them for the CPU)
 * back to the device, which refills each next time round the ring.  At
 * most a ring's worth: older ones are the same buffers again.
 */
static void bl_give_back(struct beaglelogic *bl, u32 from, u32 index)
{
	u32 n;

	if (bl->trig_on || bl->flags != BL_TRIGGERFLAGS_CONTINUOUS)
		return;
	if ((s32)(index - bl->synced) > 0)	/* not filled yet: the device's */
		index = bl->synced;
	if ((s32)(index - from) <= 0)
		return;
	for (n = min_t(u32, index - from, bl->nbufs); n; n--)
		dma_sync_single_for_device(bl->dev, bl->bufs[(index - n) % bl->nbufs].dma,
					   bl->bufunitsize, DMA_FROM_DEVICE);
}

/*
 * The reader's buffer holds data: filled, and not refilled since; with a
 * trigger, every buffer once the capture ended (the ring ran until then).
 */
static bool bl_ready(struct beaglelogic *bl, u32 index)
{
	if (bl->trig_on)
		return bl->fw_done && index < bl->nbufs;
	return (s32)(bl->filled - index) > 0;	/* the counters wrap */
}

/*
 * A continuous capture refills buffer @index % nbufs once the storer is
 * nbufs buffers further: the reader fell a whole ring behind.  Moves the
 * reader to the oldest buffer still intact.
 */
static bool bl_overrun(struct beaglelogic *bl, u32 index)
{
	u32 oldest;

	if (bl->flags != BL_TRIGGERFLAGS_CONTINUOUS || (s32)(bl->filled - index) < (s32)bl->nbufs)
		return false;
	/* the storer writes buffer @filled: @filled - nbufs + 1 is the oldest */
	oldest = bl->filled - bl->nbufs + 1;
	bl->lasterror = BL_ERR_OVERRUN | (index % bl->nbufs);
	bl->rpos = (u64)oldest * bl->bufunitsize;
	return true;
}

/*
 * Wait, with @lock held (dropped while asleep), until the reader's buffer
 * is full, the capture ended or failed.  A stopped core sends no event:
 * look again every 100 ms.
 */
static int bl_wait(struct beaglelogic *bl, bool nonblock)
{
	void __iomem *ping = bl->ctrl[BL_STORER] + offsetof(struct bl_ctrl, ping);
	void __iomem *pong = bl->ctrl[BL_STORER] + offsetof(struct bl_ctrl, pong);
	unsigned long asked = jiffies;
	u16 asking = readw(ping);

	for (;;) {
		u32 index = bl_index(bl, NULL);
		u32 seen;
		long ret;

		bl_update(bl);
		if (bl_ready(bl, index) || !bl->running)
			return 0;
		if (nonblock)
			return -EAGAIN;
		/*
		 * However slow the capture, a running storer answers a ping
		 * while it waits for a block (bl_store.S): one left unanswered
		 * is a halted or faulted core, which remoteproc does not see.
		 */
		if (readw(pong) == asking) {
			writew(++asking, ping);
			asked = jiffies;
		} else if (time_after(jiffies, asked + msecs_to_jiffies(BL_PING_MS))) {
			dev_err_ratelimited(bl->dev,
					    "the storer (PRU0) has not answered for %u ms: halted or faulted?\n",
					    BL_PING_MS);
			return -ETIMEDOUT;
		}
		seen = bl->filled;
		mutex_unlock(&bl->lock);
		ret = wait_event_interruptible_timeout(bl->wq, READ_ONCE(bl->filled) != seen ||
						       !READ_ONCE(bl->running) ||
						       READ_ONCE(bl->gone),
						       msecs_to_jiffies(100));
		mutex_lock(&bl->lock);
		if (ret < 0)
			return ret;
		if (bl->gone)
			return -ENODEV;
	}
}

static ssize_t bl_read(struct file *file, char __user *ubuf, size_t count, loff_t *ppos)
{
	struct beaglelogic *bl = file->private_data;
	u32 index, off;
	size_t n;
	int ret;

	ret = mutex_lock_interruptible(&bl->lock);
	if (ret)
		return ret;
	ret = bl_dead(bl);
	if (ret)
		goto unlock;
	if (!bl->started) {
		ret = bl_start(bl);
		if (ret)
			goto unlock;
	}
	ret = bl_wait(bl, file->f_flags & O_NONBLOCK);
	if (ret)
		goto unlock;
	index = bl_index(bl, &off);
	if (bl_overrun(bl, index)) {
		ret = -EIO;
		goto unlock;
	}
	if (!bl_ready(bl, index)) {
		/* the capture ended: all read (EOF), or failed */
		if (bl->fw_error)
			ret = -EIO;
		else if (bl->stopped)
			ret = -EPIPE;
		else
			ret = 0;
		goto unlock;
	}
	if (bl->trig_on) {
		/* from the trigger's block - trig_pre on, round the ring */
		u32 ring = bl->nbufs * bl->bufunitsize, at;

		div_u64_rem(bl->trig_start * bl_sample_bytes(bl) + bl->rpos, ring, &at);
		index = at / bl->bufunitsize;
		off = at % bl->bufunitsize;
		n = min_t(u64, min_t(size_t, count, bl->bufunitsize - off), ring - bl->rpos);
	} else {
		n = min_t(size_t, count, bl->bufunitsize - off);
	}
	if (copy_to_user(ubuf, bl->bufs[index % bl->nbufs].va + off, n)) {
		ret = -EFAULT;
		goto unlock;
	}
	/*
	 * The storer may have come round again while we copied: look at its
	 * count only after the copy's loads (rmb(): they are normal memory,
	 * the count device memory).
	 */
	rmb();
	bl_update(bl);
	if (bl_overrun(bl, index)) {
		ret = -EIO;
		goto unlock;
	}
	index = bl_index(bl, NULL);
	bl->rpos += n;
	bl_give_back(bl, index, bl_index(bl, NULL));
	*ppos = bl->rpos;
	mutex_unlock(&bl->lock);
	return n;

unlock:
	mutex_unlock(&bl->lock);
	return ret;
}

/* SEEK_SET 0 stops and rewinds; SEEK_CUR skips forward. */
static loff_t bl_llseek(struct file *file, loff_t offset, int whence)
{
	struct beaglelogic *bl = file->private_data;
	loff_t ret;

	mutex_lock(&bl->lock);
	if (bl->gone) {
		ret = -ENODEV;
	} else if (whence == SEEK_SET && offset == 0) {
		bl_rewind(bl);
		ret = 0;
	} else if (whence == SEEK_CUR && offset >= 0) {
		u64 total = (u64)bl->nbufs * bl->bufunitsize;

		/* one-shot: no further than the end; continuous: the ring wraps */
		if (bl->flags == BL_TRIGGERFLAGS_ONESHOT) {
			bl->rpos = min_t(u64, bl->rpos + min_t(u64, offset, total), total);
			ret = bl->rpos;
		} else if (offset > LLONG_MAX - (loff_t)bl->rpos) {
			ret = -EOVERFLOW;
		} else {
			u32 from = bl_index(bl, NULL);

			bl->rpos += offset;
			bl_give_back(bl, from, bl_index(bl, NULL));
			ret = bl->rpos;
		}
	} else {
		ret = -EINVAL;
	}
	if (ret >= 0)
		file->f_pos = ret;
	mutex_unlock(&bl->lock);
	return ret;
}

static __poll_t bl_poll(struct file *file, poll_table *wait)
{
	struct beaglelogic *bl = file->private_data;
	__poll_t mask = 0;

	poll_wait(file, &bl->wq, wait);
	mutex_lock(&bl->lock);
	if (bl_dead(bl)) {
		mask = EPOLLERR | EPOLLHUP;
	} else if (bl->started) {
		bl_update(bl);
		if (bl_ready(bl, bl_index(bl, NULL)) || !bl->running)
			mask = EPOLLIN | EPOLLRDNORM;
	}
	mutex_unlock(&bl->lock);
	return mask;
}

static long bl_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct beaglelogic *bl = file->private_data;
	u32 __user *uptr = (u32 __user *)arg;
	u32 val = arg;
	long ret = 0;

	mutex_lock(&bl->lock);
	switch (cmd) {
	case IOCTL_BL_GET_VERSION:
		ret = put_user(BL_DRV_VERSION, uptr);
		break;
	case IOCTL_BL_GET_SAMPLE_RATE:
		ret = put_user(bl->samplerate, uptr);
		break;
	case IOCTL_BL_GET_SAMPLE_UNIT:
		ret = put_user(bl->unit, uptr);
		break;
	case IOCTL_BL_GET_TRIGGER_FLAGS:
		ret = put_user(bl->flags, uptr);
		break;
	case IOCTL_BL_GET_CUR_INDEX:
		ret = put_user(bl->nbufs ? bl_index(bl, NULL) % bl->nbufs : 0, uptr);
		break;
	case IOCTL_BL_GET_BUFFER_SIZE:
		ret = put_user(bl->nbufs * bl->bufunitsize, uptr);
		break;
	case IOCTL_BL_GET_BUFUNIT_SIZE:
		ret = put_user(bl->bufunitsize, uptr);
		break;
	case IOCTL_BL_CACHE_INVALIDATE:
		/* every full buffer is synced for the CPU already */
		break;
	case IOCTL_BL_SET_SAMPLE_RATE:
		ret = bl_settable(bl) ?: bl_set_rate(bl, val);
		break;
	case IOCTL_BL_SET_SAMPLE_UNIT:
		ret = bl_settable(bl) ?: bl_set_unit(bl, val);
		break;
	case IOCTL_BL_SET_TRIGGER_FLAGS:
		ret = bl_settable(bl) ?: bl_set_flags(bl, val);
		break;
	case IOCTL_BL_SET_BUFFER_SIZE:
		ret = bl_settable(bl) ?: bl_memalloc(bl, val);
		break;
	case IOCTL_BL_SET_BUFUNIT_SIZE:
		ret = bl_settable(bl) ?: bl_set_bufunit(bl, val);
		break;
	case IOCTL_BL_FILL_TEST_PATTERN:
		ret = bl_settable(bl);
		if (!ret)
			bl_fill_test_pattern(bl);
		break;
	case IOCTL_BL_START:
		bl_rewind(bl);
		ret = bl_start(bl);
		break;
	case IOCTL_BL_STOP:
		bl_stop(bl);
		break;
	default:
		ret = -ENOTTY;
	}
	mutex_unlock(&bl->lock);
	return ret;
}

static void bl_vm_open(struct vm_area_struct *vma)
{
	struct beaglelogic *bl = vma->vm_private_data;

	mutex_lock(&bl->buf_lock);
	bl->maps++;
	mutex_unlock(&bl->buf_lock);
	kref_get(&bl->kref);
}

static void bl_vm_close(struct vm_area_struct *vma)
{
	struct beaglelogic *bl = vma->vm_private_data;

	mutex_lock(&bl->buf_lock);
	bl->maps--;
	mutex_unlock(&bl->buf_lock);
	bl_put(bl);
}

static const struct vm_operations_struct bl_vm_ops = {
	.open = bl_vm_open,
	.close = bl_vm_close,
};

/* Every buffer back to back from the mapping's start (the offset is ignored). */
static int bl_mmap(struct file *file, struct vm_area_struct *vma)
{
	struct beaglelogic *bl = file->private_data;
	unsigned long len = vma->vm_end - vma->vm_start, done = 0;
	struct page **pages;
	unsigned int i;
	int ret = 0;

	/*
	 * Read-only, for good: the PRU writes the buffers, and a CPU store
	 * would leave dirty cache lines that overwrite its data on eviction.
	 */
	if (vma->vm_flags & VM_WRITE)
		return -EPERM;
	prukit_vm_flags_clear(vma, VM_MAYWRITE);

	mutex_lock(&bl->buf_lock);
	if (!bl->nbufs || len > (unsigned long)bl->nbufs * bl->bufunitsize ||
	    !PAGE_ALIGNED(bl->bufunitsize)) {
		ret = -EINVAL;
		goto unlock;
	}
	/*
	 * The buffers are the page allocator's pages: mapped as pages (not as
	 * raw PFNs, VM_IO | VM_PFNMAP), what reads a process's memory through
	 * its pages (/proc/PID/mem, O_DIRECT I/O from the mapping) works.
	 */
	pages = kvmalloc_array(bl->bufunitsize >> PAGE_SHIFT, sizeof(*pages), GFP_KERNEL);
	if (!pages) {
		ret = -ENOMEM;
		goto unlock;
	}
	for (i = 0; done < len; i++) {
		unsigned long n = min_t(unsigned long, len - done, bl->bufunitsize) >> PAGE_SHIFT;
		unsigned long k, left = n;
		struct page *first = virt_to_page(bl->bufs[i].va);

		for (k = 0; k < n; k++)
			pages[k] = first + k;
		ret = vm_insert_pages(vma, vma->vm_start + done, pages, &left);
		if (ret)
			break;
		done += n << PAGE_SHIFT;
	}
	kvfree(pages);
	if (ret)
		goto unlock;
	vma->vm_private_data = bl;
	vma->vm_ops = &bl_vm_ops;
	bl->maps++;
	kref_get(&bl->kref);
unlock:
	mutex_unlock(&bl->buf_lock);
	return ret;
}

static const struct file_operations bl_fops = {
	.owner = THIS_MODULE,
	.open = bl_open,
	.release = bl_release,
	.read = bl_read,
	.llseek = bl_llseek,
	.poll = bl_poll,
	.unlocked_ioctl = bl_ioctl,
	.compat_ioctl = compat_ptr_ioctl,
	.mmap = bl_mmap,
};

/* --- sysfs: /sys/devices/virtual/misc/beaglelogic ------------------------ */

static struct beaglelogic *bl_from_dev(struct device *dev)
{
	return bl_from_misc(dev_get_drvdata(dev));
}

/* A setter attribute: parse a u32, call @set with @lock held. */
static ssize_t bl_store_u32(struct device *dev, const char *buf, size_t count,
			    int (*set)(struct beaglelogic *bl, u32 val))
{
	struct beaglelogic *bl = bl_from_dev(dev);
	u32 val;
	int ret;

	ret = kstrtou32(buf, 0, &val);
	if (ret)
		return ret;
	mutex_lock(&bl->lock);
	ret = bl_settable(bl) ?: set(bl, val);
	mutex_unlock(&bl->lock);
	return ret ?: count;
}

static ssize_t samplerate_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%u\n", READ_ONCE(bl_from_dev(dev)->samplerate));
}

static ssize_t samplerate_store(struct device *dev, struct device_attribute *attr,
				const char *buf, size_t count)
{
	return bl_store_u32(dev, buf, count, bl_set_rate);
}
static DEVICE_ATTR_RW(samplerate);

static ssize_t sampleunit_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	u32 unit = READ_ONCE(bl_from_dev(dev)->unit);

	return sysfs_emit(buf, "%u:%s\n", unit, unit == BL_SAMPLEUNIT_8_BITS ? "8bit" : "16bit");
}

static ssize_t sampleunit_store(struct device *dev, struct device_attribute *attr,
				const char *buf, size_t count)
{
	return bl_store_u32(dev, buf, count, bl_set_unit);
}
static DEVICE_ATTR_RW(sampleunit);

static ssize_t triggerflags_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	u32 flags = READ_ONCE(bl_from_dev(dev)->flags);

	return sysfs_emit(buf, "%u:%s\n", flags,
			  flags == BL_TRIGGERFLAGS_CONTINUOUS ? "continuous" : "oneshot");
}

static ssize_t triggerflags_store(struct device *dev, struct device_attribute *attr,
				  const char *buf, size_t count)
{
	return bl_store_u32(dev, buf, count, bl_set_flags);
}
static DEVICE_ATTR_RW(triggerflags);

static ssize_t bufunitsize_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%u\n", READ_ONCE(bl_from_dev(dev)->bufunitsize));
}

static ssize_t bufunitsize_store(struct device *dev, struct device_attribute *attr,
				 const char *buf, size_t count)
{
	return bl_store_u32(dev, buf, count, bl_set_bufunit);
}
static DEVICE_ATTR_RW(bufunitsize);

static ssize_t memalloc_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	u32 total;

	mutex_lock(&bl->lock);
	total = bl->nbufs * bl->bufunitsize;
	mutex_unlock(&bl->lock);
	return sysfs_emit(buf, "%u\n", total);
}

static ssize_t memalloc_store(struct device *dev, struct device_attribute *attr,
			      const char *buf, size_t count)
{
	return bl_store_u32(dev, buf, count, bl_memalloc);
}
static DEVICE_ATTR_RW(memalloc);

/* While a capture runs: wait for the reader's buffer, print its index. */
static ssize_t state_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	ssize_t ret;

	mutex_lock(&bl->lock);
	bl_update(bl);
	if (bl->running) {
		ret = bl_wait(bl, false);
		if (!ret)
			ret = sysfs_emit(buf, "%u\n", bl_index(bl, NULL) % bl->nbufs);
	} else {
		ret = sysfs_emit(buf, "%u\n", bl_state(bl));
	}
	mutex_unlock(&bl->lock);
	return ret;
}

static ssize_t state_store(struct device *dev, struct device_attribute *attr,
			   const char *buf, size_t count)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	u32 val;
	int ret;

	ret = kstrtou32(buf, 0, &val);
	if (ret)
		return ret;
	if (val > 1)
		return -EINVAL;
	mutex_lock(&bl->lock);
	if (val) {
		bl_rewind(bl);
		ret = bl_start(bl);
	} else {
		bl_stop(bl);
	}
	mutex_unlock(&bl->lock);
	return ret ?: count;
}
static DEVICE_ATTR_RW(state);

static ssize_t buffers_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	unsigned int i;
	int len = 0;

	mutex_lock(&bl->lock);
	for (i = 0; i < bl->nbufs; i++)
		len += sysfs_emit_at(buf, len, "%08llx,%u\n", (u64)bl->bufs[i].dma,
				     bl->bufunitsize);
	mutex_unlock(&bl->lock);
	return len;
}
static DEVICE_ATTR_ADMIN_RO(buffers);	/* bus addresses of kernel memory: root's */

static ssize_t lasterror_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	u32 err;

	mutex_lock(&bl->lock);
	bl_update(bl);
	err = bl->lasterror;
	mutex_unlock(&bl->lock);
	return sysfs_emit(buf, "%u\n", err);
}
static DEVICE_ATTR_RO(lasterror);

static ssize_t filltestpattern_store(struct device *dev, struct device_attribute *attr,
				     const char *buf, size_t count)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	u32 val;
	int ret;

	ret = kstrtou32(buf, 0, &val);
	if (ret)
		return ret;
	if (val != BL_FILL_TEST_PATTERN_MAGIC)
		return -EINVAL;
	mutex_lock(&bl->lock);
	ret = bl_settable(bl);
	if (!ret)
		bl_fill_test_pattern(bl);
	mutex_unlock(&bl->lock);
	return ret ?: count;
}
static DEVICE_ATTR_WO(filltestpattern);

/*
 * prukit's: the IEP counter at the first sample read() returns of the last
 * capture that ended (the sampler writes its first sample's when it stops;
 * a triggered capture's read() begins trig_start samples later, each
 * 2 * divisor cycles of the counter).
 */
static ssize_t first_sample_iep_show(struct device *dev, struct device_attribute *attr,
				     char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	ssize_t ret;
	u32 iep;

	mutex_lock(&bl->lock);
	ret = bl_dead(bl);
	if (!ret) {
		bl_update(bl);
		iep = bl_read_ctrl(bl, BL_SAMPLER, offsetof(struct bl_ctrl, first_iep));
		if (bl->trig_on && bl->trig_sample >= 0)
			iep += (u32)(bl->trig_start * 2 * bl->cap_div);
		ret = sysfs_emit(buf, "%u\n", iep);
	}
	mutex_unlock(&bl->lock);
	return ret;
}
static DEVICE_ATTR_RO(first_sample_iep);

/*
 * prukit's trigger: "none", "rising N", "falling N", "edge N" (channel N),
 * or "pattern MASK VALUE" (the channels in MASK equal to VALUE's).
 */
static ssize_t trigger_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	ssize_t ret;

	mutex_lock(&bl->lock);
	if (bl->trig_kind == BL_TRIGGER_NONE)
		ret = sysfs_emit(buf, "none\n");
	else if (bl->trig_kind == BL_TRIGGER_PATTERN)
		ret = sysfs_emit(buf, "pattern 0x%04x 0x%04x\n", bl->trig_mask, bl->trig_value);
	else
		ret = sysfs_emit(buf, "%s %u\n", bl_trig_names[bl->trig_kind], bl->trig_chan);
	mutex_unlock(&bl->lock);
	return ret;
}

static ssize_t trigger_store(struct device *dev, struct device_attribute *attr,
			     const char *buf, size_t count)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	int kind, n, ret, a = 0, b = 0;
	char word[8], extra;

	n = sscanf(buf, "%7s %i %i %c", word, &a, &b, &extra);
	kind = n >= 1 ? match_string(bl_trig_names, ARRAY_SIZE(bl_trig_names), word) : -EINVAL;
	if (kind < 0)
		return -EINVAL;
	/* an edge: its channel in a; a pattern: the mask in a, the value in b */
	if (kind == BL_TRIGGER_NONE ? n != 1 :
	    kind == BL_TRIGGER_PATTERN ? n != 3 || a <= 0 || a > 0xffff || b < 0 || b & ~a :
	    n != 2 || a < 0 || a >= BL_CHANNELS)
		return -EINVAL;
	mutex_lock(&bl->lock);
	ret = bl_settable(bl);
	if (!ret) {
		bl->trig_kind = kind;
		bl->trig_chan = kind == BL_TRIGGER_PATTERN ? 0 : a;
		bl->trig_mask = kind == BL_TRIGGER_PATTERN ? a : 0;
		bl->trig_value = kind == BL_TRIGGER_PATTERN ? b : 0;
	}
	mutex_unlock(&bl->lock);
	return ret ?: count;
}
static DEVICE_ATTR_RW(trigger);

/* No ring holds more samples than BL_MAX_BUFS full buffers of 8-bit ones. */
static int bl_set_pretrigger(struct beaglelogic *bl, u32 samples)
{
	if (samples > BL_MAX_BUFS * BL_MAX_BUFUNIT)
		return -EINVAL;
	bl->pretrigger = samples;
	return 0;
}

static ssize_t pretrigger_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%u\n", READ_ONCE(bl_from_dev(dev)->pretrigger));
}

static ssize_t pretrigger_store(struct device *dev, struct device_attribute *attr,
				const char *buf, size_t count)
{
	return bl_store_u32(dev, buf, count, bl_set_pretrigger);
}
static DEVICE_ATTR_RW(pretrigger);

/* prukit's: the trigger's sample in what read() returns, -1 if none yet */
static ssize_t trigger_sample_show(struct device *dev, struct device_attribute *attr,
				   char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	s64 n;

	mutex_lock(&bl->lock);
	bl_update(bl);
	n = bl->trig_on ? bl->trig_sample : -1;
	mutex_unlock(&bl->lock);
	return sysfs_emit(buf, "%lld\n", n);
}
static DEVICE_ATTR_RO(trigger_sample);

static struct attribute *bl_attrs[] = {
	&dev_attr_samplerate.attr,
	&dev_attr_sampleunit.attr,
	&dev_attr_triggerflags.attr,
	&dev_attr_bufunitsize.attr,
	&dev_attr_memalloc.attr,
	&dev_attr_state.attr,
	&dev_attr_buffers.attr,
	&dev_attr_lasterror.attr,
	&dev_attr_filltestpattern.attr,
	&dev_attr_first_sample_iep.attr,
	&dev_attr_trigger.attr,
	&dev_attr_pretrigger.attr,
	&dev_attr_trigger_sample.attr,
	NULL
};
ATTRIBUTE_GROUPS(bl);

/* --- probe and removal --------------------------------------------------- */

static int bl_boot(struct beaglelogic *bl, unsigned int core)
{
	void __iomem *ctrl;
	int ret;

	ret = prukit_pru_boot(bl->pru[core], NULL);
	if (ret)
		return ret;
	ctrl = prukit_pru_map(bl->pru[core], PRUKIT_CTRL_DA, sizeof(struct bl_ctrl));
	if (!ctrl)
		return -EPROTO;
	ret = prukit_pru_ctrl_check(bl->pru[core], ctrl, BL_MAGIC, BL_VERSION,
				    sizeof(struct bl_ctrl));
	if (ret)
		return ret;
	ret = prukit_pru_ctrl_wait_ready(bl->pru[core], ctrl, PRUKIT_PRU_TIMEOUT_MS);
	if (ret)
		return ret;
	bl->ctrl[core] = ctrl;
	return 0;
}

/* Before the cores go: no capture, no reader, no DMA into the buffers. */
static void bl_remove_action(void *data)
{
	struct beaglelogic *bl = data;
	unsigned int c, i;

	mutex_lock(&bl->lock);
	bl_stop(bl);
	WRITE_ONCE(bl->gone, true);
	for (c = 0; c < BL_CORES; c++) {
		bl->ctrl[c] = NULL;
		prukit_pru_shutdown(bl->pru[c]);
	}
	/* the pages stay until the last file or mapping goes */
	mutex_lock(&bl->buf_lock);
	for (i = 0; i < bl->nbufs; i++) {
		if (bl->bufs[i].mapped)
			dma_unmap_single(bl->dev, bl->bufs[i].dma, bl->bufunitsize,
					 DMA_FROM_DEVICE);
		bl->bufs[i].mapped = false;
	}
	mutex_unlock(&bl->buf_lock);
	mutex_unlock(&bl->lock);
	wake_up_interruptible(&bl->wq);
}

static void bl_misc_deregister(void *data)
{
	misc_deregister(data);
}

/*
 * First at unbind, before the misc device goes: misc_deregister() waits for
 * every sysfs call in progress, and a "state" read sleeps for as long as the
 * capture runs (days at low rates).  Stop the capture, mark the device gone
 * and wake every sleeper: they all end with -ENODEV.
 */
static void bl_unplug(void *data)
{
	struct beaglelogic *bl = data;

	mutex_lock(&bl->lock);
	bl_stop(bl);
	WRITE_ONCE(bl->gone, true);
	mutex_unlock(&bl->lock);
	wake_up_interruptible(&bl->wq);
}

static void bl_release_instance(void *data)
{
	atomic_set(&bl_taken, 0);
}

static int bl_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct beaglelogic *bl;
	unsigned int c;
	int irq, ret;

	if (atomic_cmpxchg(&bl_taken, 0, 1))
		return dev_err_probe(dev, -EBUSY, "only one beaglelogic device is supported\n");
	ret = devm_add_action_or_reset(dev, bl_release_instance, NULL);
	if (ret)
		return ret;

	bl = kzalloc(sizeof(*bl), GFP_KERNEL);
	if (!bl)
		return -ENOMEM;
	kref_init(&bl->kref);
	ret = devm_add_action_or_reset(dev, bl_put_action, bl);
	if (ret)
		return ret;
	bl->dev = dev;
	mutex_init(&bl->lock);
	mutex_init(&bl->buf_lock);
	init_waitqueue_head(&bl->wq);
	bl->samplerate = BL_MAX_RATE;
	bl->unit = BL_SAMPLEUNIT_8_BITS;
	bl->flags = BL_TRIGGERFLAGS_ONESHOT;
	bl->bufunitsize = BL_DEFAULT_BUFUNIT;
	platform_set_drvdata(pdev, bl);

	if (of_count_phandle_with_args(dev->of_node, "ti,prus", NULL) != BL_CORES)
		return dev_err_probe(dev, -EINVAL,
				     "\"ti,prus\" must list the storer's PRU, then the sampler's\n");
	for (c = 0; c < BL_CORES; c++) {
		bl->pru[c] = devm_prukit_pru_get(dev, c);
		if (IS_ERR(bl->pru[c]))
			return PTR_ERR(bl->pru[c]);
	}
	/* The storer strobes the system event the node maps (R31 reaches 16..31) */
	ret = prukit_pru_event(dev, "event");
	if (ret < 0)
		return ret;
	if (ret < 16 || ret > 31)
		return dev_err_probe(dev, -EINVAL,
				     "interrupt \"event\" is PRU system event %d: the PRU strobes only 16..31\n",
				     ret);
	bl->event = ret;
	irq = devm_prukit_pru_request_irq(dev, "event", NULL, bl_irq, 0, bl);
	if (irq < 0)
		return irq;

	ret = dma_set_mask_and_coherent(dev, DMA_BIT_MASK(32));
	if (ret)
		return dev_err_probe(dev, ret, "no 32-bit DMA\n");
	/* Registered after the cores: run before they are put. */
	ret = devm_add_action(dev, bl_remove_action, bl);
	if (ret)
		return ret;
	for (c = 0; c < BL_CORES; c++) {
		ret = bl_boot(bl, c);
		if (ret)
			return dev_err_probe(dev, ret, "the %s's firmware does not answer\n",
					     c == BL_STORER ? "storer" : "sampler");
	}
	/* A default so that dd works at once; memalloc changes it. */
	mutex_lock(&bl->lock);
	ret = bl_set_buffers(bl, BL_DEFAULT_BUFS, BL_DEFAULT_BUFUNIT);
	mutex_unlock(&bl->lock);
	if (ret)
		dev_warn(dev, "no memory for the default %u buffers (%d): set memalloc\n",
			 BL_DEFAULT_BUFS, ret);

	bl->misc.minor = MISC_DYNAMIC_MINOR;
	bl->misc.name = "beaglelogic";
	bl->misc.fops = &bl_fops;
	bl->misc.groups = bl_groups;
	/* root's, 0600: udev gives it a group (drivers/beaglelogic/udev) */
	ret = misc_register(&bl->misc);
	if (ret)
		return dev_err_probe(dev, ret, "cannot register /dev/beaglelogic\n");
	ret = devm_add_action_or_reset(dev, bl_misc_deregister, &bl->misc);
	if (ret)
		return ret;
	ret = devm_add_action_or_reset(dev, bl_unplug, bl);
	if (ret)
		return ret;
	dev_info(dev, "/dev/beaglelogic: %u buffers of %u bytes, PRU system event %u\n",
		 bl->nbufs, bl->bufunitsize, bl->event);
	return 0;
}

static const struct of_device_id bl_of_match[] = {
	{ .compatible = "prukit,beaglelogic" },
	{ }
};
MODULE_DEVICE_TABLE(of, bl_of_match);

static struct platform_driver bl_driver = {
	.probe = bl_probe,
	.driver = {
		.name = "beaglelogic",
		.of_match_table = bl_of_match,
	},
};
module_platform_driver(bl_driver);

PRUKIT_IMPORT_NS();
MODULE_DESCRIPTION("Logic analyzer on the BeagleBone's PRUs, compatible with BeagleLogic");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
