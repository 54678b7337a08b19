# SPDX-License-Identifier: GPL-2.0-only
# A long wait in the direct PRU-to-PRU transfer: PRU0's XOUT 14 in cycle 1
# waits while PRU1 sleeps until its R31 bit 0 rises at cycle 100000, then
# PRU1's XIN 14 completes both.  The wait is skipped (both cores only
# wait) and counts as stall cycles of the XOUT: 100000 cycles, 99999 stalls.
#
#   PRU0: 0 ldi, 1..100000 xout 14, 100001 halt
#   PRU1: 0-1 ldi32, 2 ldi, 3 sbbo WAKEUP_EN, 4 slp, 100000 xin 14,
#         100001 halt
#
# cores: 0 1
# args: --r31-1 {dir}/../stim/late.txt
# expect: cycles=100002
# expect: pru0.instructions=3
# expect: pru0.stalls=99999
# expect: pru1.instructions=7
# expect: pru1.stalls=0
# expect: pru1.r20=0x77

	.text
	.global	_start
_start:
	.if	PRU == 0
	ldi	r20, 0x77
	xout	14, &r20, 4
	halt
	.else
	ldi32	r2, 0x24000
	ldi	r3, 1
	sbbo	&r3, r2, 8, 4		; WAKEUP_EN: R31 bit 0
	slp	1
	xin	14, &r20, 4
	halt
	.endif
