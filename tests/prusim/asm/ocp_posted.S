# SPDX-License-Identifier: GPL-2.0-only
# Posted OCP stores (-C ocp_write_delay=100): after the master port is
# enabled (lbco 3, clr 1, sbco 1: cycles 0..4), an 8-byte store to DDR
# issued in cycle 9 lands in cycle 109.  The load of its second word, issued
# in cycle 11, travels behind it: it sees the stored word and completes in
# cycle 110, not 11 + 43.  A load of a word no store covers reads DDR as it
# is (0) and takes its 43 cycles.
#
#   5, ldi32 2, ldi32 2, sbco(8) 2, lbco 99 (11..109), lbco 43 (110..152),
#   halt in cycle 153 = 154 cycles, 11 instructions (ldi32 is two)
#
# args: --ddr 4K -C ocp_write_delay=100
# expect: pru0.state=halted
# expect: pru0.r5=0x22222222
# expect: pru0.r6=0
# expect: pru0.instructions=11
# expect: cycles=154

	.text
	.global	_start
_start:
	lbco	&r0, 4, 4, 4		; C4 = CFG: SYSCFG.STANDBY_INIT off
	clr	r0, r0, 4
	sbco	&r0, 4, 4, 4
	ldi32	r3, 0x11111111
	ldi32	r4, 0x22222222
	sbco	&r3, 31, 0x10, 8	; C31 = 0x80000000
	lbco	&r5, 31, 0x14, 4
	lbco	&r6, 31, 0x20, 4
	halt
