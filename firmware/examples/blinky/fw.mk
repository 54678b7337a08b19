# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# blinky: an 8-bit counter on R30 bits 0..7, forever (see blinky.c).
fw-srcs := blinky.c
fw-cores := 0 1
fw-stack-size := 0x100
