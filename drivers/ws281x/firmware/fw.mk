# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# ws281x: the ws281x (NeoPixel) driver's firmware, ws281x-pru0.elf and
# ws281x-pru1.elf: polls its control block (ws281x_proto.h, on the include
# path as a driver's firmware), sends frames of bit slots read from DDR on
# R30 and GPIO strings at once (ws281x_send.S), strobes an event per frame.
fw-srcs := ws281x.c ws281x_send.S
fw-cores := 0 1
fw-stack-size := 0x100
