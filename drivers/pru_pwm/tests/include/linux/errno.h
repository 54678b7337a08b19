/* SPDX-License-Identifier: GPL-2.0-only */
/* <linux/errno.h> for host builds of pru_pwm_table.c: the system's, E* */
#include_next <linux/errno.h>
