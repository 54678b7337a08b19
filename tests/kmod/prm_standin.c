// SPDX-License-Identifier: GPL-2.0-only
/*
 * prm_standin - the PRU-ICSS's reset in PRCM's PRM_PER for the test VM, as
 * omap_prm provides it on a BeagleBone.
 *
 * On a board the PRU-ICSS's interconnect target module (ti-sysc,
 * "ti,sysc-pruss") asserts the subsystem's local reset PRU_ICSS_LRST
 * (RM_PER_RSTCTRL bit 1, reset 1 of &prm_per) through omap_prm whenever
 * the module idles - once pruss is unbound - and releases it when pruss
 * binds.  omap_prm registers no resets without mach-omap2's platform data,
 * which the VM's vexpress machine does not have, so this module stands in
 * for it: it writes the same register of the QEMU device's PRCM, as
 * omap_prm does for a reset without a status bit.  A test-only module.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/bits.h>
#include <linux/io.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/reset-controller.h>
#include <linux/spinlock.h>

#define PRM_RSTCTRL	0x00	/* RM_PER_RSTCTRL */
#define PRM_ICSS_LRST	1	/* its only reset: the PRU-ICSS's */

/**
 * struct prm_standin - one PRM instance's resets
 * @rcdev: the reset controller
 * @base: the instance's registers
 * @lock: serialises read-modify-writes of RM_PER_RSTCTRL
 */
struct prm_standin {
	struct reset_controller_dev rcdev;
	void __iomem *base;
	spinlock_t lock;	/* RM_PER_RSTCTRL's read-modify-writes */
};

static struct prm_standin *to_prm_standin(struct reset_controller_dev *rcdev)
{
	return container_of(rcdev, struct prm_standin, rcdev);
}

static int prm_standin_set(struct reset_controller_dev *rcdev, unsigned long id,
			   bool assert)
{
	struct prm_standin *prm = to_prm_standin(rcdev);
	unsigned long flags;
	u32 v;

	spin_lock_irqsave(&prm->lock, flags);
	v = readl_relaxed(prm->base + PRM_RSTCTRL);
	if (assert)
		v |= BIT(id);
	else
		v &= ~BIT(id);
	writel_relaxed(v, prm->base + PRM_RSTCTRL);
	/* the write has reached PRCM before the caller goes on */
	readl_relaxed(prm->base + PRM_RSTCTRL);
	spin_unlock_irqrestore(&prm->lock, flags);
	return 0;
}

static int prm_standin_assert(struct reset_controller_dev *rcdev, unsigned long id)
{
	return prm_standin_set(rcdev, id, true);
}

static int prm_standin_deassert(struct reset_controller_dev *rcdev, unsigned long id)
{
	return prm_standin_set(rcdev, id, false);
}

static int prm_standin_status(struct reset_controller_dev *rcdev, unsigned long id)
{
	struct prm_standin *prm = to_prm_standin(rcdev);

	return !!(readl_relaxed(prm->base + PRM_RSTCTRL) & BIT(id));
}

static const struct reset_control_ops prm_standin_ops = {
	.assert = prm_standin_assert,
	.deassert = prm_standin_deassert,
	.status = prm_standin_status,
};

/* &prm_per's reset 1 is the PRU-ICSS's, as in am33xx-l4.dtsi; no other */
static int prm_standin_xlate(struct reset_controller_dev *rcdev,
			     const struct of_phandle_args *spec)
{
	if (spec->args[0] != PRM_ICSS_LRST)
		return -EINVAL;
	return PRM_ICSS_LRST;
}

static int prm_standin_probe(struct platform_device *pdev)
{
	struct prm_standin *prm;

	prm = devm_kzalloc(&pdev->dev, sizeof(*prm), GFP_KERNEL);
	if (!prm)
		return -ENOMEM;
	prm->base = devm_platform_ioremap_resource(pdev, 0);
	if (IS_ERR(prm->base))
		return dev_err_probe(&pdev->dev, PTR_ERR(prm->base),
				     "cannot map PRM_PER\n");
	spin_lock_init(&prm->lock);
	prm->rcdev.owner = THIS_MODULE;
	prm->rcdev.ops = &prm_standin_ops;
	prm->rcdev.of_node = pdev->dev.of_node;
	prm->rcdev.of_reset_n_cells = 1;
	prm->rcdev.of_xlate = prm_standin_xlate;
	prm->rcdev.nr_resets = PRM_ICSS_LRST + 1;
	return devm_reset_controller_register(&pdev->dev, &prm->rcdev);
}

static const struct of_device_id prm_standin_of_match[] = {
	{ .compatible = "prukit,prm-standin" },
	{ }
};
MODULE_DEVICE_TABLE(of, prm_standin_of_match);

static struct platform_driver prm_standin_driver = {
	.probe = prm_standin_probe,
	.driver = {
		.name = "prm-standin",
		.of_match_table = prm_standin_of_match,
		.suppress_bind_attrs = true,
	},
};
module_platform_driver(prm_standin_driver);

MODULE_DESCRIPTION("prukit test: PRM_PER's PRU-ICSS reset, as omap_prm's");
MODULE_LICENSE("GPL");
