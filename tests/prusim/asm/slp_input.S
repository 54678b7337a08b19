# SPDX-License-Identifier: GPL-2.0-only
# SLP 1 woken by an R31 input bit enabled in WAKEUP_EN: the stimulus sets
# bit 3 at cycle 5000 and the next instruction issues in that cycle.
#
#   0-1 ldi32, 2 ldi, 3 sbbo WAKEUP_EN, 4 slp, 5000 mov, 5001 halt
#
# args: --r31-0 {dir}/../stim/wake.txt
# expect: cycles=5002
# expect: pru0.instructions=7
# expect: pru0.r10=8

	.text
	.global	_start
_start:
	ldi32	r2, 0x22000
	ldi	r3, 1 << 3
	sbbo	&r3, r2, 8, 4
	slp	1
	mov	r10, r31
	halt
