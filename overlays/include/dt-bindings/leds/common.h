/* SPDX-License-Identifier: (GPL-2.0-only OR BSD-2-Clause) */
/*
 * The "color" and "function" values of the devicetree LED binding that
 * prukit's overlays use (the LED core's led_colors[] index and the function
 * strings of Documentation/leds/leds-class.rst).  scripts/overlays.sh
 * --check builds every overlay with the kernels' own headers as well and
 * requires the same blob.
 */
#ifndef _DT_BINDINGS_LEDS_COMMON_H
#define _DT_BINDINGS_LEDS_COMMON_H

#define LED_COLOR_ID_WHITE	0
#define LED_COLOR_ID_RED	1
#define LED_COLOR_ID_GREEN	2
#define LED_COLOR_ID_BLUE	3
#define LED_COLOR_ID_MULTI	8	/* several LEDs of fixed colours */
#define LED_COLOR_ID_RGB	9	/* any colour: a NeoPixel */

#define LED_FUNCTION_HEARTBEAT	"heartbeat"
#define LED_FUNCTION_INDICATOR	"indicator"
#define LED_FUNCTION_STATUS	"status"

#endif
