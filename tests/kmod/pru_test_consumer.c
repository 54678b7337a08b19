// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_test_consumer - the smallest prukit driver, for prukit's VM tests
 *
 * Reaches its PRU only through the shared consumer layer (prukit_pru), as
 * every prukit driver does: the core from "ti,prus", its firmware from
 * "firmware-name", the control block of pru_test_consumer.h polled by the
 * firmware without any kick, DMA buffers the PRU reads and writes over OCP,
 * and a PRU -> ARM event from its own "interrupts-extended".
 *
 * sysfs, on the platform device (a test module; not installed on boards):
 *   firmware   (rw) firmware "state" starts ("firmware-name" by default)
 *   state      (rw) "running" or "offline"; write "start" or "stop"
 *   ping       (wo) any write: one PING command; reads of pings (ro)
 *   dma        (wo) "coherent LEN" or "streaming LEN": the PRU copies a
 *                   buffer into another, XORing each word; checked here
 *   events     (wo) N: the firmware strobes its event N times; the write
 *                   returns once N interrupts arrived
 *   irq_count  (r)  interrupts received
 *   rproc      (r)  the remote processor's device name
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/dma-mapping.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/platform_device.h>
#include <linux/random.h>
#include <linux/remoteproc.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/wait.h>

#include "compat.h"
#include "prukit_pru.h"
#include "pru_test_consumer.h"

/**
 * struct pru_test_consumer - one test consumer
 * @pru: its PRU core
 * @lock: serialises commands, start and stop
 * @ctrl: the control block while the firmware runs, else NULL
 * @firmware: set through sysfs, or NULL for "firmware-name"
 * @irqs: interrupts received
 * @irq_wq: woken on each interrupt
 */
struct pru_test_consumer {
	struct prukit_pru *pru;
	struct mutex lock;	/* protects everything below */
	void __iomem *ctrl;
	char *firmware;
	atomic_t irqs;
	wait_queue_head_t irq_wq;
};

#define CTRL_OFF(field)	offsetof(struct pru_test_ctrl, field)

static irqreturn_t pru_test_consumer_irq(int irq, void *data)
{
	struct pru_test_consumer *tc = data;

	atomic_inc(&tc->irqs);
	wake_up(&tc->irq_wq);
	return IRQ_HANDLED;
}

static void pru_test_consumer_stop(struct pru_test_consumer *tc)
{
	tc->ctrl = NULL;
	prukit_pru_shutdown(tc->pru);
}

static int pru_test_consumer_start(struct pru_test_consumer *tc)
{
	struct prukit_pru *pru = tc->pru;
	void __iomem *ctrl;
	int ret;

	ret = prukit_pru_boot(pru, tc->firmware);
	if (ret)
		return ret;
	ctrl = prukit_pru_map(pru, PRUKIT_CTRL_DA, sizeof(struct pru_test_ctrl));
	if (!ctrl) {
		ret = -EPROTO;
		goto shutdown;
	}
	ret = prukit_pru_ctrl_check(pru, ctrl, PRU_TEST_MAGIC, PRU_TEST_VERSION,
				    sizeof(struct pru_test_ctrl));
	if (ret)
		goto shutdown;
	ret = prukit_pru_ctrl_wait_ready(pru, ctrl, PRUKIT_PRU_TIMEOUT_MS);
	if (ret)
		goto shutdown;
	tc->ctrl = ctrl;
	return 0;

shutdown:
	prukit_pru_shutdown(pru);
	return ret;
}

/* A command; the firmware's own error codes become -EINVAL. */
static int pru_test_consumer_command(struct pru_test_consumer *tc, u16 opcode)
{
	int ret;

	if (!tc->ctrl || !prukit_pru_running(tc->pru))
		return -ENODEV;
	ret = prukit_pru_ctrl_command(tc->pru, tc->ctrl, opcode, PRUKIT_PRU_TIMEOUT_MS);
	if (ret > 0) {
		dev_err(tc->pru->dev, "firmware refused command %u: result %d\n", opcode, ret);
		ret = -EINVAL;
	}
	return ret;
}

/* The PRU copies @src to @dst, XORing every word with @x. */
static int pru_test_consumer_copy(struct pru_test_consumer *tc, dma_addr_t src,
				  dma_addr_t dst, u32 len, u32 x)
{
	writel(lower_32_bits(src), tc->ctrl + CTRL_OFF(src));
	writel(lower_32_bits(dst), tc->ctrl + CTRL_OFF(dst));
	writel(len, tc->ctrl + CTRL_OFF(len));
	writel(x, tc->ctrl + CTRL_OFF(xor));
	return pru_test_consumer_command(tc, PRU_TEST_CMD_COPY);
}

static int pru_test_consumer_verify(struct device *dev, const u32 *in, const u32 *out,
				    u32 len, u32 x)
{
	u32 i;

	for (i = 0; i < len / 4; i++) {
		if (out[i] != (in[i] ^ x)) {
			dev_err(dev, "DMA word %u: 0x%08x, expected 0x%08x\n", i, out[i],
				in[i] ^ x);
			return -EIO;
		}
	}
	return 0;
}

/* Coherent buffers: no hand-over needs a sync. */
static int pru_test_consumer_dma_coherent(struct pru_test_consumer *tc, u32 len)
{
	struct device *dev = tc->pru->dev;
	dma_addr_t src_dma, dst_dma;
	u32 *src, *dst, x = get_random_u32();
	int ret = -ENOMEM;

	src = dma_alloc_coherent(dev, len, &src_dma, GFP_KERNEL);
	if (!src)
		return -ENOMEM;
	dst = dma_alloc_coherent(dev, len, &dst_dma, GFP_KERNEL);
	if (!dst)
		goto free_src;
	get_random_bytes(src, len);
	memset(dst, 0, len);
	ret = pru_test_consumer_copy(tc, src_dma, dst_dma, len, x);
	if (!ret)
		ret = pru_test_consumer_verify(dev, src, dst, len, x);
	dma_free_coherent(dev, len, dst, dst_dma);
free_src:
	dma_free_coherent(dev, len, src, src_dma);
	return ret;
}

/*
 * Streaming buffers, mapped once, as a driver does for buffers it reuses:
 * each hand-over has its explicit sync.  (QEMU has no caches, so a missing
 * sync would pass here and corrupt data on a board: review, don't test.)
 */
static int pru_test_consumer_dma_streaming(struct pru_test_consumer *tc, u32 len)
{
	struct device *dev = tc->pru->dev;
	dma_addr_t src_dma, dst_dma;
	u32 *src, *dst, x = get_random_u32();
	int ret = -ENOMEM;

	src = kmalloc(len, GFP_KERNEL);
	dst = kzalloc(len, GFP_KERNEL);
	if (!src || !dst)
		goto free;
	get_random_bytes(src, len);
	src_dma = dma_map_single(dev, src, len, DMA_TO_DEVICE);
	if (dma_mapping_error(dev, src_dma))
		goto free;
	dst_dma = dma_map_single(dev, dst, len, DMA_FROM_DEVICE);
	if (dma_mapping_error(dev, dst_dma))
		goto unmap_src;

	/* CPU -> PRU: the source was written before the mapping; write again. */
	dma_sync_single_for_cpu(dev, src_dma, len, DMA_TO_DEVICE);
	src[0] ^= x;
	dma_sync_single_for_device(dev, src_dma, len, DMA_TO_DEVICE);
	dma_sync_single_for_device(dev, dst_dma, len, DMA_FROM_DEVICE);
	ret = pru_test_consumer_copy(tc, src_dma, dst_dma, len, x);
	/* PRU -> CPU */
	dma_sync_single_for_cpu(dev, dst_dma, len, DMA_FROM_DEVICE);
	if (!ret)
		ret = pru_test_consumer_verify(dev, src, dst, len, x);

	dma_unmap_single(dev, dst_dma, len, DMA_FROM_DEVICE);
unmap_src:
	dma_unmap_single(dev, src_dma, len, DMA_TO_DEVICE);
free:
	kfree(dst);
	kfree(src);
	return ret;
}

static ssize_t firmware_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);
	ssize_t n;

	mutex_lock(&tc->lock);
	n = sysfs_emit(buf, "%s\n", tc->firmware ?: tc->pru->firmware ?: "");
	mutex_unlock(&tc->lock);
	return n;
}

static ssize_t firmware_store(struct device *dev, struct device_attribute *attr,
			      const char *buf, size_t count)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);
	char *name;

	name = kstrndup(buf, strcspn(buf, "\n"), GFP_KERNEL);
	if (!name)
		return -ENOMEM;
	if (!*name) {
		kfree(name);
		return -EINVAL;
	}
	mutex_lock(&tc->lock);
	kfree(tc->firmware);
	tc->firmware = name;
	mutex_unlock(&tc->lock);
	return count;
}
static DEVICE_ATTR_RW(firmware);

static ssize_t state_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%s\n", prukit_pru_running(tc->pru) ? "running" : "offline");
}

static ssize_t state_store(struct device *dev, struct device_attribute *attr,
			   const char *buf, size_t count)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);
	int ret;

	mutex_lock(&tc->lock);
	if (sysfs_streq(buf, "start")) {
		ret = tc->ctrl && prukit_pru_running(tc->pru) ? -EBUSY : 0;
		if (!ret) {
			pru_test_consumer_stop(tc);
			ret = pru_test_consumer_start(tc);
		}
	} else if (sysfs_streq(buf, "stop")) {
		pru_test_consumer_stop(tc);
		ret = 0;
	} else {
		ret = -EINVAL;
	}
	mutex_unlock(&tc->lock);
	return ret ?: count;
}
static DEVICE_ATTR_RW(state);

static ssize_t ping_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);
	ssize_t ret;

	mutex_lock(&tc->lock);
	if (tc->ctrl && prukit_pru_running(tc->pru))
		ret = sysfs_emit(buf, "%u\n", readl(tc->ctrl + CTRL_OFF(pings)));
	else
		ret = -ENODEV;
	mutex_unlock(&tc->lock);
	return ret;
}

static ssize_t ping_store(struct device *dev, struct device_attribute *attr,
			  const char *buf, size_t count)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);
	int ret;

	mutex_lock(&tc->lock);
	ret = pru_test_consumer_command(tc, PRU_TEST_CMD_PING);
	mutex_unlock(&tc->lock);
	return ret ?: count;
}
static DEVICE_ATTR_RW(ping);

static ssize_t dma_store(struct device *dev, struct device_attribute *attr,
			 const char *buf, size_t count)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);
	char mode[16];
	u32 len;
	int ret;

	if (sscanf(buf, "%15s %u", mode, &len) != 2 || !len || len % 4 ||
	    len > PRU_TEST_MAX_COPY)
		return -EINVAL;
	mutex_lock(&tc->lock);
	if (!tc->ctrl)
		ret = -ENODEV;
	else if (!strcmp(mode, "coherent"))
		ret = pru_test_consumer_dma_coherent(tc, len);
	else if (!strcmp(mode, "streaming"))
		ret = pru_test_consumer_dma_streaming(tc, len);
	else
		ret = -EINVAL;
	mutex_unlock(&tc->lock);
	return ret ?: count;
}
static DEVICE_ATTR_WO(dma);

static ssize_t events_store(struct device *dev, struct device_attribute *attr,
			    const char *buf, size_t count)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);
	unsigned int n;
	long left;
	int ret, want;

	ret = kstrtouint(buf, 0, &n);
	if (ret)
		return ret;
	if (!n || n > PRU_TEST_MAX_EVENTS)
		return -EINVAL;
	mutex_lock(&tc->lock);
	want = atomic_read(&tc->irqs) + n;
	if (tc->ctrl)
		writel(n, tc->ctrl + CTRL_OFF(count));
	ret = pru_test_consumer_command(tc, PRU_TEST_CMD_EVENTS);
	if (!ret) {
		left = wait_event_interruptible_timeout(tc->irq_wq,
							atomic_read(&tc->irqs) - want >= 0,
							msecs_to_jiffies(PRUKIT_PRU_TIMEOUT_MS));
		if (left < 0) {
			ret = left;
		} else if (!left) {
			dev_err(dev, "%d of %u interrupts arrived within %u ms\n",
				n - (want - atomic_read(&tc->irqs)), n, PRUKIT_PRU_TIMEOUT_MS);
			ret = -ETIMEDOUT;
		}
	}
	mutex_unlock(&tc->lock);
	return ret ?: count;
}
static DEVICE_ATTR_WO(events);

static ssize_t irq_count_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%d\n", atomic_read(&tc->irqs));
}
static DEVICE_ATTR_RO(irq_count);

static ssize_t rproc_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%s\n", dev_name(&tc->pru->rproc->dev));
}
static DEVICE_ATTR_RO(rproc);

static struct attribute *pru_test_consumer_attrs[] = {
	&dev_attr_firmware.attr,
	&dev_attr_state.attr,
	&dev_attr_ping.attr,
	&dev_attr_dma.attr,
	&dev_attr_events.attr,
	&dev_attr_irq_count.attr,
	&dev_attr_rproc.attr,
	NULL
};
ATTRIBUTE_GROUPS(pru_test_consumer);

static void pru_test_consumer_free_firmware(void *data)
{
	struct pru_test_consumer *tc = data;

	kfree(tc->firmware);
}

static int pru_test_consumer_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct pru_test_consumer *tc;
	int irq, ret;

	tc = devm_kzalloc(dev, sizeof(*tc), GFP_KERNEL);
	if (!tc)
		return -ENOMEM;
	mutex_init(&tc->lock);
	init_waitqueue_head(&tc->irq_wq);
	ret = devm_add_action_or_reset(dev, pru_test_consumer_free_firmware, tc);
	if (ret)
		return ret;

	tc->pru = devm_prukit_pru_get(dev, 0);
	if (IS_ERR(tc->pru))
		return PTR_ERR(tc->pru);

	irq = devm_prukit_pru_request_irq(dev, NULL, pru_test_consumer_irq, NULL, 0, tc);
	if (irq < 0)
		return irq;

	platform_set_drvdata(pdev, tc);
	dev_info(dev, "PRU %s, irq %d\n", dev_name(&tc->pru->rproc->dev), irq);
	return 0;
}

static const struct of_device_id pru_test_consumer_of_match[] = {
	{ .compatible = "prukit,test-pru-consumer" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_test_consumer_of_match);

static struct platform_driver pru_test_consumer_driver = {
	.probe = pru_test_consumer_probe,
	.driver = {
		.name = "pru_test_consumer",
		.of_match_table = pru_test_consumer_of_match,
		.dev_groups = pru_test_consumer_groups,
	},
};
module_platform_driver(pru_test_consumer_driver);

PRUKIT_IMPORT_NS();
MODULE_DESCRIPTION("Minimal PRU consumer for prukit's VM tests");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
