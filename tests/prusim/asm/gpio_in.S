# SPDX-License-Identifier: GPL-2.0-only
# GPIO DATAIN comes from the input stimulus (--gpio-in 1:FILE), sampled when
# the load issues; reads of GPIO1 take 34 cycles.  A read after a posted
# write to the same bank sees the write (it travels behind it) although
# the write lands (and a DATAOUT pin would change) only later.
#
#   0 lbco (3), 3 clr, 4 sbco, 5-6 ldi32, 7 ldi, 8 lbbo DATAIN (0),
#   42 lbbo DATAIN (0), 76 lbbo DATAIN (bit 22), 110 ldi32 (2), 112 ldi,
#   113 sbbo OE, 114 lbbo OE (sees 0xffff0000), 148 halt
#
# args: --gpio-in 1:{dir}/../stim/gpio1.txt
# expect: cycles=149
# expect: pru0.state=halted
# expect: pru0.r3=0
# expect: pru0.r4=0
# expect: pru0.r5=0x400000
# expect: pru0.r8=0xffff0000

	.text
	.global	_start
_start:
	lbco	&r0, 4, 4, 4
	clr	r0, r0, 4
	sbco	&r0, 4, 4, 4		; OCP master port on
	ldi32	r1, 0x4804c000		; GPIO1
	ldi	r2, 0x138		; DATAIN
	lbbo	&r3, r1, r2, 4
	lbbo	&r4, r1, r2, 4
	lbbo	&r5, r1, r2, 4
	ldi32	r6, 0xffff0000
	ldi	r7, 0x134		; OE
	sbbo	&r6, r1, r7, 4
	lbbo	&r8, r1, r7, 4
	halt
