# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# rpmsg-neopixel: the PRU Cookbook's NeoPixel-over-rpmsg firmware (PRU0): text
# lines "index red green blue" set a pixel, "-1" sends all 24 to a WS2812
# string on R30 bit 1 (P9_29).  See neopixel.c.  Built as
# rpmsg-neopixel-pru0.elf (neopixel-pru0.elf before: that name is left to
# the NeoPixel LED-class driver's firmware).
fw-srcs := neopixel.c ws2812.S
fw-lib-srcs := rpmsg.c ocp_copy.S
fw-cores := 0
fw-stack-size := 0x100
