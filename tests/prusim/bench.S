# SPDX-License-Identifier: GPL-2.0-only
# Busy two-core firmware for bench.sh: ALU work, a store and a load to
# data RAM and an R30 toggle in every iteration of an endless loop
# (12 instructions, 15 cycles per iteration).

	.text
	.global	_start
_start:
	ldi	r1, 0
	ldi32	r2, 0x12345678
loop:
	add	r1, r1, 1
	xor	r2, r2, r1
	lsl	r3, r2, 3
	adc	r4, r3, r1
	and	r5, r4, 0xf0
	qbeq	skip, r5, 0x30
	or	r6, r6, r5
skip:
	sbco	&r1, 24, 0x40, 8
	lbco	&r7, 24, 0x40, 4
	set	r30, r30, PRU
	clr	r30, r30, PRU
	jmp	loop
