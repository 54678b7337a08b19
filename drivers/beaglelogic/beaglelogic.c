// SPDX-License-Identifier: GPL-2.0-only
/*
 * beaglelogic - a logic analyzer on the BeagleBone's PRUs, compatible with
 * the original BeagleLogic's /dev/beaglelogic
 *
 * One "prukit,beaglelogic" node: PRU0 (the storer) and PRU1 (the sampler)
 * in "ti,prus", running the beaglelogic firmware (beaglelogic_proto.h), and
 * the storer's event in "interrupts-extended".  PRU1 samples R31 bits 0..13
 * (8-bit units: 0..7) at 100 MHz / n, PRU0 writes the samples into a ring
 * of buffers in DDR and raises an event per full buffer.
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
 * CMA); each full buffer is synced for the CPU before a reader sees it.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/atomic.h>
#include <linux/device.h>
#include <linux/dma-mapping.h>
#include <linux/fs.h>
#include <linux/gfp.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/irq.h>
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

#define BL_STORER		0	/* PRU0, "ti,prus" entry 0 */
#define BL_SAMPLER		1	/* PRU1, entry 1 */
#define BL_CORES		2

#define BL_MAX_RATE		100000000u
/* A buffer is one allocation of contiguous pages: at most order 10. */
#define BL_MAX_BUFUNIT		(4u << 20)
#define BL_DEFAULT_BUFUNIT	(4u << 20)
#define BL_DEFAULT_BUFS		2
/* prukit's own version number of the interface, for IOCTL_BL_GET_VERSION */
#define BL_DRV_VERSION		0x00010002u
/* lasterror when a continuous reader fell a whole ring behind */
#define BL_ERR_OVERRUN		0x10000u

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
 * @stopped: a core stopped behind the driver's back: -EPIPE
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
	struct miscdevice misc;
};

/* libsigrok knows one analyzer, at one sysfs path: one instance. */
static atomic_t bl_taken = ATOMIC_INIT(0);

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
	for (i = 0; i < bl->nbufs; i++)
		dma_sync_single_for_device(bl->dev, bl->bufs[i].dma, bl->bufunitsize,
					   DMA_FROM_DEVICE);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, unit), bl->unit);
	bl_write_ctrl(bl, BL_STORER, offsetof(struct bl_ctrl, mode), bl->flags);
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
	bl_write_ctrl(bl, BL_SAMPLER, offsetof(struct bl_ctrl, divisor),
		      BL_MAX_RATE / bl->samplerate);
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

	if (n > BL_MAX_BUFS)
		return -EINVAL;
	return bl_set_buffers(bl, n, bl->bufunitsize);
}

/* The original's test pattern: incrementing 32-bit words over every buffer. */
static void bl_fill_test_pattern(struct beaglelogic *bl)
{
	u32 word = 0;
	unsigned int i, j;

	for (i = 0; i < bl->nbufs; i++) {
		u32 *p = bl->bufs[i].va;

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

/* The reader's buffer holds data: filled, and not refilled since. */
static bool bl_ready(struct beaglelogic *bl, u32 index)
{
	return bl->filled > index;
}

/*
 * A continuous capture refills buffer @index % nbufs once the storer is
 * nbufs buffers further: the reader fell a whole ring behind.  Moves the
 * reader to the oldest buffer still intact.
 */
static bool bl_overrun(struct beaglelogic *bl, u32 index)
{
	u32 oldest;

	if (bl->flags != BL_TRIGGERFLAGS_CONTINUOUS || bl->filled < index + bl->nbufs)
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
	for (;;) {
		u32 index = bl_index(bl, NULL);
		u32 seen;
		long ret;

		bl_update(bl);
		if (bl_ready(bl, index) || !bl->running)
			return 0;
		if (nonblock)
			return -EAGAIN;
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
	n = min_t(size_t, count, bl->bufunitsize - off);
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
	bl->rpos += n;
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

		bl->rpos += offset;
		if (bl->flags == BL_TRIGGERFLAGS_ONESHOT && bl->rpos > total)
			bl->rpos = total;
		ret = bl->rpos;
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
	unsigned int i;
	int ret = 0;

	mutex_lock(&bl->buf_lock);
	if (!bl->nbufs || len > (unsigned long)bl->nbufs * bl->bufunitsize ||
	    !PAGE_ALIGNED(bl->bufunitsize)) {
		ret = -EINVAL;
		goto unlock;
	}
	for (i = 0; done < len; i++) {
		unsigned long n = min_t(unsigned long, len - done, bl->bufunitsize);

		ret = remap_pfn_range(vma, vma->vm_start + done,
				      page_to_pfn(virt_to_page(bl->bufs[i].va)), n,
				      vma->vm_page_prot);
		if (ret)
			goto unlock;
		done += n;
	}
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
static DEVICE_ATTR_RO(buffers);

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
 * prukit's: the IEP counter at the first sample of the last capture that
 * ended (the sampler writes it when it stops).
 */
static ssize_t first_sample_iep_show(struct device *dev, struct device_attribute *attr,
				     char *buf)
{
	struct beaglelogic *bl = bl_from_dev(dev);
	ssize_t ret;

	mutex_lock(&bl->lock);
	ret = bl_dead(bl);
	if (!ret)
		ret = sysfs_emit(buf, "%u\n",
				 bl_read_ctrl(bl, BL_SAMPLER, offsetof(struct bl_ctrl, first_iep)));
	mutex_unlock(&bl->lock);
	return ret;
}
static DEVICE_ATTR_RO(first_sample_iep);

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

static void bl_release_instance(void *data)
{
	atomic_set(&bl_taken, 0);
}

static int bl_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct beaglelogic *bl;
	struct irq_data *d;
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
		return dev_err_probe(dev, -EINVAL, "\"ti,prus\" must name PRU0 and PRU1\n");
	for (c = 0; c < BL_CORES; c++) {
		bl->pru[c] = devm_prukit_pru_get(dev, c);
		if (IS_ERR(bl->pru[c]))
			return PTR_ERR(bl->pru[c]);
	}
	irq = devm_prukit_pru_request_irq(dev, "event", NULL, bl_irq, 0, bl);
	if (irq < 0)
		return irq;
	/* The storer strobes the system event the node maps: the IRQ's hwirq. */
	d = irq_get_irq_data(irq);
	if (!d || d->hwirq < 16 || d->hwirq > 31)
		return dev_err_probe(dev, -EINVAL,
				     "interrupt \"event\" is no PRU system event 16..31\n");
	bl->event = d->hwirq;

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
			return dev_err_probe(dev, ret, "PRU%u's firmware does not answer\n", c);
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
	bl->misc.mode = 0444;
	ret = misc_register(&bl->misc);
	if (ret)
		return dev_err_probe(dev, ret, "cannot register /dev/beaglelogic\n");
	ret = devm_add_action_or_reset(dev, bl_misc_deregister, &bl->misc);
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
