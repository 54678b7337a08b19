// SPDX-License-Identifier: GPL-2.0-only
/*
 * rproc_hold - boots of a PRU remote processor held by a kernel user, as
 * another driver's rproc_boot() holds one.  remoteproc stops a processor
 * only at its last rproc_shutdown(): with boots held here, the shutdown
 * prukit_pru makes when the core's driver goes, and the one rproc_del()
 * makes on 5.11 and later (5.10's makes none for a PRU), leave it running.
 * For tests/vm/cases/99-kick-held-unbind.  And a kernel user that shuts a
 * processor down it never booted (a driver's bug, or what /dev/remoteprocN's
 * "stop" does where the kernel has it): the processor stops behind the back
 * of the driver that booted it (pru_encoder's test).  A test-only module.
 *
 * debugfs rproc_hold/hold: write "DEVICE N" to take N more boots of the
 * remote processor of platform device DEVICE (a core bound to pru-rproc:
 * 4a334000.pru), which must run already; read: "DEVICE boots" per line.
 * debugfs rproc_hold/stop: write "DEVICE": one rproc_shutdown() of it.
 * Unloading the module shuts down once per boot held, except on processors
 * whose driver has gone (their boots are left as they are: nothing can
 * stop those any more).
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/debugfs.h>
#include <linux/device.h>
#include <linux/list.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/platform_device.h>
#include <linux/remoteproc.h>
#include <linux/seq_file.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/uaccess.h>

/**
 * struct rproc_hold - boots held on one processor
 * @node: in rproc_holds
 * @rproc: the processor (a reference is held)
 * @name: its core's device name
 * @boots: boots held
 */
struct rproc_hold {
	struct list_head node;
	struct rproc *rproc;
	char name[32];
	unsigned int boots;
};

static LIST_HEAD(rproc_holds);
static DEFINE_MUTEX(rproc_holds_lock);
static struct dentry *rproc_hold_dir;

/* The running remote processor of a core bound to pru-rproc, with a reference */
static struct rproc *rproc_hold_find(const char *name)
{
	struct rproc *rproc = NULL;
	struct device *dev;

	dev = bus_find_device_by_name(&platform_bus_type, NULL, name);
	if (!dev)
		return NULL;
	device_lock(dev);
	if (dev->driver && !strcmp(dev->driver->name, "pru-rproc")) {
		rproc = dev_get_drvdata(dev);
		if (rproc && READ_ONCE(rproc->state) == RPROC_RUNNING)
			get_device(&rproc->dev);
		else
			rproc = NULL;
	}
	device_unlock(dev);
	put_device(dev);
	return rproc;
}

static ssize_t rproc_hold_write(struct file *file, const char __user *ubuf, size_t len,
				loff_t *ppos)
{
	struct rproc_hold *h;
	char buf[64], name[32];
	unsigned int n;
	int ret = 0;

	if (len >= sizeof(buf))
		return -EINVAL;
	if (copy_from_user(buf, ubuf, len))
		return -EFAULT;
	buf[len] = '\0';
	if (sscanf(buf, "%31s %u", name, &n) != 2 || !n || n > 16)
		return -EINVAL;
	h = kzalloc(sizeof(*h), GFP_KERNEL);
	if (!h)
		return -ENOMEM;
	h->rproc = rproc_hold_find(name);
	if (!h->rproc) {
		kfree(h);
		return -ENODEV;
	}
	strscpy(h->name, name, sizeof(h->name));
	for (; h->boots < n; h->boots++) {
		ret = rproc_boot(h->rproc);
		if (ret)
			break;
	}
	pr_info("%s: %u more boots held\n", name, h->boots);
	mutex_lock(&rproc_holds_lock);
	list_add_tail(&h->node, &rproc_holds);
	mutex_unlock(&rproc_holds_lock);
	return ret ? ret : len;
}

static ssize_t rproc_hold_stop_write(struct file *file, const char __user *ubuf, size_t len,
				     loff_t *ppos)
{
	struct rproc *rproc;
	char name[32];

	if (!len || len >= sizeof(name))
		return -EINVAL;
	if (copy_from_user(name, ubuf, len))
		return -EFAULT;
	name[len] = '\0';
	strim(name);
	rproc = rproc_hold_find(name);
	if (!rproc)
		return -ENODEV;
	pr_info("%s: shut down by a kernel user that did not boot it\n", name);
	rproc_shutdown(rproc);
	put_device(&rproc->dev);
	return len;
}

static const struct file_operations rproc_hold_stop_fops = {
	.owner = THIS_MODULE,
	.open = simple_open,
	.write = rproc_hold_stop_write,
};

static int rproc_hold_show(struct seq_file *s, void *unused)
{
	struct rproc_hold *h;

	mutex_lock(&rproc_holds_lock);
	list_for_each_entry(h, &rproc_holds, node)
		seq_printf(s, "%s %u\n", h->name, h->boots);
	mutex_unlock(&rproc_holds_lock);
	return 0;
}

static int rproc_hold_open(struct inode *inode, struct file *file)
{
	return single_open(file, rproc_hold_show, NULL);
}

static const struct file_operations rproc_hold_fops = {
	.owner = THIS_MODULE,
	.open = rproc_hold_open,
	.read = seq_read,
	.llseek = seq_lseek,
	.release = single_release,
	.write = rproc_hold_write,
};

static int __init rproc_hold_init(void)
{
	rproc_hold_dir = debugfs_create_dir("rproc_hold", NULL);
	debugfs_create_file("hold", 0600, rproc_hold_dir, NULL, &rproc_hold_fops);
	debugfs_create_file("stop", 0200, rproc_hold_dir, NULL, &rproc_hold_stop_fops);
	return 0;
}
module_init(rproc_hold_init);

static void __exit rproc_hold_exit(void)
{
	struct rproc_hold *h, *tmp;

	debugfs_remove_recursive(rproc_hold_dir);
	list_for_each_entry_safe(h, tmp, &rproc_holds, node) {
		if (READ_ONCE(h->rproc->state) != RPROC_DELETED)
			while (h->boots--)
				rproc_shutdown(h->rproc);
		put_device(&h->rproc->dev);
		list_del(&h->node);
		kfree(h);
	}
}
module_exit(rproc_hold_exit);

MODULE_DESCRIPTION("prukit test: boots of a PRU remote processor held by a kernel user");
MODULE_LICENSE("GPL");
