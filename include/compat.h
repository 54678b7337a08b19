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

/*
 * v5.11: kmap_local_page()/kunmap_local() ("mm/highmem: Provide
 * kmap_local*"); before, kmap_atomic() is the short-lived mapping.
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 11, 0)
#define prukit_kmap_local_page(page)	kmap_local_page(page)
#define prukit_kunmap_local(addr)	kunmap_local(addr)
#else
#define prukit_kmap_local_page(page)	kmap_atomic(page)
#define prukit_kunmap_local(addr)	kunmap_atomic(addr)
#endif

/*
 * v5.13: rproc_ops.da_to_va() gained "bool *is_iomem" ("remoteproc: add
 * is_iomem to da_to_va").  Declare the op with PRUKIT_RPROC_DA_TO_VA_ARGS;
 * the body uses rproc, da and len only (callers preset *is_iomem to false).
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 13, 0)
#define PRUKIT_RPROC_DA_TO_VA_ARGS \
	struct rproc *rproc, u64 da, size_t len, bool *is_iomem
#else
#define PRUKIT_RPROC_DA_TO_VA_ARGS \
	struct rproc *rproc, u64 da, size_t len
#endif

#endif /* PRUKIT_COMPAT_H */
