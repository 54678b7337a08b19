// SPDX-License-Identifier: GPL-2.0-only
/*
 * ws281x - WS281x (NeoPixel) LED strings on the BeagleBone's PRUs
 *
 * One "prukit,ws281x" node is a controller: one or two PRU cores ("ti,prus")
 * running the ws281x firmware, and up to 48 strings, each on an R30 output of
 * its core or on an AM335x GPIO pin ("gpios", owned through gpiolib; the
 * firmware writes the bank's SET/CLEARDATAOUT registers).  Each core sends
 * all its strings at once, bit slot by bit slot (ws281x_proto.h).
 *
 * Users see:
 *  - /dev/ws281xN: write() a whole frame (uapi/prukit/ws281x.h) or mmap()
 *    it and WS281X_IOC_COMMIT; a frame is converted (wire order, gamma,
 *    brightness) into each core's bit slots and queued; one frame is sent
 *    while at most one more waits, and a writer blocks (or gets -EAGAIN)
 *    until there is room;
 *  - a multicolor LED class device per "led@N" child of a string (one LED
 *    class device per colour where the kernel has no multicolor class);
 *  - sysfs attributes of the geometry and settings on the controller.
 *
 * Frames and LEDs compose in one user-format frame, the driver's copy: a
 * frame write replaces all of it, an LED write changes its pixel; either
 * shows the whole copy.  Documentation/ws281x.rst has the rest.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/bitops.h>
#include <linux/cdev.h>
#include <linux/ctype.h>
#include <linux/device.h>
#include <linux/delay.h>
#include <linux/dma-mapping.h>
#include <linux/fs.h>
#include <linux/gpio/consumer.h>
#include <linux/idr.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/kref.h>
#include <linux/led-class-multicolor.h>
#include <linux/leds.h>
#include <linux/mm.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/poll.h>
#include <linux/property.h>
#include <linux/remoteproc.h>
#include <linux/sched/signal.h>
#include <linux/slab.h>
#include <linux/uaccess.h>
#include <linux/vmalloc.h>
#include <linux/wait.h>

#include "compat.h"
#include "prukit_pru.h"
#include "uapi/prukit/ws281x.h"
#include "ws281x_conv.h"
#include "ws281x_proto.h"

#define WS281X_MAX_CORES	2
#define WS281X_MAX_STRINGS	48
#define WS281X_MAX_DEVICES	16
/* One core's slot buffer: 4 MiB holds 26214 RGB LEDs per string */
#define WS281X_MAX_BUF		(4u << 20)
/* led_compose_name()'s buffer: LED_MAX_NAME_SIZE of drivers/leds/leds.h */
#define WS281X_LED_NAME_SIZE	64

enum ws281x_color { WS281X_R, WS281X_G, WS281X_B, WS281X_W };

/**
 * struct ws281x_core - one PRU core and the frames it sends
 * @pru: the core
 * @ctrl: its control block while the firmware runs
 * @slots: its bit slots per frame (the longest string's bits)
 * @conv: how its slots are made from a frame (ws281x_conv.c)
 * @buf_size: bytes of each slot buffer
 * @buf: two slot buffers (non-coherent DMA memory: synced at each hand-over)
 * @dma: their bus addresses
 * @r30_mask: R30 bits of its strings
 * @gpio_mask: GPIO bits of its strings, per bank
 * @event: the system event of its "interrupts-extended" entry
 * @sync: WS281X_SYNC_*: in step with the other core (both drive GPIO pins)
 * @posted: frames posted (the next one goes into buf[@posted % 2])
 * @seq: sequence number of the last SHOW posted, 0 before the first
 */
struct ws281x_core {
	struct prukit_pru *pru;
	void __iomem *ctrl;
	unsigned int slots;
	struct ws281x_conv *conv;
	size_t buf_size;
	struct ws281x_slot *buf[2];
	dma_addr_t dma[2];
	u32 r30_mask;
	u32 gpio_mask[WS281X_GPIO_BANKS];
	u32 event;
	u32 sync;
	u64 posted;
	int seq;
};

/**
 * struct ws281x_led - one LED class device (or one per colour)
 * @ws: its controller
 * @mc: the multicolor device (CONFIG_LEDS_CLASS_MULTICOLOR)
 * @cdev: one colour's device otherwise
 * @subled: the multicolor device's channels
 * @color: the colour @cdev stands for, without multicolor
 * @string: its string
 * @pos: its position on the string
 */
struct ws281x_led {
	struct ws281x *ws;
	struct led_classdev_mc mc;
	struct led_classdev cdev;
	struct mc_subled subled[4];
	enum ws281x_color color;
	unsigned int string;
	unsigned int pos;
};

/**
 * struct ws281x - one controller
 * @dev: the platform device
 * @kref: the last reference (device, open file, mapping) frees it
 * @lock: serialises frames, settings and start/stop
 * @gone: the platform device was unbound: every call fails with -ENODEV
 * @stopped: a core crashed or restarted behind the driver's back: -EPIPE
 * @dirty: an LED changed the frame while no room was free: the next event
 *	shows it
 * @events: events received from the cores
 * @wq: woken by the cores' events, and when @gone is set
 * @cores: the cores
 * @ncores: how many
 * @strings: the strings, in frame order
 * @nstrings: how many
 * @max_leds: LEDs of the longest string
 * @bpl: bytes per LED in the user's frame: 3 (RGB), or 4 (RGBW)
 * @frame_size: bytes of the user's frame
 * @frame: the driver's user-format frame (vmalloc_user(): mmap()able)
 * @stage: a write()'s frame, copied (under @lock) before it replaces @frame
 * @lut: the user's lookup table (gamma), applied after @brightness
 * @brightness: global brightness, 0..255
 * @tab: what each value becomes on the wire: @lut of the value scaled by
 *	@brightness, as conversion uses it
 * @reset: cycles the outputs stay low after a frame
 * @shown: frames the PRUs completed (the first core's count)
 * @dropped: LED changes merged into a later frame (not shown on their own)
 * @minor: /dev/ws281x<@minor>
 * @cdev: the character device
 * @cdev_dev: its device
 */
struct ws281x {
	struct device *dev;
	struct kref kref;
	struct mutex lock;	/* protects everything below and the cores */
	bool gone;
	bool stopped;
	bool dirty;
	unsigned int events;
	wait_queue_head_t wq;
	struct ws281x_core cores[WS281X_MAX_CORES];
	unsigned int ncores;
	struct ws281x_string *strings;
	unsigned int nstrings;
	unsigned int max_leds;
	unsigned int bpl;
	size_t frame_size;
	u8 *frame;
	u8 *stage;
	u8 lut[256];
	u8 brightness;
	struct ws281x_tab tab;
	u32 reset;
	u64 shown;
	u64 dropped;
	int minor;
	struct cdev cdev;
	struct device cdev_dev;
};

static DEFINE_IDA(ws281x_minors);
static dev_t ws281x_devt;

static void ws281x_free(struct kref *kref)
{
	struct ws281x *ws = container_of(kref, struct ws281x, kref);

	vfree(ws->frame);
	kvfree(ws->stage);
	kfree(ws->strings);
	kfree(ws);
}

static void ws281x_put(struct ws281x *ws)
{
	kref_put(&ws->kref, ws281x_free);
}

static void ws281x_put_action(void *data)
{
	ws281x_put(data);
}

/* --- turning a frame into bit slots (ws281x_conv.c) ---------------------- */

static void ws281x_update_tab(struct ws281x *ws)
{
	ws281x_conv_tab(&ws->tab, ws->lut, ws->brightness);
}

/* --- the cores ----------------------------------------------------------- */

static bool ws281x_core_ok(struct ws281x_core *core)
{
	return core->ctrl && prukit_pru_running(core->pru);
}

/*
 * Whether every core took its last frame: then the next frame may be
 * posted (its buffer's previous frame is done, since a core takes a frame
 * only after the one before it).  Sets @stopped when a core stopped: every
 * core is looked at for that first, so that a writer waiting for a slow
 * core learns at once that another one stopped.  Called with @lock held.
 */
static bool ws281x_room(struct ws281x *ws)
{
	unsigned int c;

	for (c = 0; c < ws->ncores; c++) {
		if (!ws281x_core_ok(&ws->cores[c])) {
			ws->stopped = true;
			return true;
		}
	}
	for (c = 0; c < ws->ncores; c++) {
		struct ws281x_core *core = &ws->cores[c];

		if (core->seq && prukit_pru_ctrl_answer(core->ctrl, core->seq) < 0)
			return false;
	}
	return true;
}

/* Post the driver's frame to every core; caller checked ws281x_room(). */
static int ws281x_post(struct ws281x *ws)
{
	unsigned int c;
	int ret;

	for (c = 0; c < ws->ncores; c++) {
		struct ws281x_core *core = &ws->cores[c];
		unsigned int b = core->posted % 2;
		void __iomem *ctrl = core->ctrl;
		unsigned int i;

		dma_sync_single_for_cpu(ws->dev, core->dma[b], core->buf_size, DMA_TO_DEVICE);
		ws281x_convert(core->conv, &ws->tab, ws->frame, core->buf[b]);
		dma_sync_single_for_device(ws->dev, core->dma[b], core->buf_size, DMA_TO_DEVICE);

		writel(core->dma[b], ctrl + offsetof(struct ws281x_ctrl, frame));
		writel(core->slots, ctrl + offsetof(struct ws281x_ctrl, slots));
		writel(core->r30_mask, ctrl + offsetof(struct ws281x_ctrl, r30_mask));
		for (i = 0; i < WS281X_GPIO_BANKS; i++)
			writel(core->gpio_mask[i],
			       ctrl + offsetof(struct ws281x_ctrl, gpio_mask) + 4 * i);
		writel(ws->reset, ctrl + offsetof(struct ws281x_ctrl, reset));
		writel(core->event, ctrl + offsetof(struct ws281x_ctrl, event));
		writel(core->sync, ctrl + offsetof(struct ws281x_ctrl, sync));
		ret = prukit_pru_ctrl_post(core->pru, ctrl, WS281X_CMD_SHOW);
		if (ret < 0) {
			ws->stopped = true;
			return ret;
		}
		core->seq = ret;
		core->posted++;
	}
	return 0;
}

/* An error of the calls that need the PRUs, or 0 while they run. */
static int ws281x_dead(struct ws281x *ws)
{
	if (ws->gone)
		return -ENODEV;
	if (ws->stopped)
		return -EPIPE;
	return 0;
}

/*
 * How long a writer waits for room: the time of two frames (one being sent,
 * one waiting) plus slack for scheduling and, in the VM, the emulation.
 * A core that takes no frame for that long has halted or faulted behind
 * remoteproc's back.
 */
#define WS281X_WAIT_SLACK_MS	2000

static unsigned int ws281x_wait_ms(struct ws281x *ws)
{
	/* 1.25 us a bit, 8 bits a byte; @reset in 5 ns cycles */
	u64 ns = (u64)ws->max_leds * ws->bpl * 8 * 1250 + (u64)ws->reset * 5;

	return 2 * DIV_ROUND_UP_ULL(ns, NSEC_PER_MSEC) + WS281X_WAIT_SLACK_MS;
}

/*
 * Wait until there is room for a frame (one sent, at most one waiting), with
 * @lock held, which it drops while it sleeps.  An idle core takes a frame
 * at once but says so with no event: look again for a few hundred
 * microseconds first.  A core stopped behind the driver's back sends no
 * event either: look again every 100 ms.  A core that takes nothing within
 * ws281x_wait_ms(): -ETIMEDOUT.
 */
static int ws281x_wait_room(struct ws281x *ws, bool nonblock)
{
	unsigned int ms = ws281x_wait_ms(ws);
	unsigned long deadline = jiffies + msecs_to_jiffies(ms);
	unsigned int tries = 0;
	int ret;

	for (;;) {
		unsigned int seen = READ_ONCE(ws->events);

		ret = ws281x_dead(ws);
		if (ret)
			return ret;
		if (ws281x_room(ws))
			return ws281x_dead(ws);
		if (nonblock)
			return -EAGAIN;
		if (time_after(jiffies, deadline)) {
			dev_err_ratelimited(ws->dev,
					    "no PRU took a frame in %u ms: halted or faulted? (%llu frames shown)\n",
					    ms, ws->shown);
			return -ETIMEDOUT;
		}
		mutex_unlock(&ws->lock);
		if (tries++ < 5)
			usleep_range(100, 200);
		else
			ret = wait_event_interruptible_timeout(ws->wq,
							       READ_ONCE(ws->events) != seen ||
							       READ_ONCE(ws->gone),
							       msecs_to_jiffies(100));
		mutex_lock(&ws->lock);
		if (ret < 0)
			return ret;
	}
}

/* Show the driver's frame, waiting for room; with @lock held. */
static int ws281x_show(struct ws281x *ws, bool nonblock)
{
	int ret = ws281x_wait_room(ws, nonblock);

	if (ret)
		return ret;
	ws->dirty = false;
	return ws281x_post(ws);
}

/*
 * Every event means a core took a frame or finished one: wake writers, and
 * show what LEDs changed while no room was free.
 */
static irqreturn_t ws281x_irq(int irq, void *data)
{
	struct ws281x *ws = data;

	mutex_lock(&ws->lock);
	if (!ws->gone && ws281x_core_ok(&ws->cores[0]))
		WRITE_ONCE(ws->shown,
			   readl(ws->cores[0].ctrl + offsetof(struct ws281x_ctrl, frames)));
	if (ws->dirty && !ws281x_dead(ws) && ws281x_room(ws) && !ws281x_dead(ws)) {
		ws->dirty = false;
		ws281x_post(ws);
	}
	WRITE_ONCE(ws->events, ws->events + 1);
	mutex_unlock(&ws->lock);
	wake_up_interruptible(&ws->wq);
	return IRQ_HANDLED;
}

static int ws281x_start(struct ws281x *ws)
{
	unsigned int c;
	int ret;

	for (c = 0; c < ws->ncores; c++) {
		struct ws281x_core *core = &ws->cores[c];
		void __iomem *ctrl;

		ret = prukit_pru_boot(core->pru, NULL);
		if (ret)
			return ret;
		ctrl = prukit_pru_map(core->pru, PRUKIT_CTRL_DA, sizeof(struct ws281x_ctrl));
		if (!ctrl)
			return -EPROTO;
		ret = prukit_pru_ctrl_check(core->pru, ctrl, WS281X_MAGIC, WS281X_VERSION,
					    sizeof(struct ws281x_ctrl));
		if (ret)
			return ret;
		ret = prukit_pru_ctrl_wait_ready(core->pru, ctrl, PRUKIT_PRU_TIMEOUT_MS);
		if (ret)
			return ret;
		core->ctrl = ctrl;
		core->seq = 0;
		core->posted = 0;
	}
	return 0;
}

/*
 * Before the cores stop: all LEDs off, shown (bounded wait), so that a
 * removed driver leaves the strings dark rather than in a torn state.
 */
static void ws281x_blank(struct ws281x *ws)
{
	unsigned int c;

	if (ws->stopped || !ws->cores[0].ctrl)
		return;
	memset(ws->frame, 0, ws->frame_size);
	/* (ws281x_room() is true, and sets @stopped, once a core stopped) */
	if (prukit_pru_poll_timeout(ws->cores[0].pru, ws281x_room(ws), 2000,
				    PRUKIT_PRU_TIMEOUT_MS))
		return;
	if (ws->stopped || ws281x_post(ws))
		return;
	/* Done once each core counted every frame it was sent (the counts wrap). */
	for (c = 0; c < ws->ncores; c++) {
		struct ws281x_core *core = &ws->cores[c];
		void __iomem *frames = core->ctrl + offsetof(struct ws281x_ctrl, frames);

		if (prukit_pru_poll_timeout(core->pru,
					    (s32)(readl(frames) - (u32)core->posted) >= 0,
					    2000, PRUKIT_PRU_TIMEOUT_MS) == -ETIMEDOUT) {
			dev_warn(ws->dev, "PRU %s did not finish the blank frame\n",
				 dev_name(&core->pru->rproc->dev));
			return;
		}
	}
}

static void ws281x_stop(void *data)
{
	struct ws281x *ws = data;
	unsigned int c;

	mutex_lock(&ws->lock);
	ws281x_blank(ws);
	WRITE_ONCE(ws->gone, true);
	for (c = 0; c < ws->ncores; c++) {
		ws->cores[c].ctrl = NULL;
		prukit_pru_shutdown(ws->cores[c].pru);
	}
	mutex_unlock(&ws->lock);
	wake_up_interruptible(&ws->wq);
}

/* --- /dev/ws281xN -------------------------------------------------------- */

static int ws281x_open(struct inode *inode, struct file *file)
{
	struct ws281x *ws = container_of(inode->i_cdev, struct ws281x, cdev);

	kref_get(&ws->kref);
	file->private_data = ws;
	return nonseekable_open(inode, file);
}

static int ws281x_release(struct inode *inode, struct file *file)
{
	ws281x_put(file->private_data);
	return 0;
}

static ssize_t ws281x_write(struct file *file, const char __user *buf, size_t len, loff_t *ppos)
{
	struct ws281x *ws = file->private_data;
	int ret;

	if (len != ws->frame_size)
		return -EINVAL;
	ret = mutex_lock_interruptible(&ws->lock);
	if (ret)
		return ret;
	ret = ws281x_dead(ws);
	if (ret)
		goto unlock;
	/*
	 * Room first, then the frame changes: what waits is not torn.  The
	 * copy comes after the wait, which drops @lock: another writer may
	 * use @stage meanwhile.  A faulting copy leaves the frame as it was.
	 */
	ret = ws281x_wait_room(ws, file->f_flags & O_NONBLOCK);
	if (ret)
		goto unlock;
	if (copy_from_user(ws->stage, buf, len)) {
		ret = -EFAULT;
		goto unlock;
	}
	memcpy(ws->frame, ws->stage, len);
	ws->dirty = false;
	ret = ws281x_post(ws);
unlock:
	mutex_unlock(&ws->lock);
	return ret ?: len;
}

static __poll_t ws281x_poll(struct file *file, poll_table *wait)
{
	struct ws281x *ws = file->private_data;
	__poll_t mask = 0;

	poll_wait(file, &ws->wq, wait);
	mutex_lock(&ws->lock);
	if (ws281x_dead(ws))
		mask = EPOLLERR | EPOLLHUP;
	else if (ws281x_room(ws))
		mask = EPOLLOUT | EPOLLWRNORM;
	mutex_unlock(&ws->lock);
	return mask;
}

static long ws281x_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct ws281x *ws = file->private_data;
	int ret;

	if (cmd != WS281X_IOC_COMMIT)
		return -ENOTTY;
	ret = mutex_lock_interruptible(&ws->lock);
	if (ret)
		return ret;
	ret = ws281x_show(ws, file->f_flags & O_NONBLOCK);
	mutex_unlock(&ws->lock);
	return ret;
}

static void ws281x_vm_open(struct vm_area_struct *vma)
{
	struct ws281x *ws = vma->vm_private_data;

	kref_get(&ws->kref);
}

static void ws281x_vm_close(struct vm_area_struct *vma)
{
	ws281x_put(vma->vm_private_data);
}

static const struct vm_operations_struct ws281x_vm_ops = {
	.open = ws281x_vm_open,
	.close = ws281x_vm_close,
};

static int ws281x_mmap(struct file *file, struct vm_area_struct *vma)
{
	struct ws281x *ws = file->private_data;
	int ret;

	if (vma->vm_pgoff || vma->vm_end - vma->vm_start > PAGE_ALIGN(ws->frame_size))
		return -EINVAL;
	ret = remap_vmalloc_range(vma, ws->frame, 0);
	if (ret)
		return ret;
	vma->vm_private_data = ws;
	vma->vm_ops = &ws281x_vm_ops;
	ws281x_vm_open(vma);
	return 0;
}

static const struct file_operations ws281x_fops = {
	.owner = THIS_MODULE,
	.open = ws281x_open,
	.release = ws281x_release,
	.write = ws281x_write,
	.poll = ws281x_poll,
	.unlocked_ioctl = ws281x_ioctl,
	.compat_ioctl = compat_ptr_ioctl,
	.mmap = ws281x_mmap,
};

/* --- sysfs --------------------------------------------------------------- */

static ssize_t strings_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%u\n", ws->nstrings);
}
static DEVICE_ATTR_RO(strings);

static ssize_t leds_per_string_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%u\n", ws->max_leds);
}
static DEVICE_ATTR_RO(leds_per_string);

static ssize_t bytes_per_led_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%u\n", ws->bpl);
}
static DEVICE_ATTR_RO(bytes_per_led);

static ssize_t frames_shown_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%llu\n", READ_ONCE(ws->shown));
}
static DEVICE_ATTR_RO(frames_shown);

static ssize_t frames_dropped_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%llu\n", READ_ONCE(ws->dropped));
}
static DEVICE_ATTR_RO(frames_dropped);

static ssize_t brightness_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%u\n", ws->brightness);
}

static ssize_t brightness_store(struct device *dev, struct device_attribute *attr,
				const char *buf, size_t len)
{
	struct ws281x *ws = dev_get_drvdata(dev);
	u8 v;
	int ret;

	ret = kstrtou8(buf, 0, &v);
	if (ret)
		return ret;
	mutex_lock(&ws->lock);
	ws->brightness = v;
	ws281x_update_tab(ws);
	mutex_unlock(&ws->lock);
	return len;
}
static DEVICE_ATTR_RW(brightness);

/* The lookup table: 256 values 0..255, separated by white space. */
static ssize_t lut_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);
	int i, n = 0;

	mutex_lock(&ws->lock);
	for (i = 0; i < 256; i++)
		n += sysfs_emit_at(buf, n, "%u%c", ws->lut[i], i % 16 == 15 ? '\n' : ' ');
	mutex_unlock(&ws->lock);
	return n;
}

static ssize_t lut_store(struct device *dev, struct device_attribute *attr,
			 const char *buf, size_t len)
{
	struct ws281x *ws = dev_get_drvdata(dev);
	const char *p = buf;
	u8 lut[256];
	int i;

	for (i = 0; i < 256; i++) {
		unsigned int v;
		int n;

		if (sscanf(p, " %u%n", &v, &n) != 1 || v > 255)
			return -EINVAL;
		lut[i] = v;
		p += n;
	}
	while (isspace(*p))
		p++;
	if (*p)
		return -EINVAL;
	mutex_lock(&ws->lock);
	memcpy(ws->lut, lut, sizeof(lut));
	ws281x_update_tab(ws);
	mutex_unlock(&ws->lock);
	return len;
}
static DEVICE_ATTR_RW(lut);

static ssize_t reset_us_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct ws281x *ws = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%u\n", ws->reset / 200);
}

static ssize_t reset_us_store(struct device *dev, struct device_attribute *attr,
			      const char *buf, size_t len)
{
	struct ws281x *ws = dev_get_drvdata(dev);
	unsigned int us;
	int ret;

	ret = kstrtouint(buf, 0, &us);
	if (ret)
		return ret;
	if (us < WS281X_RESET_MIN / 200 || us > 100000)
		return -ERANGE;
	mutex_lock(&ws->lock);
	ws->reset = us * 200;
	mutex_unlock(&ws->lock);
	return len;
}
static DEVICE_ATTR_RW(reset_us);

static struct attribute *ws281x_attrs[] = {
	&dev_attr_strings.attr,
	&dev_attr_leds_per_string.attr,
	&dev_attr_bytes_per_led.attr,
	&dev_attr_frames_shown.attr,
	&dev_attr_frames_dropped.attr,
	&dev_attr_brightness.attr,
	&dev_attr_lut.attr,
	&dev_attr_reset_us.attr,
	NULL
};
ATTRIBUTE_GROUPS(ws281x);

/* --- LED class devices ------------------------------------------------------ */

static u8 *ws281x_pixel(struct ws281x *ws, struct ws281x_led *led)
{
	return ws->frame + ((size_t)led->string * ws->max_leds + led->pos) * ws->bpl;
}

/*
 * An LED write changes its pixel in the driver's frame and shows the frame
 * if there is room; otherwise the frame is shown at the next event, with
 * whatever else changed by then (triggers such as timer write often): the
 * merged change is counted in frames_dropped.  LED writes never block and
 * never fail once the PRUs stopped: the LED core has no use for the error.
 */
static void ws281x_led_show(struct ws281x *ws)
{
	if (ws281x_dead(ws))
		return;
	if (ws281x_room(ws) && !ws281x_dead(ws)) {
		ws->dirty = false;
		ws281x_post(ws);
		return;
	}
	if (ws->dirty)
		WRITE_ONCE(ws->dropped, ws->dropped + 1);
	ws->dirty = true;
}

static int ws281x_mc_set(struct led_classdev *cdev, enum led_brightness value)
{
	struct led_classdev_mc *mc = lcdev_to_mccdev(cdev);
	struct ws281x_led *led = container_of(mc, struct ws281x_led, mc);
	struct ws281x *ws = led->ws;
	unsigned int i;

	led_mc_calc_color_components(mc, value);
	mutex_lock(&ws->lock);
	for (i = 0; i < mc->num_colors; i++)
		ws281x_pixel(ws, led)[mc->subled_info[i].channel] = mc->subled_info[i].brightness;
	ws281x_led_show(ws);
	mutex_unlock(&ws->lock);
	return 0;
}

static int ws281x_color_set(struct led_classdev *cdev, enum led_brightness value)
{
	struct ws281x_led *led = container_of(cdev, struct ws281x_led, cdev);
	struct ws281x *ws = led->ws;

	mutex_lock(&ws->lock);
	ws281x_pixel(ws, led)[led->color] = value;
	ws281x_led_show(ws);
	mutex_unlock(&ws->lock);
	return 0;
}

static const char * const ws281x_color_names[] = { "red", "green", "blue", "white" };
static const int ws281x_color_ids[] = {
	LED_COLOR_ID_RED, LED_COLOR_ID_GREEN, LED_COLOR_ID_BLUE, LED_COLOR_ID_WHITE,
};

/*
 * Without the multicolor class (Debian's 5.10): one LED class device per
 * colour, named as the LED would be with that colour: "rgb:status-0"
 * becomes "red:status-0", "green:status-0" and "blue:status-0" (a "label"
 * gets "-red" ... appended).
 */
static int ws281x_led_register_plain(struct ws281x *ws, struct fwnode_handle *fw,
				     unsigned int string, unsigned int pos, unsigned int ncolors)
{
	struct led_init_data init = { .fwnode = fw };
	char name[WS281X_LED_NAME_SIZE];
	const char *trigger = NULL, *rest;
	unsigned int k;
	int ret;

	ret = led_compose_name(ws->dev, &init, name);
	if (ret)
		return dev_err_probe(ws->dev, ret, "%pfw: no name for the LED\n", fw);
	rest = strncmp(name, "rgb:", 4) ? NULL : name + 4;
	fwnode_property_read_string(fw, "linux,default-trigger", &trigger);
	for (k = 0; k < ncolors; k++) {
		struct ws281x_led *led;

		led = devm_kzalloc(ws->dev, sizeof(*led), GFP_KERNEL);
		if (!led)
			return -ENOMEM;
		led->ws = ws;
		led->string = string;
		led->pos = pos;
		led->color = k;
		led->cdev.name = rest ?
			devm_kasprintf(ws->dev, GFP_KERNEL, "%s:%s", ws281x_color_names[k], rest) :
			devm_kasprintf(ws->dev, GFP_KERNEL, "%s-%s", name, ws281x_color_names[k]);
		if (!led->cdev.name)
			return -ENOMEM;
		led->cdev.max_brightness = LED_FULL;
		led->cdev.brightness_set_blocking = ws281x_color_set;
		led->cdev.default_trigger = trigger;
		ret = devm_led_classdev_register(ws->dev, &led->cdev);
		if (ret)
			return dev_err_probe(ws->dev, ret, "cannot register LED %s\n",
					     led->cdev.name);
	}
	return 0;
}

static int ws281x_led_register(struct ws281x *ws, struct fwnode_handle *fw,
			       unsigned int string, unsigned int pos, unsigned int ncolors)
{
	struct led_init_data init = { .fwnode = fw };
	struct ws281x_led *led;
	unsigned int k;
	int ret;

	if (!IS_ENABLED(CONFIG_LEDS_CLASS_MULTICOLOR))
		return ws281x_led_register_plain(ws, fw, string, pos, ncolors);

	led = devm_kzalloc(ws->dev, sizeof(*led), GFP_KERNEL);
	if (!led)
		return -ENOMEM;
	led->ws = ws;
	led->string = string;
	led->pos = pos;
	for (k = 0; k < ncolors; k++) {
		led->subled[k].color_index = ws281x_color_ids[k];
		led->subled[k].channel = k;
		led->subled[k].intensity = LED_FULL;
	}
	led->mc.subled_info = led->subled;
	led->mc.num_colors = ncolors;
	led->mc.led_cdev.max_brightness = LED_FULL;
	led->mc.led_cdev.brightness_set_blocking = ws281x_mc_set;
	ret = devm_led_classdev_multicolor_register_ext(ws->dev, &led->mc, &init);
	if (ret)
		return dev_err_probe(ws->dev, ret, "cannot register the LED of %pfw\n", fw);
	return 0;
}

/* --- probe ----------------------------------------------------------------- */

/* Chips and their wire order (indices into R, G, B, W) */
static const struct {
	const char *name;
	const char *order;
} ws281x_chips[] = {
	{ "ws2811", "rgb" },
	{ "ws2812", "grb" },
	{ "ws2812b", "grb" },
	{ "sk6812", "grb" },
	{ "sk6812-rgbw", "grbw" },
};

static int ws281x_parse_order(struct ws281x_string *st, const char *order)
{
	static const char letters[] = "rgbw";
	unsigned int n = strlen(order), k, seen = 0;

	if (n != 3 && n != 4)
		return -EINVAL;
	for (k = 0; k < n; k++) {
		const char *l = strchr(letters, order[k]);

		if (!order[k] || !l || l - letters >= n || seen & BIT(l - letters))
			return -EINVAL;
		seen |= BIT(l - letters);
		st->order[k] = l - letters;
	}
	st->bpl = n;
	return 0;
}

static int ws281x_parse_output(struct ws281x *ws, struct fwnode_handle *fw,
			       struct ws281x_string *st, unsigned int idx)
{
	struct device *dev = ws->dev;
	struct device_node *np = to_of_node(fw);
	struct of_phandle_args args;
	struct gpio_desc *gpiod;
	int bank, ret;
	u32 bit;

	if (!fwnode_property_read_u32(fw, "prukit,r30-bit", &bit)) {
		if (bit > 31)
			return dev_err_probe(dev, -EINVAL, "%pfw: R30 bit %u\n", fw, bit);
		st->bit = bit;
		return 0;
	}
	ret = of_parse_phandle_with_args(np, "gpios", "#gpio-cells", 0, &args);
	if (ret)
		return dev_err_probe(dev, -EINVAL,
				     "%pfw: neither \"prukit,r30-bit\" nor \"gpios\"\n", fw);
	bank = prukit_pru_gpio_bank(args.np);
	of_node_put(args.np);
	if (bank < 0 || args.args_count < 1 || args.args[0] > 31)
		return dev_err_probe(dev, -EINVAL,
				     "%pfw: \"gpios\" is no pin of an AM335x GPIO bank\n", fw);
	/* Owned through gpiolib: nothing else claims it, the bank stays on. */
	gpiod = devm_fwnode_gpiod_get_index(dev, fw, NULL, 0, GPIOD_OUT_LOW,
					    devm_kasprintf(dev, GFP_KERNEL, "ws281x string %u",
							   idx));
	if (IS_ERR(gpiod))
		return dev_err_probe(dev, PTR_ERR(gpiod), "%pfw: cannot take its GPIO\n", fw);
	st->gpio = true;
	st->bank = bank;
	st->bit = args.args[0];
	return 0;
}

static int ws281x_parse_string(struct ws281x *ws, struct fwnode_handle *fw,
			       struct ws281x_string *st, unsigned int idx)
{
	struct device *dev = ws->dev;
	const char *chip = "ws2812b", *order = NULL;
	unsigned int k;

	if (fwnode_property_read_u32(fw, "prukit,led-count", &st->leds) || !st->leds)
		return dev_err_probe(dev, -EINVAL, "%pfw: no \"prukit,led-count\"\n", fw);
	fwnode_property_read_u32(fw, "prukit,pru", &st->core);
	if (st->core >= ws->ncores)
		return dev_err_probe(dev, -EINVAL,
				     "%pfw: \"prukit,pru\" %u, but %u in \"ti,prus\"\n",
				     fw, st->core, ws->ncores);
	fwnode_property_read_string(fw, "prukit,chip", &chip);
	for (k = 0; k < ARRAY_SIZE(ws281x_chips); k++)
		if (!strcmp(chip, ws281x_chips[k].name))
			order = ws281x_chips[k].order;
	if (!order)
		return dev_err_probe(dev, -EINVAL, "%pfw: unknown chip \"%s\"\n", fw, chip);
	fwnode_property_read_string(fw, "prukit,color-order", &order);
	if (ws281x_parse_order(st, order))
		return dev_err_probe(dev, -EINVAL, "%pfw: bad color order \"%s\"\n", fw, order);
	if ((u64)st->leds * st->bpl * 8 > WS281X_MAX_SLOTS ||
	    (u64)st->leds * st->bpl * 8 * sizeof(struct ws281x_slot) > WS281X_MAX_BUF)
		return dev_err_probe(dev, -EINVAL,
				     "%pfw: %u LEDs do not fit the PRU's frame buffer (at most %zu)\n",
				     fw, st->leds,
				     WS281X_MAX_BUF / (st->bpl * 8 * sizeof(struct ws281x_slot)));
	return ws281x_parse_output(ws, fw, st, idx);
}

static bool ws281x_any(const u32 *gpio_mask)
{
	return gpio_mask[0] | gpio_mask[1] | gpio_mask[2] | gpio_mask[3];
}

static int ws281x_parse(struct ws281x *ws)
{
	struct device *dev = ws->dev;
	struct fwnode_handle *fw;
	unsigned int n = 0, c, s;
	u32 reg;
	int ret;

	ws->nstrings = device_get_child_node_count(dev);
	if (!ws->nstrings || ws->nstrings > WS281X_MAX_STRINGS)
		return dev_err_probe(dev, -EINVAL, "%u strings; 1 to %u are supported\n",
				     ws->nstrings, WS281X_MAX_STRINGS);
	ws->strings = kcalloc(ws->nstrings, sizeof(*ws->strings), GFP_KERNEL);
	if (!ws->strings)
		return -ENOMEM;
	/* reg is the string's place in the frame: 0..N-1, each once. */
	device_for_each_child_node(dev, fw) {
		if (fwnode_property_read_u32(fw, "reg", &reg) || reg >= ws->nstrings ||
		    ws->strings[reg].leds) {
			fwnode_handle_put(fw);
			return dev_err_probe(dev, -EINVAL,
					     "%pfw: \"reg\" must number the strings 0..%u, once each\n",
					     fw, ws->nstrings - 1);
		}
		ret = ws281x_parse_string(ws, fw, &ws->strings[reg], reg);
		if (ret) {
			fwnode_handle_put(fw);
			return ret;
		}
		n++;
	}
	ws->bpl = 3;
	for (s = 0; s < ws->nstrings; s++) {
		struct ws281x_string *st = &ws->strings[s];
		struct ws281x_core *core = &ws->cores[st->core];
		u32 *mask = st->gpio ? &core->gpio_mask[st->bank] : &core->r30_mask;

		if (*mask & BIT(st->bit))
			return dev_err_probe(dev, -EINVAL,
					     "string %u: its output is another string's\n", s);
		*mask |= BIT(st->bit);
		ws->max_leds = max(ws->max_leds, st->leds);
		ws->bpl = max(ws->bpl, st->bpl);
		core->slots = max(core->slots, st->leds * st->bpl * 8);
	}
	for (c = 0; c < ws->ncores; c++)
		if (!ws->cores[c].slots)
			return dev_err_probe(dev, -EINVAL,
					     "PRU %u in \"ti,prus\" drives no string\n", c);
	/*
	 * Both cores writing GPIO banks share the OCP master port: they run
	 * in step, PRU0 (first in "ti,prus") leading (ws281x_proto.h).
	 */
	if (ws->ncores == 2 && ws281x_any(ws->cores[0].gpio_mask) &&
	    ws281x_any(ws->cores[1].gpio_mask)) {
		ws->cores[0].sync = WS281X_SYNC_LEADER;
		ws->cores[1].sync = WS281X_SYNC_FOLLOWER;
	}
	ws->frame_size = (size_t)ws->nstrings * ws->max_leds * ws->bpl;
	return 0;
}

static int ws281x_leds(struct ws281x *ws)
{
	struct fwnode_handle *fw, *child;
	u32 reg, pos;
	int ret;

	device_for_each_child_node(ws->dev, fw) {
		fwnode_property_read_u32(fw, "reg", &reg);
		fwnode_for_each_child_node(fw, child) {
			if (fwnode_property_read_u32(child, "reg", &pos) ||
			    pos >= ws->strings[reg].leds) {
				ret = dev_err_probe(ws->dev, -EINVAL,
						    "%pfw: \"reg\" is no position on the string\n",
						    child);
				goto put;
			}
			ret = ws281x_led_register(ws, child, reg, pos, ws->strings[reg].bpl);
			if (ret)
				goto put;
		}
	}
	return 0;
put:
	fwnode_handle_put(child);
	fwnode_handle_put(fw);
	return ret;
}

static void ws281x_free_bufs(void *data)
{
	struct ws281x_core *core = data;
	struct device *dev = core->pru->dev;
	unsigned int b;

	for (b = 0; b < 2; b++)
		if (core->buf[b])
			prukit_dma_free_noncoherent(dev, core->buf_size, core->buf[b],
						    core->dma[b], DMA_TO_DEVICE);
	kvfree(core->conv);
}

static int ws281x_core_init(struct ws281x *ws, unsigned int c)
{
	struct ws281x_core *core = &ws->cores[c];
	struct device *dev = ws->dev;
	char name[8];
	unsigned int b;
	int irq, ret;

	core->pru = devm_prukit_pru_get(dev, c);
	if (IS_ERR(core->pru))
		return PTR_ERR(core->pru);
	core->buf_size = (size_t)core->slots * sizeof(struct ws281x_slot);
	ret = devm_add_action(dev, ws281x_free_bufs, core);
	if (ret)
		return ret;
	core->conv = kvzalloc(ws281x_conv_size(ws->strings, ws->nstrings, c), GFP_KERNEL);
	if (!core->conv)
		return -ENOMEM;
	ws281x_conv_init(core->conv, ws->strings, ws->nstrings, c, ws->max_leds, ws->bpl);
	for (b = 0; b < 2; b++) {
		core->buf[b] = prukit_dma_alloc_noncoherent(dev, core->buf_size, &core->dma[b],
							    DMA_TO_DEVICE);
		if (!core->buf[b])
			return dev_err_probe(dev, -ENOMEM, "no DMA memory for %zu-byte frames\n",
					     core->buf_size);
	}
	snprintf(name, sizeof(name), "event%u", c);
	/* The PRU strobes the system event the node maps (R31 reaches 16..31) */
	ret = prukit_pru_event(dev, name);
	if (ret < 0)
		return ret;
	if (ret < 16 || ret > 31)
		return dev_err_probe(dev, -EINVAL,
				     "interrupt %s is PRU system event %d: the PRU strobes only 16..31\n",
				     name, ret);
	core->event = ret;
	irq = devm_prukit_pru_request_irq(dev, name, NULL, ws281x_irq, 0, ws);
	return irq < 0 ? irq : 0;
}

static void ws281x_cdev_release(struct device *dev)
{
	struct ws281x *ws = container_of(dev, struct ws281x, cdev_dev);

	ida_free(&ws281x_minors, ws->minor);
	ws281x_put(ws);
}

static struct class ws281x_class = {
	.name = "ws281x",
};

static void ws281x_cdev_del(void *data)
{
	struct ws281x *ws = data;

	cdev_device_del(&ws->cdev, &ws->cdev_dev);
	put_device(&ws->cdev_dev);
}

static int ws281x_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct ws281x *ws;
	unsigned int c;
	int ret, n;

	ws = kzalloc(sizeof(*ws), GFP_KERNEL);
	if (!ws)
		return -ENOMEM;
	kref_init(&ws->kref);
	ret = devm_add_action_or_reset(dev, ws281x_put_action, ws);
	if (ret)
		return ret;
	ws->dev = dev;
	mutex_init(&ws->lock);
	init_waitqueue_head(&ws->wq);
	platform_set_drvdata(pdev, ws);

	BUILD_BUG_ON(WS281X_GPIO_BANKS != PRUKIT_PRU_GPIO_BANKS);
	/* ws281x_convert() writes the slots as words */
	BUILD_BUG_ON(sizeof(struct ws281x_slot) != WS281X_SLOT_WORDS * sizeof(u32));
	n = of_count_phandle_with_args(dev->of_node, "ti,prus", NULL);
	if (n < 1 || n > WS281X_MAX_CORES)
		return dev_err_probe(dev, -EINVAL,
				     "\"ti,prus\" names %d cores; 1 or 2 are supported\n", n);
	ws->ncores = n;
	ret = ws281x_parse(ws);
	if (ret)
		return ret;

	ws->frame = vmalloc_user(ws->frame_size);
	ws->stage = kvmalloc(ws->frame_size, GFP_KERNEL);
	if (!ws->frame || !ws->stage)
		return -ENOMEM;
	for (c = 0; c < 256; c++)
		ws->lut[c] = c;
	ws->brightness = 255;
	ws281x_update_tab(ws);
	ws->reset = WS281X_RESET_DEFAULT;

	for (c = 0; c < ws->ncores; c++) {
		ret = ws281x_core_init(ws, c);
		if (ret)
			return ret;
	}
	/* Registered after the cores: released before them, blank first. */
	ret = devm_add_action(dev, ws281x_stop, ws);
	if (ret)
		return ret;
	ret = ws281x_start(ws);
	if (ret)
		return ret;

	ws->minor = ida_alloc_max(&ws281x_minors, WS281X_MAX_DEVICES - 1, GFP_KERNEL);
	if (ws->minor < 0)
		return ws->minor;
	kref_get(&ws->kref);	/* the character device's */
	device_initialize(&ws->cdev_dev);
	ws->cdev_dev.class = &ws281x_class;
	ws->cdev_dev.parent = dev;
	ws->cdev_dev.devt = MKDEV(MAJOR(ws281x_devt), ws->minor);
	ws->cdev_dev.release = ws281x_cdev_release;
	ws->cdev_dev.groups = ws281x_groups;
	dev_set_drvdata(&ws->cdev_dev, ws);
	ret = dev_set_name(&ws->cdev_dev, "ws281x%d", ws->minor);
	if (ret)
		goto put_cdev_dev;
	cdev_init(&ws->cdev, &ws281x_fops);
	ws->cdev.owner = THIS_MODULE;
	ret = cdev_device_add(&ws->cdev, &ws->cdev_dev);
	if (ret)
		goto put_cdev_dev;
	ret = devm_add_action_or_reset(dev, ws281x_cdev_del, ws);
	if (ret)
		return ret;

	ret = ws281x_leds(ws);
	if (ret)
		return ret;
	dev_info(dev, "%u strings of up to %u LEDs on %u PRU core(s): /dev/%s\n",
		 ws->nstrings, ws->max_leds, ws->ncores, dev_name(&ws->cdev_dev));
	return 0;

put_cdev_dev:
	put_device(&ws->cdev_dev);
	return ret;
}

static const struct of_device_id ws281x_of_match[] = {
	{ .compatible = "prukit,ws281x" },
	{ }
};
MODULE_DEVICE_TABLE(of, ws281x_of_match);

static struct platform_driver ws281x_driver = {
	.probe = ws281x_probe,
	.driver = {
		.name = "ws281x",
		.of_match_table = ws281x_of_match,
	},
};

static int __init ws281x_init(void)
{
	int ret;

	ret = alloc_chrdev_region(&ws281x_devt, 0, WS281X_MAX_DEVICES, "ws281x");
	if (ret)
		return ret;
	ret = class_register(&ws281x_class);
	if (ret)
		goto unregister_chrdev;
	ret = platform_driver_register(&ws281x_driver);
	if (ret)
		goto unregister_class;
	return 0;

unregister_class:
	class_unregister(&ws281x_class);
unregister_chrdev:
	unregister_chrdev_region(ws281x_devt, WS281X_MAX_DEVICES);
	return ret;
}
module_init(ws281x_init);

static void __exit ws281x_exit(void)
{
	platform_driver_unregister(&ws281x_driver);
	class_unregister(&ws281x_class);
	unregister_chrdev_region(ws281x_devt, WS281X_MAX_DEVICES);
}
module_exit(ws281x_exit);

PRUKIT_IMPORT_NS();
MODULE_DESCRIPTION("WS281x (NeoPixel) LED strings on the BeagleBone's PRUs");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
