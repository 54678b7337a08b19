// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * pru_pwm: PRU firmware of the pru_pwm driver (pru_pwm_proto.h has the
 * protocol).  Starts the IEP counter, whose count the loop's deadlines
 * are (one per PRU cycle; left running as it is if another core's
 * firmware started it so), says it is ready and hands over to
 * pru_pwm_run.S, which polls the command word until the first table comes
 * and then plays tables for ever.
 */
#include <stdint.h>
#include <am335x/pruss_iep.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>

#include "pru_pwm_fw.h"

PRUKIT_RESOURCE_TABLE_EMPTY();

/* The image initialises the header: the driver checks it right after loading. */
struct pru_pwm_ctrl pru_pwm_ctrl __attribute__((section(".prukit_ctrl"), used)) = {
	.hdr = {
		.magic = PRU_PWM_MAGIC,
		.version = PRU_PWM_VERSION,
		.size = sizeof(struct pru_pwm_ctrl),
	},
	.active = PRU_PWM_NONE,
};

int main(void)
{
	uint32_t cfg = (1u << PRU_IEP_GLOBAL_CFG_DEFAULT_INC_SHIFT) |
		       (1u << PRU_IEP_GLOBAL_CFG_CMP_INC_SHIFT) | PRU_IEP_GLOBAL_CFG_CNT_ENABLE;
	volatile struct pru_pwm_ctrl *c = &pru_pwm_ctrl;

	if (pru_iep_read(PRU_IEP_GLOBAL_CFG) != cfg)
		pru_iep_write(PRU_IEP_GLOBAL_CFG, cfg);
	c->active = PRU_PWM_NONE;
	c->periods = 0;
	c->late = 0;
	c->hdr.status = PRUKIT_CTRL_STATUS(0, PRU_PWM_OK);
	pru_pwm_run(c);
}
