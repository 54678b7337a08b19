/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prusim platform glue: the simulator core is compiled unchanged in the Linux
 * kernel (its KUnit suite) and in userspace (the prusim tool and its tests,
 * the QEMU PRU-ICSS).  This
 * header is the only place that knows the difference.
 */
#ifndef _PRUSIM_PLATFORM_H
#define _PRUSIM_PLATFORM_H

#ifdef __KERNEL__

#include <linux/bits.h>
#include <linux/compiler.h>
#include <linux/errno.h>
#include <linux/kernel.h>
#include <linux/math64.h>
#include <linux/string.h>
#include <linux/types.h>

static inline u64 prusim_div_u64(u64 dividend, u32 divisor)
{
	return div_u64(dividend, divisor);
}

static inline u64 prusim_rem_u64(u64 dividend, u64 divisor)
{
	u64 rem;

	div64_u64_rem(dividend, divisor, &rem);
	return rem;
}

#else /* !__KERNEL__ */

#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef uint8_t u8;
typedef uint16_t u16;
typedef uint32_t u32;
typedef uint64_t u64;

#define BIT(nr)		(1UL << (nr))

#ifndef likely
#define likely(x)	__builtin_expect(!!(x), 1)
#define unlikely(x)	__builtin_expect(!!(x), 0)
#endif

#ifndef fallthrough
#define fallthrough	__attribute__((__fallthrough__))
#endif

#ifndef __always_inline
#define __always_inline	inline __attribute__((__always_inline__))
#endif

#ifndef noinline
#define noinline	__attribute__((__noinline__))
#endif

#ifndef __always_unused
#define __always_unused	__attribute__((__unused__))
#endif

#ifndef __printf
#define __printf(a, b)	__attribute__((__format__(printf, a, b)))
#endif

#ifndef __packed
#define __packed	__attribute__((__packed__))
#endif

#ifndef ARRAY_SIZE
#define ARRAY_SIZE(a)	(sizeof(a) / sizeof((a)[0]))
#endif

static inline u64 prusim_div_u64(u64 dividend, u32 divisor)
{
	return dividend / divisor;
}

static inline u64 prusim_rem_u64(u64 dividend, u64 divisor)
{
	return dividend % divisor;
}

#endif /* __KERNEL__ */

/* A cycle number that is never reached: "not scheduled". */
#define PRUSIM_NEVER	(~(u64)0)

static inline u64 prusim_min_u64(u64 a, u64 b)
{
	return a < b ? a : b;
}

static inline u32 prusim_get_le32(const u8 *p)
{
	return p[0] | (u32)p[1] << 8 | (u32)p[2] << 16 | (u32)p[3] << 24;
}

static inline u16 prusim_get_le16(const u8 *p)
{
	return p[0] | (u16)(p[1] << 8);
}

static inline void prusim_put_le32(u8 *p, u32 v)
{
	p[0] = v;
	p[1] = v >> 8;
	p[2] = v >> 16;
	p[3] = v >> 24;
}

#endif /* _PRUSIM_PLATFORM_H */
