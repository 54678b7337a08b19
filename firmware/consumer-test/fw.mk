# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# consumer-test: the firmware of prukit's test consumer (tests/kmod): polls
# its control block, copies DMA buffers over OCP, strobes events.
fw-srcs := consumer-test.c
fw-lib-srcs := ocp_copy.S
fw-cores := 0
fw-cflags := -I$(FWDIR)/../tests/kmod
fw-stack-size := 0x200
fw-test := y
