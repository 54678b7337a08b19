/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * pru_pwm firmware: what pru_pwm.c hands to the loop of pru_pwm_run.S,
 * and the layout that loop assumes, checked against the protocol header.
 */
#ifndef _PRU_PWM_FW_H
#define _PRU_PWM_FW_H

#include <assert.h>
#include <stddef.h>
#include <stdint.h>

#include "pru_pwm_proto.h"

/* Play the control block's tables for ever (pru_pwm_run.S). */
void __attribute__((noreturn)) pru_pwm_run(volatile struct pru_pwm_ctrl *c);

/* pru_pwm_run.S's offsets and constants */
static_assert(offsetof(struct pru_pwm_ctrl, hdr.command) == 8, "CMD_OFF");
static_assert(offsetof(struct pru_pwm_ctrl, hdr.status) == 12, "STATUS_OFF");
static_assert(offsetof(struct pru_pwm_ctrl, next) == 16, "NEXT_OFF");
static_assert(offsetof(struct pru_pwm_ctrl, active) == 20, "ACTIVE_OFF");
static_assert(offsetof(struct pru_pwm_ctrl, periods) == 24, "PERIODS_OFF");
static_assert(offsetof(struct pru_pwm_ctrl, late) == 28, "LATE_OFF, after periods");
static_assert(offsetof(struct pru_pwm_ctrl, started_at) == 32, "STARTED_OFF");
static_assert(offsetof(struct pru_pwm_ctrl, table) == 36, "TABLE0_OFF");
static_assert(sizeof(struct pru_pwm_table) == 176, "TABLE_BYTES");
static_assert(offsetof(struct pru_pwm_table, step) == 8, "STEP0_OFF");
static_assert(sizeof(struct pru_pwm_step) == 8, "STEP_BYTES");
static_assert(PRU_PWM_MAX_STEPS == 9 && PRU_PWM_MIN_PERIOD == 264 &&
	      PRU_PWM_MAX_PERIOD == 0x7fffffffu && PRU_PWM_LEAD == 64,
	      "pru_pwm_run.S: constants");
static_assert(PRU_PWM_CMD_SET == 1 && PRU_PWM_OK == 0 && PRU_PWM_EINVAL == 1 &&
	      PRU_PWM_EOPCODE == 2, "pru_pwm_run.S: opcodes and results");

#endif /* _PRU_PWM_FW_H */
