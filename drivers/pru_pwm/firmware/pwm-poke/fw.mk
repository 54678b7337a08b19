# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# pwm-poke: test firmware for drivers/pru_pwm/tests (prusim on the host):
# on PRU0, writes words into memory at given cycles, as the driver would
# post commands to the pru_pwm firmware on PRU1 while it plays a table.
fw-srcs := pwm-poke.c
fw-cores := 0
fw-stack-size := 0x100
fw-test := y
