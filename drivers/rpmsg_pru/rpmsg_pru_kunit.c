// SPDX-License-Identifier: GPL-2.0-only
/*
 * KUnit tests for rpmsg_pru, run against a fake rpmsg bus.
 *
 * Included at the end of rpmsg_pru.c when CONFIG_PRUKIT_RPMSG_PRU_KUNIT_TEST
 * is set, so that the tests reach the driver's static functions.  The fake
 * channel implements the rpmsg core's device and endpoint operations: it
 * records what the driver sends, delivers messages to the driver's
 * callback, has a number of transmit slots that the tests fill and free,
 * and is removed like a real channel whose remote processor stops.
 *
 * Files are opened on anonymous inodes with the driver's file operations
 * and used through kernel_read()/kernel_write()/vfs_poll().
 */
#include <kunit/test.h>
#include <linux/anon_inodes.h>
#include <linux/completion.h>
#include <linux/delay.h>
#include <linux/file.h>
#include <linux/kthread.h>

#include "rpmsg_internal.h"

#define FAKE_DST	30
#define FAKE_TX_SLOTS	4

struct fake_chan {
	struct rpmsg_device rpdev;
	struct rpmsg_endpoint *ept;
	struct mutex cb_lock;		/* serialises delivery and destroy_ept */
	spinlock_t tx_lock;		/* protects the tx_* fields */
	unsigned int tx_free;
	unsigned int tx_count;
	size_t tx_last_len;
	u8 tx_last[RPMSG_PRU_BUF_SIZE];
	u32 tx_sum;			/* sum of the first bytes of all sent messages */
	wait_queue_head_t tx_wq;
};

#define to_fake(r) container_of(r, struct fake_chan, rpdev)

#define EXPECT_BYTES(test, a, b, n) KUNIT_EXPECT_EQ(test, memcmp(a, b, n), 0)

static void fake_destroy_ept(struct rpmsg_endpoint *ept)
{
	struct fake_chan *fake = to_fake(ept->rpdev);

	mutex_lock(&fake->cb_lock);
	fake->ept = NULL;
	mutex_unlock(&fake->cb_lock);
	kfree(ept);
}

static int fake_trysend(struct rpmsg_endpoint *ept, void *data, int len)
{
	struct fake_chan *fake = to_fake(ept->rpdev);
	int ret = 0;

	spin_lock(&fake->tx_lock);
	if (!fake->tx_free) {
		ret = -ENOMEM;
	} else {
		fake->tx_free--;
		fake->tx_count++;
		fake->tx_sum += *(u8 *)data;
		fake->tx_last_len = len;
		memcpy(fake->tx_last, data, len);
	}
	spin_unlock(&fake->tx_lock);
	return ret;
}

static __poll_t fake_poll(struct rpmsg_endpoint *ept, struct file *filp, poll_table *wait)
{
	struct fake_chan *fake = to_fake(ept->rpdev);
	__poll_t mask;

	poll_wait(filp, &fake->tx_wq, wait);
	spin_lock(&fake->tx_lock);
	mask = fake->tx_free ? EPOLLOUT : 0;
	spin_unlock(&fake->tx_lock);
	return mask;
}

static const struct rpmsg_endpoint_ops fake_ept_ops = {
	.destroy_ept = fake_destroy_ept,
	.trysend = fake_trysend,
	.poll = fake_poll,
};

static struct rpmsg_endpoint *fake_create_ept(struct rpmsg_device *rpdev, rpmsg_rx_cb_t cb,
					      void *priv, struct rpmsg_channel_info chinfo)
{
	struct fake_chan *fake = to_fake(rpdev);
	struct rpmsg_endpoint *ept;

	ept = kzalloc(sizeof(*ept), GFP_KERNEL);
	if (!ept)
		return NULL;
	kref_init(&ept->refcount);
	mutex_init(&ept->cb_lock);
	ept->rpdev = rpdev;
	ept->cb = cb;
	ept->priv = priv;
	ept->addr = 1024;
	ept->ops = &fake_ept_ops;

	mutex_lock(&fake->cb_lock);
	fake->ept = ept;
	mutex_unlock(&fake->cb_lock);
	return ept;
}

static const struct rpmsg_device_ops fake_rpdev_ops = {
	.create_ept = fake_create_ept,
};

static void fake_release(struct device *dev)
{
	kfree(to_fake(container_of(dev, struct rpmsg_device, dev)));
}

/* Deliver a message from the "PRU", as the transport's receive path does. */
static void fake_deliver(struct fake_chan *fake, const void *data, int len)
{
	mutex_lock(&fake->cb_lock);
	if (fake->ept)
		fake->ept->cb(&fake->rpdev, (void *)data, len, fake->ept->priv, FAKE_DST);
	mutex_unlock(&fake->cb_lock);
}

/* The "PRU" consumed n transmit buffers: announce them as the transport does. */
static void fake_free_tx(struct fake_chan *fake, unsigned int n)
{
	spin_lock(&fake->tx_lock);
	fake->tx_free += n;
	spin_unlock(&fake->tx_lock);
	wake_up_interruptible(&fake->tx_wq);
}

static void fake_set_tx_free(struct fake_chan *fake, unsigned int n)
{
	spin_lock(&fake->tx_lock);
	fake->tx_free = n;
	spin_unlock(&fake->tx_lock);
}

static unsigned int fake_tx_count(struct fake_chan *fake)
{
	unsigned int n;

	spin_lock(&fake->tx_lock);
	n = fake->tx_count;
	spin_unlock(&fake->tx_lock);
	return n;
}

struct rpmsg_pru_test {
	struct device *root;
	struct fake_chan *fake;
	struct rpmsg_pru_port *port;
	bool registered;
};

static int rpmsg_pru_test_init(struct kunit *test)
{
	struct rpmsg_pru_test *t;
	struct fake_chan *fake;
	int ret;

	t = kunit_kzalloc(test, sizeof(*t), GFP_KERNEL);
	KUNIT_ASSERT_NOT_NULL(test, t);
	test->priv = t;

	t->root = root_device_register("rpmsg_pru_kunit");
	KUNIT_ASSERT_FALSE(test, IS_ERR(t->root));

	fake = kzalloc(sizeof(*fake), GFP_KERNEL);
	KUNIT_ASSERT_NOT_NULL(test, fake);
	mutex_init(&fake->cb_lock);
	spin_lock_init(&fake->tx_lock);
	init_waitqueue_head(&fake->tx_wq);
	fake->tx_free = FAKE_TX_SLOTS;
	strscpy(fake->rpdev.id.name, RPMSG_PRU_CHAN_NAME, sizeof(fake->rpdev.id.name));
	fake->rpdev.src = RPMSG_ADDR_ANY;
	fake->rpdev.dst = FAKE_DST;
	fake->rpdev.ops = &fake_rpdev_ops;
	fake->rpdev.dev.parent = t->root;
	fake->rpdev.dev.release = fake_release;

	ret = rpmsg_register_device(&fake->rpdev);
	KUNIT_ASSERT_EQ(test, ret, 0);
	/* Our own reference: the fake outlives its registration. */
	get_device(&fake->rpdev.dev);
	t->fake = fake;
	t->registered = true;

	t->port = dev_get_drvdata(&fake->rpdev.dev);
	KUNIT_ASSERT_NOT_NULL(test, t->port);
	get_device(&t->port->dev);
	return 0;
}

static void rpmsg_pru_test_remove(struct rpmsg_pru_test *t)
{
	if (t->registered)
		device_unregister(&t->fake->rpdev.dev);
	t->registered = false;
}

static void rpmsg_pru_test_exit(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;

	if (t->fake) {
		rpmsg_pru_test_remove(t);
		put_device(&t->fake->rpdev.dev);
	}
	if (t->port)
		put_device(&t->port->dev);
	if (!IS_ERR_OR_NULL(t->root))
		root_device_unregister(t->root);
}

static struct file *test_open(struct kunit *test, int flags)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp;

	filp = anon_inode_getfile("rpmsg_pru_kunit", &rpmsg_pru_fops, NULL, O_RDWR | flags);
	KUNIT_ASSERT_FALSE(test, IS_ERR(filp));
	rpmsg_pru_attach_file(t->port, filp);
	return filp;
}

static ssize_t test_read(struct file *filp, void *buf, size_t len)
{
	loff_t pos = 0;

	return kernel_read(filp, buf, len, &pos);
}

static ssize_t test_write(struct file *filp, const void *buf, size_t len)
{
	loff_t pos = 0;

	return kernel_write(filp, buf, len, &pos);
}

/* Runs a read or write in a thread of its own, to be blocked and woken. */
struct test_io {
	struct file *filp;
	bool write;
	size_t len;
	u8 buf[RPMSG_PRU_BUF_SIZE];
	ssize_t ret;
	struct completion done;
};

static int test_io_fn(void *data)
{
	struct test_io *io = data;

	io->ret = io->write ? test_write(io->filp, io->buf, io->len) :
			      test_read(io->filp, io->buf, io->len);
	complete(&io->done);
	return 0;
}

static struct test_io *test_io_start(struct kunit *test, struct file *filp, bool write,
				     size_t len)
{
	struct rpmsg_pru_test *t = test->priv;
	struct task_struct *task;
	struct test_io *io;
	int i;

	io = kunit_kzalloc(test, sizeof(*io), GFP_KERNEL);
	KUNIT_ASSERT_NOT_NULL(test, io);
	io->filp = filp;
	io->write = write;
	io->len = len;
	memset(io->buf, 0x5a, sizeof(io->buf));
	init_completion(&io->done);

	task = kthread_run(test_io_fn, io, "rpmsg_pru_kunit");
	KUNIT_ASSERT_FALSE(test, IS_ERR(task));

	/* Wait until it sleeps on the port (or is done already). */
	for (i = 0; i < 1000; i++) {
		/* Unlocked is enough: a stale answer only costs another lap. */
		if (waitqueue_active(&t->port->wq) || completion_done(&io->done))
			break;
		usleep_range(5000, 10000);
	}
	return io;
}

static ssize_t test_io_wait(struct kunit *test, struct test_io *io)
{
	KUNIT_ASSERT_NE_MSG(test, wait_for_completion_timeout(&io->done, 10 * HZ), 0,
			    "blocked %s did not return", io->write ? "write" : "read");
	return io->ret;
}

static void rpmsg_pru_test_probe(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;

	KUNIT_EXPECT_STREQ(test, dev_name(&t->port->dev), "rpmsg_pru30");
	KUNIT_EXPECT_EQ(test, MAJOR(t->port->dev.devt), MAJOR(rpmsg_pru_devt));
	KUNIT_EXPECT_PTR_EQ(test, t->port->dev.parent, &t->fake->rpdev.dev);
	KUNIT_EXPECT_NOT_NULL(test, t->port->ept);
	/* The transport's wait queue was found through its poll operation. */
	KUNIT_EXPECT_PTR_EQ(test, t->port->tx_whead, &t->fake->tx_wq);
}

static void rpmsg_pru_test_boundaries(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, O_NONBLOCK);
	u8 big[RPMSG_PRU_MAX_PAYLOAD];
	char buf[RPMSG_PRU_BUF_SIZE];
	int i;

	for (i = 0; i < sizeof(big); i++)
		big[i] = i * 7;
	fake_deliver(t->fake, "abc", 3);
	fake_deliver(t->fake, "defgh", 5);
	fake_deliver(t->fake, big, sizeof(big));
	fake_deliver(t->fake, "", 0);
	fake_deliver(t->fake, "z", 1);

	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), 3);
	EXPECT_BYTES(test, buf, "abc", 3);
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), 5);
	EXPECT_BYTES(test, buf, "defgh", 5);
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), sizeof(big));
	EXPECT_BYTES(test, buf, big, sizeof(big));
	/* An empty message is a read of 0 bytes, not the end of anything. */
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), 0);
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), 1);
	KUNIT_EXPECT_EQ(test, buf[0], 'z');
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), -EAGAIN);
	KUNIT_EXPECT_EQ(test, t->port->rx_truncated, 0);
	fput(filp);
}

static void rpmsg_pru_test_short_read(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, O_NONBLOCK);
	char buf[16];

	fake_deliver(t->fake, "0123456789", 10);
	fake_deliver(t->fake, "next", 4);

	/* A zero-length read consumes nothing. */
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, 0), 0);
	KUNIT_EXPECT_EQ(test, t->port->queued, 2);

	memset(buf, 0, sizeof(buf));
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, 4), 4);
	EXPECT_BYTES(test, buf, "0123", 4);
	KUNIT_EXPECT_EQ(test, buf[4], 0);
	KUNIT_EXPECT_EQ(test, t->port->rx_truncated, 1);
	/* The rest of the short-read message is gone; the next one is whole. */
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), 4);
	EXPECT_BYTES(test, buf, "next", 4);
	KUNIT_EXPECT_EQ(test, t->port->rx_truncated, 1);
	fput(filp);
}

static void rpmsg_pru_test_write(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, 0);
	u8 buf[RPMSG_PRU_MAX_PAYLOAD + 1];
	int i;

	for (i = 0; i < sizeof(buf); i++)
		buf[i] = i ^ 0xa5;

	KUNIT_EXPECT_EQ(test, test_write(filp, buf, RPMSG_PRU_MAX_PAYLOAD), RPMSG_PRU_MAX_PAYLOAD);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 1);
	KUNIT_EXPECT_EQ(test, t->fake->tx_last_len, RPMSG_PRU_MAX_PAYLOAD);
	EXPECT_BYTES(test, t->fake->tx_last, buf, RPMSG_PRU_MAX_PAYLOAD);

	/* Too big: refused whole, nothing sent. */
	KUNIT_EXPECT_EQ(test, test_write(filp, buf, sizeof(buf)), -EMSGSIZE);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 1);

	/* Nothing to send: nothing sent. */
	KUNIT_EXPECT_EQ(test, test_write(filp, buf, 0), 0);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 1);

	KUNIT_EXPECT_EQ(test, test_write(filp, "hi", 2), 2);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 2);
	KUNIT_EXPECT_EQ(test, t->fake->tx_last_len, 2);
	EXPECT_BYTES(test, t->fake->tx_last, "hi", 2);
	fput(filp);
}

static void rpmsg_pru_test_overflow(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, O_NONBLOCK);
	unsigned int i, extra = 5;
	u32 seq;

	for (i = 0; i < rx_queue_len + extra; i++)
		fake_deliver(t->fake, &i, sizeof(i));

	KUNIT_EXPECT_EQ(test, t->port->queued, rx_queue_len);
	KUNIT_EXPECT_EQ(test, t->port->rx_dropped, extra);

	/* The queue kept the oldest messages, in order; the newest were dropped. */
	for (i = 0; i < rx_queue_len; i++) {
		KUNIT_ASSERT_EQ(test, test_read(filp, &seq, sizeof(seq)), sizeof(seq));
		KUNIT_ASSERT_EQ(test, seq, i);
	}
	KUNIT_EXPECT_EQ(test, test_read(filp, &seq, sizeof(seq)), -EAGAIN);

	/* There is room again. */
	fake_deliver(t->fake, "x", 1);
	KUNIT_EXPECT_EQ(test, t->port->queued, 1);
	KUNIT_EXPECT_EQ(test, t->port->rx_dropped, extra);
	fput(filp);
}

static void rpmsg_pru_test_nonblock(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, O_NONBLOCK);
	char buf[8];

	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), -EAGAIN);

	/* All transmit buffers busy: EAGAIN at once, nothing sent. */
	fake_set_tx_free(t->fake, 0);
	KUNIT_EXPECT_EQ(test, test_write(filp, "abc", 3), -EAGAIN);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 0);

	fake_free_tx(t->fake, 1);
	KUNIT_EXPECT_EQ(test, test_write(filp, "abc", 3), 3);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 1);
	KUNIT_EXPECT_EQ(test, test_write(filp, "abc", 3), -EAGAIN);
	fput(filp);
}

static void rpmsg_pru_test_blocking_write(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, 0);
	struct test_io *io;

	fake_set_tx_free(t->fake, 0);
	io = test_io_start(test, filp, true, 7);
	KUNIT_EXPECT_FALSE(test, completion_done(&io->done));
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 0);

	/* The transport announces a free buffer: the writer goes through. */
	fake_free_tx(t->fake, 1);
	KUNIT_EXPECT_EQ(test, test_io_wait(test, io), 7);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 1);
	KUNIT_EXPECT_EQ(test, t->fake->tx_last_len, 7);
	fput(filp);
}

/*
 * virtio's rpmsg bus has no poll operation and never announces a freed
 * transmit buffer: a message from the remote side lets blocked writers retry.
 */
static void rpmsg_pru_test_blocking_write_unannounced(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, 0);
	struct test_io *io;
	int events;

	/* As if the transport had no poll operation */
	rpmsg_pru_detach_tx(t->port);
	fake_set_tx_free(t->fake, 0);
	io = test_io_start(test, filp, true, 7);
	KUNIT_EXPECT_FALSE(test, completion_done(&io->done));

	events = atomic_read(&t->port->tx_events);
	/* The "PRU" takes the message, silently, and answers */
	fake_set_tx_free(t->fake, 1);
	fake_deliver(t->fake, "ack", 3);
	KUNIT_EXPECT_NE(test, atomic_read(&t->port->tx_events), events);
	KUNIT_EXPECT_EQ(test, test_io_wait(test, io), 7);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 1);
	fput(filp);
}

static void rpmsg_pru_test_poll(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, O_NONBLOCK);
	char buf[8];

	KUNIT_EXPECT_EQ(test, vfs_poll(filp, NULL), EPOLLOUT | EPOLLWRNORM);
	fake_deliver(t->fake, "m", 1);
	KUNIT_EXPECT_EQ(test, vfs_poll(filp, NULL),
			EPOLLIN | EPOLLRDNORM | EPOLLOUT | EPOLLWRNORM);
	fake_set_tx_free(t->fake, 0);
	KUNIT_EXPECT_EQ(test, vfs_poll(filp, NULL), EPOLLIN | EPOLLRDNORM);
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), 1);
	KUNIT_EXPECT_EQ(test, vfs_poll(filp, NULL), 0);
	fake_free_tx(t->fake, 1);
	KUNIT_EXPECT_EQ(test, vfs_poll(filp, NULL), EPOLLOUT | EPOLLWRNORM);
	fput(filp);
}

static void rpmsg_pru_test_remove_blocked_reader(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, 0);
	struct test_io *io;

	io = test_io_start(test, filp, false, 64);
	KUNIT_EXPECT_FALSE(test, completion_done(&io->done));

	rpmsg_pru_test_remove(t);
	KUNIT_EXPECT_EQ(test, test_io_wait(test, io), -EPIPE);
	fput(filp);
}

static void rpmsg_pru_test_remove_blocked_writer(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, 0);
	struct test_io *io;

	fake_set_tx_free(t->fake, 0);
	io = test_io_start(test, filp, true, 5);
	KUNIT_EXPECT_FALSE(test, completion_done(&io->done));

	rpmsg_pru_test_remove(t);
	KUNIT_EXPECT_EQ(test, test_io_wait(test, io), -EPIPE);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 0);
	fput(filp);
}

static void rpmsg_pru_test_remove_open(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct file *filp = test_open(test, 0);
	char buf[8];

	fake_deliver(t->fake, "last", 4);
	rpmsg_pru_test_remove(t);

	KUNIT_EXPECT_NULL(test, t->port->ept);
	KUNIT_EXPECT_NULL(test, t->port->tx_whead);
	/* What arrived before the channel went away can still be read... */
	KUNIT_EXPECT_EQ(test, vfs_poll(filp, NULL), EPOLLIN | EPOLLRDNORM | EPOLLHUP);
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), 4);
	EXPECT_BYTES(test, buf, "last", 4);
	/* ...then every call fails cleanly, without blocking. */
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), -EPIPE);
	KUNIT_EXPECT_EQ(test, test_write(filp, "x", 1), -EPIPE);
	KUNIT_EXPECT_EQ(test, vfs_poll(filp, NULL), EPOLLHUP);
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), 0);

	/* A file opened after removal (a race with open) behaves the same. */
	fput(filp);
	filp = test_open(test, O_NONBLOCK);
	KUNIT_EXPECT_EQ(test, test_read(filp, buf, sizeof(buf)), -EPIPE);
	fput(filp);
}

#define CONC_THREADS	2
#define CONC_MSGS	200

struct conc_ctx {
	struct file *filp;
	struct fake_chan *fake;
	bool writer;
	unsigned int done;	/* messages read or written */
	unsigned long seen[BITS_TO_LONGS(CONC_THREADS * CONC_MSGS)];
	int err;
	struct completion finished;
};

static int conc_fn(void *data)
{
	struct conc_ctx *c = data;
	u32 v;
	ssize_t ret;

	while (c->done < CONC_MSGS) {
		if (c->writer) {
			v = c->done;
			ret = test_write(c->filp, &v, 1);
			if (ret != 1) {
				c->err = ret;
				break;
			}
		} else {
			ret = test_read(c->filp, &v, sizeof(v));
			if (ret != sizeof(v) || v >= CONC_THREADS * CONC_MSGS ||
			    test_and_set_bit(v, c->seen)) {
				c->err = ret < 0 ? ret : -EIO;
				break;
			}
		}
		c->done++;
	}
	complete(&c->finished);
	return 0;
}

static int conc_free_tx_fn(void *data)
{
	struct conc_ctx *c = data;

	/* The "PRU" consumes what the writers send, a few buffers at a time. */
	while (fake_tx_count(c->fake) < CONC_THREADS * CONC_MSGS) {
		fake_free_tx(c->fake, 2);
		usleep_range(50, 100);
	}
	complete(&c->finished);
	return 0;
}

static void rpmsg_pru_test_concurrent(struct kunit *test)
{
	struct rpmsg_pru_test *t = test->priv;
	struct conc_ctx *ctx;
	unsigned int i, sum = 0, expect_sum = 0;
	int n;

	ctx = kunit_kcalloc(test, 2 * CONC_THREADS + 1, sizeof(*ctx), GFP_KERNEL);
	KUNIT_ASSERT_NOT_NULL(test, ctx);
	fake_set_tx_free(t->fake, 0);

	for (n = 0; n < 2 * CONC_THREADS + 1; n++) {
		ctx[n].filp = test_open(test, 0);
		ctx[n].fake = t->fake;
		ctx[n].writer = n >= CONC_THREADS;
		init_completion(&ctx[n].finished);
		KUNIT_ASSERT_FALSE(test, IS_ERR(kthread_run(n < 2 * CONC_THREADS ? conc_fn :
							    conc_free_tx_fn,
							    &ctx[n], "rpmsg_pru_conc")));
	}

	/* Deliver sequence numbers while readers and writers run. */
	for (i = 0; i < CONC_THREADS * CONC_MSGS; i++) {
		while (READ_ONCE(t->port->queued) >= rx_queue_len)
			usleep_range(50, 100);
		fake_deliver(t->fake, &i, sizeof(i));
	}

	for (n = 0; n < 2 * CONC_THREADS + 1; n++) {
		KUNIT_ASSERT_NE(test, wait_for_completion_timeout(&ctx[n].finished, 30 * HZ), 0);
		KUNIT_EXPECT_EQ(test, ctx[n].err, 0);
	}

	/* Every message went to exactly one reader. */
	for (i = 0; i < CONC_THREADS * CONC_MSGS; i++) {
		n = test_bit(i, ctx[0].seen) + test_bit(i, ctx[1].seen);
		KUNIT_EXPECT_EQ_MSG(test, n, 1, "message %u read %d times", i, n);
	}
	KUNIT_EXPECT_EQ(test, ctx[0].done + ctx[1].done, CONC_THREADS * CONC_MSGS);
	KUNIT_EXPECT_EQ(test, t->port->rx_dropped, 0);

	/* Every write was sent once. */
	KUNIT_EXPECT_EQ(test, fake_tx_count(t->fake), CONC_THREADS * CONC_MSGS);
	for (i = 0; i < CONC_MSGS; i++)
		expect_sum += CONC_THREADS * (i & 0xff);
	sum = t->fake->tx_sum;
	KUNIT_EXPECT_EQ(test, sum, expect_sum);

	for (n = 0; n < 2 * CONC_THREADS + 1; n++)
		fput(ctx[n].filp);
}

static struct kunit_case rpmsg_pru_test_cases[] = {
	KUNIT_CASE(rpmsg_pru_test_probe),
	KUNIT_CASE(rpmsg_pru_test_boundaries),
	KUNIT_CASE(rpmsg_pru_test_short_read),
	KUNIT_CASE(rpmsg_pru_test_write),
	KUNIT_CASE(rpmsg_pru_test_overflow),
	KUNIT_CASE(rpmsg_pru_test_nonblock),
	KUNIT_CASE(rpmsg_pru_test_blocking_write),
	KUNIT_CASE(rpmsg_pru_test_blocking_write_unannounced),
	KUNIT_CASE(rpmsg_pru_test_poll),
	KUNIT_CASE(rpmsg_pru_test_remove_blocked_reader),
	KUNIT_CASE(rpmsg_pru_test_remove_blocked_writer),
	KUNIT_CASE(rpmsg_pru_test_remove_open),
	KUNIT_CASE(rpmsg_pru_test_concurrent),
	{}
};

static struct kunit_suite rpmsg_pru_test_suite = {
	.name = "rpmsg_pru",
	.init = rpmsg_pru_test_init,
	.exit = rpmsg_pru_test_exit,
	.test_cases = rpmsg_pru_test_cases,
};

kunit_test_suite(rpmsg_pru_test_suite);
