// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_sim - the rest of the simulated AM335x a PRU-ICSS is wired to: pad
 * control (the "am33xx_pinmux" pin controller) and the four GPIO banks
 *
 * A BeagleBone overlay mux its pins with groups under &am33xx_pinmux
 * ("pinctrl-single,pins", AM33XX_PADCONF()) and names GPIOs as <&gpioN bit
 * flags>.  The simulated board offers the same labels, so such an overlay
 * applies unchanged: a "prukit,am33xx-pinmux-sim" child of the PRU-ICSS node
 * registers a pin controller that takes those groups, and four
 * "prukit,am335x-gpio-sim" children register GPIO chips backed by the
 * simulator's GPIO banks, the registers the PRU reaches over OCP.
 *
 * While the pin controller is bound, a PRU output reaches the pin trace only
 * through a pad muxed to it (pru_sim_r30_pads[]): R30 bits whose pad is in
 * another mode are not driven, as on the chip, and are counted in "stats".
 * The pad registers can also be written through debugfs ("pads"), as
 * config-pin does on BeagleBoard's images, unless a pinctrl state holds them.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/debugfs.h>
#include <linux/gpio/driver.h>
#include <linux/list.h>
#include <linux/module.h>
#include <linux/of.h>
#include <linux/pinctrl/pinctrl.h>
#include <linux/pinctrl/pinmux.h>
#include <linux/platform_device.h>
#include <linux/seq_file.h>
#include <linux/slab.h>
#include <linux/uaccess.h>

#include "compat.h"
#include "pru_sim.h"

/* The control module's pad registers: conf_* at 0x44e10800..0x44e10a34. */
#define PRU_SIM_PAD_FIRST	0x800
#define PRU_SIM_PAD_MUX_MASK	0x7f	/* pinctrl-single,function-mask */
#define PRU_SIM_PAD_MODE(v)	((v) & 0x7)
/* Reset value of a pad: mode 7 (GPIO), pull-down, receiver enabled */
#define PRU_SIM_PAD_RESET	0x27

static inline unsigned int pru_sim_pad_offset(unsigned int pin)
{
	return PRU_SIM_PAD_FIRST + 4 * pin;
}

/**
 * struct pru_sim_r30_pad - the pad that carries one PRU output
 * @offset: pad register offset in the control module (as the AM335X_PIN_*
 *	macros give it), 0 if the output reaches no BeagleBone header pin
 * @mode: mux mode that connects the pad to the output
 */
struct pru_sim_r30_pad {
	u16 offset;
	u8 mode;
};

/*
 * PRU outputs and their pads (AM335x datasheet pin attributes; the same
 * rows as sim/am335x-pins.tsv, which the overlay check uses).
 */
static const struct pru_sim_r30_pad pru_sim_r30_pads[PRUSIM_NUM_CORES][32] = {
	[0] = {
		{ 0x990, 5 }, { 0x994, 5 }, { 0x998, 5 }, { 0x99c, 5 },	/* mcasp0 */
		{ 0x9a0, 5 }, { 0x9a4, 5 }, { 0x9a8, 5 }, { 0x9ac, 5 },
		[14] = { 0x830, 6 }, [15] = { 0x834, 6 },		/* gpmc_ad12/13 */
	},
	[1] = {
		{ 0x8a0, 5 }, { 0x8a4, 5 }, { 0x8a8, 5 }, { 0x8ac, 5 },	/* lcd_data0..7 */
		{ 0x8b0, 5 }, { 0x8b4, 5 }, { 0x8b8, 5 }, { 0x8bc, 5 },
		{ 0x8e0, 5 }, { 0x8e4, 5 }, { 0x8e8, 5 }, { 0x8ec, 5 },	/* lcd ctl */
		{ 0x880, 5 }, { 0x884, 5 },				/* gpmc_csn1/2 */
		{ 0x970, 5 }, { 0x974, 5 },				/* uart0 */
	},
};

/* Is R30 pin @pin (PRUSIM_PIN_R30()) connected to its pad?  Under @sim->lock. */
static bool pru_sim_r30_muxed(struct pru_sim *sim, unsigned int pin)
{
	const struct pru_sim_r30_pad *p = &pru_sim_r30_pads[pin / 32][pin % 32];

	if (!p->offset)
		return false;
	return PRU_SIM_PAD_MODE(sim->pad[(p->offset - PRU_SIM_PAD_FIRST) / 4]) == p->mode;
}

/* Record the level a PRU output pad shows, if it changed.  Under @sim->lock. */
static void pru_sim_r30_show(struct pru_sim *sim, u64 cycle, unsigned int pin)
{
	u64 bit = BIT_ULL(pin);
	bool level = sim->r30 & bit;

	if (sim->pads_live && !pru_sim_r30_muxed(sim, pin))
		level = false;
	if (!!(sim->r30_shown & bit) == level)
		return;
	sim->r30_shown ^= bit;
	pru_sim_trace_pin(sim, cycle, pin, level);
}

/**
 * pru_sim_r30_changed() - a PRU output changed
 * @sim: the PRU-ICSS
 * @cycle: when
 * @pin: PRUSIM_PIN_R30() number
 * @level: its new level
 *
 * Called from the simulation (under @sim->lock): the change reaches the pin
 * trace if the pad is muxed to the output, or if the board has no pin
 * controller at all; otherwise it is counted and reported once per pin.
 */
void pru_sim_r30_changed(struct pru_sim *sim, u64 cycle, unsigned int pin, bool level)
{
	u64 bit = BIT_ULL(pin);

	lockdep_assert_held(&sim->lock);
	if (level)
		sim->r30 |= bit;
	else
		sim->r30 &= ~bit;
	if (sim->pads_live && !pru_sim_r30_muxed(sim, pin)) {
		sim->unmuxed_writes++;
		if (!(sim->unmuxed_warned & bit)) {
			sim->unmuxed_warned |= bit;
			dev_info(sim->dev, "pru%u r30 bit %u: %s, not driven\n", pin / 32, pin % 32,
				 pru_sim_r30_pads[pin / 32][pin % 32].offset ?
				 "its pad is not muxed to the PRU" : "no header pin carries it");
		}
	}
	pru_sim_r30_show(sim, cycle, pin);
}

/* Pads changed: show the PRU outputs they now connect or disconnect. */
static void pru_sim_pads_changed(struct pru_sim *sim)
{
	unsigned int pin;

	lockdep_assert_held(&sim->lock);
	for (pin = 0; pin < 64; pin++)
		pru_sim_r30_show(sim, sim->s->now, pin);
}

/* ------------------------------------------------------------------ */
/* Pin controller                                                      */

/**
 * struct pru_sim_pingroup - one "pinctrl-single,pins" node, as a group and
 *	a function of the same name
 * @node: in &pru_sim_pinmux.groups
 * @np: the device tree node (referenced)
 * @name: its full name
 * @pins: pin numbers (pad index from 0x800)
 * @vals: the value each pad gets
 * @npins: entries in @pins and @vals
 */
struct pru_sim_pingroup {
	struct list_head node;
	struct device_node *np;
	const char *name;
	unsigned int *pins;
	u32 *vals;
	unsigned int npins;
};

/**
 * struct pru_sim_pinmux - the simulated am33xx_pinmux
 * @dev: its device
 * @sim: the PRU-ICSS whose pads these are
 * @desc: pin controller description
 * @pctl: the registered pin controller
 * @cells: #pinctrl-cells (1: offset value; 2: offset conf mux)
 * @lock: protects @groups and @ngroups
 * @groups: &struct pru_sim_pingroup in selector order
 * @ngroups: entries in @groups
 * @claimed: pins held by a pinctrl state (debugfs may not change them)
 * @debugfs: the "pads" file
 */
struct pru_sim_pinmux {
	struct device *dev;
	struct pru_sim *sim;
	struct pinctrl_desc desc;
	struct pinctrl_dev *pctl;
	u32 cells;
	struct mutex lock;		/* protects @groups, @ngroups */
	struct list_head groups;
	unsigned int ngroups;
	DECLARE_BITMAP(claimed, PRU_SIM_NUM_PADS);
	struct dentry *debugfs;
};

static struct pru_sim_pingroup *pru_sim_group(struct pru_sim_pinmux *pm, unsigned int selector)
{
	struct pru_sim_pingroup *g;

	mutex_lock(&pm->lock);
	list_for_each_entry(g, &pm->groups, node)
		if (!selector--)
			goto out;
	g = NULL;
out:
	mutex_unlock(&pm->lock);
	return g;
}

static int pru_sim_get_groups_count(struct pinctrl_dev *pctl)
{
	struct pru_sim_pinmux *pm = pinctrl_dev_get_drvdata(pctl);

	return pm->ngroups;
}

static const char *pru_sim_get_group_name(struct pinctrl_dev *pctl, unsigned int selector)
{
	struct pru_sim_pingroup *g = pru_sim_group(pinctrl_dev_get_drvdata(pctl), selector);

	return g ? g->name : NULL;
}

static int pru_sim_get_group_pins(struct pinctrl_dev *pctl, unsigned int selector,
				  const unsigned int **pins, unsigned int *npins)
{
	struct pru_sim_pingroup *g = pru_sim_group(pinctrl_dev_get_drvdata(pctl), selector);

	if (!g)
		return -EINVAL;
	*pins = g->pins;
	*npins = g->npins;
	return 0;
}

static void pru_sim_pin_dbg_show(struct pinctrl_dev *pctl, struct seq_file *s, unsigned int pin)
{
	struct pru_sim_pinmux *pm = pinctrl_dev_get_drvdata(pctl);

	seq_printf(s, "0x%08x", READ_ONCE(pm->sim->pad[pin]));
}

static void pru_sim_group_free(struct pru_sim_pingroup *g)
{
	of_node_put(g->np);
	kfree(g->vals);
	kfree(g->pins);
	kfree(g->name);
	kfree(g);
}

/* Parse one "pinctrl-single,pins" node into a new group (under @pm->lock). */
static struct pru_sim_pingroup *pru_sim_group_create(struct pru_sim_pinmux *pm,
						     struct device_node *np)
{
	unsigned int per = pm->cells + 1, i;
	struct pru_sim_pingroup *g;
	int n;

	n = of_property_count_u32_elems(np, "pinctrl-single,pins");
	if (n <= 0 || n % per) {
		dev_err(pm->dev, "%pOF: pinctrl-single,pins needs %u cells per pad\n", np, per);
		return ERR_PTR(-EINVAL);
	}
	/* Not devm: created after probe, freed by pru_sim_pinmux_detach() */
	g = kzalloc(sizeof(*g), GFP_KERNEL);
	if (!g)
		return ERR_PTR(-ENOMEM);
	g->npins = n / per;
	g->name = kasprintf(GFP_KERNEL, "%pOF", np);
	g->pins = kcalloc(g->npins, sizeof(*g->pins), GFP_KERNEL);
	g->vals = kcalloc(g->npins, sizeof(*g->vals), GFP_KERNEL);
	if (!g->name || !g->pins || !g->vals) {
		pru_sim_group_free(g);
		return ERR_PTR(-ENOMEM);
	}
	for (i = 0; i < g->npins; i++) {
		u32 cell[3] = { };
		unsigned int c;

		for (c = 0; c < per; c++)
			of_property_read_u32_index(np, "pinctrl-single,pins", i * per + c,
						   &cell[c]);
		if (cell[0] % 4 || cell[0] / 4 >= PRU_SIM_NUM_PADS) {
			dev_err(pm->dev, "%pOF: no pad at offset 0x%x\n", np, cell[0]);
			pru_sim_group_free(g);
			return ERR_PTR(-EINVAL);
		}
		g->pins[i] = cell[0] / 4;
		g->vals[i] = cell[1] | cell[2];
	}
	g->np = of_node_get(np);
	list_add_tail(&g->node, &pm->groups);
	pm->ngroups++;
	return g;
}

static int pru_sim_dt_node_to_map(struct pinctrl_dev *pctl, struct device_node *np,
				  struct pinctrl_map **map, unsigned int *num_maps)
{
	struct pru_sim_pinmux *pm = pinctrl_dev_get_drvdata(pctl);
	struct pru_sim_pingroup *g;
	struct pinctrl_map *m;

	mutex_lock(&pm->lock);
	list_for_each_entry(g, &pm->groups, node)
		if (g->np == np)
			goto found;
	g = pru_sim_group_create(pm, np);
found:
	mutex_unlock(&pm->lock);
	if (IS_ERR(g))
		return PTR_ERR(g);

	m = kzalloc(sizeof(*m), GFP_KERNEL);
	if (!m)
		return -ENOMEM;
	m->type = PIN_MAP_TYPE_MUX_GROUP;
	m->data.mux.group = g->name;
	m->data.mux.function = g->name;
	*map = m;
	*num_maps = 1;
	return 0;
}

static void pru_sim_dt_free_map(struct pinctrl_dev *pctl, struct pinctrl_map *map,
				unsigned int num_maps)
{
	kfree(map);
}

static const struct pinctrl_ops pru_sim_pinctrl_ops = {
	.get_groups_count = pru_sim_get_groups_count,
	.get_group_name = pru_sim_get_group_name,
	.get_group_pins = pru_sim_get_group_pins,
	.pin_dbg_show = pru_sim_pin_dbg_show,
	.dt_node_to_map = pru_sim_dt_node_to_map,
	.dt_free_map = pru_sim_dt_free_map,
};

static int pru_sim_get_function_groups(struct pinctrl_dev *pctl, unsigned int selector,
				       const char * const **groups, unsigned int *ngroups)
{
	struct pru_sim_pingroup *g = pru_sim_group(pinctrl_dev_get_drvdata(pctl), selector);

	if (!g)
		return -EINVAL;
	*groups = &g->name;
	*ngroups = 1;
	return 0;
}

static int pru_sim_pmx_request(struct pinctrl_dev *pctl, unsigned int pin)
{
	struct pru_sim_pinmux *pm = pinctrl_dev_get_drvdata(pctl);

	set_bit(pin, pm->claimed);
	return 0;
}

static int pru_sim_pmx_free(struct pinctrl_dev *pctl, unsigned int pin)
{
	struct pru_sim_pinmux *pm = pinctrl_dev_get_drvdata(pctl);

	clear_bit(pin, pm->claimed);
	return 0;
}

static int pru_sim_set_mux(struct pinctrl_dev *pctl, unsigned int func, unsigned int group)
{
	struct pru_sim_pinmux *pm = pinctrl_dev_get_drvdata(pctl);
	struct pru_sim_pingroup *g = pru_sim_group(pm, group);
	struct pru_sim *sim = pm->sim;
	unsigned int i;

	if (!g)
		return -EINVAL;
	mutex_lock(&sim->lock);
	for (i = 0; i < g->npins; i++) {
		u32 *pad = &sim->pad[g->pins[i]];

		WRITE_ONCE(*pad, (*pad & ~PRU_SIM_PAD_MUX_MASK) |
			   (g->vals[i] & PRU_SIM_PAD_MUX_MASK));
	}
	pru_sim_pads_changed(sim);
	mutex_unlock(&sim->lock);
	return 0;
}

static const struct pinmux_ops pru_sim_pinmux_ops = {
	.request = pru_sim_pmx_request,
	.free = pru_sim_pmx_free,
	.get_functions_count = pru_sim_get_groups_count,
	.get_function_name = pru_sim_get_group_name,
	.get_function_groups = pru_sim_get_function_groups,
	.set_mux = pru_sim_set_mux,
	.strict = true,
};

/*
 * debugfs "pads": (r) every pad not at its reset value and every pad of a
 * PRU output, "0xOFFSET 0xVALUE [pruN_r30_B muxed|unmuxed] [claimed]";
 * (w) "0xOFFSET 0xVALUE" sets a pad's mux field (bits 0..6) unless a
 * pinctrl state holds it (-EBUSY).
 */
static int pru_sim_pads_show(struct seq_file *m, void *unused)
{
	struct pru_sim_pinmux *pm = m->private;
	struct pru_sim *sim = pm->sim;
	unsigned int pin, core, bit;

	mutex_lock(&sim->lock);
	for (pin = 0; pin < PRU_SIM_NUM_PADS; pin++) {
		unsigned int off = pru_sim_pad_offset(pin);
		bool shown = sim->pad[pin] != PRU_SIM_PAD_RESET;
		char sig[32] = "";

		for (core = 0; core < PRUSIM_NUM_CORES; core++)
			for (bit = 0; bit < 32; bit++)
				if (pru_sim_r30_pads[core][bit].offset == off) {
					snprintf(sig, sizeof(sig), " pru%u_r30_%u %s", core, bit,
						 pru_sim_r30_muxed(sim, PRUSIM_PIN_R30(core, bit)) ?
						 "muxed" : "unmuxed");
					shown = true;
				}
		if (shown)
			seq_printf(m, "0x%03x 0x%02x%s%s\n", off, sim->pad[pin], sig,
				   test_bit(pin, pm->claimed) ? " claimed" : "");
	}
	mutex_unlock(&sim->lock);
	return 0;
}

static int pru_sim_pads_open(struct inode *inode, struct file *file)
{
	return single_open(file, pru_sim_pads_show, inode->i_private);
}

static ssize_t pru_sim_pads_write(struct file *file, const char __user *ubuf, size_t len,
				  loff_t *ppos)
{
	struct pru_sim_pinmux *pm = ((struct seq_file *)file->private_data)->private;
	struct pru_sim *sim = pm->sim;
	unsigned int off, val, pin;
	char buf[32];

	if (len >= sizeof(buf))
		return -EINVAL;
	if (copy_from_user(buf, ubuf, len))
		return -EFAULT;
	buf[len] = '\0';
	if (sscanf(buf, "%x %x", &off, &val) != 2 || off < PRU_SIM_PAD_FIRST || off % 4 ||
	    (off - PRU_SIM_PAD_FIRST) / 4 >= PRU_SIM_NUM_PADS || val > PRU_SIM_PAD_MUX_MASK) {
		dev_err(pm->dev, "pads: expected \"0xOFFSET 0xVALUE\", 0x800..0x%x, <= 0x7f\n",
			pru_sim_pad_offset(PRU_SIM_NUM_PADS - 1));
		return -EINVAL;
	}
	pin = (off - PRU_SIM_PAD_FIRST) / 4;
	if (test_bit(pin, pm->claimed)) {
		dev_err(pm->dev, "pads: pad 0x%x is held by a pinctrl state\n", off);
		return -EBUSY;
	}
	mutex_lock(&sim->lock);
	WRITE_ONCE(sim->pad[pin], val);
	pru_sim_pads_changed(sim);
	mutex_unlock(&sim->lock);
	return len;
}

static const struct file_operations pru_sim_pads_fops = {
	.owner = THIS_MODULE,
	.open = pru_sim_pads_open,
	.read = seq_read,
	.write = pru_sim_pads_write,
	.llseek = seq_lseek,
	.release = single_release,
};

static void pru_sim_pinmux_detach(void *data)
{
	struct pru_sim_pinmux *pm = data;
	struct pru_sim *sim = pm->sim;
	struct pru_sim_pingroup *g, *next;

	debugfs_remove(pm->debugfs);
	mutex_lock(&sim->lock);
	sim->pads_live = false;
	pru_sim_pads_changed(sim);
	mutex_unlock(&sim->lock);
	list_for_each_entry_safe(g, next, &pm->groups, node)
		pru_sim_group_free(g);
}

static int pru_sim_pinmux_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct pru_sim *sim = dev_get_drvdata(dev->parent);
	struct pinctrl_pin_desc *pins;
	struct pru_sim_pinmux *pm;
	unsigned int i;
	int ret;

	if (!sim)
		return -EPROBE_DEFER;
	pm = devm_kzalloc(dev, sizeof(*pm), GFP_KERNEL);
	pins = devm_kcalloc(dev, PRU_SIM_NUM_PADS, sizeof(*pins), GFP_KERNEL);
	if (!pm || !pins)
		return -ENOMEM;
	pm->dev = dev;
	pm->sim = sim;
	mutex_init(&pm->lock);
	INIT_LIST_HEAD(&pm->groups);
	if (of_property_read_u32(dev->of_node, "#pinctrl-cells", &pm->cells) ||
	    pm->cells < 1 || pm->cells > 2)
		return dev_err_probe(dev, -EINVAL, "#pinctrl-cells must be 1 or 2\n");

	for (i = 0; i < PRU_SIM_NUM_PADS; i++) {
		pins[i].number = i;
		pins[i].name = devm_kasprintf(dev, GFP_KERNEL, "pad 0x%03x", pru_sim_pad_offset(i));
		if (!pins[i].name)
			return -ENOMEM;
	}
	pm->desc.name = dev_name(dev);
	pm->desc.pins = pins;
	pm->desc.npins = PRU_SIM_NUM_PADS;
	pm->desc.pctlops = &pru_sim_pinctrl_ops;
	pm->desc.pmxops = &pru_sim_pinmux_ops;
	/*
	 * No owner: the pinctrl core would take a module reference for every
	 * pin held, and the pins are held by pru_sim's own cores, so the
	 * module could never be removed.  The cores go before the controller
	 * (pru_sim_depopulate()); a consumer outside pru_sim that holds pins
	 * of the simulated board must be removed before pru_sim is.
	 */
	pm->desc.owner = NULL;

	mutex_lock(&sim->lock);
	for (i = 0; i < PRU_SIM_NUM_PADS; i++)
		WRITE_ONCE(sim->pad[i], PRU_SIM_PAD_RESET);
	sim->pads_live = true;
	pru_sim_pads_changed(sim);
	mutex_unlock(&sim->lock);
	ret = devm_add_action_or_reset(dev, pru_sim_pinmux_detach, pm);
	if (ret)
		return ret;
	pm->debugfs = debugfs_create_file("pads", 0600, sim->debugfs, pm, &pru_sim_pads_fops);

	pm->pctl = devm_pinctrl_register(dev, &pm->desc, pm);
	if (IS_ERR(pm->pctl))
		return dev_err_probe(dev, PTR_ERR(pm->pctl), "cannot register pin control\n");
	dev_info(dev, "simulated AM335x pad control, %u pads\n", PRU_SIM_NUM_PADS);
	return 0;
}

static const struct of_device_id pru_sim_pinmux_of_match[] = {
	{ .compatible = "prukit,am33xx-pinmux-sim" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_sim_pinmux_of_match);

struct platform_driver pru_sim_pinmux_driver = {
	.probe = pru_sim_pinmux_probe,
	.driver = {
		.name = "pru_sim_pinmux",
		.of_match_table = pru_sim_pinmux_of_match,
		/* a consumer's pinctrl state must not outlive its controller */
		.suppress_bind_attrs = true,
	},
};

/* ------------------------------------------------------------------ */
/* GPIO banks                                                          */

/**
 * struct pru_sim_gpio - one GPIO bank as a Linux GPIO chip
 * @chip: the chip
 * @sim: the PRU-ICSS whose simulator holds the bank's registers
 * @bank: 0..3
 */
struct pru_sim_gpio {
	struct gpio_chip chip;
	struct pru_sim *sim;
	unsigned int bank;
};

static u32 pru_sim_gpio_reg(struct pru_sim_gpio *g, u32 reg)
{
	u32 v;

	mutex_lock(&g->sim->lock);
	v = prusim_gpio_read(g->sim->s, g->bank, reg);
	mutex_unlock(&g->sim->lock);
	return v;
}

static void pru_sim_gpio_update(struct pru_sim_gpio *g, u32 reg, u32 mask, u32 bits)
{
	struct pru_sim *sim = g->sim;
	u32 v;

	mutex_lock(&sim->lock);
	v = prusim_gpio_read(sim->s, g->bank, reg);
	prusim_gpio_write(sim->s, g->bank, reg, (v & ~mask) | bits);
	mutex_unlock(&sim->lock);
	pru_sim_kick_thread(sim);
}

static int pru_sim_gpio_get_direction(struct gpio_chip *chip, unsigned int offset)
{
	struct pru_sim_gpio *g = gpiochip_get_data(chip);

	return pru_sim_gpio_reg(g, PRUSIM_GPIO_OE) & BIT(offset) ?
		GPIO_LINE_DIRECTION_IN : GPIO_LINE_DIRECTION_OUT;
}

static int pru_sim_gpio_direction_input(struct gpio_chip *chip, unsigned int offset)
{
	pru_sim_gpio_update(gpiochip_get_data(chip), PRUSIM_GPIO_OE, BIT(offset), BIT(offset));
	return 0;
}

static int pru_sim_gpio_get(struct gpio_chip *chip, unsigned int offset)
{
	struct pru_sim_gpio *g = gpiochip_get_data(chip);
	u32 oe = pru_sim_gpio_reg(g, PRUSIM_GPIO_OE);

	return !!(pru_sim_gpio_reg(g, oe & BIT(offset) ? PRUSIM_GPIO_DATAIN :
				   PRUSIM_GPIO_DATAOUT) & BIT(offset));
}

static void pru_sim_gpio_set_value(struct pru_sim_gpio *g, unsigned int offset, int value)
{
	pru_sim_gpio_update(g, PRUSIM_GPIO_DATAOUT, BIT(offset), value ? BIT(offset) : 0);
}

static void pru_sim_gpio_set_void(struct gpio_chip *chip, unsigned int offset, int value)
{
	pru_sim_gpio_set_value(gpiochip_get_data(chip), offset, value);
}

static int pru_sim_gpio_set_int(struct gpio_chip *chip, unsigned int offset, int value)
{
	pru_sim_gpio_set_value(gpiochip_get_data(chip), offset, value);
	return 0;
}

static int pru_sim_gpio_direction_output(struct gpio_chip *chip, unsigned int offset, int value)
{
	struct pru_sim_gpio *g = gpiochip_get_data(chip);

	pru_sim_gpio_set_value(g, offset, value);
	pru_sim_gpio_update(g, PRUSIM_GPIO_OE, BIT(offset), 0);
	return 0;
}

static int pru_sim_gpio_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct pru_sim *sim = dev_get_drvdata(dev->parent);
	struct pru_sim_gpio *g;
	int bank;
	u32 base;

	if (!sim)
		return -EPROBE_DEFER;
	g = devm_kzalloc(dev, sizeof(*g), GFP_KERNEL);
	if (!g)
		return -ENOMEM;
	if (of_property_read_u32(dev->of_node, "reg", &base))
		return dev_err_probe(dev, -EINVAL, "no reg\n");
	bank = prusim_gpio_bank(base);
	if (bank < 0 || base & 0xfff)
		return dev_err_probe(dev, -EINVAL, "0x%08x is not an AM335x GPIO bank\n", base);
	g->bank = bank;
	g->sim = sim;
	g->chip.label = devm_kasprintf(dev, GFP_KERNEL, "gpio%u", g->bank);
	if (!g->chip.label)
		return -ENOMEM;
	g->chip.parent = dev;
	g->chip.owner = THIS_MODULE;
	g->chip.base = -1;
	g->chip.ngpio = 32;
	g->chip.can_sleep = true;
	g->chip.get_direction = pru_sim_gpio_get_direction;
	g->chip.direction_input = pru_sim_gpio_direction_input;
	g->chip.direction_output = pru_sim_gpio_direction_output;
	g->chip.get = pru_sim_gpio_get;
	prukit_gpio_chip_set(&g->chip, pru_sim_gpio_set_void, pru_sim_gpio_set_int);
	return devm_gpiochip_add_data(dev, &g->chip, g);
}

static const struct of_device_id pru_sim_gpio_of_match[] = {
	{ .compatible = "prukit,am335x-gpio-sim" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_sim_gpio_of_match);

struct platform_driver pru_sim_gpio_driver = {
	.probe = pru_sim_gpio_probe,
	.driver = {
		.name = "pru_sim_gpio",
		.of_match_table = pru_sim_gpio_of_match,
		.suppress_bind_attrs = true,
	},
};
