// SPDX-License-Identifier: GPL-2.0-only
/*
 * prukit_pru - the one way every prukit driver takes and uses a PRU core
 *
 * The contract (Documentation/writing-a-driver.rst), the same on every
 * kernel a board runs:
 *  - the driver's node names its cores in "ti,prus" (and their firmware in
 *    "firmware-name"); devm_prukit_pru_get() holds one, exclusively, until
 *    the driver unbinds, and the driver core unbinds the driver before the
 *    core's own device goes (a device link);
 *  - prukit_pru_boot() sets the firmware and starts the core; the layer
 *    shuts it down again when the driver unbinds;
 *  - the control block (include/prukit/pru_ctrl.h) in the core's data RAM
 *    is reached through prukit_pru_map() as __iomem, checked with
 *    prukit_pru_ctrl_check(), and commands go through it without any
 *    interrupt towards the PRU;
 *  - PRU -> ARM events are ordinary interrupts of the driver's own node
 *    (devm_prukit_pru_request_irq());
 *  - bulk data lives in DMA buffers of the driver's device (32-bit, set up
 *    here), whose bus addresses the PRU reaches over its OCP master port.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/delay.h>
#include <linux/device.h>
#include <linux/dma-direct.h>	/* struct bus_dma_region */
#include <linux/dma-mapping.h>
#include <linux/err.h>
#include <linux/firmware.h>
#include <linux/io.h>
#include <linux/jiffies.h>
#include <linux/kernfs.h>
#include <linux/list.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/of_address.h>
#include <linux/of_irq.h>
#include <linux/of_platform.h>
#include <linux/platform_device.h>
#include <linux/remoteproc.h>
#include <linux/slab.h>
#include <linux/sysfs.h>

#include "compat.h"
#include "prukit_pru.h"
#include "prukit_pru_fw.h"

/* Cores taken through rproc_get_by_phandle(), which does not claim them. */
struct prukit_pru_claim {
	struct list_head node;
	struct rproc *rproc;
	struct device *owner;
};

static LIST_HEAD(prukit_pru_claims);
static DEFINE_MUTEX(prukit_pru_claims_lock);	/* protects prukit_pru_claims */

static int prukit_pru_claim(struct device *dev, struct rproc *rproc)
{
	struct prukit_pru_claim *c;
	int ret = 0;

	mutex_lock(&prukit_pru_claims_lock);
	list_for_each_entry(c, &prukit_pru_claims, node) {
		if (c->rproc == rproc) {
			dev_err(dev, "PRU %s is already used by %s\n", dev_name(&rproc->dev),
				dev_name(c->owner));
			ret = -EBUSY;
			goto unlock;
		}
	}
	c = kzalloc(sizeof(*c), GFP_KERNEL);
	if (!c) {
		ret = -ENOMEM;
		goto unlock;
	}
	c->rproc = rproc;
	c->owner = dev;
	list_add(&c->node, &prukit_pru_claims);
unlock:
	mutex_unlock(&prukit_pru_claims_lock);
	return ret;
}

static void prukit_pru_unclaim(struct rproc *rproc)
{
	struct prukit_pru_claim *c;

	mutex_lock(&prukit_pru_claims_lock);
	list_for_each_entry(c, &prukit_pru_claims, node) {
		if (c->rproc == rproc) {
			list_del(&c->node);
			kfree(c);
			break;
		}
	}
	mutex_unlock(&prukit_pru_claims_lock);
}

/*
 * A core whose node, or an ancestor's (its PRUSS, the target module), is
 * disabled never gets a device: say which node, rather than wait for it.
 */
static struct device_node *prukit_pru_disabled(struct device_node *np)
{
	struct device_node *p;

	for (p = of_node_get(np); p; p = of_get_next_parent(p))
		if (!of_device_is_available(p))
			return p;
	return NULL;
}

/*
 * The core's remote processor, from whichever driver owns the core: the
 * kernel's PRU remoteproc driver hands its cores out with pru_rproc_get(),
 * which answers -ENODEV for a core that is not its own (another remoteproc
 * driver's); those, and every core on kernels without pru_rproc_get(), are
 * found with rproc_get_by_phandle().  Each way it can fail ends in a
 * message that says which and what to do: a disabled node (-ENODEV), a
 * core bound to a driver that is no remote processor, UIO's say (-EBUSY),
 * and, as a deferral's reason (devices_deferred), a core no driver has
 * taken yet (pru_rproc not loaded).
 */
static struct rproc *prukit_pru_find(struct prukit_pru *pru, struct device_node *np)
{
	struct device *dev = pru->dev;
	struct device_node *off;
	struct platform_device *pdev;
	struct rproc *rproc;

	off = prukit_pru_disabled(np);
	if (off) {
		const char *status;

		if (of_property_read_string(off, "status", &status))
			status = "?";
		dev_err(dev, "PRU %pOF is disabled: %pOF has status \"%s\"; enable it in an overlay (prukit's set status = \"okay\" on pruss_tm, pruss, pruss_intc and the cores)\n",
			np, off, status);
		of_node_put(off);
		return ERR_PTR(-ENODEV);
	}

	rproc = prukit_pru_rproc_get(dev->of_node, pru->index);
	if (!IS_ERR(rproc)) {
		pru->via_pru_rproc = true;
		return rproc;
	}
	if (PTR_ERR(rproc) != -ENODEV && PTR_ERR(rproc) != -EPROBE_DEFER) {
		dev_err(dev, "PRU %pOF not available: pru_rproc_get() says %pe%s\n", np, rproc,
			PTR_ERR(rproc) == -EBUSY ?
			" (another driver holds it, or it runs firmware)" : "");
		return rproc;
	}
	if (PTR_ERR(rproc) == -ENODEV) {
		rproc = rproc_get_by_phandle(np->phandle);
		if (rproc)
			return rproc;
	}

	/*
	 * The core's driver, read as dev_driver_string() does (taking the
	 * core's device lock here, in the consumer's probe, would order the
	 * two devices' locks against the driver core's unbind of the core).
	 */
	pdev = of_find_device_by_node(np);
	if (pdev) {
		const struct device_driver *drv = READ_ONCE(pdev->dev.driver);

		if (drv && strcmp(drv->name, "pru-rproc")) {
			dev_err(dev, "PRU %pOF is bound to %s, which is no remote processor driver: unbind it (echo %s > /sys/bus/platform/drivers/%s/unbind) or drop the overlay that gives it the core\n",
				np, drv->name, dev_name(&pdev->dev), drv->name);
			put_device(&pdev->dev);
			return ERR_PTR(-EBUSY);
		}
		put_device(&pdev->dev);
	}
	return ERR_PTR(dev_err_probe(dev, -EPROBE_DEFER,
				     "PRU %pOF not available: no remote processor driver has it yet (is pru_rproc loaded? modprobe pru_rproc)\n",
				     np));
}

/*
 * remoteproc's sysfs files that change a core: the ones mainline's
 * rproc_is_visible() makes read-only for a core with sysfs_read_only.
 */
static const char * const prukit_pru_rproc_files[PRUKIT_PRU_RPROC_FILES] = {
	"state", "firmware", "recovery", "coredump",
};

/*
 * Lock users out of the core's remoteproc sysfs files while a driver holds
 * it, on every kernel: pru_rproc_get() sets rproc->sysfs_read_only, but
 * remoteproc applies it only when it registers the core, and 5.10 has no
 * such flag at all.  Files without write permission cannot be opened for
 * writing in sysfs, by root either (KERNFS_ROOT_EXTRA_OPEN_PERM_CHECK).  A
 * file opened before stays writable through that descriptor; the layer's
 * boot and shutdown check what happened under rproc->lock.
 */
static void prukit_pru_sysfs_lock(struct prukit_pru *pru, bool lock)
{
	struct kobject *kobj = &pru->rproc->dev.kobj;
	unsigned int i;
	umode_t mode;
	int ret;

	for (i = 0; i < PRUKIT_PRU_RPROC_FILES; i++) {
		struct attribute attr = { .name = prukit_pru_rproc_files[i] };
		struct kernfs_node *kn;

		if (!lock) {
			if (pru->sysfs_mode[i] &&
			    sysfs_chmod_file(kobj, &attr, pru->sysfs_mode[i]))
				dev_warn(pru->dev, "cannot give PRU %s's %s its mode back\n",
					 dev_name(&pru->rproc->dev), attr.name);
			continue;
		}
		kn = kernfs_find_and_get(kobj->sd, attr.name);
		if (!kn)
			continue;
		mode = kn->mode & 0777;
		kernfs_put(kn);
		ret = sysfs_chmod_file(kobj, &attr, mode & ~0222);
		if (ret)
			dev_warn(pru->dev, "cannot make PRU %s's %s read-only: %d\n",
				 dev_name(&pru->rproc->dev), attr.name, ret);
		else
			pru->sysfs_mode[i] = mode;
	}
}

/*
 * The layer's view of the core's starts and stops: a remoteproc subdevice,
 * whose callbacks remoteproc makes under rproc->lock at every start and
 * stop of the core, whoever asks for it and whichever way (a stop for a
 * crash's recovery included).  Each one ends the generation the driver's
 * boot began.
 */
static int prukit_pru_subdev_start(struct rproc_subdev *subdev)
{
	struct prukit_pru *pru = container_of(subdev, struct prukit_pru, subdev);

	WRITE_ONCE(pru->gen, pru->gen + 1);
	/* a start while the driver's boot runs: someone started it again */
	if (READ_ONCE(pru->booted) && pru->on_stop)
		schedule_work(&pru->stop_work);
	return 0;
}

static void prukit_pru_subdev_stop(struct rproc_subdev *subdev, bool crashed)
{
	struct prukit_pru *pru = container_of(subdev, struct prukit_pru, subdev);

	WRITE_ONCE(pru->gen, pru->gen + 1);
	if (crashed && pru->booted)
		dev_err(pru->dev, "PRU %s crashed: remoteproc restarts it for recovery, without the driver's state\n",
			dev_name(&pru->rproc->dev));
	/* not the driver's own shutdown: that clears @booted first */
	if (READ_ONCE(pru->booted) && pru->on_stop)
		schedule_work(&pru->stop_work);
}

/* Tell the driver, once per boot, that its firmware no longer runs */
static void prukit_pru_stop_work(struct work_struct *work)
{
	struct prukit_pru *pru = container_of(work, struct prukit_pru, stop_work);

	if (!READ_ONCE(pru->booted) || prukit_pru_running(pru) || xchg(&pru->stop_told, true))
		return;
	pru->on_stop(pru->on_stop_data);
}

/*
 * A crash report (remoteproc's debugfs "crash" file; pru_rproc itself
 * detects none) marks the core crashed and, recovery being disabled for
 * PRUs, calls no subdevice and notifies no one: looked for here.
 */
static void prukit_pru_crash_watch(struct work_struct *work)
{
	struct prukit_pru *pru = container_of(to_delayed_work(work), struct prukit_pru,
					      crash_watch);

	if (!READ_ONCE(pru->booted) || READ_ONCE(pru->stop_told))
		return;
	if (READ_ONCE(pru->rproc->state) == RPROC_CRASHED)
		schedule_work(&pru->stop_work);
	else
		schedule_delayed_work(&pru->crash_watch, msecs_to_jiffies(PRUKIT_PRU_WATCH_MS));
}

/**
 * prukit_pru_notify_stop() - be told when the core stops behind the driver's back
 * @pru: the core
 * @fn: called once per boot of prukit_pru_boot(), from a workqueue (process
 *	context, without remoteproc's lock), when the core stopped (at once),
 *	was reported crashed (within PRUKIT_PRU_WATCH_MS) or started again,
 *	whoever did it; never for prukit_pru_shutdown() or the driver's unbind
 * @data: @fn's argument
 *
 * For drivers that must wake their waiters when the firmware is gone (the
 * firmware sends them nothing any more).  Set it before prukit_pru_boot();
 * the layer cancels it when the driver unbinds, before @data's devres goes
 * if @data was allocated before devm_prukit_pru_get().
 */
void prukit_pru_notify_stop(struct prukit_pru *pru, void (*fn)(void *data), void *data)
{
	pru->on_stop_data = data;
	pru->on_stop = fn;
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_notify_stop);

/* Let go of the core that prukit_pru_find() returned (and a claim on it) */
static void prukit_pru_put(struct prukit_pru *pru)
{
	if (pru->via_pru_rproc) {
		prukit_pru_rproc_put(pru->rproc);
	} else {
		prukit_pru_unclaim(pru->rproc);
		rproc_put(pru->rproc);
	}
}

static void prukit_pru_release(void *data)
{
	struct prukit_pru *pru = data;
	struct rproc *rproc = pru->rproc;

	prukit_pru_shutdown(pru);
	mutex_lock(&rproc->lock);
	rproc_remove_subdev(rproc, &pru->subdev);
	mutex_unlock(&rproc->lock);
	cancel_delayed_work_sync(&pru->crash_watch);
	cancel_work_sync(&pru->stop_work);
	prukit_pru_sysfs_lock(pru, false);
	prukit_pru_put(pru);
}

/*
 * Consumers hand the PRU the DMA addresses of their buffers, and the PRU
 * reaches DDR through the PRU-ICSS's OCP master port at the ARM's physical
 * addresses (32 bits).  Right only where the consumer's DMA addresses are
 * its physical ones: no IOMMU and no "dma-ranges" offset on its bus (the
 * AM335x's L3 has none; a tree that says otherwise is refused).
 */
static int prukit_pru_dma_setup(struct device *dev)
{
	const struct bus_dma_region *map;
	int ret;

	ret = dma_set_mask_and_coherent(dev, DMA_BIT_MASK(32));
	if (ret)
		return dev_err_probe(dev, ret, "no 32-bit DMA\n");
	if (device_iommu_mapped(dev))
		return dev_err_probe(dev, -EINVAL,
				     "behind an IOMMU: the PRU would get addresses it cannot use\n");
	for (map = dev->dma_range_map; map && map->size; map++)
		if (map->cpu_start != map->dma_start)
			return dev_err_probe(dev, -EINVAL,
					     "dma-ranges maps %pa to DMA address %pad: the PRU uses physical addresses\n",
					     &map->cpu_start, &map->dma_start);
	return 0;
}

/**
 * devm_prukit_pru_get() - take a PRU core named in the device's "ti,prus"
 * @dev: the consumer device; its node has "ti,prus" and maybe "firmware-name"
 * @index: which entry of "ti,prus"
 *
 * The core is held exclusively until @dev unbinds; then it is shut down (if
 * prukit_pru_boot() started it) and released.  Meanwhile the core's
 * remoteproc sysfs files that change it (state, firmware, recovery,
 * coredump) are read-only, for root too.  A device link makes the driver
 * core unbind @dev before the core's device goes away.  @dev gets a 32-bit
 * DMA mask: the PRU's OCP master port addresses 32 bits.
 *
 * Return: the core, or an ERR_PTR(): -EPROBE_DEFER until the core's driver
 * registered it, -ENODEV for a disabled core, -EBUSY if another driver holds
 * it or it is not offline (someone runs firmware on it), -EINVAL for a bad
 * "ti,prus" (each with a message; a deferral's is its reason in
 * devices_deferred).
 */
struct prukit_pru *devm_prukit_pru_get(struct device *dev, unsigned int index)
{
	enum rproc_state state;
	struct device_node *np;
	struct prukit_pru *pru;
	struct rproc *rproc;
	int ret;

	pru = devm_kzalloc(dev, sizeof(*pru), GFP_KERNEL);
	if (!pru)
		return ERR_PTR(-ENOMEM);
	pru->dev = dev;
	pru->index = index;
	INIT_WORK(&pru->stop_work, prukit_pru_stop_work);
	INIT_DELAYED_WORK(&pru->crash_watch, prukit_pru_crash_watch);

	np = of_parse_phandle(dev->of_node, "ti,prus", index);
	if (!np)
		return ERR_PTR(dev_err_probe(dev, -EINVAL, "no \"ti,prus\" entry %u\n", index));
	rproc = prukit_pru_find(pru, np);
	of_node_put(np);
	if (IS_ERR(rproc))
		return ERR_CAST(rproc);
	pru->rproc = rproc;
	if (!pru->via_pru_rproc) {
		ret = prukit_pru_claim(dev, rproc);
		if (ret) {
			rproc_put(rproc);
			return ERR_PTR(ret);
		}
	}

	/*
	 * A core that runs someone else's firmware is not taken: the driver
	 * would lock that user out of stopping it.  (pru_rproc_get() refuses it
	 * already, as it sets the consumer's firmware.)
	 */
	mutex_lock(&rproc->lock);
	state = rproc->state;
	if (state == RPROC_OFFLINE) {
		pru->subdev.start = prukit_pru_subdev_start;
		pru->subdev.stop = prukit_pru_subdev_stop;
		rproc_add_subdev(rproc, &pru->subdev);
	}
	mutex_unlock(&rproc->lock);
	if (state != RPROC_OFFLINE) {
		dev_err(dev, "PRU %s is not offline (it runs %s): stop it (echo stop > /sys/class/remoteproc/%s/state), then bind the driver\n",
			dev_name(&rproc->dev), rproc->firmware, dev_name(&rproc->dev));
		prukit_pru_put(pru);
		return ERR_PTR(-EBUSY);
	}
	prukit_pru_sysfs_lock(pru, true);
	ret = devm_add_action_or_reset(dev, prukit_pru_release, pru);
	if (ret)
		return ERR_PTR(ret);

	if (!device_link_add(dev, rproc->dev.parent, DL_FLAG_AUTOREMOVE_CONSUMER))
		return ERR_PTR(dev_err_probe(dev, -EINVAL, "cannot link to PRU %s\n",
					     dev_name(&rproc->dev)));

	if (of_property_read_string_index(dev->of_node, "firmware-name", index, &pru->firmware))
		pru->firmware = NULL;

	ret = prukit_pru_dma_setup(dev);
	if (ret)
		return ERR_PTR(ret);
	return pru;
}
EXPORT_SYMBOL_PRUKIT(devm_prukit_pru_get);

/*
 * The system events the consumer's own node takes from the PRU-ICSS's INTC
 * (the "interrupt-controller" child of the core's parent, as pru_rproc
 * finds it for .pru_irq_map), as a bitmap.
 */
static u64 prukit_pru_own_events(struct prukit_pru *pru)
{
	struct device_node *parent, *intc;
	struct of_phandle_args args;
	u64 events = 0;
	int i;

	parent = of_get_parent(pru->rproc->dev.parent->of_node);
	intc = parent ? of_get_child_by_name(parent, "interrupt-controller") : NULL;
	of_node_put(parent);
	if (!intc)
		return 0;
	for (i = 0; !of_irq_parse_one(pru->dev->of_node, i, &args); i++) {
		if (args.np == intc && args.args_count && args.args[0] < PRUKIT_INTC_EVENTS)
			events |= BIT_ULL(args.args[0]);
		of_node_put(args.np);
	}
	of_node_put(intc);
	return events;
}

/*
 * The PRU remoteproc driver maps the events of a firmware's .pru_irq_map
 * when the core starts and disposes of the mappings when it stops.  An
 * event the consumer's node also takes is the same Linux interrupt: the
 * disposal would free it under the driver's handler (and the driver's own
 * free_irq() would then free an interrupt that is gone).  Such firmware is
 * refused, and so is firmware whose section table cannot be read safely
 * (the PRU remoteproc driver checks less).  A file that cannot be loaded is
 * left to rproc_boot(), which reports it.
 */
static int prukit_pru_check_irq_map(struct prukit_pru *pru, const char *firmware)
{
	const struct firmware *fw;
	u64 own, mapped;
	int ret;

	own = prukit_pru_own_events(pru);
	if (!own || firmware_request_nowarn(&fw, firmware, pru->dev))
		return 0;
	ret = prukit_pru_fw_irq_events(fw->data, fw->size, &mapped);
	release_firmware(fw);
	if (ret) {
		dev_err(pru->dev, "%s: not a PRU ELF32 image whose sections and .pru_irq_map can be read\n",
			firmware);
		return ret;
	}
	if (!(own & mapped))
		return 0;
	dev_err(pru->dev, "%s maps system event %u in its .pru_irq_map, which %pOF takes as its interrupt: the PRU remoteproc driver would dispose of that mapping when the core stops, under the driver's handler\n",
		firmware, (unsigned int)__ffs64(own & mapped), pru->dev->of_node);
	return -EBUSY;
}

/**
 * prukit_pru_boot() - load firmware into the core and start it
 * @pru: the core
 * @firmware: file under /lib/firmware, or NULL for the "firmware-name" entry
 *
 * Fails with -EBUSY if the core is not offline (crashed, or started through
 * a remoteproc sysfs file opened before the driver took the core) or was
 * started by someone else while this boot ran: prukit never takes over
 * firmware someone else started; and if the firmware's .pru_irq_map maps a
 * system event that the consumer's node takes as its interrupt (the PRU
 * remoteproc driver would dispose of that interrupt at the core's stop);
 * with -EINVAL if, with such an interrupt, the file's sections cannot be
 * read safely.  prukit_pru_shutdown(), or the driver unbinding, stops it
 * again.
 *
 * Return: 0 or a negative errno (also logged).
 */
int prukit_pru_boot(struct prukit_pru *pru, const char *firmware)
{
	struct rproc *rproc = pru->rproc;
	enum rproc_state state;
	bool alone;
	int ret;

	if (pru->booted)
		return -EBUSY;
	firmware = firmware ?: pru->firmware;
	if (!firmware) {
		dev_err(pru->dev, "no firmware for PRU %s (\"firmware-name\")\n",
			dev_name(&rproc->dev));
		return -EINVAL;
	}
	mutex_lock(&rproc->lock);
	state = rproc->state;
	mutex_unlock(&rproc->lock);
	if (state != RPROC_OFFLINE) {
		dev_err(pru->dev, "PRU %s is %s, not offline (firmware %s): unbind the driver to stop it\n",
			dev_name(&rproc->dev), state == RPROC_CRASHED ? "crashed" : "running",
			rproc->firmware);
		return -EBUSY;
	}
	ret = prukit_pru_check_irq_map(pru, firmware);
	if (ret)
		return ret;
	ret = prukit_rproc_set_firmware(rproc, firmware);
	if (ret) {
		dev_err(pru->dev, "cannot set firmware %s on PRU %s: %d\n", firmware,
			dev_name(&rproc->dev), ret);
		return ret;
	}
	ret = rproc_boot(rproc);
	if (ret) {
		dev_err(pru->dev, "PRU %s did not start %s: %d\n", dev_name(&rproc->dev),
			firmware, ret);
		return ret;
	}
	/*
	 * rproc_boot() of a core that runs is only a reference: if someone
	 * started the core between the check above and the boot, this was one.
	 * Either way the driver's is one of the references now.
	 */
	mutex_lock(&rproc->lock);
	alone = atomic_read(&rproc->power) == 1 && rproc->state == RPROC_RUNNING;
	pru->boot_gen = pru->gen;
	mutex_unlock(&rproc->lock);
	if (!alone) {
		dev_err(pru->dev, "PRU %s was started by someone else while the driver booted it: not taken over\n",
			dev_name(&rproc->dev));
		rproc_shutdown(rproc);
		return -EBUSY;
	}
	pru->stop_told = false;
	WRITE_ONCE(pru->booted, true);
	pru->seq = 0;
	if (pru->on_stop)
		schedule_delayed_work(&pru->crash_watch, msecs_to_jiffies(PRUKIT_PRU_WATCH_MS));
	return 0;
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_boot);

/* A core that does not stop after this many shutdowns has no one to stop it. */
#define PRUKIT_PRU_STOP_TRIES	8

/**
 * prukit_pru_shutdown() - stop the core that prukit_pru_boot() started
 * @pru: the core
 *
 * Does nothing if the driver did not boot it.  Otherwise the core ends
 * offline, whatever happened to it since: every reference a start took
 * while the driver held it goes (the driver's buffers go next), and a core
 * remoteproc marked crashed is stopped too.
 */
void prukit_pru_shutdown(struct prukit_pru *pru)
{
	struct rproc *rproc = pru->rproc;
	bool up = false;
	unsigned int i;

	if (!pru->booted)
		return;
	WRITE_ONCE(pru->booted, false);
	for (i = 0; i < PRUKIT_PRU_STOP_TRIES; i++) {
		mutex_lock(&rproc->lock);
		/*
		 * A crash report leaves a PRU running (pru_rproc disables
		 * recovery and halts nothing) and the core "crashed" with its
		 * references, which rproc_shutdown() refuses on 6.1 and 6.12
		 * (5.10 does not check): what runs is stopped as a running core.
		 */
		if (rproc->state == RPROC_CRASHED)
			rproc->state = RPROC_RUNNING;
		up = rproc->state == RPROC_RUNNING;
		mutex_unlock(&rproc->lock);
		if (!up)
			break;
		if (i == 1)
			dev_warn(pru->dev, "PRU %s was started again behind the driver's back: stopping it\n",
				 dev_name(&rproc->dev));
		rproc_shutdown(rproc);
	}
	if (up)
		dev_err(pru->dev, "PRU %s did not stop\n", dev_name(&rproc->dev));
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_shutdown);

/**
 * prukit_pru_running() - whether the driver's firmware still runs
 * @pru: the core
 *
 * False once the core stopped, crashed or started again since the driver
 * booted it (a remoteproc sysfs file opened before the driver took it, a
 * crash report, remoteproc's recovery): a driver checks it before it waits
 * for the firmware, and the waits below return -EPIPE when it turns false.
 * A snapshot without rproc->lock, as polling wants it: the boot and the
 * shutdown, which change the core, decide under the lock.
 *
 * Return: true while the core runs the firmware prukit_pru_boot() started.
 */
bool prukit_pru_running(struct prukit_pru *pru)
{
	return pru->booted && READ_ONCE(pru->gen) == pru->boot_gen &&
	       READ_ONCE(pru->rproc->state) == RPROC_RUNNING;
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_running);

/**
 * prukit_pru_map() - the core's memory at a device address, for the ARM
 * @pru: the core
 * @da: device address as the core sees it (its data RAM at 0, shared RAM
 *	at 0x10000)
 * @len: bytes
 *
 * The PRU remoteproc driver hands out ioremapped (Device) memory: access
 * it only with readl()/writel()/memcpy_toio()/memcpy_fromio().
 * Valid while the firmware is loaded.
 *
 * Return: the mapping, or NULL if @da..@da+@len is no memory of the core.
 */
void __iomem *prukit_pru_map(struct prukit_pru *pru, u32 da, size_t len)
{
	bool is_iomem = false;
	void *va;

	va = prukit_rproc_da_to_va(pru->rproc, da, len, &is_iomem);
	if (!va)
		dev_err(pru->dev, "PRU %s has no memory at 0x%x (%zu bytes)\n",
			dev_name(&pru->rproc->dev), da, len);
	return (void __force __iomem *)va;
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_map);

/**
 * prukit_pru_ctrl_check() - is this the firmware the driver speaks with?
 * @pru: the core
 * @ctrl: the control block (prukit_pru_map() of PRUKIT_CTRL_DA)
 * @magic: the driver's protocol magic
 * @version: the protocol version the driver speaks
 * @size: sizeof the driver's control block
 *
 * The image initialises the header, so this works right after the boot.
 *
 * Return: 0, or -EPROTO with a line in dmesg saying what disagrees.
 */
int prukit_pru_ctrl_check(struct prukit_pru *pru, void __iomem *ctrl, u32 magic,
			  u16 version, u16 size)
{
	u32 m = readl(ctrl + offsetof(struct prukit_ctrl_hdr, magic));
	u16 v = readw(ctrl + offsetof(struct prukit_ctrl_hdr, version));
	u16 s = readw(ctrl + offsetof(struct prukit_ctrl_hdr, size));
	const char *fw = pru->rproc->firmware;

	if (m != magic) {
		dev_err(pru->dev, "%s is not this driver's firmware: control block magic 0x%08x, expected 0x%08x\n",
			fw, m, magic);
		return -EPROTO;
	}
	if (v != version || s != size) {
		dev_err(pru->dev, "%s speaks protocol version %u (%u-byte control block), the driver version %u (%u bytes): rebuild the firmware with this driver\n",
			fw, v, s, version, size);
		return -EPROTO;
	}
	return 0;
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_ctrl_check);

/* What became of a core that no longer runs the driver's firmware */
static const char *prukit_pru_lost(struct prukit_pru *pru)
{
	switch (READ_ONCE(pru->rproc->state)) {
	case RPROC_CRASHED:
		return "crashed";
	case RPROC_RUNNING:
		return "was started again behind the driver's back";
	default:
		return "stopped";
	}
}

/*
 * Poll the status word until the firmware is ready (and, unless @any_seq,
 * answered @want_seq), the core stops or time runs out.  Looks every
 * 200 us at most; the emulated PRU-ICSS answers within about a millisecond
 * of host time, a real PRU within microseconds.
 */
static int prukit_pru_poll(struct prukit_pru *pru, void __iomem *ctrl, u32 want_seq,
			   bool any_seq, unsigned int timeout_ms, const char *what, u32 *status)
{
	void __iomem *st = ctrl + offsetof(struct prukit_ctrl_hdr, status);
	u32 v = 0;
	int ret;

	ret = prukit_pru_poll_timeout(pru, ((v = readl(st)) & PRUKIT_CTRL_READY) &&
				      (any_seq || PRUKIT_CTRL_SEQ(v) == want_seq),
				      200, timeout_ms);
	if (!ret)
		*status = v;
	else if (ret == -EPIPE)
		dev_err(pru->dev, "PRU %s %s while the driver waited for %s\n",
			dev_name(&pru->rproc->dev), prukit_pru_lost(pru), what);
	else
		dev_err(pru->dev, "%s on PRU %s: no answer to %s within %u ms\n",
			pru->rproc->firmware, dev_name(&pru->rproc->dev), what, timeout_ms);
	return ret;
}

/**
 * prukit_pru_ctrl_wait_ready() - wait until the firmware polls its block
 * @pru: the core
 * @ctrl: the control block
 * @timeout_ms: how long (PRUKIT_PRU_TIMEOUT_MS suits emulation as well)
 *
 * Return: 0; -ETIMEDOUT (logged with the firmware's name) if the firmware
 * never set PRUKIT_CTRL_READY; -EPIPE if the core stopped.
 */
int prukit_pru_ctrl_wait_ready(struct prukit_pru *pru, void __iomem *ctrl,
			       unsigned int timeout_ms)
{
	u32 status;

	return prukit_pru_poll(pru, ctrl, 0, true, timeout_ms, "its start", &status);
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_ctrl_wait_ready);

/**
 * prukit_pru_ctrl_command() - send a command and wait for its result
 * @pru: the core
 * @ctrl: the control block; the command's parameters are already written
 * @opcode: the driver protocol's command
 * @timeout_ms: how long to wait for the answer
 *
 * Writes @command (after every parameter: writel() orders the stores) and
 * polls @status until the firmware answers that sequence number.  Callers
 * serialise commands to one control block.
 *
 * Return: the firmware's result (0 for success, positive: the protocol's
 * error codes), or -ETIMEDOUT/-EPIPE as prukit_pru_ctrl_wait_ready().
 */
int prukit_pru_ctrl_command(struct prukit_pru *pru, void __iomem *ctrl, u16 opcode,
			    unsigned int timeout_ms)
{
	int seq = prukit_pru_ctrl_post(pru, ctrl, opcode);

	if (seq < 0)
		return seq;
	return prukit_pru_ctrl_wait(pru, ctrl, seq, timeout_ms);
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_ctrl_command);

/**
 * prukit_pru_ctrl_wait() - wait for the answer to a posted command
 * @pru: the core
 * @ctrl: the control block
 * @seq: the sequence number prukit_pru_ctrl_post() returned
 * @timeout_ms: how long to wait for the answer
 *
 * After -ETIMEDOUT the command is still posted: the firmware may take it
 * later, and a caller whose parameters the firmware reads when it takes the
 * command must leave them alone until prukit_pru_ctrl_answer() says it did.
 *
 * Return: as prukit_pru_ctrl_command().
 */
int prukit_pru_ctrl_wait(struct prukit_pru *pru, void __iomem *ctrl, u16 seq,
			 unsigned int timeout_ms)
{
	char what[32];
	u32 status;
	int ret;

	snprintf(what, sizeof(what), "command %u (seq %u)",
		 PRUKIT_CTRL_OPCODE(readl(ctrl + offsetof(struct prukit_ctrl_hdr, command))),
		 seq);
	ret = prukit_pru_poll(pru, ctrl, seq, false, timeout_ms, what, &status);
	if (ret)
		return ret;
	return PRUKIT_CTRL_RESULT(status);
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_ctrl_wait);

/**
 * prukit_pru_ctrl_post() - send a command without waiting for its answer
 * @pru: the core
 * @ctrl: the control block; the command's parameters are already written
 * @opcode: the driver protocol's command
 *
 * For firmware that takes commands only at certain points (between two
 * frames, say): the caller learns the answer later with
 * prukit_pru_ctrl_answer() on the returned sequence number, typically when
 * the firmware's event arrives.  A command posted before the previous one
 * was answered replaces it; callers serialise commands and post the next one
 * only once the previous one was answered.
 *
 * Return: the command's sequence number (1..65535), or -EPIPE if the core
 * does not run the driver's firmware.
 */
int prukit_pru_ctrl_post(struct prukit_pru *pru, void __iomem *ctrl, u16 opcode)
{
	if (!prukit_pru_running(pru))
		return -EPIPE;
	pru->seq = pru->seq == U16_MAX ? 1 : pru->seq + 1;
	writel(PRUKIT_CTRL_CMD(opcode, pru->seq),
	       ctrl + offsetof(struct prukit_ctrl_hdr, command));
	return pru->seq;
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_ctrl_post);

/**
 * prukit_pru_ctrl_answer() - the answer to a posted command, if it came
 * @ctrl: the control block
 * @seq: the sequence number prukit_pru_ctrl_post() returned
 *
 * Return: the firmware's result (0 for success, positive: the protocol's
 * error codes) once it answered @seq, else -EAGAIN.
 */
int prukit_pru_ctrl_answer(void __iomem *ctrl, u16 seq)
{
	u32 status = readl(ctrl + offsetof(struct prukit_ctrl_hdr, status));

	if (!(status & PRUKIT_CTRL_READY) || PRUKIT_CTRL_SEQ(status) != seq)
		return -EAGAIN;
	return PRUKIT_CTRL_RESULT(status);
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_ctrl_answer);

/* The AM335x GPIO banks, as the PRU reaches them over OCP */
static const u32 prukit_pru_gpio_banks[PRUKIT_PRU_GPIO_BANKS] = {
	0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000,
};

/**
 * prukit_pru_gpio_bank() - which AM335x GPIO bank a GPIO controller is
 * @np: the controller's node (a "gpios" phandle's target)
 *
 * For firmware that drives GPIO pins itself, through the bank's
 * SETDATAOUT/CLEARDATAOUT registers: the driver owns the pins through
 * gpiolib and tells the firmware the bank: the controller's translated
 * address.
 *
 * Return: the bank, 0..3, or -EINVAL if @np is no AM335x GPIO bank.
 */
int prukit_pru_gpio_bank(struct device_node *np)
{
	struct resource res;
	unsigned int b;

	if (of_address_to_resource(np, 0, &res))
		return -EINVAL;
	for (b = 0; b < PRUKIT_PRU_GPIO_BANKS; b++)
		if (res.start == prukit_pru_gpio_banks[b])
			return b;
	return -EINVAL;
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_gpio_bank);

/*
 * The node's interrupt @name (NULL: the first) as the PRUSS INTC's
 * specifier <EVENT CHANNEL HOST> in @spec: true if it is one, false if the
 * node has no such interrupt or it is another controller's.
 */
static bool prukit_pru_event_spec(struct device *dev, const char *name,
				  struct of_phandle_args *spec)
{
	int index = 0;
	bool ret;

	if (name)
		index = of_property_match_string(dev->of_node, "interrupt-names", name);
	if (index < 0 || of_irq_parse_one(dev->of_node, index, spec))
		return false;
	ret = of_device_is_compatible(spec->np, "ti,pruss-intc") && spec->args_count == 3;
	of_node_put(spec->np);
	return ret;
}

/*
 * Only hosts 2..9 of the PRUSS INTC reach the ARM (host_intr0..7); hosts 0
 * and 1 are the PRUs' own R31 bits.  pruss_intc maps any host below 10, so
 * an event routed to 0 or 1 would map and never arrive: refuse it here.
 */
static int prukit_pru_event_host(struct device *dev, const char *name)
{
	struct of_phandle_args spec;

	if (!prukit_pru_event_spec(dev, name, &spec))
		return 0;	/* of_irq_get*() says what is missing */
	if (spec.args[2] < PRUKIT_INTC_HOST_ARM_FIRST || spec.args[2] > PRUKIT_INTC_HOST_LAST)
		return dev_err_probe(dev, -EINVAL,
				     "PRU event %u%s%s is routed to host %u, which no ARM interrupt receives: route it to a host of 2..9 (PRU_EVTOUT0..7)\n",
				     spec.args[0], name ? " " : "", name ?: "", spec.args[2]);
	return 0;
}

/**
 * prukit_pru_event() - the PRU system event of a consumer's interrupt
 * @dev: the consumer device
 * @name: its "interrupt-names" entry, or NULL for the first interrupt
 *
 * What the firmware strobes to raise it: EVENT of the node's own
 * "interrupts-extended = <&pruss_intc EVENT CHANNEL HOST>", as the binding
 * defines it (not the interrupt's hwirq, which is the INTC driver's own
 * numbering).
 *
 * Return: the event (0..63), or -EINVAL (with a message) if that interrupt
 * is not a PRUSS INTC event.
 */
int prukit_pru_event(struct device *dev, const char *name)
{
	struct of_phandle_args spec;

	if (!prukit_pru_event_spec(dev, name, &spec) || spec.args[0] > 63)
		return dev_err_probe(dev, -EINVAL,
				     "interrupt %s is no PRU system event (<&pruss_intc EVENT CHANNEL HOST>)\n",
				     name ?: "0");
	return spec.args[0];
}
EXPORT_SYMBOL_PRUKIT(prukit_pru_event);

/**
 * devm_prukit_pru_request_irq() - request a PRU -> ARM event of the node
 * @dev: the consumer device
 * @name: its "interrupt-names" entry, or NULL for the first interrupt
 * @handler: hard interrupt handler (or NULL with @thread_fn)
 * @thread_fn: threaded handler, or NULL
 * @flags: IRQF_* (IRQF_ONESHOT is added with a NULL @handler)
 * @data: passed to the handlers
 *
 * The rule for events: a consumer's events come from its own
 * "interrupts-extended = <&pruss_intc EVENT CHANNEL HOST>", never from the
 * firmware's .pru_irq_map, whose mappings the PRU remoteproc driver
 * disposes of when the core stops.
 *
 * Return: the Linux interrupt number, or a negative errno (-EPROBE_DEFER
 * until the INTC is there, -EINVAL for an event routed to a host the ARM
 * does not receive).
 */
int devm_prukit_pru_request_irq(struct device *dev, const char *name,
				irq_handler_t handler, irq_handler_t thread_fn,
				unsigned long flags, void *data)
{
	int irq, ret;

	ret = prukit_pru_event_host(dev, name);
	if (ret)
		return ret;
	irq = name ? of_irq_get_byname(dev->of_node, name) : of_irq_get(dev->of_node, 0);
	if (irq <= 0)
		return dev_err_probe(dev, irq ?: -ENXIO, "no PRU event interrupt %s\n",
				     name ?: "");
	if (!handler)
		flags |= IRQF_ONESHOT;
	ret = devm_request_threaded_irq(dev, irq, handler, thread_fn, flags, dev_name(dev), data);
	if (ret)
		return dev_err_probe(dev, ret, "cannot request interrupt %d\n", irq);
	return irq;
}
EXPORT_SYMBOL_PRUKIT(devm_prukit_pru_request_irq);

MODULE_DESCRIPTION("prukit: the shared way drivers take and use a PRU core");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
