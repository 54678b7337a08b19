# SPDX-License-Identifier: GPL-2.0-only
# The multiplier (XFR device 0): it samples r28/r29 every cycle and needs a
# cycle, so an XIN right after loading the operands sees the previous r29
# (the gnupru wiki's "-1001" pitfall); with a NOP in between the product is
# right.  MAC mode: r25 = 1 selects it, r25 = 3 clears the accumulator, each
# XOUT of r25 = 1 adds the product, XIN reads mode/carry and the sum.
#
#   99787 * 3319 = 331193053, accumulated twice = 662386106.
#   23 instructions, 23 cycles.
#
# expect: cycles=23
# expect: pru0.state=halted
# expect: pru0.r0=0xfffffc17
# expect: pru0.r1=0x3e8
# expect: pru0.r2=2004002
# expect: pru0.r3=0
# expect: pru0.r25=1
# expect: pru0.r26=662386106
# expect: pru0.r27=0

	.text
	.global	_start
_start:
	fill	&r28, 8			; r28 = r29 = 0xffffffff
	ldi	r28, 1001
	ldi	r29, 2002
	xin	0, &r26, 8		; operands of one cycle ago: 1001 * 0xffffffff
	mov	r0, r26
	mov	r1, r27
	nop
	xin	0, &r26, 8
	mov	r2, r26
	mov	r3, r27
	ldi	r25, 1
	xout	0, &r25, 1		; MAC mode
	ldi	r25, 3
	xout	0, &r25, 1		; clear the accumulator
	ldi	r25, 1
	ldi	r28, 0x85cb		; 99787 = 0x185cb: ldi then set the w2 part
	ldi	r28.w2, 1
	ldi	r29, 3319
	nop
	xout	0, &r25, 1		; accumulate
	xout	0, &r25, 1		; accumulate
	xin	0, &r25, 12
	halt
