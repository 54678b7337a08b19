// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_sim - the simulated PRU cores as remote processors
 *
 * Each "prukit,pru-sim" child of the simulated PRU-ICSS is one rproc.  The
 * flow is the PRU Cookbook's: write a name to .../firmware, "start" to
 * .../state.  Firmware is a GNU pru-gcc ELF: code to IRAM, data to DRAM,
 * .pru_irq_map routed in the INTC while the core runs (as the PRU remoteproc
 * driver does: mapped at start, disposed of at stop, a conflicting route
 * fails the start), and a resource table, which may hold an
 * rpmsg vdev: "kick" then raises the ARM -> PRU system event named by the
 * node's "kick" interrupt, and the PRU -> ARM event of its "vring" interrupt
 * runs the virtqueues, as TI's pru_rproc does.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/delay.h>
#include <linux/dma-mapping.h>
#include <linux/firmware.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/module.h>
#include <linux/of.h>
#include <linux/of_irq.h>
#include <linux/platform_device.h>
#include <linux/slab.h>

#include "compat.h"
#include "pru_sim.h"

/* Local address of each core's IRAM in the PRU-ICSS, as in the reg property. */
static const u32 pru_sim_iram_offset[PRUSIM_NUM_CORES] = { 0x34000, 0x38000 };

static int pru_sim_start(struct rproc *rproc)
{
	struct pru_sim_core *pc = rproc->priv;
	struct pru_sim *sim = pc->sim;
	int ret;

	ret = pru_sim_intc_map_firmware(pc);
	if (ret)
		return ret;

	mutex_lock(&sim->lock);
	prusim_core_reset(sim->s, pc->index, pc->elf.entry / 4);
	prusim_core_enable(sim->s, pc->index, true);
	pru_sim_core_started(sim);
	mutex_unlock(&sim->lock);

	pru_sim_kick_thread(sim);

	/* Last in the list: rproc_stop() stops it before the vdevs. */
	rproc_add_subdev(rproc, &pc->quiesce);
	return 0;
}

static int pru_sim_stop(struct rproc *rproc)
{
	struct pru_sim_core *pc = rproc->priv;
	struct pru_sim *sim = pc->sim;
	unsigned int delay_us;

	rproc_remove_subdev(rproc, &pc->quiesce);

	/* debugfs stop_delay_us: as if this task were preempted right here */
	delay_us = READ_ONCE(sim->stop_delay_us);
	if (delay_us)
		fsleep(delay_us);

	/* Disabled and reset, whether it was running, sleeping or halted. */
	mutex_lock(&sim->lock);
	prusim_core_enable(sim->s, pc->index, false);
	prusim_core_reset(sim->s, pc->index, pc->elf.entry / 4);
	mutex_unlock(&sim->lock);

	pru_sim_intc_unmap_firmware(pc);
	return 0;
}

/*
 * rproc_stop() stops the subdevices before it calls ->stop: the rpmsg vdev is
 * reset and virtio_rpmsg_bus frees its buffers while the core still runs.
 * Firmware checks DRIVER_OK right before each store into those buffers, but
 * a slice may end between the check and the store (a PRU -> ARM event of
 * either core ends it), and the thread drops sim->lock and reschedules
 * there: the store then lands, a slice later, in freed memory.  So the core
 * is halted first, under sim->lock: once that is taken no slice runs, and
 * the next one finds the core disabled.
 */
static void pru_sim_quiesce(struct rproc_subdev *subdev, bool crashed)
{
	struct pru_sim_core *pc = container_of(subdev, struct pru_sim_core, quiesce);
	struct pru_sim *sim = pc->sim;

	mutex_lock(&sim->lock);
	prusim_core_enable(sim->s, pc->index, false);
	mutex_unlock(&sim->lock);
}

static void pru_sim_kick(struct rproc *rproc, int vqid)
{
	struct pru_sim_core *pc = rproc->priv;
	int ret;

	/* Any context: the INTC marks the event; the thread raises it. */
	ret = irq_set_irqchip_state(pc->kick_irq, IRQCHIP_STATE_PENDING, true);
	if (ret)
		dev_err_ratelimited(pc->dev, "kick failed: %d\n", ret);
}

/* DRAM and shared RAM; IRAM is predecoded and loaded only through the ELF. */
static void *pru_sim_da_to_va(PRUKIT_RPROC_DA_TO_VA_ARGS)
{
	struct pru_sim_core *pc = rproc->priv;

	if (da > U32_MAX)
		return NULL;
	return prusim_da_to_va(pc->sim->s, pc->index, da, len);
}

/* Load the image into the simulator: every check of the loader applies. */
static int pru_sim_load_elf(struct rproc *rproc, const struct firmware *fw)
{
	struct pru_sim_core *pc = rproc->priv;
	struct pru_sim *sim = pc->sim;
	int ret;

	mutex_lock(&sim->lock);
	ret = prusim_load_elf(sim->s, pc->index, fw->data, fw->size, &pc->elf);
	mutex_unlock(&sim->lock);
	if (ret) {
		dev_err(pc->dev, "%s: %s\n", rproc->firmware, pc->elf.err);
		return -EINVAL;
	}
	if (!pc->elf.rsc_size) {
		dev_err(pc->dev, "%s: no .resource_table section (an empty one will do)\n",
			rproc->firmware);
		return -EINVAL;
	}
	return 0;
}

static int pru_sim_sanity_check(struct rproc *rproc, const struct firmware *fw)
{
	return pru_sim_load_elf(rproc, fw);
}

static u64 pru_sim_get_boot_addr(struct rproc *rproc, const struct firmware *fw)
{
	struct pru_sim_core *pc = rproc->priv;

	return pc->elf.entry;
}

static int pru_sim_parse_fw(struct rproc *rproc, const struct firmware *fw)
{
	struct pru_sim_core *pc = rproc->priv;

	rproc->cached_table = kmemdup(fw->data + pc->elf.rsc_offset, pc->elf.rsc_size,
				      GFP_KERNEL);
	if (!rproc->cached_table)
		return -ENOMEM;
	rproc->table_ptr = rproc->cached_table;
	rproc->table_sz = pc->elf.rsc_size;
	return 0;
}

static struct resource_table *
pru_sim_find_loaded_rsc_table(struct rproc *rproc, const struct firmware *fw)
{
	struct pru_sim_core *pc = rproc->priv;

	return prusim_da_to_va(pc->sim->s, pc->index, pc->elf.rsc_addr, pc->elf.rsc_size);
}

/* The image was checked and loaded by sanity_check; load it afresh. */
static int pru_sim_load(struct rproc *rproc, const struct firmware *fw)
{
	return pru_sim_load_elf(rproc, fw);
}

#define PRU_SIM_RPROC_OPS						\
	.start = pru_sim_start,						\
	.stop = pru_sim_stop,						\
	.da_to_va = pru_sim_da_to_va,					\
	.sanity_check = pru_sim_sanity_check,				\
	.get_boot_addr = pru_sim_get_boot_addr,				\
	.parse_fw = pru_sim_parse_fw,					\
	.find_loaded_rsc_table = pru_sim_find_loaded_rsc_table,		\
	.load = pru_sim_load

/* Like mainline pru_rproc, a core without a "kick" interrupt cannot kick. */
static const struct rproc_ops pru_sim_rproc_ops = {
	PRU_SIM_RPROC_OPS,
};

static const struct rproc_ops pru_sim_rproc_ops_kick = {
	PRU_SIM_RPROC_OPS,
	.kick = pru_sim_kick,
};

/*
 * PRU -> ARM: the firmware filled used buffers of one of the virtqueues.
 *
 * Under the remote processor's lock, which remoteproc holds while it creates
 * the virtqueues (boot) and deletes them (shutdown): rproc_vq_interrupt()
 * does not synchronise with either, and an interrupt racing with a stop ran
 * rpmsg_recv_done() on a freed virtio_rpmsg device (an oops seen in the VM).
 * Nothing that holds the lock waits for this thread.
 */
static irqreturn_t pru_sim_vring_thread(int irq, void *data)
{
	struct pru_sim_core *pc = data;

	mutex_lock(&pc->rproc->lock);
	rproc_vq_interrupt(pc->rproc, 0);
	rproc_vq_interrupt(pc->rproc, 1);
	mutex_unlock(&pc->rproc->lock);
	return IRQ_HANDLED;
}

/*
 * A running processor is shut down before it is deleted, whoever started
 * it: 5.10's rproc_del() shuts down only auto-booted processors and would
 * leave an rpmsg channel whose kick calls into this module after it is
 * gone.  6.1's and 6.12's rproc_del() shut down any running processor; they
 * then find it offline and do nothing more.  The same on every kernel, so
 * this is no compat.h entry.
 */
static void pru_sim_core_shutdown(void *data)
{
	struct pru_sim_core *pc = data;
	struct rproc *rproc = pc->rproc;

	if (READ_ONCE(rproc->state) != RPROC_RUNNING)
		return;
	dev_info(pc->dev, "PRU%u still runs %s: shutting it down\n", pc->index,
		 rproc->firmware);
	rproc_shutdown(rproc);
}

/* The core leaves the simulator before its remote processor goes. */
static void pru_sim_core_detach(void *data)
{
	struct pru_sim_core *pc = data;
	struct pru_sim *sim = pc->sim;

	mutex_lock(&sim->lock);
	prusim_core_enable(sim->s, pc->index, false);
	sim->core[pc->index] = NULL;
	mutex_unlock(&sim->lock);
}

static int pru_sim_core_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct device_node *np = dev->of_node;
	struct pru_sim *sim = dev_get_drvdata(dev->parent);
	unsigned int index;
	const char *fw_name;
	struct pru_sim_core *pc;
	struct rproc *rproc;
	int kick_irq, ret;
	u32 iram;

	if (!sim)
		return -EPROBE_DEFER;
	if (of_property_read_u32(np, "reg", &iram))
		return dev_err_probe(dev, -EINVAL, "no reg property\n");

	ret = dma_coerce_mask_and_coherent(dev, DMA_BIT_MASK(32));
	if (ret)
		return dev_err_probe(dev, ret, "no 32-bit DMA\n");

	for (index = 0; index < PRUSIM_NUM_CORES; index++)
		if (pru_sim_iram_offset[index] == iram)
			break;
	if (index == PRUSIM_NUM_CORES)
		return dev_err_probe(dev, -EINVAL, "reg 0x%x is no PRU core's IRAM\n", iram);
	if (of_property_read_string(np, "firmware-name", &fw_name))
		fw_name = index ? "am335x-pru1-fw" : "am335x-pru0-fw";

	kick_irq = of_irq_get_byname(np, "kick");
	if (kick_irq == -EPROBE_DEFER)
		return kick_irq;
	rproc = devm_rproc_alloc(dev, dev_name(dev),
				 kick_irq > 0 ? &pru_sim_rproc_ops_kick : &pru_sim_rproc_ops,
				 fw_name, sizeof(*pc));
	if (!rproc)
		return -ENOMEM;
	pc = rproc->priv;
	pc->kick_irq = max(kick_irq, 0);
	pc->index = index;
	pc->sim = sim;
	pc->dev = dev;
	pc->rproc = rproc;
	pc->quiesce.stop = pru_sim_quiesce;
	/* PRUs wait for their consumer (or for "start" in sysfs). */
	rproc->auto_boot = false;

	ret = of_irq_get_byname(np, "vring");
	if (ret == -EPROBE_DEFER)
		return ret;
	if (ret > 0) {
		pc->vring_irq = ret;
		ret = devm_request_threaded_irq(dev, pc->vring_irq, NULL, pru_sim_vring_thread,
						IRQF_ONESHOT, dev_name(dev), pc);
		if (ret)
			return dev_err_probe(dev, ret, "cannot request the vring interrupt\n");
	}

	ret = devm_rproc_add(dev, rproc);
	if (ret)
		return dev_err_probe(dev, ret, "cannot register the remote processor\n");

	mutex_lock(&sim->lock);
	sim->core[pc->index] = pc;
	mutex_unlock(&sim->lock);
	ret = devm_add_action_or_reset(dev, pru_sim_core_detach, pc);
	if (ret)
		return ret;
	ret = devm_add_action_or_reset(dev, pru_sim_core_shutdown, pc);
	if (ret)
		return ret;
	dev_info(dev, "PRU%u: %s, firmware %s%s\n", pc->index, dev_name(&rproc->dev),
		 rproc->firmware, pc->kick_irq ? ", rpmsg kick" : "");
	return 0;
}

static const struct of_device_id pru_sim_core_of_match[] = {
	{ .compatible = "prukit,pru-sim" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_sim_core_of_match);

struct platform_driver pru_sim_core_driver = {
	.probe = pru_sim_core_probe,
	.driver = {
		.name = "pru_sim_core",
		.of_match_table = pru_sim_core_of_match,
	},
};
