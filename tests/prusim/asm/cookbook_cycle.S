# SPDX-License-Identifier: GPL-2.0-only
# The PRU Cookbook's section 7.3, "Using the Built In Counter for Timing"
# (cycle.c and its listing cycle.lst), on both cores.  The board read
# CYCLE = 3, STALL = 5, and with the two reads swapped CYCLE = 7, STALL = 2.
#
# The listing: the STANDBY_INIT clear (lbco CFG, clr, sbco), ldi32 r0,
# 0x22000; lbbo CONTROL; set CTR_EN; sbbo CONTROL; set r30.1; sbbo CYCLE
# (reset); clr r30.1; lbbo CYCLE -> r1; lbbo STALL -> r0.  CTRL loads take
# 4 cycles (3 of them stalls).  The rule that gives both results:
#
# - a store to CYCLE lands at the end of the cycle after it: CYCLE holds
#   the value written (0) and STALL 0 then; counting resumes one cycle
#   later (neither the store's cycle nor the next one is counted);
# - a load samples CYCLE/STALL at the start of its last cycle: its first
#   three cycles (issue and two stalls) are in the value it returns;
# - CYCLE counts every cycle, stalled or not.
#
#   t     instruction          CYCLE STALL at the start of t
#   s     sbbo CYCLE           -     -
#   s+1   clr r30.1            -     -     the write lands at the end of s+1
#   s+2   lbbo: issue          0     0
#   s+3   lbbo: stall          1     0
#   s+4   lbbo: stall          2     1
#   s+5   lbbo: stall, sample  3     2     listing: CYCLE 3; swapped: STALL 2
#   s+6   lbbo: issue          4     3
#   s+7   lbbo: stall          5     3
#   s+8   lbbo: stall          6     4
#   s+9   lbbo: stall, sample  7     5     listing: STALL 5; swapped: CYCLE 7
#   s+10  next instruction     8     6
#
# Each core runs both orders, PRU0 the listing's first, PRU1 the swapped
# one first; the second run reuses the running counter (the store to
# CYCLE clears STALL too).  r10/r11: CYCLE/STALL of the listing's order,
# r12/r13: STALL/CYCLE of the swapped order.  The value stored to CYCLE is
# 0 (the Cookbook stores an uninitialised variable and reports that the
# counter always restarts from 0).
#
# Cycles: ldi 0, lbco 1-3, clr 4, sbco 5; first order 6-26 (reset store
# in 15, r30.1 high 14-15), second 27-47 (store in 36, r30.1 high 35-36),
# halt 48.  CYCLE at the end counts 38-48: 11, STALL 6.
#
# cores: 0 1
# expect: cycles=49
# expect: pru0.state=halted
# expect: pru0.instructions=29
# expect: pru0.stalls=20
# expect: pru0.r10=3
# expect: pru0.r11=5
# expect: pru0.r12=2
# expect: pru0.r13=7
# expect: pru0.cycle_counter=11
# expect: pru0.stall_counter=6
# expect: pru1.state=halted
# expect: pru1.instructions=29
# expect: pru1.stalls=20
# expect: pru1.r10=3
# expect: pru1.r11=5
# expect: pru1.r12=2
# expect: pru1.r13=7
# expect: pru1.cycle_counter=11
# expect: pru1.stall_counter=6
# edges: P9_29=14,16,35,37
# edges: P8_46=14,16,35,37

	.if	PRU == 0
	.equ	CTRL, 0x22000
	.else
	.equ	CTRL, 0x24000
	.endif

	; cycle.lst, lines 20-26 of cycle.c: enable the counter, reset it
	.macro	enable_and_reset
	ldi32	r0, CTRL
	lbbo	&r1, r0, 0, 4		; CONTROL
	set	r1, r1, 3		; CTR_EN
	sbbo	&r1, r0, 0, 4
	set	r30, r30, 1
	sbbo	&r2, r0, 0xc, 4		; CYCLE = 0
	clr	r30, r30, 1
	.endm

	; lines 27, 28: cycle = CYCLE; stall = STALL
	.macro	listing_order
	enable_and_reset
	lbbo	&r1, r0, 0xc, 4		; CYCLE
	lbbo	&r0, r0, 0x10, 4	; STALL
	mov	r10, r1
	mov	r11, r0
	.endm

	; the two lines swapped: stall = STALL; cycle = CYCLE
	.macro	swapped_order
	enable_and_reset
	lbbo	&r3, r0, 0x10, 4	; STALL
	lbbo	&r1, r0, 0xc, 4		; CYCLE
	mov	r12, r3
	mov	r13, r1
	.endm

	.text
	.global	_start
_start:
	ldi	r2, 0
	lbco	&r0, 4, 4, 4		; CFG SYSCFG: clear STANDBY_INIT
	clr	r0, r0, 4
	sbco	&r0, 4, 4, 4
	.if	PRU == 0
	listing_order
	swapped_order
	.else
	swapped_order
	listing_order
	.endif
	halt
