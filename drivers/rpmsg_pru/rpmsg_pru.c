// SPDX-License-Identifier: GPL-2.0-only
/*
 * rpmsg_pru - character devices for the rpmsg channels of PRU firmware
 *
 * Every "rpmsg-pru" channel that PRU firmware announces becomes
 * /dev/rpmsg_pru<N>, N being the channel's address on the firmware side (30
 * for PRU0 and 31 for PRU1 by convention).  The interface is the one of TI's
 * driver of the same name, which the PRU Cookbook uses:
 *
 *	echo "0 0xff 0 127" > /dev/rpmsg_pru30
 *
 * One write() sends one message and one read() returns one message.  Any
 * number of processes may open a device: writes are independent and each
 * received message goes to exactly one reader, as with a FIFO.  Received
 * messages wait in a bounded queue; what does not fit is dropped and counted.
 * When the channel goes away (the PRU is stopped), blocked callers wake up
 * and every later call fails with -EPIPE; the device's memory lives on until
 * the last file is closed.  Documentation/ABI/testing/dev-rpmsg_pru has the
 * details.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/cdev.h>
#include <linux/device.h>
#include <linux/fs.h>
#include <linux/idr.h>
#include <linux/list.h>
#include <linux/module.h>
#include <linux/overflow.h>
#include <linux/poll.h>
#include <linux/rpmsg.h>
#include <linux/rwsem.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux/uio.h>
#include <linux/wait.h>

#include "compat.h"
#include "rpmsg_pru_proto.h"

#define RPMSG_PRU_MAX_DEVICES	64

/*
 * A blocked writer waits for the transport to announce a free transmit
 * buffer, or for a message from the remote side.  virtio's rpmsg bus - the
 * one PRUs use - announces nothing (it has no poll operation), so a writer
 * also retries after this long: a message that the remote side answers
 * nothing to is delayed by at most this much per full transmit ring.
 */
#define RPMSG_PRU_TX_RETRY	msecs_to_jiffies(5)

static unsigned int rx_queue_len = 64;
module_param(rx_queue_len, uint, 0444);
MODULE_PARM_DESC(rx_queue_len,
		 "Received messages queued per device before new ones are dropped (default 64)");

/**
 * struct rpmsg_pru_msg - a received message waiting for a reader
 * @node: entry in &rpmsg_pru_port.queue
 * @len: payload length in bytes
 * @data: payload
 */
struct rpmsg_pru_msg {
	struct list_head node;
	size_t len;
	u8 data[];
};

/**
 * struct rpmsg_pru_port - one "rpmsg-pru" channel and its character device
 * @dev: the device behind /dev/rpmsg_pruN; its last reference frees the port
 * @cdev: the character device
 * @ept_rwsem: held for reading while a message is sent and for writing while
 *	the channel is taken away, so that nothing is sent to a gone channel
 * @ept: the channel's endpoint; NULL once the channel is gone
 * @tx_pt: poll table used once, to find the wait queue on which the
 *	transport announces that transmit buffers were freed
 * @tx_whead: that wait queue, NULL if the transport has none
 * @tx_wait: our entry on @tx_whead
 * @tx_events: bumped whenever a transmit buffer may have been freed
 * @lock: protects @queue, @queued, @gone and the counters
 * @queue: received messages not yet read, oldest first
 * @queued: number of messages on @queue
 * @gone: the channel has been removed
 * @rx_dropped: messages dropped because @queue was full
 * @rx_truncated: messages cut short by a read buffer smaller than them
 * @wq: readers, blocked writers and pollers wait here
 */
struct rpmsg_pru_port {
	struct device dev;
	struct cdev cdev;
	struct rw_semaphore ept_rwsem;
	struct rpmsg_endpoint *ept;
	poll_table tx_pt;
	wait_queue_head_t *tx_whead;
	wait_queue_entry_t tx_wait;
	atomic_t tx_events;
	spinlock_t lock;		/* protects the receive queue and counters */
	struct list_head queue;
	unsigned int queued;
	bool gone;
	u64 rx_dropped;
	u64 rx_truncated;
	wait_queue_head_t wq;
};

#define dev_to_port(d) container_of(d, struct rpmsg_pru_port, dev)

static dev_t rpmsg_pru_devt;
static DEFINE_IDA(rpmsg_pru_minors);

/* Let blocked writers retry and pollers look again: a buffer may be free. */
static void rpmsg_pru_tx_may_be_free(struct rpmsg_pru_port *port)
{
	atomic_inc(&port->tx_events);
	wake_up_interruptible_poll(&port->wq, EPOLLOUT | EPOLLWRNORM);
}

/*
 * When the transport announces no freed transmit buffers, a message from the
 * remote side is the best sign that it has taken ours: when it answers, as
 * most PRU firmware does, writers go on at once, not after RPMSG_PRU_TX_RETRY.
 */
static void rpmsg_pru_rx_frees_tx(struct rpmsg_pru_port *port)
{
	if (!READ_ONCE(port->tx_whead))
		rpmsg_pru_tx_may_be_free(port);
}

static int rpmsg_pru_cb(struct rpmsg_device *rpdev, void *data, int len,
			void *priv, u32 src)
{
	struct rpmsg_pru_port *port = priv;
	struct rpmsg_pru_msg *msg;
	unsigned long flags;

	msg = kmalloc(struct_size(msg, data, len), GFP_ATOMIC);
	if (msg) {
		msg->len = len;
		memcpy(msg->data, data, len);
	}

	spin_lock_irqsave(&port->lock, flags);
	if (!msg || port->queued >= rx_queue_len) {
		port->rx_dropped++;
		spin_unlock_irqrestore(&port->lock, flags);
		kfree(msg);
		dev_dbg_ratelimited(&port->dev, "dropped a %d-byte message\n", len);
		rpmsg_pru_rx_frees_tx(port);
		return 0;
	}
	list_add_tail(&msg->node, &port->queue);
	WRITE_ONCE(port->queued, port->queued + 1);
	spin_unlock_irqrestore(&port->lock, flags);

	wake_up_interruptible_poll(&port->wq, EPOLLIN | EPOLLRDNORM);
	rpmsg_pru_rx_frees_tx(port);
	return 0;
}

/*
 * Called from the transport's "transmit buffer freed" wake-up: let blocked
 * writers retry and pollers see EPOLLOUT.
 */
static int rpmsg_pru_tx_wake(wait_queue_entry_t *wait, unsigned int mode,
			     int sync, void *key)
{
	struct rpmsg_pru_port *port = container_of(wait, struct rpmsg_pru_port, tx_wait);

	rpmsg_pru_tx_may_be_free(port);
	return 0;
}

/*
 * Readers, writers and pollers only ever sleep on our own wait queue, which
 * lives as long as the port.  The transport's queue is reached through this
 * single entry, which rpmsg_pru_detach_tx() removes while the transport still
 * exists, so no sleeper is left on it when the channel goes away.
 */
static void rpmsg_pru_tx_queue_proc(struct file *filp, wait_queue_head_t *whead,
				    poll_table *pt)
{
	struct rpmsg_pru_port *port = container_of(pt, struct rpmsg_pru_port, tx_pt);

	if (port->tx_whead)
		return;
	init_waitqueue_func_entry(&port->tx_wait, rpmsg_pru_tx_wake);
	add_wait_queue(whead, &port->tx_wait);
	WRITE_ONCE(port->tx_whead, whead);
}

static void rpmsg_pru_attach_tx(struct rpmsg_pru_port *port)
{
	init_poll_funcptr(&port->tx_pt, rpmsg_pru_tx_queue_proc);
	rpmsg_poll(port->ept, NULL, &port->tx_pt);
}

static void rpmsg_pru_detach_tx(struct rpmsg_pru_port *port)
{
	if (port->tx_whead)
		remove_wait_queue(port->tx_whead, &port->tx_wait);
	WRITE_ONCE(port->tx_whead, NULL);
}

/* Whether a transmit buffer is free; arms the transport's announcement if not. */
static bool rpmsg_pru_tx_ready(struct rpmsg_pru_port *port)
{
	lockdep_assert_held(&port->ept_rwsem);

	if (!port->tx_whead)
		return true;
	return rpmsg_poll(port->ept, NULL, NULL) & EPOLLOUT;
}

static int rpmsg_pru_trysend(struct rpmsg_pru_port *port, void *buf, size_t len)
{
	int ret;

	if (down_read_interruptible(&port->ept_rwsem))
		return -ERESTARTSYS;

	if (!port->ept) {
		ret = -EPIPE;
	} else {
		ret = rpmsg_trysend(port->ept, buf, len);
		/* -ENOMEM and -EAGAIN: every transmit buffer is in use. */
		if (ret == -ENOMEM)
			ret = -EAGAIN;
		/* A buffer freed since the attempt may not have been announced. */
		if (ret == -EAGAIN && port->tx_whead &&
		    (rpmsg_poll(port->ept, NULL, NULL) & EPOLLOUT))
			atomic_inc(&port->tx_events);
	}

	up_read(&port->ept_rwsem);
	return ret;
}

static int rpmsg_pru_send(struct rpmsg_pru_port *port, void *buf, size_t len,
			  bool nonblock)
{
	int events, ret;
	long waited;

	for (;;) {
		events = atomic_read(&port->tx_events);
		ret = rpmsg_pru_trysend(port, buf, len);
		if (ret != -EAGAIN || nonblock)
			return ret;

		waited = wait_event_interruptible_timeout(port->wq,
							  atomic_read(&port->tx_events) != events ||
							  READ_ONCE(port->gone),
							  RPMSG_PRU_TX_RETRY);
		if (waited < 0)
			return waited;
	}
}

/*
 * Take the oldest message off the queue: 0 and the message, -EAGAIN if
 * there is none yet, -EPIPE if there is none and the channel is gone.
 */
static int rpmsg_pru_dequeue(struct rpmsg_pru_port *port, struct rpmsg_pru_msg **msgp)
{
	struct rpmsg_pru_msg *msg;
	int ret = 0;

	spin_lock_irq(&port->lock);
	msg = list_first_entry_or_null(&port->queue, struct rpmsg_pru_msg, node);
	if (msg) {
		list_del(&msg->node);
		WRITE_ONCE(port->queued, port->queued - 1);
		*msgp = msg;
	} else {
		ret = port->gone ? -EPIPE : -EAGAIN;
	}
	spin_unlock_irq(&port->lock);

	return ret;
}

/* Put back a message that could not be delivered, so that it is not lost. */
static void rpmsg_pru_requeue(struct rpmsg_pru_port *port, struct rpmsg_pru_msg *msg)
{
	spin_lock_irq(&port->lock);
	list_add(&msg->node, &port->queue);
	WRITE_ONCE(port->queued, port->queued + 1);
	spin_unlock_irq(&port->lock);
}

static bool rpmsg_pru_readable(struct rpmsg_pru_port *port)
{
	return READ_ONCE(port->queued) || READ_ONCE(port->gone);
}

static bool rpmsg_pru_nonblock(struct kiocb *iocb)
{
	return (iocb->ki_filp->f_flags & O_NONBLOCK) || (iocb->ki_flags & IOCB_NOWAIT);
}

static ssize_t rpmsg_pru_read_iter(struct kiocb *iocb, struct iov_iter *to)
{
	struct rpmsg_pru_port *port = iocb->ki_filp->private_data;
	struct rpmsg_pru_msg *msg;
	size_t len;
	int ret;

	/* A zero-length read takes nothing off the queue. */
	if (!iov_iter_count(to))
		return 0;

	for (;;) {
		ret = rpmsg_pru_dequeue(port, &msg);
		if (ret != -EAGAIN || rpmsg_pru_nonblock(iocb))
			break;
		if (wait_event_interruptible(port->wq, rpmsg_pru_readable(port)))
			return -ERESTARTSYS;
	}
	if (ret)
		return ret;

	/* Datagram semantics: what does not fit in the buffer is discarded. */
	len = min(iov_iter_count(to), msg->len);
	if (copy_to_iter(msg->data, len, to) != len) {
		rpmsg_pru_requeue(port, msg);
		return -EFAULT;
	}
	if (len < msg->len) {
		spin_lock_irq(&port->lock);
		port->rx_truncated++;
		spin_unlock_irq(&port->lock);
	}
	kfree(msg);

	return len;
}

static ssize_t rpmsg_pru_write_iter(struct kiocb *iocb, struct iov_iter *from)
{
	struct rpmsg_pru_port *port = iocb->ki_filp->private_data;
	size_t len = iov_iter_count(from);
	void *buf;
	int ret;

	if (len > RPMSG_PRU_MAX_PAYLOAD)
		return -EMSGSIZE;
	if (!len)
		return 0;

	buf = kmalloc(len, GFP_KERNEL);
	if (!buf)
		return -ENOMEM;

	if (copy_from_iter_full(buf, len, from))
		ret = rpmsg_pru_send(port, buf, len, rpmsg_pru_nonblock(iocb));
	else
		ret = -EFAULT;

	kfree(buf);
	return ret ? ret : len;
}

static __poll_t rpmsg_pru_poll(struct file *filp, poll_table *wait)
{
	struct rpmsg_pru_port *port = filp->private_data;
	__poll_t mask = 0;

	poll_wait(filp, &port->wq, wait);

	spin_lock_irq(&port->lock);
	if (port->queued)
		mask |= EPOLLIN | EPOLLRDNORM;
	if (port->gone)
		mask |= EPOLLHUP;
	spin_unlock_irq(&port->lock);

	down_read(&port->ept_rwsem);
	if (port->ept && rpmsg_pru_tx_ready(port))
		mask |= EPOLLOUT | EPOLLWRNORM;
	up_read(&port->ept_rwsem);

	return mask;
}

/* Each open file holds a reference on the port: it outlives the channel. */
static void rpmsg_pru_attach_file(struct rpmsg_pru_port *port, struct file *filp)
{
	get_device(&port->dev);
	filp->private_data = port;
}

static int rpmsg_pru_open(struct inode *inode, struct file *filp)
{
	struct rpmsg_pru_port *port = container_of(inode->i_cdev, struct rpmsg_pru_port, cdev);

	int ret;

	rpmsg_pru_attach_file(port, filp);
	ret = stream_open(inode, filp);
	/*
	 * Reads and writes honour IOCB_NOWAIT as O_NONBLOCK: preadv2()/
	 * pwritev2() with RWF_NOWAIT get EAGAIN instead of EOPNOTSUPP.
	 */
	filp->f_mode |= FMODE_NOWAIT;
	return ret;
}

static int rpmsg_pru_release(struct inode *inode, struct file *filp)
{
	struct rpmsg_pru_port *port = filp->private_data;

	put_device(&port->dev);
	return 0;
}

static const struct file_operations rpmsg_pru_fops = {
	.owner = THIS_MODULE,
	.open = rpmsg_pru_open,
	.release = rpmsg_pru_release,
	.read_iter = rpmsg_pru_read_iter,
	.write_iter = rpmsg_pru_write_iter,
	.poll = rpmsg_pru_poll,
};

static ssize_t rpmsg_pru_counter_show(struct rpmsg_pru_port *port, u64 *counter,
				      char *buf)
{
	u64 val;

	spin_lock_irq(&port->lock);
	val = *counter;
	spin_unlock_irq(&port->lock);

	return sysfs_emit(buf, "%llu\n", val);
}

static ssize_t rx_dropped_show(struct device *dev, struct device_attribute *attr,
			       char *buf)
{
	struct rpmsg_pru_port *port = dev_to_port(dev);

	return rpmsg_pru_counter_show(port, &port->rx_dropped, buf);
}
static DEVICE_ATTR_RO(rx_dropped);

static ssize_t rx_truncated_show(struct device *dev, struct device_attribute *attr,
				 char *buf)
{
	struct rpmsg_pru_port *port = dev_to_port(dev);

	return rpmsg_pru_counter_show(port, &port->rx_truncated, buf);
}
static DEVICE_ATTR_RO(rx_truncated);

static ssize_t rx_queued_show(struct device *dev, struct device_attribute *attr,
			      char *buf)
{
	struct rpmsg_pru_port *port = dev_to_port(dev);

	return sysfs_emit(buf, "%u\n", READ_ONCE(port->queued));
}
static DEVICE_ATTR_RO(rx_queued);

static struct attribute *rpmsg_pru_attrs[] = {
	&dev_attr_rx_dropped.attr,
	&dev_attr_rx_truncated.attr,
	&dev_attr_rx_queued.attr,
	NULL
};
ATTRIBUTE_GROUPS(rpmsg_pru);

static char *rpmsg_pru_devnode(PRUKIT_CLASS_DEVNODE_CONST struct device *dev,
			       umode_t *mode)
{
	/* The shipped udev rule gives the nodes to group "remoteproc". */
	if (mode)
		*mode = 0660;
	return NULL;
}

static struct class rpmsg_pru_class = {
	.name = "rpmsg_pru",
	.devnode = rpmsg_pru_devnode,
};

static void rpmsg_pru_dev_release(struct device *dev)
{
	struct rpmsg_pru_port *port = dev_to_port(dev);
	struct rpmsg_pru_msg *msg, *tmp;

	list_for_each_entry_safe(msg, tmp, &port->queue, node)
		kfree(msg);
	if (dev->devt)
		ida_free(&rpmsg_pru_minors, MINOR(dev->devt));
	kfree(port);
}

static int rpmsg_pru_probe(struct rpmsg_device *rpdev)
{
	struct rpmsg_channel_info chinfo = {
		.src = RPMSG_ADDR_ANY,
		.dst = RPMSG_ADDR_ANY,
	};
	struct rpmsg_pru_port *port;
	int minor, ret;

	port = kzalloc(sizeof(*port), GFP_KERNEL);
	if (!port)
		return -ENOMEM;

	init_rwsem(&port->ept_rwsem);
	atomic_set(&port->tx_events, 0);
	spin_lock_init(&port->lock);
	INIT_LIST_HEAD(&port->queue);
	init_waitqueue_head(&port->wq);

	device_initialize(&port->dev);
	port->dev.class = &rpmsg_pru_class;
	port->dev.parent = &rpdev->dev;
	port->dev.groups = rpmsg_pru_groups;
	port->dev.release = rpmsg_pru_dev_release;
	/* From here on, the last put_device() frees the port. */

	minor = ida_alloc_max(&rpmsg_pru_minors, RPMSG_PRU_MAX_DEVICES - 1, GFP_KERNEL);
	if (minor < 0) {
		ret = dev_err_probe(&rpdev->dev, minor, "no free minor number\n");
		goto put_port;
	}
	port->dev.devt = MKDEV(MAJOR(rpmsg_pru_devt), minor);

	ret = dev_set_name(&port->dev, "rpmsg_pru%u", rpdev->dst);
	if (ret)
		goto put_port;

	/*
	 * An endpoint of our own rather than the channel's default one, so
	 * that the receive callback has the port from the first message on.
	 */
	strscpy(chinfo.name, rpdev->id.name, sizeof(chinfo.name));
	port->ept = rpmsg_create_ept(rpdev, rpmsg_pru_cb, port, chinfo);
	if (!port->ept) {
		ret = dev_err_probe(&rpdev->dev, -ENOMEM, "cannot create an endpoint\n");
		goto put_port;
	}
	rpmsg_pru_attach_tx(port);

	cdev_init(&port->cdev, &rpmsg_pru_fops);
	port->cdev.owner = THIS_MODULE;
	ret = cdev_device_add(&port->cdev, &port->dev);
	if (ret) {
		dev_err_probe(&rpdev->dev, ret, "cannot add /dev/%s\n", dev_name(&port->dev));
		goto destroy_ept;
	}

	dev_set_drvdata(&rpdev->dev, port);
	dev_info(&rpdev->dev, "new rpmsg_pru device: /dev/%s\n", dev_name(&port->dev));
	return 0;

destroy_ept:
	rpmsg_pru_detach_tx(port);
	rpmsg_destroy_ept(port->ept);
put_port:
	put_device(&port->dev);
	return ret;
}

static void rpmsg_pru_remove(struct rpmsg_device *rpdev)
{
	struct rpmsg_pru_port *port = dev_get_drvdata(&rpdev->dev);

	cdev_device_del(&port->cdev, &port->dev);

	/* Wait for senders, then take the channel away from them. */
	down_write(&port->ept_rwsem);
	rpmsg_pru_detach_tx(port);
	rpmsg_destroy_ept(port->ept);
	port->ept = NULL;
	up_write(&port->ept_rwsem);

	spin_lock_irq(&port->lock);
	WRITE_ONCE(port->gone, true);
	spin_unlock_irq(&port->lock);
	wake_up_interruptible_all(&port->wq);

	/* Open files hold their own references; the last one frees the port. */
	put_device(&port->dev);
}

static const struct rpmsg_device_id rpmsg_pru_id_table[] = {
	{ .name = RPMSG_PRU_CHAN_NAME },
	{ },
};
MODULE_DEVICE_TABLE(rpmsg, rpmsg_pru_id_table);

static struct rpmsg_driver rpmsg_pru_driver = {
	.drv.name = KBUILD_MODNAME,
	.id_table = rpmsg_pru_id_table,
	.probe = rpmsg_pru_probe,
	.remove = rpmsg_pru_remove,
};

static int __init rpmsg_pru_init(void)
{
	int ret;

	if (!rx_queue_len) {
		pr_err("rx_queue_len must be at least 1\n");
		return -EINVAL;
	}

	ret = alloc_chrdev_region(&rpmsg_pru_devt, 0, RPMSG_PRU_MAX_DEVICES, "rpmsg_pru");
	if (ret)
		return ret;

	ret = class_register(&rpmsg_pru_class);
	if (ret)
		goto unregister_chrdev;

	ret = register_rpmsg_driver(&rpmsg_pru_driver);
	if (ret)
		goto unregister_class;

	return 0;

unregister_class:
	class_unregister(&rpmsg_pru_class);
unregister_chrdev:
	unregister_chrdev_region(rpmsg_pru_devt, RPMSG_PRU_MAX_DEVICES);
	return ret;
}
module_init(rpmsg_pru_init);

static void __exit rpmsg_pru_exit(void)
{
	unregister_rpmsg_driver(&rpmsg_pru_driver);
	class_unregister(&rpmsg_pru_class);
	unregister_chrdev_region(rpmsg_pru_devt, RPMSG_PRU_MAX_DEVICES);
}
module_exit(rpmsg_pru_exit);

#if IS_ENABLED(CONFIG_PRUKIT_RPMSG_PRU_KUNIT_TEST)
#include "rpmsg_pru_kunit.c"
#endif

MODULE_DESCRIPTION("Character devices for PRU rpmsg channels (/dev/rpmsg_pruN)");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
