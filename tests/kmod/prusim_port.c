// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim_port - the test port of the VM's simulated PRU-ICSS, in debugfs
 *
 * The PRU-ICSS of prukit's test VM is a QEMU device (qemu/am335x_pruss.c)
 * that the kernel's own pruss, pruss_intc and pru_rproc drivers use as on a
 * board.  What a test needs beyond the board - the pin trace, input
 * stimulus, statistics, pad registers, timing knobs - sits behind a
 * separate register block, the test port ("prukit,prusim-port"), which this
 * driver shows as files in /sys/kernel/debug/prusim/.  The files, their
 * formats and their errors are the QEMU device's (Documentation/
 * qemu-pruss.rst); this driver only carries bytes: each command runs
 * synchronously in the device while the guest's register write traps, so a
 * test's actions and the simulator stay in step.
 *
 * A file is either a "snapshot" file (trace, stats, pads, the knobs): opening
 * it for reading takes a copy of its content, each write() is one command;
 * or a "staged" file (the input files): what is written is collected by the device
 * and checked line by line, and takes effect when the file is closed.
 *
 * Test-only: not built into prukit's packages, never on a board.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/debugfs.h>
#include <linux/fs.h>
#include <linux/io.h>
#include <linux/mm.h>
#include <linux/module.h>
#include <linux/mod_devicetable.h>
#include <linux/mutex.h>
#include <linux/platform_device.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/uaccess.h>

#include "prusim_port.h"

#define PRUSIM_PORT_FILES	32

struct prusim_port;

/**
 * struct prusim_port_file - one file of the device
 * @port: the device
 * @index: the device's number for it
 * @staged: written text takes effect at close (input files)
 */
struct prusim_port_file {
	struct prusim_port *port;
	unsigned int index;
	bool staged;
};

/**
 * struct prusim_port - the test port
 * @dev: its platform device
 * @regs: the command registers
 * @buf: the buffer requests and replies travel in
 * @buf_size: its size
 * @lock: one command at a time (@buf is shared)
 * @dir: /sys/kernel/debug/prusim
 * @files: the device's files
 * @nfiles: entries in @files
 */
struct prusim_port {
	struct device *dev;
	void __iomem *regs;
	void *buf;
	u32 buf_size;
	struct mutex lock;		/* serialises commands and @buf */
	struct dentry *dir;
	struct prusim_port_file files[PRUSIM_PORT_FILES];
	unsigned int nfiles;
};

/**
 * struct prusim_port_open - an open file
 * @file: which
 * @data: the content taken at open (snapshot files opened for reading)
 * @len: bytes in @data
 * @handle: the device's handle of a staged file opened for writing, or -1
 */
struct prusim_port_open {
	struct prusim_port_file *file;
	char *data;
	size_t len;
	int handle;
};

/*
 * Run one command: @len bytes of request already in @pp->buf.  Returns 0
 * or the device's -errno; *@reply_len is the length of the reply in @pp->buf.
 */
static int prusim_port_cmd(struct prusim_port *pp, u32 op, u32 index, u32 handle, size_t len,
			   u32 *reply_len)
{
	u32 status;

	lockdep_assert_held(&pp->lock);
	writel(len, pp->regs + PRUSIM_TEST_PORT_REG_LEN);
	writel(PRUSIM_TEST_PORT_CMD(op, index, handle), pp->regs + PRUSIM_TEST_PORT_REG_CMD);
	status = readl(pp->regs + PRUSIM_TEST_PORT_REG_STATUS);
	*reply_len = min(readl(pp->regs + PRUSIM_TEST_PORT_REG_LEN), pp->buf_size);
	if (status > MAX_ERRNO)
		return -EPROTO;
	return -(int)status;
}

/* The device's reason for a refused command (it names the file and line) */
static void prusim_port_log_error(struct prusim_port *pp, struct prusim_port_file *f,
				  int err, u32 reply_len)
{
	if (reply_len)
		dev_err(pp->dev, "%.*s\n", (int)reply_len, (char *)pp->buf);
	else
		dev_err(pp->dev, "file %u: error %d\n", f->index, err);
}

static int prusim_port_open(struct inode *inode, struct file *file)
{
	struct prusim_port_file *f = inode->i_private;
	struct prusim_port *pp = f->port;
	struct prusim_port_open *o;
	u32 len;
	int ret = 0;

	o = kzalloc(sizeof(*o), GFP_KERNEL);
	if (!o)
		return -ENOMEM;
	o->file = f;
	o->handle = -1;

	mutex_lock(&pp->lock);
	if (file->f_mode & FMODE_READ) {
		ret = prusim_port_cmd(pp, PRUSIM_TEST_PORT_OP_READ, f->index, 0, 0, &len);
		if (!ret) {
			o->data = kvmalloc(len ?: 1, GFP_KERNEL);
			if (o->data) {
				memcpy(o->data, pp->buf, len);
				o->len = len;
			} else {
				ret = -ENOMEM;
			}
		}
	}
	if (!ret && f->staged && (file->f_mode & FMODE_WRITE)) {
		ret = prusim_port_cmd(pp, PRUSIM_TEST_PORT_OP_OPEN, f->index, 0, 0, &len);
		if (!ret) {
			u32 handle = readl(pp->regs + PRUSIM_TEST_PORT_REG_HANDLE);

			/* CMD carries 16 bits of it */
			if (handle > U16_MAX)
				ret = -EPROTO;
			else
				o->handle = handle;
		}
	}
	mutex_unlock(&pp->lock);

	if (ret) {
		kvfree(o->data);
		kfree(o);
		return ret;
	}
	file->private_data = o;
	return 0;
}

static ssize_t prusim_port_read(struct file *file, char __user *ubuf, size_t count,
				loff_t *ppos)
{
	struct prusim_port_open *o = file->private_data;

	if (!o->data)
		return -EBADF;
	return simple_read_from_buffer(ubuf, count, ppos, o->data, o->len);
}

static ssize_t prusim_port_write(struct file *file, const char __user *ubuf, size_t count,
				 loff_t *ppos)
{
	struct prusim_port_open *o = file->private_data;
	struct prusim_port_file *f = o->file;
	struct prusim_port *pp = f->port;
	size_t done = 0;
	u32 reply;
	int ret = 0;

	if (!f->staged && count > pp->buf_size)
		return -EINVAL;
	if (f->staged && o->handle < 0)
		return -EBADF;
	if (!count)
		return 0;

	mutex_lock(&pp->lock);
	do {
		size_t n = min_t(size_t, count - done, pp->buf_size);

		if (copy_from_user(pp->buf, ubuf + done, n)) {
			ret = -EFAULT;
			break;
		}
		if (f->staged)
			ret = prusim_port_cmd(pp, PRUSIM_TEST_PORT_OP_APPEND, 0, o->handle, n,
					      &reply);
		else
			ret = prusim_port_cmd(pp, PRUSIM_TEST_PORT_OP_WRITE, f->index, 0, n,
					      &reply);
		if (ret) {
			prusim_port_log_error(pp, f, ret, reply);
			break;
		}
		done += n;
	} while (done < count);
	mutex_unlock(&pp->lock);

	return ret ?: count;
}

static int prusim_port_release(struct inode *inode, struct file *file)
{
	struct prusim_port_open *o = file->private_data;
	struct dentry *dentry = file->f_path.dentry;
	u32 reply;
	int ret;

	/*
	 * A staged file takes effect now.  debugfs calls release even after
	 * the files were removed (the port was unbound with this file open):
	 * then the port is gone, @o->file with it, and the text too.
	 */
	if (o->handle >= 0 && !debugfs_file_get(dentry)) {
		struct prusim_port_file *f = o->file;
		struct prusim_port *pp = f->port;

		mutex_lock(&pp->lock);
		ret = prusim_port_cmd(pp, PRUSIM_TEST_PORT_OP_CLOSE, 0, o->handle, 0, &reply);
		if (ret)
			prusim_port_log_error(pp, f, ret, reply);
		mutex_unlock(&pp->lock);
		debugfs_file_put(dentry);
	}
	kvfree(o->data);
	kfree(o);
	return 0;
}

static const struct file_operations prusim_port_fops = {
	.owner = THIS_MODULE,
	.open = prusim_port_open,
	.read = prusim_port_read,
	.write = prusim_port_write,
	.release = prusim_port_release,
	.llseek = default_llseek,
};

/* The device's file list: "name mode kind" lines */
static int prusim_port_files(struct prusim_port *pp)
{
	char *list, *line, *next, subname[48] = "";
	struct dentry *sub = NULL;
	u32 len;
	int ret;

	mutex_lock(&pp->lock);
	ret = prusim_port_cmd(pp, PRUSIM_TEST_PORT_OP_LIST, 0, 0, 0, &len);
	list = ret ? NULL : kmemdup_nul(pp->buf, len, GFP_KERNEL);
	mutex_unlock(&pp->lock);
	if (ret)
		return dev_err_probe(pp->dev, ret, "cannot list the port's files\n");
	if (!list)
		return -ENOMEM;

	for (line = list; line && *line && !ret; line = next) {
		struct prusim_port_file *f = &pp->files[pp->nfiles];
		char name[48], kind[16], *base;
		struct dentry *dir = pp->dir;
		umode_t mode;

		next = strchr(line, '\n');
		if (next)
			*next++ = 0;
		if (pp->nfiles == PRUSIM_PORT_FILES ||
		    sscanf(line, "%47s %ho %15s", name, &mode, kind) != 3) {
			ret = dev_err_probe(pp->dev, -EPROTO, "bad file list line \"%s\"\n", line);
			break;
		}
		f->port = pp;
		f->index = pp->nfiles++;
		f->staged = !strcmp(kind, "staged");
		base = strchr(name, '/');
		if (base) {
			/* one level of directories ("input/r31-0") */
			*base++ = 0;
			if (!sub || strcmp(subname, name)) {
				/* the device lists a directory's files together */
				sub = debugfs_create_dir(name, pp->dir);
				if (IS_ERR(sub)) {
					ret = dev_err_probe(pp->dev, PTR_ERR(sub),
							    "cannot create debugfs prusim/%s\n",
							    name);
					break;
				}
				strscpy(subname, name, sizeof(subname));
			}
			dir = sub;
		} else {
			base = name;
		}
		debugfs_create_file(base, mode & 0600, dir, f, &prusim_port_fops);
	}
	kfree(list);
	return ret;
}

static void prusim_port_remove_debugfs(void *data)
{
	struct prusim_port *pp = data;

	debugfs_remove_recursive(pp->dir);
}

static int prusim_port_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct prusim_port *pp;
	struct resource *res;
	u32 id, version;
	int ret;

	pp = devm_kzalloc(dev, sizeof(*pp), GFP_KERNEL);
	if (!pp)
		return -ENOMEM;
	pp->dev = dev;
	mutex_init(&pp->lock);

	pp->regs = devm_platform_ioremap_resource_byname(pdev, "regs");
	if (IS_ERR(pp->regs))
		return PTR_ERR(pp->regs);
	id = readl(pp->regs + PRUSIM_TEST_PORT_REG_ID);
	version = readl(pp->regs + PRUSIM_TEST_PORT_REG_VERSION);
	if (id != PRUSIM_TEST_PORT_ID || version != PRUSIM_TEST_PORT_VERSION)
		return dev_err_probe(dev, -ENODEV, "no test port here (id 0x%08x version %u)\n",
				     id, version);

	res = platform_get_resource_byname(pdev, IORESOURCE_MEM, "buf");
	if (!res)
		return dev_err_probe(dev, -EINVAL, "no \"buf\" region\n");
	pp->buf_size = min_t(u64, resource_size(res),
			     readl(pp->regs + PRUSIM_TEST_PORT_REG_BUFSIZE));
	if (!pp->buf_size)
		return dev_err_probe(dev, -EPROTO, "the port has no buffer\n");
	/* plain memory inside the device: mapped cacheable, copied with memcpy */
	pp->buf = devm_memremap(dev, res->start, pp->buf_size, MEMREMAP_WB);
	if (IS_ERR(pp->buf))
		return dev_err_probe(dev, PTR_ERR(pp->buf), "cannot map the buffer\n");

	pp->dir = debugfs_create_dir("prusim", NULL);
	if (IS_ERR(pp->dir))
		return dev_err_probe(dev, PTR_ERR(pp->dir),
				     "cannot create debugfs prusim/ (debugfs off, or a second port?)\n");
	ret = devm_add_action_or_reset(dev, prusim_port_remove_debugfs, pp);
	if (ret)
		return ret;
	ret = prusim_port_files(pp);
	if (ret)
		return ret;
	platform_set_drvdata(pdev, pp);
	dev_info(dev, "simulated PRU-ICSS test port: %u files in debugfs prusim/\n", pp->nfiles);
	return 0;
}

static const struct of_device_id prusim_port_of_match[] = {
	{ .compatible = "prukit,prusim-port" },
	{ }
};
MODULE_DEVICE_TABLE(of, prusim_port_of_match);

static struct platform_driver prusim_port_driver = {
	.probe = prusim_port_probe,
	.driver = {
		.name = "prusim_port",
		.of_match_table = prusim_port_of_match,
	},
};
module_platform_driver(prusim_port_driver);

MODULE_DESCRIPTION("Test port of the VM's simulated PRU-ICSS (pin trace, stimulus, statistics)");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
