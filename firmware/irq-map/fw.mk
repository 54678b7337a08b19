# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# irq-map: a .pru_irq_map and nothing else, for the VM tests.  PRU0's
# routes event 20 to channel 5, host 5: the test consumer's device tree
# node has event 20 on channel 4, host 4, so the start must fail.  PRU1's
# routes the free event 22 to channel 6, host 6, which must appear while the
# core runs and go when it stops.
fw-srcs := irq-map.c
fw-cores := 0 1
fw-cflags-pru0 := -DIRQ_MAP_EVENT=20 -DIRQ_MAP_CHANNEL=5 -DIRQ_MAP_HOST=5
fw-cflags-pru1 := -DIRQ_MAP_EVENT=22 -DIRQ_MAP_CHANNEL=6 -DIRQ_MAP_HOST=6
fw-stack-size := 0x100
fw-test := y
