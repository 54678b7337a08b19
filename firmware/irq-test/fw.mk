# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# irq-test: raise system event 20 (PRU0) or 21 (PRU1) a few times and halt.
fw-srcs := irq-test.c
fw-cores := 0 1
fw-cflags-pru0 := -DIRQ_TEST_EVENT=20
fw-cflags-pru1 := -DIRQ_TEST_EVENT=21
fw-stack-size := 0x100
fw-test := y
