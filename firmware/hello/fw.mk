# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# hello: pulse R30 bit 5 ten times and halt (see hello.c for the header pins).
fw-srcs := hello.c
fw-cores := 0 1
fw-cflags-pru0 := -DHELLO_BIT=5
fw-cflags-pru1 := -DHELLO_BIT=5
fw-stack-size := 0x100
