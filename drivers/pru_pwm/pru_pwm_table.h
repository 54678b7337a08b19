/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * pru_pwm_table.h - turning the channels' states into the table the
 * pru_pwm firmware plays (pru_pwm_proto.h).
 *
 * pru_pwm_table.c is compiled unchanged in the kernel module and in host
 * programs (drivers/pru_pwm/tests), which put drivers/pru_pwm/tests/include
 * first on the include path: its <linux/types.h> gives them the kernel's
 * names for the types used here.
 */
#ifndef _PRU_PWM_TABLE_H
#define _PRU_PWM_TABLE_H

#include <linux/types.h>

#include "pru_pwm_proto.h"

/* The period played while no channel is enabled: 100 us */
#define PRU_PWM_IDLE_PERIOD	20000

/**
 * struct pru_pwm_req - what was asked of one channel, in PRU cycles
 * @period: cycles per period
 * @duty: cycles active per period, at most @period
 * @enabled: the channel runs
 * @inversed: active low
 */
struct pru_pwm_req {
	u32 period;
	u32 duty;
	bool enabled;
	bool inversed;
};

int pru_pwm_table_build(const struct pru_pwm_req *req, const u8 *r30_bit,
			unsigned int nchan, struct pru_pwm_table *t);

#endif /* _PRU_PWM_TABLE_H */
