/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/* ws2812_send(), exact to the cycle: prukit's NeoPixel firmware's own. */
#include "../../neopixel/ws2812.S"
