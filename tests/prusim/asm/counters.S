# SPDX-License-Identifier: GPL-2.0-only
# CTRL CYCLE and STALL: they count while CONTROL.CTR_EN is set, every
# cycle, stalled or not; the store that sets CTR_EN is counted, the one that
# clears it is not.  A load of CYCLE/STALL samples them at the start of its
# last cycle, so its own first cycles are in the value (a CTRL load: 3
# cycles, 2 of them stalls; asm/cookbook_cycle.S is the measurement this
# reproduces).  Writing 0 to CYCLE (here with the counter off) clears both.
# STATUS reads the pc (word address) of the reading instruction.
#
#   set CTR_EN (1) lbco (3, 2 stalls) nop (1)           CYCLE 5, STALL 2
#   lbbo CYCLE -> 5 + 3 = 8, then +4/+3                 CYCLE 9, STALL 5
#   lbbo STALL -> 5 + 2 = 7, then +4/+3                 CYCLE 13, STALL 8
#   clr (1)                                             CYCLE 14
#   store clearing CTR_EN: not counted; reads 14 and 8 (the counter stands)
#
# Cycles: 2 4 1 1 3 1 4 4 1 1 4 4 1 1 4 4 4 1 = 45
#
# expect: cycles=45
# expect: pru0.state=halted
# expect: pru0.r2=0x8003
# expect: pru0.r4=8
# expect: pru0.r5=7
# expect: pru0.r6=14
# expect: pru0.r7=8
# expect: pru0.r9=0
# expect: pru0.r10=0
# expect: pru0.r11=17
# expect: pru0.pc=18
# expect: pru0.cycle_counter=0
# expect: pru0.stall_counter=0

	.text
	.global	_start
_start:
	ldi32	r1, 0x22000
	lbbo	&r2, r1, 0, 4		; CONTROL: SOFT_RST_N | EN | RUNSTATE
	set	r12, r2, 3
	sbbo	&r12, r1, 0, 4		; CTR_EN on
	lbco	&r3, 24, 0, 4
	nop
	lbbo	&r4, r1, 0xc, 4		; CYCLE
	lbbo	&r5, r1, 0x10, 4	; STALL
	clr	r12, r12, 3
	sbbo	&r12, r1, 0, 4		; CTR_EN off
	lbbo	&r6, r1, 0xc, 4
	lbbo	&r7, r1, 0x10, 4
	ldi	r8, 0
	sbbo	&r8, r1, 0xc, 4		; clear CYCLE (and STALL)
	lbbo	&r9, r1, 0xc, 4
	lbbo	&r10, r1, 0x10, 4
	lbbo	&r11, r1, 4, 4		; STATUS: word 17
	halt
