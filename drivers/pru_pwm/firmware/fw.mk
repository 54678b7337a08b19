# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# pru_pwm: the pru_pwm driver's firmware, pru_pwm-pru0.elf and
# pru_pwm-pru1.elf: plays the period tables of its control block
# (pru_pwm_proto.h, on the include path as a driver's firmware) on R30,
# every write at its deadline on the IEP counter (pru_pwm_run.S).
fw-srcs := pru_pwm.c pru_pwm_run.S
fw-cores := 0 1
fw-stack-size := 0x100
