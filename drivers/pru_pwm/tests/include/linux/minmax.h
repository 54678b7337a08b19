/* SPDX-License-Identifier: GPL-2.0-only */
/* <linux/minmax.h> for host builds of pru_pwm_table.c (no type checks) */
#ifndef _PRU_PWM_TEST_LINUX_MINMAX_H
#define _PRU_PWM_TEST_LINUX_MINMAX_H
#define min(a, b)	({				\
	typeof(a) __a = (a);				\
	typeof(b) __b = (b);				\
	__a < __b ? __a : __b;				\
})
#endif
