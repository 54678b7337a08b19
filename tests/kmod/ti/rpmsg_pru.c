// SPDX-License-Identifier: GPL-2.0-only
/*
 * A stand-in for TI's own rpmsg_pru (5.10-ti, 6.1-ti): the same module name
 * and alias, installed where TI's kernels have it
 * (kernel/drivers/rpmsg/rpmsg_pru.ko; scripts/vm.sh puts it there), so that
 * tests/vm/cases/71-rpmsg-ti-module can show which of the two modprobe
 * takes.  It binds nothing.  A test-only module.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/module.h>

static int __init ti_standin_init(void)
{
	pr_info("TI's rpmsg_pru stand-in loaded\n");
	return 0;
}
module_init(ti_standin_init);

static void __exit ti_standin_exit(void)
{
}
module_exit(ti_standin_exit);

MODULE_ALIAS("rpmsg:rpmsg-pru");
MODULE_DESCRIPTION("prukit test: a stand-in for TI's rpmsg_pru");
MODULE_LICENSE("GPL");
