# SPDX-License-Identifier: GPL-2.0-only
# XIN/XOUT/XCHG between the cores: scratchpad banks 10..12, fill/zero,
# a same-cycle XOUT collision on bank 11 (PRU0 wins, PRU1 stalls one
# cycle and writes afterwards) and the direct PRU-to-PRU transfer (device
# 14): PRU0's XOUT 14 at cycle 15 waits until PRU1's XIN 14 at cycle 20.
#
#   PRU0: 0-3 ldi32 x2, 4 xout 10, 5 ldi, 6 xout 11, 7 nop, 8 xin 11,
#         9 ldi, 10 xchg 12, 11 fill, 12 zero, 13-14 ldi, 15-20 xout 14
#         (5 stall cycles), 21 halt                  -> 22 cycles, 1+5 stalls
#   PRU1: 0 ldi, 1-4 nop, 5 xin 10, 6 xout 11 (collides), 7 xout 11,
#         8-10 nop, 11 xin 12, 12-19 nop, 20 xin 14, 21 halt
#
# cores: 0 1
# expect: cycles=22
# expect: pru0.state=halted
# expect: pru1.state=halted
# expect: pru0.stalls=5
# expect: pru1.stalls=1
# expect: pru0.instructions=17
# expect: pru1.instructions=21
# expect: pru1.r1=0x11112222
# expect: pru1.r2=0x33334444
# expect: pru0.r10=0xbb
# expect: pru0.r15=0
# expect: pru1.r15=0x5555
# expect: pru0.r16=0xffffffff
# expect: pru0.r17=0
# expect: pru1.r20=0x1234
# expect: pru1.r21=0x5678

	.text
	.global	_start
_start:
	.if	PRU == 0
	ldi32	r1, 0x11112222
	ldi32	r2, 0x33334444
	xout	10, &r1, 8
	ldi	r10, 0xaa
	xout	11, &r10, 4		; cycle 6, same as PRU1
	nop
	xin	11, &r10, 4		; PRU1's value, written in cycle 7
	ldi	r15, 0x5555
	xchg	12, &r15, 4		; r15 <- 0, bank 12 r15 <- 0x5555
	fill	&r16, 8
	zero	&r17, 4
	ldi	r20, 0x1234
	ldi	r21, 0x5678
	xout	14, &r20, 8		; waits for PRU1
	halt
	.else
	ldi	r10, 0xbb
	.rept	4
	nop
	.endr
	xin	10, &r1, 8
	xout	11, &r10, 4		; collides with PRU0: one stall
	.rept	3
	nop
	.endr
	xin	12, &r15, 4
	.rept	8
	nop
	.endr
	xin	14, &r20, 8
	halt
	.endif
