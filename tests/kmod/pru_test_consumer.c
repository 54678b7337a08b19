// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_test_consumer - the smallest PRU consumer, for prukit's VM tests
 *
 * Does what every prukit driver does to reach its PRU, and nothing more:
 * finds the core through its "ti,prus" phandle and requests the interrupt
 * of its "interrupts" property (a PRU -> ARM system event through the
 * PRU-ICSS INTC).  The tests start firmware through remoteproc sysfs and
 * read how many interrupts arrived.
 *
 * sysfs, on the platform device:
 *   irq_count  (r)  interrupts received
 *   rproc      (r)  the remote processor's device name
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/interrupt.h>
#include <linux/module.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/remoteproc.h>

#include "compat.h"

struct pru_test_consumer {
	struct rproc *rproc;
	atomic_t irqs;
};

static irqreturn_t pru_test_consumer_irq(int irq, void *data)
{
	struct pru_test_consumer *tc = data;

	atomic_inc(&tc->irqs);
	return IRQ_HANDLED;
}

static ssize_t irq_count_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%d\n", atomic_read(&tc->irqs));
}
static DEVICE_ATTR_RO(irq_count);

static ssize_t rproc_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct pru_test_consumer *tc = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%s\n", dev_name(&tc->rproc->dev));
}
static DEVICE_ATTR_RO(rproc);

static struct attribute *pru_test_consumer_attrs[] = {
	&dev_attr_irq_count.attr,
	&dev_attr_rproc.attr,
	NULL
};
ATTRIBUTE_GROUPS(pru_test_consumer);

static void pru_test_consumer_put_rproc(void *data)
{
	rproc_put(data);
}

static int pru_test_consumer_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct pru_test_consumer *tc;
	struct device_node *pru;
	int irq, ret;

	tc = devm_kzalloc(dev, sizeof(*tc), GFP_KERNEL);
	if (!tc)
		return -ENOMEM;

	pru = of_parse_phandle(dev->of_node, "ti,prus", 0);
	if (!pru)
		return dev_err_probe(dev, -EINVAL, "no ti,prus phandle\n");
	tc->rproc = rproc_get_by_phandle(pru->phandle);
	of_node_put(pru);
	if (!tc->rproc)
		return dev_err_probe(dev, -EPROBE_DEFER, "PRU core not registered yet\n");
	ret = devm_add_action_or_reset(dev, pru_test_consumer_put_rproc, tc->rproc);
	if (ret)
		return ret;

	irq = platform_get_irq(pdev, 0);
	if (irq < 0)
		return irq;
	ret = devm_request_irq(dev, irq, pru_test_consumer_irq, 0, dev_name(dev), tc);
	if (ret)
		return dev_err_probe(dev, ret, "cannot request irq %d\n", irq);

	platform_set_drvdata(pdev, tc);
	dev_info(dev, "PRU %s, irq %d\n", dev_name(&tc->rproc->dev), irq);
	return 0;
}

static const struct of_device_id pru_test_consumer_of_match[] = {
	{ .compatible = "prukit,test-pru-consumer" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_test_consumer_of_match);

static struct platform_driver pru_test_consumer_driver = {
	.probe = pru_test_consumer_probe,
	.driver = {
		.name = "pru_test_consumer",
		.of_match_table = pru_test_consumer_of_match,
		.dev_groups = pru_test_consumer_groups,
	},
};
module_platform_driver(pru_test_consumer_driver);

MODULE_DESCRIPTION("Minimal PRU consumer for prukit's VM tests");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
