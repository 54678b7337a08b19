// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_sim - a simulated AM335x PRU-ICSS, in the spirit of mac80211_hwsim
 *
 * The "prukit,pruss-sim" device tree node is laid out like the real PRU-ICSS:
 * two PRU cores (children "prukit,pru-sim", registered as remote processors
 * that consumers find through "ti,prus" phandles) and an interrupt controller
 * (child "prukit,pruss-sim-intc", three cells as the TI PRUSS INTC: system
 * event, channel, host interrupt).  The real firmware runs, cycle by cycle,
 * in the prusim core (sim/), the same code as the prusim host tool, in a
 * kernel thread.  OCP master port accesses reach the ARM's RAM through the
 * node's dma-ranges, so buffers allocated with the DMA API are what the
 * firmware reads and writes.  debugfs has the pin trace, input stimulus and
 * statistics (Documentation/pru_sim.rst).
 *
 * This file: the PRU-ICSS device, the simulation thread and the OCP port.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/delay.h>
#include <linux/highmem.h>
#include <linux/io.h>
#include <linux/ktime.h>
#include <linux/mm.h>
#include <linux/module.h>
#include <linux/of.h>
#include <linux/of_address.h>
#include <linux/of_platform.h>
#include <linux/platform_device.h>
#include <linux/sched.h>
#include <linux/slab.h>
#include <linux/vmalloc.h>

#include "compat.h"
#include "pru_sim.h"

/*
 * Cycles per slice while a core does real work.  The lock is held for a
 * slice, so this bounds how long a kick or a remoteproc operation waits -
 * in PRU cycles too: firmware spinning in a loop the idle detector cannot
 * prove idle (prukit's rpmsg wait reads R31 and the vdev status into the
 * same register) runs flat out, and a kick reaches it at the end of the
 * slice.  A slice costs a lock, two clock reads and a look at the INTC:
 * at 2000 cycles still well under 1% of the simulation.
 */
#define PRU_SIM_SLICE		2000
static struct dentry *pru_sim_debugfs_root;

static unsigned int slice_cycles = PRU_SIM_SLICE;
module_param(slice_cycles, uint, 0444);
MODULE_PARM_DESC(slice_cycles, "PRU cycles simulated between scheduling points (default 2000)");

/*
 * A core that spins on a word of its memory (a driver's control block, say)
 * waits for a store by the ARM, which nothing announces: while every core
 * only waits and one of them spins, the thread looks again this often.
 */
static unsigned int idle_poll_us = 1000;
module_param(idle_poll_us, uint, 0644);
MODULE_PARM_DESC(idle_poll_us,
		 "Microseconds between looks at a core spinning on memory the ARM may write (default 1000, 0: only on kicks)");

void pru_sim_kick_thread(struct pru_sim *sim)
{
	atomic_set(&sim->work, 1);
	wake_up(&sim->wq);
}

/*
 * Is this page free in the page allocator (on a free list or a per-CPU
 * list)?  A free page has no reference; every page of a live allocation has
 * one, or belongs to a compound page whose head has one (page_count()).
 * The exception, tail pages of a non-compound high-order allocation, is not
 * what DMA buffers are on ARM: CMA and split_page() hand out pages that
 * each hold a reference.  A page freed and allocated again is not caught.
 */
static bool pru_sim_page_free(unsigned long pfn)
{
	return !page_count(pfn_to_page(pfn));
}

/*
 * OCP master port: addresses in the dma-ranges window are the ARM's RAM,
 * reached page by page; anything else stops the core.  A write that lands
 * in a free page - a buffer freed under the firmware - is made all the
 * same, as on a board, and counted (debugfs "stats").
 */
static int pru_sim_ocp_access(struct pru_sim *sim, u32 addr, void *buf,
			      unsigned int len, bool write)
{
	u64 off = (u64)addr - sim->ram_bus;
	unsigned int total = len;
	bool to_free = false;
	phys_addr_t phys;

	if (addr < sim->ram_bus || off + len > sim->ram_size) {
		snprintf(sim->ocp_err, sizeof(sim->ocp_err),
			 "OCP %s of %u bytes at 0x%08x is outside RAM", write ? "write" : "read",
			 len, addr);
		return -EFAULT;
	}

	phys = sim->ram_phys + off;
	while (len) {
		unsigned int chunk = min_t(unsigned int, len, PAGE_SIZE - offset_in_page(phys));
		unsigned long pfn = PHYS_PFN(phys);
		void *va;

		if (!pfn_valid(pfn)) {
			snprintf(sim->ocp_err, sizeof(sim->ocp_err),
				 "OCP access at 0x%08x: no RAM at %pa", addr, &phys);
			return -EFAULT;
		}
		if (write && !to_free && pru_sim_page_free(pfn)) {
			to_free = true;
			sim->ocp_free_writes++;
			dev_err_ratelimited(sim->dev,
					    "PRU OCP write of %u bytes at 0x%08x lands in a free page (%pa)\n",
					    total, addr, &phys);
		}
		va = prukit_kmap_local_page(pfn_to_page(pfn));
		if (write)
			memcpy(va + offset_in_page(phys), buf, chunk);
		else
			memcpy(buf, va + offset_in_page(phys), chunk);
		prukit_kunmap_local(va);
		buf += chunk;
		phys += chunk;
		len -= chunk;
	}
	/* debugfs ocp_write_pause_us: let the ARM run before the next store */
	if (write && READ_ONCE(sim->ocp_write_pause_us)) {
		sim->ocp_pause = true;
		prusim_yield(sim->s);
	}
	return 0;
}

static int pru_sim_ocp_read(void *ctx, u32 addr, void *buf, unsigned int len)
{
	return pru_sim_ocp_access(ctx, addr, buf, len, false);
}

static int pru_sim_ocp_write(void *ctx, u32 addr, const void *buf, unsigned int len)
{
	return pru_sim_ocp_access(ctx, addr, (void *)buf, len, true);
}

static void pru_sim_pin(void *ctx, u64 cycle, unsigned int pin, bool level)
{
	if (pin < PRUSIM_PIN_GPIO(0, 0))
		pru_sim_r30_changed(ctx, cycle, pin, level);
	else
		pru_sim_trace_pin(ctx, cycle, pin, level);
}

static u32 pru_sim_input_cb(void *ctx, unsigned int port, u64 cycle, u64 *next_change)
{
	return pru_sim_input(ctx, port, cycle, next_change);
}

/*
 * A host interrupt line rose.  If it goes to the ARM, end the slice now:
 * the event is taken out of the INTC and delivered as soon as prusim_run()
 * returns, not when the slice would have ended (which is up to
 * slice_cycles later in simulated time).
 */
static void pru_sim_host_irq(void *ctx, u64 cycle, unsigned int host, bool level)
{
	struct pru_sim *sim = ctx;
	u64 strobe = cycle - min_t(u64, cycle, sim->s->cfg.event_latency);

	if (!level || host < PRU_SIM_FIRST_ARM_HOST)
		return;
	if (!sim->irq_since)
		sim->irq_since = strobe ?: 1;
	prusim_yield(sim->s);
}

static const struct prusim_ops pru_sim_ops = {
	.pin = pru_sim_pin,
	.input = pru_sim_input_cb,
	.host_irq = pru_sim_host_irq,
	.ocp_read = pru_sim_ocp_read,
	.ocp_write = pru_sim_ocp_write,
};

/* Instructions executed, not counted by skipping over a wait. */
static u64 pru_sim_insns(struct pru_sim *sim)
{
	const struct prusim_core *c = sim->s->core;

	return c[0].insns - c[0].skipped_insns + c[1].insns - c[1].skipped_insns;
}

/* A core executes a loop (perhaps one that reads memory the ARM writes). */
static bool pru_sim_spinning(struct pru_sim *sim)
{
	unsigned int i;

	for (i = 0; i < PRUSIM_NUM_CORES; i++)
		if (sim->s->core[i].state == PRUSIM_RUNNING)
			return true;
	return false;
}

/* Log why a core stopped, once. */
static void pru_sim_report_stops(struct pru_sim *sim, bool *reported)
{
	unsigned int i;

	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		struct prusim_status st;

		prusim_get_status(sim->s, i, &st);
		if (st.state != PRUSIM_STOPPED) {
			reported[i] = false;
			continue;
		}
		if (!reported[i])
			dev_err(sim->dev, "PRU%u stopped at pc 0x%x: %s%s%s\n", i, st.pc * 4,
				st.reason, sim->ocp_err[0] ? ": " : "", sim->ocp_err);
		reported[i] = true;
	}
}

/*
 * The simulation thread: run slices while a core has work; sleep while
 * every core is disabled, halted or only waiting for something that only
 * the outside can bring - a kick, new input, a start, a store into its
 * memory.  (The simulator skips waits at no cost, so a slice that executed
 * next to nothing means every core waits; unless an input pattern or a
 * queued action still has a change to come, nothing inside can end the
 * wait.)  Kicks, inputs and starts wake the thread; stores by the ARM do
 * not, so while a core spins the thread looks again every idle_poll_us.
 * It sleeps interruptibly: an idle simulator is no hung task.
 */
static int pru_sim_thread(void *data)
{
	struct pru_sim *sim = data;
	bool reported[PRUSIM_NUM_CORES] = { };
	bool spinning = false;

	while (!kthread_should_stop()) {
		unsigned int poll_us = READ_ONCE(idle_poll_us);
		ktime_t poll = ns_to_ktime((u64)poll_us * NSEC_PER_USEC);
		u64 raise, insns, ran;
		bool busy;
		unsigned int pause_us;
		ktime_t t0;

		if (spinning && poll_us)
			wait_event_interruptible_hrtimeout(sim->wq,
							   atomic_read(&sim->work) ||
							   kthread_should_stop(),
							   poll);
		else
			wait_event_interruptible(sim->wq, atomic_read(&sim->work) ||
						 kthread_should_stop());
		atomic_set(&sim->work, 0);

		do {
			mutex_lock(&sim->lock);
			raise = atomic64_xchg(&sim->raise, 0);
			while (raise) {
				unsigned int ev = __ffs64(raise);

				prusim_raise_event(sim->s, ev);
				raise &= raise - 1;
			}
			/* The ARM may have stored into PRU memory since the last slice. */
			prusim_memory_written(sim->s);
			busy = prusim_active(sim->s);
			if (busy) {
				insns = pru_sim_insns(sim);
				t0 = ktime_get();
				ran = prusim_run(sim->s, sim->slice_cycles);
				sim->host_ns += ktime_to_ns(ktime_sub(ktime_get(), t0));
				atomic64_set(&sim->cycle, sim->s->now);
				insns = pru_sim_insns(sim) - insns;
				if (sim->s->waiting ||
				    (insns < ran / 64 && sim->s->next_event == PRUSIM_NEVER &&
				     !pru_sim_inputs_pending(sim)))
					busy = false;
				pru_sim_intc_collect(sim);
				pru_sim_report_stops(sim, reported);
			}
			spinning = !busy && pru_sim_spinning(sim);
			pause_us = sim->ocp_pause ? READ_ONCE(sim->ocp_write_pause_us) : 0;
			sim->ocp_pause = false;
			mutex_unlock(&sim->lock);
			if (pause_us)
				fsleep(pause_us);
			else
				cond_resched();
		} while (busy && !kthread_should_stop() && !atomic_read(&sim->work));

		if (busy)
			atomic_set(&sim->work, 1);
	}
	return 0;
}

/* The RAM window of the OCP port, from the node's single dma-ranges entry. */
static int pru_sim_parse_dma_ranges(struct pru_sim *sim, struct device_node *np)
{
	const __be32 *prop;
	u32 na, ns;
	int pna, len;

	/* Bus addresses use our cells, CPU addresses our parent's. */
	if (of_property_read_u32(np, "#address-cells", &na) ||
	    of_property_read_u32(np, "#size-cells", &ns) || na > 2 || ns > 2)
		return dev_err_probe(sim->dev, -EINVAL, "bad #address-cells/#size-cells\n");
	pna = of_n_addr_cells(np);
	prop = of_get_property(np, "dma-ranges", &len);
	if (!prop || len != (na + pna + ns) * sizeof(__be32))
		return dev_err_probe(sim->dev, -EINVAL,
				     "dma-ranges must hold one <bus cpu size> entry\n");
	sim->ram_bus = of_read_number(prop, na);
	sim->ram_phys = of_read_number(prop + na, pna);
	sim->ram_size = of_read_number(prop + na + pna, ns);
	if (!sim->ram_size || sim->ram_bus + sim->ram_size > SZ_4G)
		return dev_err_probe(sim->dev, -EINVAL, "dma-ranges window outside 32 bits\n");
	return 0;
}

static void pru_sim_free_state(void *data)
{
	struct pru_sim *sim = data;

	pru_sim_inputs_free(sim);
	vfree(sim->trace.rec);
	vfree(sim->s);
}

static void pru_sim_stop_thread(void *data)
{
	struct pru_sim *sim = data;

	kthread_stop(sim->thread);
}

static bool pru_sim_is_board(struct device *dev)
{
	return of_device_is_compatible(dev->of_node, "prukit,am33xx-pinmux-sim") ||
	       of_device_is_compatible(dev->of_node, "prukit,am335x-gpio-sim");
}

static int pru_sim_destroy_users(struct device *dev, void *data)
{
	return pru_sim_is_board(dev) ? 0 : of_platform_device_destroy(dev, data);
}

/*
 * The cores (which may hold pins through their own pinctrl state) go
 * before the board's pin controller and GPIO chips, whatever their order
 * in the tree: fdtoverlay, for one, reverses the children it adds.
 */
static void pru_sim_depopulate(void *data)
{
	struct pru_sim *sim = data;

	device_for_each_child_reverse(sim->dev, NULL, pru_sim_destroy_users);
	of_platform_depopulate(sim->dev);
}

static void pru_sim_remove_debugfs(void *data)
{
	struct pru_sim *sim = data;

	debugfs_remove_recursive(sim->debugfs);
}

static int pru_sim_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct device_node *np = dev->of_node;
	struct prusim_config cfg;
	struct pru_sim *sim;
	int ret;

	sim = devm_kzalloc(dev, sizeof(*sim), GFP_KERNEL);
	if (!sim)
		return -ENOMEM;
	sim->dev = dev;
	mutex_init(&sim->lock);
	spin_lock_init(&sim->stat_lock);
	init_waitqueue_head(&sim->wq);
	sim->slice_cycles = slice_cycles ?: PRU_SIM_SLICE;

	ret = pru_sim_parse_dma_ranges(sim, np);
	if (ret)
		return ret;

	sim->s = vzalloc(sizeof(*sim->s));
	sim->trace.rec = vzalloc(array_size(PRU_SIM_TRACE_LEN, sizeof(*sim->trace.rec)));
	ret = devm_add_action_or_reset(dev, pru_sim_free_state, sim);
	if (ret)
		return ret;
	if (!sim->s || !sim->trace.rec)
		return -ENOMEM;
	prusim_default_config(&cfg);
	/* Routed when a core starts, undone when it stops: pru_sim_core.c */
	cfg.irq_map_by_embedder = true;
	/*
	 * While every core waits for the ARM the thread sleeps, and simulated
	 * time stands still; it does not leap a slice ahead first.
	 */
	cfg.stop_when_idle = true;
	prusim_init(sim->s, &cfg, &pru_sim_ops, sim);

	ret = pru_sim_intc_init(sim, np);
	if (ret)
		return ret;

	sim->thread = kthread_run(pru_sim_thread, sim, "pru_sim/%s", dev_name(dev));
	if (IS_ERR(sim->thread))
		return dev_err_probe(dev, PTR_ERR(sim->thread), "cannot start the thread\n");
	ret = devm_add_action_or_reset(dev, pru_sim_stop_thread, sim);
	if (ret)
		return ret;

	platform_set_drvdata(pdev, sim);
	pru_sim_debugfs_init(sim, pru_sim_debugfs_root);
	ret = devm_add_action_or_reset(dev, pru_sim_remove_debugfs, sim);
	if (ret)
		return ret;

	/* The cores and the INTC are child devices, as on the real PRU-ICSS. */
	ret = of_platform_populate(np, NULL, NULL, dev);
	if (ret)
		return dev_err_probe(dev, ret, "cannot create the PRU core devices\n");
	ret = devm_add_action_or_reset(dev, pru_sim_depopulate, sim);
	if (ret)
		return ret;

	dev_info(dev, "simulated PRU-ICSS, RAM at PRU address 0x%llx\n", sim->ram_bus);
	return 0;
}

static const struct of_device_id pru_sim_of_match[] = {
	{ .compatible = "prukit,pruss-sim" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_sim_of_match);

static struct platform_driver pru_sim_driver = {
	.probe = pru_sim_probe,
	.driver = {
		.name = "pru_sim",
		.of_match_table = pru_sim_of_match,
	},
};

/* The children's drivers first: pru_sim_probe() populates them at once. */
static struct platform_driver * const pru_sim_drivers[] = {
	&pru_sim_core_driver,
	&pru_sim_pinmux_driver,
	&pru_sim_gpio_driver,
	&pru_sim_driver,
};

static int __init pru_sim_init(void)
{
	int ret;

	pru_sim_debugfs_root = debugfs_create_dir("pru_sim", NULL);
	ret = platform_register_drivers(pru_sim_drivers, ARRAY_SIZE(pru_sim_drivers));
	if (ret)
		debugfs_remove(pru_sim_debugfs_root);
	return ret;
}
module_init(pru_sim_init);

static void __exit pru_sim_exit(void)
{
	platform_unregister_drivers(pru_sim_drivers, ARRAY_SIZE(pru_sim_drivers));
	debugfs_remove(pru_sim_debugfs_root);
}
module_exit(pru_sim_exit);

MODULE_DESCRIPTION("Simulated AM335x PRU-ICSS: remote processors running firmware in prusim");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
