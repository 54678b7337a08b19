/* SPDX-License-Identifier: GPL-2.0-only */
/* <linux/string.h> for host builds of pru_pwm_table.c */
#include <string.h>
