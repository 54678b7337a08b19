// SPDX-License-Identifier: GPL-2.0-only
/*
 * Kernel build check of the prusim core: a module that runs a few cycles of
 * a tiny program on load, so the core is compiled and linked as kernel code.
 */
#include <linux/module.h>
#include <linux/vmalloc.h>

#include "prusim.h"

static int __init prusim_kcheck_init(void)
{
	static const u8 prog[] = {
		0xe1, 0x05, 0x00, 0x24,		/* ldi r1, 5 */
		0x00, 0x00, 0x00, 0x2a,		/* halt */
	};
	struct prusim_status st;
	struct prusim *s;

	s = vzalloc(sizeof(*s));
	if (!s)
		return -ENOMEM;
	prusim_init(s, NULL, NULL, NULL);
	prusim_write_iram(s, 0, 0, prog, sizeof(prog));
	prusim_core_enable(s, 0, true);
	prusim_run(s, 100);
	prusim_get_status(s, 0, &st);
	pr_info("prusim_kcheck: r1=%u after %llu cycles\n", st.regs[1],
		(unsigned long long)s->now);
	vfree(s);
	return 0;
}
module_init(prusim_kcheck_init);

static void __exit prusim_kcheck_exit(void)
{
}
module_exit(prusim_kcheck_exit);

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("prusim kernel build check");
