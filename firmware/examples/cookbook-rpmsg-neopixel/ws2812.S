/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/* ws2812_send(), exact to the cycle: prukit's rpmsg-neopixel firmware's own. */
#include "../../rpmsg-neopixel/ws2812.S"
