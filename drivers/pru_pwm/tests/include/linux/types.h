/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The kernel's <linux/types.h> names for host programs that compile
 * drivers/pru_pwm/pru_pwm_table.c unchanged: put drivers/pru_pwm/tests/include
 * first on the include path.  __u32, __packed and __aligned() come from
 * the header PRU firmware uses for them.
 */
#ifndef _PRU_PWM_TEST_LINUX_TYPES_H
#define _PRU_PWM_TEST_LINUX_TYPES_H

#include <stdbool.h>
#include <stddef.h>

#include <prukit/kernel_types.h>

typedef unsigned char u8;
typedef unsigned int u32;
typedef unsigned long long u64;

#endif /* _PRU_PWM_TEST_LINUX_TYPES_H */
