/* SPDX-License-Identifier: (GPL-2.0-only OR BSD-2-Clause) */
/*
 * The GPIO specifier flags of the devicetree gpio binding (the values the
 * kernel's gpiolib decodes from a "gpios" cell), for prukit's overlays.
 * scripts/overlays.sh --check builds every overlay with the kernels' own
 * headers as well and requires the same blob.
 */
#ifndef _DT_BINDINGS_GPIO_GPIO_H
#define _DT_BINDINGS_GPIO_GPIO_H

/* bit 0: polarity */
#define GPIO_ACTIVE_HIGH	0
#define GPIO_ACTIVE_LOW		1

/* bit 1: single-ended; bit 2: which side is driven when single-ended */
#define GPIO_PUSH_PULL		0
#define GPIO_SINGLE_ENDED	2
#define GPIO_LINE_OPEN_SOURCE	0
#define GPIO_LINE_OPEN_DRAIN	4
#define GPIO_OPEN_DRAIN		(GPIO_SINGLE_ENDED | GPIO_LINE_OPEN_DRAIN)
#define GPIO_OPEN_SOURCE	(GPIO_SINGLE_ENDED | GPIO_LINE_OPEN_SOURCE)

/* bit 3: state kept over suspend; bits 4-6: bias */
#define GPIO_PERSISTENT		0
#define GPIO_TRANSITORY		8
#define GPIO_PULL_UP		16
#define GPIO_PULL_DOWN		32
#define GPIO_PULL_DISABLE	64

#endif
