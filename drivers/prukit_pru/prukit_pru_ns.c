// SPDX-License-Identifier: GPL-2.0-only
/*
 * prukit_pru - the PRU support package's 72-byte name service message
 *
 * A PRU firmware announces its rpmsg channel ("rpmsg-pru" at port 30 or
 * 31) with a name service message to address 53.  The PRU Software Support
 * Package's releases for TI's 4.x kernels, and the firmware built with
 * them, send a 72-byte form: { char name[32]; char desc[32]; u32 addr;
 * u32 flags; }.  TI's kernels take it ("TI-HACK: rpmsg: introduce
 * rpmsg_ns_msg_ext"); upstream's name service takes only the 40-byte form
 * without desc and drops the other ("malformed ns msg (72)"), so no
 * channel, and no /dev/rpmsg_pru30, comes of it.
 *
 * Since v5.11 the name service is an rpmsg device of its own, bound to the
 * rpmsg_ns driver, whose endpoint (rpdev->ept) receives the messages.  Here
 * that endpoint's callback is wrapped, for the name services of PRU remote
 * processors that prukit_pru knows and nothing else: a 72-byte message is
 * rewritten in place into the 40-byte one (addr and flags move up over
 * desc) and handed on, every other one is handed on untouched.  The
 * wrapping happens when the name service device binds (a bus notifier on
 * the rpmsg bus, reached through a driver registered only for it), which is
 * before its virtio device is ready and the firmware can send anything.
 * This was the least invasive place: the kernel's modules stay as they
 * are, the firmware stays as built, and nothing but the one message of
 * that size to that endpoint changes.  Where the kernel's name service
 * takes the 72-byte form itself (TI's), none of this is built
 * (include/compat.h).
 *
 * The callback is changed and given back under the endpoint's cb_lock,
 * which the bus holds while it calls it, so no call of the wrapper is
 * under way when the module goes.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include "compat.h"

#ifdef PRUKIT_PRU_NS_HOOK

#include <linux/device.h>
#include <linux/list.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/rpmsg.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux/string.h>

#include "prukit_pru_ns.h"

/* The name service's driver, upstream's rpmsg_ns */
#define PRU_NS_DRIVER		"rpmsg_ns"
#define PRU_NS_NAME_SIZE	32
/* The two forms: name, [desc,] addr, flags */
#define PRU_NS_LEN		(PRU_NS_NAME_SIZE + 8)
#define PRU_NS_DESC_LEN		(2 * PRU_NS_NAME_SIZE + 8)

/**
 * struct pru_ns - the name service endpoint of a PRU processor's rpmsg bus
 * @node: in pru_ns_list
 * @rpdev: the name service device (a reference is held)
 * @ept: its endpoint, whose callback is wrapped
 * @cb: the callback the endpoint had (rpmsg_ns's)
 */
struct pru_ns {
	struct list_head node;
	struct rpmsg_device *rpdev;
	struct rpmsg_endpoint *ept;
	rpmsg_rx_cb_t cb;
};

static LIST_HEAD(pru_ns_list);
/* Protects pru_ns_list; taken inside an endpoint's cb_lock, never around it */
static DEFINE_SPINLOCK(pru_ns_lock);

static rpmsg_rx_cb_t pru_ns_cb_of(struct rpmsg_device *rpdev)
{
	rpmsg_rx_cb_t cb = NULL;
	struct pru_ns *ns;

	spin_lock(&pru_ns_lock);
	list_for_each_entry(ns, &pru_ns_list, node)
		if (ns->rpdev == rpdev)
			cb = ns->cb;
	spin_unlock(&pru_ns_lock);
	return cb;
}

/* The endpoint's callback while wrapped; the bus holds its cb_lock */
static int pru_ns_cb(struct rpmsg_device *rpdev, void *data, int len, void *priv, u32 src)
{
	rpmsg_rx_cb_t cb = pru_ns_cb_of(rpdev);
	char desc[PRU_NS_NAME_SIZE];
	u8 *msg = data;

	if (!cb)
		return -ENODEV;
	if (len == PRU_NS_DESC_LEN) {
		memcpy(desc, msg + PRU_NS_NAME_SIZE, PRU_NS_NAME_SIZE);
		/* addr and flags over desc: the 40-byte form */
		memmove(msg + PRU_NS_NAME_SIZE, msg + 2 * PRU_NS_NAME_SIZE, 8);
		len = PRU_NS_LEN;
		dev_info(&rpdev->dev, "a 72-byte name service message (TI's support package; \"%*pE\") is taken as the 40-byte one\n",
			 (int)strnlen(desc, PRU_NS_NAME_SIZE), desc);
	}
	return cb(rpdev, data, len, priv, src);
}

/* The name service device's endpoint is the bus's: wrap its callback */
static void pru_ns_hook(struct device *dev)
{
	struct rpmsg_device *rpdev = container_of(dev, struct rpmsg_device, dev);
	struct rpmsg_endpoint *ept = rpdev->ept;
	struct pru_ns *ns;

	if (!ept || !prukit_pru_kick_owns(dev))
		return;
	ns = kzalloc(sizeof(*ns), GFP_KERNEL);
	if (!ns) {
		dev_warn(dev, "no memory: 72-byte name service messages will be refused\n");
		return;
	}
	ns->rpdev = rpdev;
	ns->ept = ept;
	get_device(dev);

	mutex_lock(&ept->cb_lock);
	ns->cb = ept->cb;
	if (ns->cb && ns->cb != pru_ns_cb) {
		spin_lock(&pru_ns_lock);
		list_add_tail(&ns->node, &pru_ns_list);
		spin_unlock(&pru_ns_lock);
		ept->cb = pru_ns_cb;
		ns = NULL;
	}
	mutex_unlock(&ept->cb_lock);
	if (ns) {
		put_device(dev);
		kfree(ns);
	}
}

/* Give the endpoint its callback back; it is still there (bound device) */
static void pru_ns_unhook(struct pru_ns *ns)
{
	struct rpmsg_endpoint *ept = ns->ept;

	mutex_lock(&ept->cb_lock);
	if (ept->cb == pru_ns_cb)
		ept->cb = ns->cb;
	mutex_unlock(&ept->cb_lock);
	spin_lock(&pru_ns_lock);
	list_del(&ns->node);
	spin_unlock(&pru_ns_lock);
	put_device(&ns->rpdev->dev);
	kfree(ns);
}

static struct pru_ns *pru_ns_find(struct device *dev)
{
	struct pru_ns *ns, *found = NULL;

	spin_lock(&pru_ns_lock);
	list_for_each_entry(ns, &pru_ns_list, node)
		if (&ns->rpdev->dev == dev)
			found = ns;
	spin_unlock(&pru_ns_lock);
	return found;
}

static bool pru_ns_is_ns(struct device *dev)
{
	return dev->driver && !strcmp(dev->driver->name, PRU_NS_DRIVER);
}

/* Serialises hooking and unhooking (the notifier and module exit) */
static DEFINE_MUTEX(pru_ns_mutex);

static int pru_ns_notify(struct notifier_block *nb, unsigned long action, void *data)
{
	struct device *dev = data;
	struct pru_ns *ns;

	mutex_lock(&pru_ns_mutex);
	switch (action) {
	case BUS_NOTIFY_BOUND_DRIVER:
		if (pru_ns_is_ns(dev) && !pru_ns_find(dev))
			pru_ns_hook(dev);
		break;
	case BUS_NOTIFY_UNBIND_DRIVER:
		/* before rpmsg_ns's remove destroys the endpoint */
		ns = pru_ns_find(dev);
		if (ns)
			pru_ns_unhook(ns);
		break;
	}
	mutex_unlock(&pru_ns_mutex);
	return NOTIFY_DONE;
}

static struct notifier_block pru_ns_nb = {
	.notifier_call = pru_ns_notify,
};

/* Registered for its bus only: it matches no device (no id table) */
static int pru_ns_probe(struct rpmsg_device *rpdev)
{
	return -ENODEV;
}

static struct rpmsg_driver pru_ns_driver = {
	.drv.name = "prukit_pru_ns",
	.probe = pru_ns_probe,
};

static int pru_ns_existing(struct device *dev, void *data)
{
	device_lock(dev);
	mutex_lock(&pru_ns_mutex);
	if (pru_ns_is_ns(dev) && !pru_ns_find(dev))
		pru_ns_hook(dev);
	mutex_unlock(&pru_ns_mutex);
	device_unlock(dev);
	return 0;
}

/**
 * prukit_pru_ns_init() - take 72-byte name service messages on the rpmsg
 *	buses of PRU processors from now on
 *
 * Return: 0, or what registering the driver or the notifier returned.
 */
int prukit_pru_ns_init(void)
{
	int ret;

	ret = register_rpmsg_driver(&pru_ns_driver);
	if (ret)
		return ret;
	ret = bus_register_notifier(pru_ns_driver.drv.bus, &pru_ns_nb);
	if (ret)
		goto unregister_driver;
	bus_for_each_dev(pru_ns_driver.drv.bus, NULL, NULL, pru_ns_existing);
	return 0;

unregister_driver:
	unregister_rpmsg_driver(&pru_ns_driver);
	return ret;
}

/**
 * prukit_pru_ns_exit() - give every wrapped endpoint its callback back
 */
void prukit_pru_ns_exit(void)
{
	struct pru_ns *ns;

	bus_unregister_notifier(pru_ns_driver.drv.bus, &pru_ns_nb);
	for (;;) {
		struct device *dev;

		spin_lock(&pru_ns_lock);
		ns = list_first_entry_or_null(&pru_ns_list, struct pru_ns, node);
		spin_unlock(&pru_ns_lock);
		if (!ns)
			break;
		/* an unbind meanwhile (no notifier now) destroyed the endpoint */
		dev = get_device(&ns->rpdev->dev);
		device_lock(dev);
		mutex_lock(&pru_ns_mutex);
		if (pru_ns_is_ns(dev) && ns->rpdev->ept == ns->ept) {
			pru_ns_unhook(ns);
		} else {
			spin_lock(&pru_ns_lock);
			list_del(&ns->node);
			spin_unlock(&pru_ns_lock);
			put_device(dev);
			kfree(ns);
		}
		mutex_unlock(&pru_ns_mutex);
		device_unlock(dev);
		put_device(dev);
	}
	unregister_rpmsg_driver(&pru_ns_driver);
}

#endif /* PRUKIT_PRU_NS_HOOK */
