// SPDX-License-Identifier: GPL-2.0-only
/*
 * Kernel build check of the prusim core: a module that runs a few cycles of
 * a tiny program on load and parses a stimulus, so the core is compiled and
 * linked as kernel code.  It also pins down the binary trace layout.
 */
#include <linux/build_bug.h>
#include <linux/mm.h>
#include <linux/module.h>
#include <linux/slab.h>
#include <linux/vmalloc.h>

#include "prusim.h"
#include "prusim_stim.h"
#include "prusim_trace.h"

/* R31 input of a stimulus text: a 25 MHz clock on bit 0 */
static u32 prusim_kcheck_input(void *ctx, unsigned int port, u64 cycle, u64 *next_change)
{
	const struct prusim_stim *st = ctx;

	if (port != PRUSIM_PORT_R31(0)) {
		*next_change = PRUSIM_NEVER;
		return 0;
	}
	return prusim_stim_value(st, cycle, next_change);
}

static int __init prusim_kcheck_init(void)
{
	static const u8 prog[] = {
		0xe1, 0x05, 0x00, 0x24,		/* ldi r1, 5 */
		0x00, 0x00, 0x00, 0x2a,		/* halt */
	};
	static const char text[] = "# clock\n0 0\n4 1\nrepeat 8\n";
	const struct prusim_ops ops = { .input = prusim_kcheck_input };
	struct prusim_stim stim = { };
	struct prusim_status st;
	char err[PRUSIM_REASON_LEN];
	struct prusim *s;
	int n;

	BUILD_BUG_ON(sizeof(struct prusim_trace_hdr) != 48);
	BUILD_BUG_ON(sizeof(struct prusim_trace_rec) != 16);

	n = prusim_stim_parse(text, sizeof(text) - 1, NULL, err, sizeof(err));
	if (n < 0) {
		pr_err("prusim_kcheck: %s\n", err);
		return n;
	}
	stim.cycle = kvmalloc_array(n, sizeof(*stim.cycle), GFP_KERNEL);
	stim.value = kvmalloc_array(n, sizeof(*stim.value), GFP_KERNEL);
	stim.count = n;
	s = vzalloc(sizeof(*s));
	if (!s || !stim.cycle || !stim.value) {
		n = -ENOMEM;
		goto out;
	}
	n = prusim_stim_parse(text, sizeof(text) - 1, &stim, err, sizeof(err));
	if (n < 0) {
		pr_err("prusim_kcheck: %s\n", err);
		goto out;
	}
	prusim_init(s, NULL, &ops, &stim);
	prusim_write_iram(s, 0, 0, prog, sizeof(prog));
	prusim_core_enable(s, 0, true);
	prusim_run(s, 100);
	prusim_get_status(s, 0, &st);
	pr_info("prusim_kcheck: r1=%u after %llu cycles\n", st.regs[1],
		(unsigned long long)s->now);
	n = 0;
out:
	vfree(s);
	kvfree(stim.cycle);
	kvfree(stim.value);
	return n;
}
module_init(prusim_kcheck_init);

static void __exit prusim_kcheck_exit(void)
{
}
module_exit(prusim_kcheck_exit);

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("prusim kernel build check");
