// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_standin - a driver that takes a PRU core's device and is no remote
 * processor driver, as UIO's uio_pruss would (Debian's armmp kernels have
 * none).  It matches nothing by itself: tests/vm/cases/93-pru-unavailable
 * binds a core to it with driver_override.  A test-only module.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/module.h>
#include <linux/platform_device.h>

static int pru_standin_probe(struct platform_device *pdev)
{
	dev_info(&pdev->dev, "held by the stand-in\n");
	return 0;
}

static struct platform_driver pru_standin_driver = {
	.probe = pru_standin_probe,
	.driver = {
		.name = "pru-standin",
	},
};
module_platform_driver(pru_standin_driver);

MODULE_DESCRIPTION("prukit test: a non-remoteproc driver holding a PRU core");
MODULE_LICENSE("GPL");
