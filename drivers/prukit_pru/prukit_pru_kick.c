// SPDX-License-Identifier: GPL-2.0-only
/*
 * prukit_pru - rpmsg on PRU remote processors whose driver cannot kick
 *
 * Mainline's pru_rproc (and what prukit builds of it for Debian's kernels)
 * has no .kick and no vring interrupt: remoteproc refuses every firmware
 * with a vdev (".kick method not defined"), so the PRU Cookbook's rpmsg
 * firmware cannot run.  TI's pru_rproc has both.  The layer's module (its
 * only initialisation is this; loaded with pru_rproc, see the module aliases
 * below) gives a PRU
 * remote processor that lacks them both, as it appears (it is bound to
 * "pru-rproc"), and stays out of the way of one that has a kick; it does
 * not change the kernel or pru_rproc on disk.  The choice and the reasons
 * are in Documentation/rpmsg-kick.rst.
 *
 * remoteproc gives each processor its own copy of the operations
 * (rproc_alloc() duplicates them, and pru_rproc itself sets ->load and
 * ->parse_fw in that copy): this sets ->kick and wraps ->parse_fw, ->load,
 * ->start and ->stop there, and adds a subdevice.  For each boot of a
 * firmware with a vdev:
 *
 *  - parse_fw (every boot, both modes below): a firmware with no
 *    .pru_irq_map but the older support package's type 5 interrupt
 *    resource is parsed as a copy with that resource as its map
 *    (pru_kick_parse_fw()).
 *  - load: the firmware's .pru_irq_map names the events.  Its first entry,
 *    routed to host 0 or 1, is the ARM -> PRU event (TI's pru_rproc raises
 *    the same one); the PRU -> ARM ("vring") event is the node's "vring"
 *    interrupt where the tree has one (TI's trees, prukit's rpmsg overlay),
 *    else the map's first entry routed to the ARM (host 2..9).  A firmware
 *    without them is refused here, with a message, before it runs.
 *  - start: pru_rproc's start maps the map's events; then the kick's Linux
 *    interrupt is looked up, and the vring interrupt is requested - on
 *    pru_rproc's mapping if the map has the event, else on a mapping made
 *    here from the tree's specifier.
 *  - The subdevice comes after the vdev's (it is moved to the end of the
 *    list at each load), so remoteproc stops it first: the vring interrupt
 *    is freed, and the kick forgotten, before the virtio device goes and
 *    before pru_rproc's stop disposes of the mappings.  The handler
 *    therefore never runs on a freed virtio device or a disposed mapping,
 *    and it needs no lock that a stop holds while it waits for the handler.
 *    Then it runs pru_rproc's stop, which halts the core: remoteproc would
 *    halt it only after freeing the vdev's buffers, and a firmware that
 *    checked DRIVER_OK just before would store into freed memory.
 *  - stop: the same for a boot whose subdevice did not stop (a start that
 *    failed after pru_rproc's start); pru_rproc's stop runs once.
 *
 * The module holds a reference to itself from start to stop, so it cannot
 * go while a processor runs rpmsg through it; when it goes, it gives every
 * processor back its own operations.
 *
 * A processor whose driver kicks by itself (TI's pru_rproc: 5.10-ti, 6.1-ti,
 * 6.6+) keeps its kick and vring interrupt; prukit guards them ("guard"):
 *
 *  - load: TI's kick raises the first event of the firmware's map without
 *    looking whether there is a map, and dereferences NULL for a firmware
 *    with a vdev and none (5.10-ti, TI's 6.x pru_rproc.c).  Such a firmware
 *    is refused at load, with the same message as on mainline, so that one
 *    firmware runs, or is refused, alike on every kernel.
 *  - stop: TI's pru_rproc halts the core in its stop, which remoteproc runs
 *    after freeing the vdev's buffers, so a firmware that checked DRIVER_OK
 *    stores into freed memory.  The same subdevice as on mainline runs
 *    TI's stop (halt, free the vring interrupt, dispose of the mappings)
 *    before the vdev goes; from then on kicks are dropped (TI's kick would
 *    raise an event whose mapping is gone), and remoteproc's own call of
 *    the stop returns what the first one did.
 *
 * The guard also parks TI's stale vring interrupt.  TI's pru_rproc keeps
 * the Linux interrupt of the "vring" event it requested for an rpmsg boot
 * (pru->irq_vring) after that boot, and disposes of that number again at
 * every later stop of the core, rpmsg or not (5.10-ti; TI's 6.x
 * pru_rproc_stop()).  Once the first dispose freed it, the next interrupt
 * mapped anywhere may get the number: a prukit driver's own event on that
 * core (its interrupts-extended) did in the VM, and the driver's unbind
 * then hung, disposing of its own interrupt under its live handler
 * (irq_dispose_mapping() waiting in synchronize_irq() for the handler,
 * which waited for the lock the unbind held).  So after every stop of TI's
 * the number goes to a placeholder in an interrupt domain of this
 * module's, which nothing requests, until TI's next rpmsg boot takes a
 * fresh one.  TI's dispose then frees only the placeholder.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/device.h>
#include <linux/firmware.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/irqdomain.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/of_irq.h>
#include <linux/platform_device.h>
#include <linux/rculist.h>
#include <linux/remoteproc.h>
#include <linux/slab.h>
#include <linux/spinlock.h>

#include "compat.h"
#include "prukit_pru_fw.h"
#include "prukit_pru_ns.h"

/* The PRU remoteproc driver's name, TI's and mainline's */
#define PRU_KICK_RPROC_DRIVER	"pru-rproc"

/**
 * struct pru_kick - a PRU remote processor this module gives a kick
 * @node: in pru_kicks
 * @rproc: the processor (a reference is held)
 * @dev: its PRU core's platform device (a reference is held)
 * @subdev: stops the vring interrupt before the vdev stops
 * @parse_fw: pru_rproc's parse_fw operation
 * @load: its load operation
 * @start: its start
 * @stop: its stop
 * @lock: protects @kick_irq (and in guard mode @halted) against kicks (from
 *	any context)
 * @kick_irq: the Linux interrupt of the ARM -> PRU event while a boot with
 *	rpmsg runs, else 0
 * @kick: this boot's ARM -> PRU event
 * @vring: its PRU -> ARM event
 * @vring_irq: the vring event's Linux interrupt while requested, else 0
 * @vring_mapped: the mapping of @vring_irq was made here (not by pru_rproc)
 * @rpmsg: this boot's firmware has a vdev
 * @guard: the driver kicks by itself (TI's): @load is wrapped to refuse a
 *	firmware its kick would crash on, @start and @stop to park @stale_irq
 *	and halt the core before the vdev goes, @ti_kick to drop kicks then
 * @ti_kick: (guard) TI's kick
 * @stale_irq: (guard) the vring interrupt TI's pru_rproc remembers from its
 *	last rpmsg boot and disposes of at each stop, 0 before any
 * @held: an rpmsg boot runs, and the module holds a reference to itself
 *	for it
 * @halted: the subdevice's stop ran pru_rproc's stop already
 * @halt_ret: what that returned
 * @fw_copy: a copy of a firmware with the .pru_irq_map made of its type 5
 *	resource, kept while pru_rproc may read the map in it (until its
 *	start, which forgets it)
 * @boot_elf: this boot's firmware as pru_rproc parsed it: @fw_copy, or
 *	NULL for the file itself
 * @boot_size: @boot_elf's size
 */
struct pru_kick {
	struct list_head node;
	struct rproc *rproc;
	struct device *dev;
	struct rproc_subdev subdev;
	int (*parse_fw)(struct rproc *rproc, const struct firmware *fw);
	int (*load)(struct rproc *rproc, const struct firmware *fw);
	int (*start)(struct rproc *rproc);
	int (*stop)(struct rproc *rproc);
	void (*ti_kick)(struct rproc *rproc, int vqid);
	spinlock_t lock;		/* kick_irq, against kicks */
	unsigned int kick_irq;
	struct prukit_pru_fw_irq kick;
	struct prukit_pru_fw_irq vring;
	unsigned int vring_irq;
	bool vring_mapped;
	bool rpmsg;
	bool guard;
	unsigned int stale_irq;
	bool held;
	bool halted;
	int halt_ret;
	u8 *fw_copy;
	const u8 *boot_elf;
	size_t boot_size;
};

/* Changes under pru_kicks_mutex; read under RCU (kicks come from any context) */
static LIST_HEAD(pru_kicks);
static DEFINE_MUTEX(pru_kicks_mutex);

static struct pru_kick *pru_kick_find(struct rproc *rproc)
{
	struct pru_kick *k;

	list_for_each_entry_rcu(k, &pru_kicks, node)
		if (k->rproc == rproc)
			return k;
	return NULL;
}

/**
 * prukit_pru_kick_owns() - whether a device belongs to a PRU processor
 *	this module knows
 * @dev: the device: the processor's, or one below it (its virtio device,
 *	an rpmsg device of that)
 *
 * Return: true if @dev or one of its parents is such a processor's
 * device or its PRU core's platform device.
 */
bool prukit_pru_kick_owns(struct device *dev)
{
	struct pru_kick *k;
	bool owns = false;

	rcu_read_lock();
	for (; dev && !owns; dev = dev->parent)
		list_for_each_entry_rcu(k, &pru_kicks, node)
			if (dev == &k->rproc->dev || dev == k->dev)
				owns = true;
	rcu_read_unlock();
	return owns;
}

/* Called by remoteproc's operations, which only installed processors reach */
static struct pru_kick *pru_kick_of(struct rproc *rproc)
{
	struct pru_kick *k;

	rcu_read_lock();
	k = pru_kick_find(rproc);
	rcu_read_unlock();
	return k;
}

/* ARM -> PRU: raise the firmware's kick event (the INTC's pending state) */
static void pru_kick_kick(struct rproc *rproc, int vqid)
{
	struct pru_kick *k;
	unsigned long flags;
	int ret = -ENODEV;

	rcu_read_lock();
	k = pru_kick_find(rproc);
	if (k) {
		spin_lock_irqsave(&k->lock, flags);
		if (k->kick_irq)
			ret = irq_set_irqchip_state(k->kick_irq, IRQCHIP_STATE_PENDING, true);
		spin_unlock_irqrestore(&k->lock, flags);
	}
	rcu_read_unlock();
	/* outside a running boot (a stop under way) a kick has nobody to reach */
	if (ret && k)
		dev_dbg_ratelimited(&rproc->dev, "kick of vq %d dropped: %d\n", vqid, ret);
}

/* PRU -> ARM: the event says "look at the virtqueues", not which one */
static irqreturn_t pru_kick_vring_thread(int irq, void *data)
{
	struct pru_kick *k = data;

	rproc_vq_interrupt(k->rproc, 0);
	rproc_vq_interrupt(k->rproc, 1);
	return IRQ_HANDLED;
}

/* The PRU subsystem's INTC, whose domain maps the events */
static struct device_node *pru_kick_intc(struct pru_kick *k)
{
	struct device_node *parent, *intc;

	parent = of_get_parent(k->dev->of_node);
	if (!parent)
		return NULL;
	intc = of_get_child_by_name(parent, "interrupt-controller");
	of_node_put(parent);
	return intc;
}

/*
 * The tree's "vring" interrupt (TI's binding; prukit's rpmsg overlay adds
 * it where BeagleBoard's trees lack it), as a map entry: 1 if the node has
 * one, 0 if not, or an error for one that is no event of this PRUSS's INTC.
 */
static int pru_kick_tree_vring(struct pru_kick *k, struct prukit_pru_fw_irq *vring)
{
	struct device_node *np = k->dev->of_node, *intc;
	struct of_phandle_args spec;
	int index, ret;

	index = of_property_match_string(np, "interrupt-names", "vring");
	if (index < 0)
		return 0;
	ret = of_irq_parse_one(np, index, &spec);
	if (ret)
		return ret;
	intc = pru_kick_intc(k);
	ret = -EINVAL;
	if (spec.np == intc && spec.args_count == 3 && spec.args[0] < PRUKIT_INTC_EVENTS &&
	    spec.args[1] < PRUKIT_INTC_CHANNELS && spec.args[2] >= PRUKIT_INTC_HOST_ARM_FIRST &&
	    spec.args[2] <= PRUKIT_INTC_HOST_LAST) {
		vring->event = spec.args[0];
		vring->channel = spec.args[1];
		vring->host = spec.args[2];
		ret = 1;
	}
	of_node_put(intc);
	of_node_put(spec.np);
	return ret;
}

/* Put the subdevice last, after the vdevs this boot's resources added */
static void pru_kick_subdev_last(struct pru_kick *k)
{
	struct rproc_subdev *s;

	list_for_each_entry(s, &k->rproc->subdevs, node) {
		if (s == &k->subdev) {
			rproc_remove_subdev(k->rproc, &k->subdev);
			break;
		}
	}
	rproc_add_subdev(k->rproc, &k->subdev);
}

/* pru_rproc's start forgot the map it parsed: the copy can go */
static void pru_kick_forget_copy(struct pru_kick *k)
{
	kvfree(k->fw_copy);
	k->fw_copy = NULL;
	k->boot_elf = NULL;
}

/*
 * A firmware built with the PRU Software Support Package's releases for
 * TI's 4.x kernels has its INTC routing in a type 5 resource and no
 * .pru_irq_map, which every later PRU driver needs for rpmsg (TI's kick
 * dereferences NULL without one, mainline's routes nothing).  pru_rproc
 * parses a copy of it with the map made of that resource added
 * (prukit_pru_fw_ssp_irq_map()); its start maps the events from the copy,
 * as from any map.  remoteproc still warns "unsupported resource 5".
 */
static int pru_kick_parse_fw(struct rproc *rproc, const struct firmware *fw)
{
	struct pru_kick *k = pru_kick_of(rproc);
	struct firmware view = {};
	u8 map[PRUKIT_PRU_FW_IRQ_MAP_MAX];
	const u8 *entries;
	unsigned int count;
	size_t len;
	u8 *copy;
	int ret;

	k->boot_elf = NULL;
	ret = prukit_pru_fw_irq_map(fw->data, fw->size, &entries, &count);
	/* a map of its own (or a file pru_rproc judges itself) */
	if (ret || entries)
		return k->parse_fw(rproc, fw);
	ret = prukit_pru_fw_ssp_irq_map(fw->data, fw->size, map, &len);
	if (ret == -ENOENT)
		return k->parse_fw(rproc, fw);
	if (ret) {
		dev_err(k->dev, "%s: its interrupt resource (type 5, TI's 4.x support package) is malformed\n",
			rproc->firmware);
		return ret;
	}
	copy = prukit_pru_fw_add_irq_map(fw->data, fw->size, map, len, &view.size);
	if (!copy)
		return -ENOMEM;
	view.data = copy;
	ret = k->parse_fw(rproc, &view);
	if (ret) {
		kvfree(copy);
		return ret;
	}
	/*
	 * pru_rproc reads the map in this copy now, no longer in an older one.
	 * (It keeps the pointer after a boot that fails before its start, as
	 * it keeps one into the released file of any firmware then; the copy
	 * stays until the next start, or until the module goes.)
	 */
	kvfree(k->fw_copy);
	k->fw_copy = copy;
	k->boot_elf = copy;
	k->boot_size = view.size;
	dev_info(k->dev, "%s has no .pru_irq_map: its type 5 interrupt resource routes %u events instead\n",
		 rproc->firmware, map[1]);
	return 0;
}

static int pru_kick_load(struct rproc *rproc, const struct firmware *fw)
{
	struct pru_kick *k = pru_kick_of(rproc);
	struct prukit_pru_fw_irq tree;
	const u8 *map;
	unsigned int count;
	int ret;

	ret = k->load(rproc, fw);
	if (ret)
		return ret;
	pru_kick_subdev_last(k);
	k->rpmsg = !list_empty(&rproc->rvdevs);
	if (!k->rpmsg)
		return 0;

	/* the map pru_rproc parsed: the file's, or the one made of its resource */
	if (k->boot_elf)
		ret = prukit_pru_fw_irq_map(k->boot_elf, k->boot_size, &map, &count);
	else
		ret = prukit_pru_fw_irq_map(fw->data, fw->size, &map, &count);
	if (ret) {
		dev_err(k->dev, "%s: its .pru_irq_map cannot be read\n", rproc->firmware);
		return ret;
	}
	ret = prukit_pru_fw_rpmsg_events(map, count, &k->kick, &k->vring);
	if (ret) {
		dev_err(k->dev, "%s has an rpmsg vdev, but its .pru_irq_map %s: nothing could kick it (the map's first entry is the ARM -> PRU event, routed to host 0 or 1)\n",
			rproc->firmware, map ? "does not start with such an event" :
			"is missing");
		return -EINVAL;
	}
	ret = pru_kick_tree_vring(k, &tree);
	if (ret < 0) {
		dev_err(k->dev, "the \"vring\" interrupt of %pOF is no event of its PRUSS's INTC routed to the ARM (host 2..9)\n",
			k->dev->of_node);
		return ret;
	}
	if (ret > 0) {
		/* the map may route the same event; then the two must agree */
		unsigned int n;

		for (n = 0; n < count; n++) {
			const u8 *e = map + 3 * n;

			if (e[0] == tree.event && (e[1] != tree.channel || e[2] != tree.host)) {
				dev_err(k->dev, "%s routes system event %u to channel %u, host %u; %pOF's \"vring\" interrupt to channel %u, host %u\n",
					rproc->firmware, e[0], e[1], e[2], k->dev->of_node,
					tree.channel, tree.host);
				return -EINVAL;
			}
		}
		k->vring = tree;
	}
	/* TI's pru_rproc requests the tree's vring interrupt itself */
	if (k->guard)
		return 0;
	if (k->vring.event < 0) {
		dev_err(k->dev, "%s has an rpmsg vdev, but no PRU -> ARM event: neither %pOF has a \"vring\" interrupt nor its .pru_irq_map routes an event to host 2..9\n",
			rproc->firmware, k->dev->of_node);
		return -EINVAL;
	}
	return 0;
}

/* Forget the kick and free the vring interrupt: before the vdev stops */
static void pru_kick_quiesce(struct pru_kick *k)
{
	unsigned long flags;

	spin_lock_irqsave(&k->lock, flags);
	k->kick_irq = 0;
	spin_unlock_irqrestore(&k->lock, flags);
	if (k->vring_irq) {
		free_irq(k->vring_irq, k);
		if (k->vring_mapped)
			irq_dispose_mapping(k->vring_irq);
		k->vring_irq = 0;
		k->vring_mapped = false;
	}
}

static int pru_kick_start(struct rproc *rproc)
{
	struct pru_kick *k = pru_kick_of(rproc);
	struct irq_domain *domain;
	struct device_node *intc;
	unsigned int kick_irq;
	unsigned long flags;
	int ret;

	ret = k->start(rproc);
	pru_kick_forget_copy(k);
	if (ret || !k->rpmsg)
		return ret;
	/* the module stays until this boot's stop */
	if (!try_module_get(THIS_MODULE)) {
		ret = -ENODEV;
		goto stop;
	}
	k->held = true;

	ret = -ENODEV;
	intc = pru_kick_intc(k);
	domain = intc ? irq_find_host(intc) : NULL;
	if (!domain) {
		dev_err(k->dev, "no interrupt domain for the PRUSS's INTC\n");
		goto put_intc;
	}
	/* pru_rproc's start mapped every event of the firmware's map */
	kick_irq = irq_find_mapping(domain, k->kick.event);
	if (!kick_irq) {
		dev_err(k->dev, "system event %d of %s is not mapped\n", k->kick.event,
			rproc->firmware);
		goto put_intc;
	}
	k->vring_irq = irq_find_mapping(domain, k->vring.event);
	if (!k->vring_irq) {
		struct irq_fwspec spec = {
			.fwnode = of_node_to_fwnode(intc),
			.param_count = 3,
			.param = { k->vring.event, k->vring.channel, k->vring.host },
		};

		k->vring_irq = irq_create_fwspec_mapping(&spec);
		if (!k->vring_irq) {
			dev_err(k->dev, "cannot map the vring event %d (channel %u, host %u)\n",
				k->vring.event, k->vring.channel, k->vring.host);
			goto put_intc;
		}
		k->vring_mapped = true;
	}
	of_node_put(intc);

	ret = request_threaded_irq(k->vring_irq, NULL, pru_kick_vring_thread, IRQF_ONESHOT,
				   dev_name(k->dev), k);
	if (ret) {
		dev_err(k->dev, "cannot request the vring interrupt (event %d): %d\n",
			k->vring.event, ret);
		if (k->vring_mapped)
			irq_dispose_mapping(k->vring_irq);
		k->vring_irq = 0;
		k->vring_mapped = false;
		goto release;
	}
	spin_lock_irqsave(&k->lock, flags);
	k->kick_irq = kick_irq;
	spin_unlock_irqrestore(&k->lock, flags);
	dev_dbg(k->dev, "rpmsg: kick event %d, vring event %d\n", k->kick.event, k->vring.event);
	return 0;

put_intc:
	of_node_put(intc);
release:
	pru_kick_quiesce(k);
	module_put(THIS_MODULE);
	k->held = false;
stop:
	k->stop(rproc);
	return ret;
}

static int pru_kick_stop(struct rproc *rproc)
{
	struct pru_kick *k = pru_kick_of(rproc);
	int ret;

	pru_kick_quiesce(k);
	ret = k->halted ? k->halt_ret : k->stop(rproc);
	k->halted = false;
	if (k->held) {
		k->held = false;
		/* the caller holds rproc->lock, which unloading waits for */
		module_put(THIS_MODULE);
	}
	return ret;
}

/* First of a stop: quiet the interrupts, halt the core, then the vdev goes */
static void pru_kick_subdev_stop(struct rproc_subdev *subdev, bool crashed)
{
	struct pru_kick *k = container_of(subdev, struct pru_kick, subdev);

	pru_kick_quiesce(k);
	if (k->held && !k->halted) {
		k->halt_ret = k->stop(k->rproc);
		k->halted = true;
	}
}

/* The placeholders of TI's stale vring interrupts (guard), hwirq = virq */
static struct irq_domain *pru_kick_parking;
static const struct irq_domain_ops pru_kick_parking_ops;

static bool pru_kick_parked(unsigned int virq)
{
	struct irq_data *d = irq_get_irq_data(virq);

	return d && d->domain == pru_kick_parking;
}

/* Under rproc->lock: give @k's stale number a placeholder, if it has none */
static void pru_kick_park(struct pru_kick *k)
{
	unsigned int virq = k->stale_irq;
	int ret;

	if (!virq || pru_kick_parked(virq))
		return;
	ret = irq_alloc_desc_at(virq, NUMA_NO_NODE);
	if (ret == virq) {
		ret = irq_domain_associate(pru_kick_parking, virq, virq);
		if (!ret)
			return;
		irq_free_desc(virq);
	}
	dev_warn(k->dev, "%s's driver disposes of interrupt %u at every stop, which another driver may use now (%d): rebind it (%s) before unbinding that driver\n",
		 k->rproc->name, virq, ret, dev_name(k->dev));
	k->stale_irq = 0;
}

static void pru_kick_unpark(struct pru_kick *k)
{
	if (k->stale_irq && pru_kick_parked(k->stale_irq))
		irq_dispose_mapping(k->stale_irq);
	k->stale_irq = 0;
}

/* TI's kick, until the subdevice halted the core */
static void pru_kick_guard_kick(struct rproc *rproc, int vqid)
{
	struct pru_kick *k;
	unsigned long flags;

	rcu_read_lock();
	k = pru_kick_find(rproc);
	if (k) {
		spin_lock_irqsave(&k->lock, flags);
		if (!k->halted)
			k->ti_kick(rproc, vqid);
		spin_unlock_irqrestore(&k->lock, flags);
	}
	rcu_read_unlock();
}

/* TI's start: an rpmsg boot requested the tree's vring interrupt afresh */
static int pru_kick_guard_start(struct rproc *rproc)
{
	struct pru_kick *k = pru_kick_of(rproc);
	struct prukit_pru_fw_irq tree;
	struct irq_domain *domain;
	struct device_node *intc;
	int ret;

	ret = k->start(rproc);
	pru_kick_forget_copy(k);
	if (ret || !k->rpmsg)
		return ret;
	/* the module stays until this boot's stop: its kick is called */
	if (!try_module_get(THIS_MODULE)) {
		k->stop(rproc);
		pru_kick_park(k);
		return -ENODEV;
	}
	k->held = true;
	if (pru_kick_tree_vring(k, &tree) <= 0)
		return 0;
	pru_kick_unpark(k);
	intc = pru_kick_intc(k);
	domain = intc ? irq_find_host(intc) : NULL;
	of_node_put(intc);
	if (domain)
		k->stale_irq = irq_find_mapping(domain, tree.event);
	return 0;
}

/*
 * TI's stop disposes of the vring interrupt it remembers: park the number.
 * For an rpmsg boot, the subdevice ran it already, before the vdev went.
 */
static int pru_kick_guard_stop(struct rproc *rproc)
{
	struct pru_kick *k = pru_kick_of(rproc);
	unsigned long flags;
	int ret;

	ret = k->halted ? k->halt_ret : k->stop(rproc);
	spin_lock_irqsave(&k->lock, flags);
	k->halted = false;
	spin_unlock_irqrestore(&k->lock, flags);
	pru_kick_park(k);
	if (k->held) {
		k->held = false;
		/* the caller holds rproc->lock, which unloading waits for */
		module_put(THIS_MODULE);
	}
	return ret;
}

/* First of a stop of an rpmsg boot: TI's stop halts the core, then the vdev goes */
static void pru_kick_guard_subdev_stop(struct rproc_subdev *subdev, bool crashed)
{
	struct pru_kick *k = container_of(subdev, struct pru_kick, subdev);
	unsigned long flags;

	if (!k->held || k->halted)
		return;
	spin_lock_irqsave(&k->lock, flags);
	k->halted = true;
	spin_unlock_irqrestore(&k->lock, flags);
	k->halt_ret = k->stop(k->rproc);
	pru_kick_park(k);
}

/* Give a processor bound to pru-rproc its kick, or only the load check where it kicks */
static void pru_kick_add(struct device *dev)
{
	struct rproc *rproc = dev_get_drvdata(dev);
	struct pru_kick *k;

	if (!rproc)
		return;
	mutex_lock(&pru_kicks_mutex);
	list_for_each_entry(k, &pru_kicks, node)
		if (k->rproc == rproc)
			goto out;
	k = kzalloc(sizeof(*k), GFP_KERNEL);
	if (!k)
		goto out;
	get_device(&rproc->dev);
	k->rproc = rproc;
	k->dev = get_device(dev);
	k->guard = prukit_pru_kick_choose(rproc->ops) == PRUKIT_PRU_KICK_ASIDE;
	spin_lock_init(&k->lock);
	k->subdev.stop = k->guard ? pru_kick_guard_subdev_stop : pru_kick_subdev_stop;
	list_add_tail_rcu(&k->node, &pru_kicks);

	mutex_lock(&rproc->lock);
	k->parse_fw = rproc->ops->parse_fw;
	k->load = rproc->ops->load;
	k->start = rproc->ops->start;
	k->stop = rproc->ops->stop;
	/* both pru_rproc drivers parse the firmware themselves */
	if (k->parse_fw)
		rproc->ops->parse_fw = pru_kick_parse_fw;
	rproc->ops->load = pru_kick_load;
	if (k->guard) {
		k->ti_kick = rproc->ops->kick;
		rproc->ops->start = pru_kick_guard_start;
		rproc->ops->stop = pru_kick_guard_stop;
		rproc->ops->kick = pru_kick_guard_kick;
	} else {
		rproc->ops->start = pru_kick_start;
		rproc->ops->stop = pru_kick_stop;
		rproc->ops->kick = pru_kick_kick;
	}
	rproc_add_subdev(rproc, &k->subdev);
	mutex_unlock(&rproc->lock);
	if (k->guard)
		dev_info(dev, "%s kicks by itself: prukit only refuses rpmsg firmware it could not kick\n",
			 rproc->name);
	else
		dev_info(dev, "%s: rpmsg kick and vring interrupt by prukit\n", rproc->name);
out:
	mutex_unlock(&pru_kicks_mutex);
}

/* Under pru_kicks_mutex: give the operations back and forget the processor */
static void pru_kick_remove(struct pru_kick *k)
{
	struct rproc *rproc = k->rproc;

	mutex_lock(&rproc->lock);
	rproc->ops->parse_fw = k->parse_fw;
	rproc->ops->load = k->load;
	rproc->ops->start = k->start;
	rproc->ops->stop = k->stop;
	rproc->ops->kick = k->guard ? k->ti_kick : NULL;
	rproc_remove_subdev(rproc, &k->subdev);
	if (k->guard)
		pru_kick_unpark(k);
	mutex_unlock(&rproc->lock);
	list_del_rcu(&k->node);
	synchronize_rcu();
	put_device(&rproc->dev);
	put_device(k->dev);
	/* a boot that failed before pru_rproc's start left a copy */
	kvfree(k->fw_copy);
	kfree(k);
}

/*
 * A shutdown does not always stop the processor: another kernel user's
 * rproc_boot() still holds it (rproc->power above 1), or a signal cut
 * rproc_shutdown()'s mutex_lock_interruptible() short; 5.10's rproc_del()
 * does not shut down at all.  The driver goes all the same, and an rpmsg
 * boot would run on with the vring interrupt requested with @k as its data
 * and the vdev kicking through @k.  Do what the subdevice's stop does
 * before a vdev goes: forget the kick, free the vring interrupt and halt the
 * core (guard mode: TI's stop).  @k stays, with the operations, until that
 * boot's stop (pru_kick_unbound()).
 */
static void pru_kick_halt_held(struct device *dev, struct rproc *rproc)
{
	struct pru_kick *k;

	mutex_lock(&pru_kicks_mutex);
	mutex_lock(&rproc->lock);
	list_for_each_entry(k, &pru_kicks, node) {
		if (k->rproc != rproc || !k->held)
			continue;
		dev_warn(dev, "%s still runs %s after its shutdown (another boot holds it): halting it, without its rpmsg interrupts, as its driver goes\n",
			 rproc->name, rproc->firmware);
		k->subdev.stop(&k->subdev, false);
	}
	mutex_unlock(&rproc->lock);
	mutex_unlock(&pru_kicks_mutex);
}

/*
 * The PRU's driver is about to go.  5.10's rproc_del() (mainline's and
 * 5.10-ti's) shuts down only processors it booted itself: a core started
 * through sysfs runs on with its driver gone, a running rpmsg boot's
 * virtio device stays behind with this module's kick, and on 5.10-ti the
 * module reference rproc_boot() took is never dropped (pru_rproc can no
 * longer be unloaded).  Shut a running processor down first; later
 * kernels' rproc_del() does the same, and then finds it offline.
 */
static void pru_kick_unbind(struct device *dev)
{
	struct rproc *rproc = dev_get_drvdata(dev);
	struct pru_kick *k;
	bool ours = false;

	mutex_lock(&pru_kicks_mutex);
	list_for_each_entry(k, &pru_kicks, node)
		if (k->rproc == rproc)
			ours = true;
	mutex_unlock(&pru_kicks_mutex);
	if (!ours)
		return;
	if (READ_ONCE(rproc->state) == RPROC_RUNNING) {
		dev_info(dev, "%s still runs %s: shutting it down\n", rproc->name,
			 rproc->firmware);
		rproc_shutdown(rproc);
	}
	pru_kick_halt_held(dev, rproc);
}

/*
 * The driver has gone and deleted its processor (our reference keeps it).
 * A boot that still holds the processor (pru_kick_halt_held()) keeps @k and
 * the operations, which its stop and its vdev still call, and the module
 * reference it took.
 */
static void pru_kick_unbound(struct device *dev)
{
	struct pru_kick *k, *tmp;

	mutex_lock(&pru_kicks_mutex);
	list_for_each_entry_safe(k, tmp, &pru_kicks, node)
		if (k->dev == dev && !READ_ONCE(k->held))
			pru_kick_remove(k);
	mutex_unlock(&pru_kicks_mutex);
}

static bool pru_kick_is_pru(struct device *dev)
{
	return dev->driver && !strcmp(dev->driver->name, PRU_KICK_RPROC_DRIVER);
}

static int pru_kick_notify(struct notifier_block *nb, unsigned long action, void *data)
{
	struct device *dev = data;

	switch (action) {
	case BUS_NOTIFY_BOUND_DRIVER:
		if (pru_kick_is_pru(dev))
			pru_kick_add(dev);
		break;
	case BUS_NOTIFY_UNBIND_DRIVER:
		if (pru_kick_is_pru(dev))
			pru_kick_unbind(dev);
		break;
	case BUS_NOTIFY_UNBOUND_DRIVER:
		pru_kick_unbound(dev);
		break;
	}
	return NOTIFY_DONE;
}

static struct notifier_block pru_kick_nb = {
	.notifier_call = pru_kick_notify,
};

/*
 * The cores already bound.  Walked over the platform bus, not with
 * driver_find() and driver_for_each_device(): driver_find() hands back
 * pru_rproc's driver without a reference, and an unload of pru_rproc during
 * the walk would free it under us; the bus walk holds each device it looks
 * at, and the notifier, registered first, sees any unbind.
 */
static int pru_kick_existing(struct device *dev, void *data)
{
	device_lock(dev);
	if (pru_kick_is_pru(dev))
		pru_kick_add(dev);
	device_unlock(dev);
	return 0;
}

static void pru_kick_remove_all(void)
{
	struct pru_kick *k, *tmp;

	mutex_lock(&pru_kicks_mutex);
	list_for_each_entry_safe(k, tmp, &pru_kicks, node)
		pru_kick_remove(k);
	mutex_unlock(&pru_kicks_mutex);
}

static int __init pru_kick_init(void)
{
	int ret;

	pru_kick_parking = irq_domain_create_tree(NULL, &pru_kick_parking_ops, NULL);
	if (!pru_kick_parking)
		return -ENOMEM;
	ret = bus_register_notifier(&platform_bus_type, &pru_kick_nb);
	if (ret)
		goto remove_parking;
	ret = bus_for_each_dev(&platform_bus_type, NULL, NULL, pru_kick_existing);
	if (ret)
		goto remove_kicks;
	/* after the processors: it wraps the name services of those it knows */
	ret = prukit_pru_ns_init();
	if (ret)
		goto remove_kicks;
	return 0;

remove_kicks:
	bus_unregister_notifier(&platform_bus_type, &pru_kick_nb);
	pru_kick_remove_all();
remove_parking:
	irq_domain_remove(pru_kick_parking);
	return ret;
}
module_init(pru_kick_init);

/*
 * Loaded with the PRU cores' driver.  Where pru_rproc is a module,
 * /lib/modprobe.d/prukit.conf's "softdep pru_rproc post: prukit_pru" loads
 * this right after it.  Where it is built in (PRU_REMOTEPROC=y) nothing
 * loads pru_rproc; these aliases match the cores' nodes instead, and udev,
 * which loads every module whose alias matches a device's MODALIAS when the
 * device is added (at boot, its coldplug), loads this with the first core.
 * The AM335x's, AM437x's and AM57xx's PRUs: an INTC of the size prukit_pru
 * knows (prukit_pru_fw.h).
 */
MODULE_ALIAS("of:N*T*Cti,am3356-pru");
MODULE_ALIAS("of:N*T*Cti,am3356-pruC*");
MODULE_ALIAS("of:N*T*Cti,am4376-pru");
MODULE_ALIAS("of:N*T*Cti,am4376-pruC*");
MODULE_ALIAS("of:N*T*Cti,am5728-pru");
MODULE_ALIAS("of:N*T*Cti,am5728-pruC*");

static void __exit pru_kick_exit(void)
{
	prukit_pru_ns_exit();
	bus_unregister_notifier(&platform_bus_type, &pru_kick_nb);
	pru_kick_remove_all();
	irq_domain_remove(pru_kick_parking);
}
module_exit(pru_kick_exit);
