# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# consumer-irqmap: the test consumer's firmware (firmware/consumer-test) with
# a .pru_irq_map that maps the consumer's own event 20 (-> channel 4 -> host
# 4), which the PRU-consumer layer must refuse to boot: the PRU remoteproc
# driver would dispose of that interrupt at the core's stop, under the
# consumer's handler (tests/vm/cases/62-irq-map).
fw-srcs := consumer-irqmap.c
fw-lib-srcs := ocp_copy.S
fw-cores := 0
fw-cflags := -I$(FWDIR)/../tests/kmod
fw-stack-size := 0x200
fw-test := y
