# SPDX-License-Identifier: GPL-2.0-only
# Bursts counted by R0.bN (12 bytes: a store costs 1 + 2, a load 3 + 2
# cycles) and the scratchpad register shift (CFG SPP.XFR_SHIFT_EN, shift
# r0[4:0] = 2): XOUT of r5 lands in bank register r7.
#
#   0-5 ldi32 x3, 6 ldi, 7 sbco (3), 10 lbco (5), 15 lbco SPP (3), 18 set,
#   19 sbco, 20 ldi, 21-22 ldi32, 23 xout, 24 clr, 25 sbco, 26 xin, 27 halt
#
# expect: cycles=28
# expect: pru0.instructions=20
# expect: pru0.stalls=8
# expect: pru0.r10=0x11111111
# expect: pru0.r11=0x22222222
# expect: pru0.r12=0x33333333
# expect: pru0.r7=0xabcd1234

	.text
	.global	_start
_start:
	ldi32	r1, 0x11111111
	ldi32	r2, 0x22222222
	ldi32	r3, 0x33333333
	ldi	r0.b2, 12
	sbco	&r1, 24, 0x40, r0.b2
	lbco	&r10, 24, 0x40, r0.b2
	lbco	&r20, 4, 0x34, 4	; CFG SPP
	set	r20, r20, 1		; XFR_SHIFT_EN
	sbco	&r20, 4, 0x34, 4
	ldi	r0.b0, 2		; shift by two registers
	ldi32	r5, 0xabcd1234
	xout	10, &r5, 4
	clr	r20, r20, 1
	sbco	&r20, 4, 0x34, 4
	xin	10, &r7, 4
	halt
