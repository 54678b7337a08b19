/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: the kernel's names for fixed-width types and attributes, for the
 * headers that kernel drivers and PRU firmware share verbatim
 * (include/prukit/pru_ctrl.h and each driver's protocol header).
 */
#ifndef _PRUKIT_KERNEL_TYPES_H
#define _PRUKIT_KERNEL_TYPES_H

#include <stdint.h>

typedef uint8_t __u8;
typedef uint16_t __u16;
typedef uint32_t __u32;
typedef uint64_t __u64;

#ifndef __packed
#define __packed		__attribute__((packed))
#endif
#ifndef __aligned
#define __aligned(x)		__attribute__((aligned(x)))
#endif

#endif /* _PRUKIT_KERNEL_TYPES_H */
