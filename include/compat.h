/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Kernel API differences between Linux 5.10 and 6.12 that prukit meets.
 *
 * This is the only file in prukit that tests the kernel version.  Each entry
 * names the upstream release that changed the interface; drivers use the
 * prukit_* names below and never test versions themselves.
 */
#ifndef PRUKIT_COMPAT_H
#define PRUKIT_COMPAT_H

#include <linux/version.h>

#if LINUX_VERSION_CODE < KERNEL_VERSION(5, 10, 0)
#error "prukit needs Linux 5.10 or later"
#endif

/*
 * v6.2: struct class.devnode() takes a const struct device *
 * ("driver core: make struct class.devnode() take a const *").
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 2, 0)
#define PRUKIT_CLASS_DEVNODE_CONST	const
#else
#define PRUKIT_CLASS_DEVNODE_CONST
#endif

#endif /* PRUKIT_COMPAT_H */
