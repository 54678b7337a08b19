// SPDX-License-Identifier: GPL-2.0-only
/*
 * clkctrl_standin - PRCM's module clocks (CM_PER's and CM_WKUP's CLKCTRL
 * registers) for the test VM, as TI's clkctrl driver provides them on a
 * BeagleBone.
 *
 * On a board each GPIO bank sits in an interconnect target module
 * (ti-sysc, "ti,sysc-omap2") whose functional clock is the bank's CLKCTRL:
 * ti-sysc enables it while the bank is in use (gpio-omap holds a runtime PM
 * reference for every requested line) and disables it when the bank idles,
 * and a bank whose clock is off takes no access.  TI's clkctrl driver
 * ("ti,clkctrl") needs mach-omap2's low-level clock operations, which the
 * VM's vexpress machine does not have, so this module stands in for it: one
 * gate clock per CLKCTRL register of its node, which writes MODULEMODE and
 * waits for IDLEST as TI's driver does.  A test-only module.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/bitfield.h>
#include <linux/bits.h>
#include <linux/clk-provider.h>
#include <linux/io.h>
#include <linux/iopoll.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/spinlock.h>

#define CLKCTRL_MODULEMODE	GENMASK(1, 0)
#define CLKCTRL_MODULEMODE_ON	2
#define CLKCTRL_IDLEST		GENMASK(17, 16)
#define CLKCTRL_IDLEST_FUNC	0
#define CLKCTRL_IDLEST_DISABLED	3
#define CLKCTRL_TIMEOUT_US	2000	/* TI's driver waits as long */

/**
 * struct clkctrl_standin_clk - one module's clock: its CLKCTRL register
 * @hw: the clock
 * @reg: the register
 * @lock: the provider's, for the register's read-modify-write
 */
struct clkctrl_standin_clk {
	struct clk_hw hw;
	void __iomem *reg;
	spinlock_t *lock;	/* the provider's: the register's read-modify-write */
};

/**
 * struct clkctrl_standin - one node's CLKCTRL registers
 * @clks: their clocks, one per 32-bit register from the start of reg
 * @num: how many
 * @lock: serialises read-modify-writes of the registers
 */
struct clkctrl_standin {
	struct clkctrl_standin_clk *clks;
	unsigned int num;
	spinlock_t lock;	/* the CLKCTRL registers' read-modify-writes */
};

static struct clkctrl_standin_clk *to_clkctrl_clk(struct clk_hw *hw)
{
	return container_of(hw, struct clkctrl_standin_clk, hw);
}

static void clkctrl_standin_mode(struct clkctrl_standin_clk *c, u32 mode)
{
	unsigned long flags;
	u32 v;

	spin_lock_irqsave(c->lock, flags);
	v = readl_relaxed(c->reg);
	v &= ~CLKCTRL_MODULEMODE;
	v |= FIELD_PREP(CLKCTRL_MODULEMODE, mode);
	writel_relaxed(v, c->reg);
	spin_unlock_irqrestore(c->lock, flags);
}

static int clkctrl_standin_enable(struct clk_hw *hw)
{
	struct clkctrl_standin_clk *c = to_clkctrl_clk(hw);
	u32 v;
	int ret;

	clkctrl_standin_mode(c, CLKCTRL_MODULEMODE_ON);
	ret = readl_poll_timeout_atomic(c->reg, v,
					FIELD_GET(CLKCTRL_IDLEST, v) == CLKCTRL_IDLEST_FUNC,
					1, CLKCTRL_TIMEOUT_US);
	if (ret)
		pr_err("%s: not functional (CLKCTRL 0x%08x)\n", clk_hw_get_name(hw), v);
	return ret;
}

static void clkctrl_standin_disable(struct clk_hw *hw)
{
	struct clkctrl_standin_clk *c = to_clkctrl_clk(hw);
	u32 v;

	clkctrl_standin_mode(c, 0);
	if (readl_poll_timeout_atomic(c->reg, v,
				      FIELD_GET(CLKCTRL_IDLEST, v) == CLKCTRL_IDLEST_DISABLED,
				      1, CLKCTRL_TIMEOUT_US))
		pr_err("%s: not disabled (CLKCTRL 0x%08x)\n", clk_hw_get_name(hw), v);
}

static int clkctrl_standin_is_enabled(struct clk_hw *hw)
{
	struct clkctrl_standin_clk *c = to_clkctrl_clk(hw);

	return FIELD_GET(CLKCTRL_MODULEMODE, readl_relaxed(c->reg)) ==
	       CLKCTRL_MODULEMODE_ON;
}

static const struct clk_ops clkctrl_standin_ops = {
	.enable = clkctrl_standin_enable,
	.disable = clkctrl_standin_disable,
	.is_enabled = clkctrl_standin_is_enabled,
};

/* <offset bit>: the register's offset from reg's start; bit 0, MODULEMODE */
static struct clk_hw *clkctrl_standin_get(struct of_phandle_args *spec, void *data)
{
	struct clkctrl_standin *cc = data;
	unsigned int off = spec->args[0];

	if (spec->args_count != 2 || off % 4 || off / 4 >= cc->num ||
	    spec->args[1] != 0)
		return ERR_PTR(-EINVAL);
	return &cc->clks[off / 4].hw;
}

static int clkctrl_standin_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct clkctrl_standin *cc;
	struct resource *res;
	void __iomem *base;
	unsigned int i;
	int ret;

	cc = devm_kzalloc(dev, sizeof(*cc), GFP_KERNEL);
	if (!cc)
		return -ENOMEM;
	base = devm_platform_get_and_ioremap_resource(pdev, 0, &res);
	if (IS_ERR(base))
		return dev_err_probe(dev, PTR_ERR(base), "cannot map the CLKCTRL registers\n");
	cc->num = resource_size(res) / 4;
	cc->clks = devm_kcalloc(dev, cc->num, sizeof(*cc->clks), GFP_KERNEL);
	if (!cc->clks)
		return -ENOMEM;
	spin_lock_init(&cc->lock);
	for (i = 0; i < cc->num; i++) {
		struct clkctrl_standin_clk *c = &cc->clks[i];
		struct clk_init_data init = { };

		init.name = devm_kasprintf(dev, GFP_KERNEL, "%s:%04x:0", dev_name(dev), 4 * i);
		if (!init.name)
			return -ENOMEM;
		init.ops = &clkctrl_standin_ops;
		c->reg = base + 4 * i;
		c->lock = &cc->lock;
		c->hw.init = &init;
		ret = devm_clk_hw_register(dev, &c->hw);
		if (ret)
			return dev_err_probe(dev, ret, "cannot register %s\n", init.name);
	}
	return devm_of_clk_add_hw_provider(dev, clkctrl_standin_get, cc);
}

static const struct of_device_id clkctrl_standin_of_match[] = {
	{ .compatible = "prukit,clkctrl-standin" },
	{ }
};
MODULE_DEVICE_TABLE(of, clkctrl_standin_of_match);

static struct platform_driver clkctrl_standin_driver = {
	.probe = clkctrl_standin_probe,
	.driver = {
		.name = "clkctrl-standin",
		.of_match_table = clkctrl_standin_of_match,
		.suppress_bind_attrs = true,
	},
};
module_platform_driver(clkctrl_standin_driver);

MODULE_DESCRIPTION("prukit test: PRCM's CLKCTRL module clocks, as TI's clkctrl driver's");
MODULE_LICENSE("GPL");
