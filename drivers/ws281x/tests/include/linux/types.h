/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The kernel's <linux/types.h> names for host programs that compile
 * kernel code unchanged (drivers/ws281x/ws281x_conv.c): put
 * drivers/ws281x/tests/include first on the include path.  __u32, __packed
 * and __aligned() come from the header PRU firmware uses for them.
 */
#ifndef _WS281X_TEST_LINUX_TYPES_H
#define _WS281X_TEST_LINUX_TYPES_H

#include <stdbool.h>
#include <stddef.h>

#include <prukit/kernel_types.h>

/* as the kernel defines them (int-ll64.h) */
typedef unsigned char u8;
typedef unsigned short u16;
typedef unsigned int u32;
typedef unsigned long long u64;

/* The kernel has it in every file (compiler_attributes.h). */
#ifndef fallthrough
#define fallthrough	__attribute__((__fallthrough__))
#endif

#endif /* _WS281X_TEST_LINUX_TYPES_H */
