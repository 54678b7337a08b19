# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# cookbook-rpmsg-neopixel: the PRU Cookbook's NeoPixel-over-rpmsg program
# (neo4.c) in its own shape - R31 host bit, clear the event, receive until no
# more - against the support package's rpmsg API (<pru_rpmsg.h>), which
# prukit's lib/pru_rpmsg.c provides.  24 WS2812 LEDs on R30 bit 1 (P9_29),
# "index red green blue" lines and "-1" as firmware/rpmsg-neopixel; the bits
# go out through firmware/rpmsg-neopixel's cycle-exact ws2812.S.
fw-srcs := neo.c ws2812.S
fw-lib-srcs := pru_rpmsg.c ocp_copy.S
fw-cores := 0
