# SPDX-License-Identifier: GPL-2.0-only
# SLP and idle waiting.  PRU0 enables system event 21 on host 0 through the
# INTC registers, sets WAKEUP_EN to R31 bit 30 and sleeps; the embedder
# raises event 21 at cycle 1000 (--event), which wakes PRU0 in that cycle.
# PRU1 reads PRU0's CONTROL while it sleeps (SLEEPING set) and waits for the
# same host interrupt with WBS.  The idle cycles are skipped, which must
# not change any count.
#
#   PRU0: 0-11 setup + slp, asleep 12..999, 1000 ldi, 1001 ldi, 1002 sbco
#         SICR, 1003 halt: 16 instructions
#   PRU1: 0-1 ldi32, 2-11 nop, 12 lbbo (4), 16..1000 wbs (985 times),
#         1001 ldi, 1002 halt: 1000 instructions
#
# cores: 0 1
# args: --event 1000:21
# expect: cycles=1004
# expect: pru0.state=halted
# expect: pru1.state=halted
# expect: pru0.instructions=16
# expect: pru1.instructions=1000
# expect: pru1.stalls=3
# expect: pru0.r4=1
# expect: pru1.r4=2
# expect: pru1.r5=0x8007
# expect: intc.raw=0

	.text
	.global	_start
_start:
	.if	PRU == 0
	ldi	r1, 21
	sbco	&r1, 0, 0x28, 4		; EISR: enable event 21 (channel 0 -> host 0)
	ldi	r1, 0
	sbco	&r1, 0, 0x34, 4		; HIEISR: enable host 0
	ldi	r1, 1
	sbco	&r1, 0, 0x10, 4		; GER
	ldi32	r2, 0x22000
	ldi32	r3, 1 << 30
	sbbo	&r3, r2, 8, 4		; WAKEUP_EN: R31 bit 30
	slp	1
	ldi	r4, 1
	ldi	r1, 21
	sbco	&r1, 0, 0x24, 4		; SICR
	halt
	.else
	ldi32	r2, 0x22000
	.rept	10
	nop
	.endr
	lbbo	&r5, r2, 0, 4		; PRU0 CONTROL
	wbs	r31, 30
	ldi	r4, 2
	halt
	.endif
