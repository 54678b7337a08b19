# SPDX-License-Identifier: GPL-2.0-only
# Repeated skips of two idle loops with different periods, stall cycles and
# the cycle counter on.  PRU0 polls a flag in shared RAM (load 3 cycles, 2
# of them stalls, + branch: 4 cycles) with CTR_EN set; PRU1 polls R31 bit
# 2 (3 cycles).  The common period is 12.  Skips end at stimulus entries
# that change nothing, at entries that change a bit the loop ignores, at
# the two unrouted events (each a separate prusim_run() call) and 12-cycle
# rounding; after every one the loops are found idle again.  Every count,
# CYCLE and STALL must equal the stepped run.
#
#   PRU1: reads R31 at 3k; bit 2 (7777) is seen at 7779; and 7780, qbeq
#         7781, ldi32 7782-7783, ldi 7784, sbbo flag 7785, halt 7786.
#         2594 iterations * 3 + 5 = 7787 instructions.
#   PRU0: ldi32 0-1, ldi 2, sbbo CTR_EN 3 (counted), ldi32 4-5, loads at
#         6 + 4k; the one in 7786 sees the flag (PRU1's store in 7785; PRU0
#         issues first within a cycle), qbeq 7789, lbbo CYCLE 7790 reads
#         7790 (cycles 3..7792: a load samples at the start of its last
#         cycle), lbbo STALL 7794 reads 1946 * 2 + 3 + 2 = 3897, halt
#         7798.  6 + 1946 * 2 + 3 = 3901 instructions, 3898 stalls; CYCLE
#         ends at 7787 + 4 + 4 + 1 = 7796, STALL at 3898.
#
# cores: 0 1
# args: --r31-1 {dir}/../stim/multi.txt --event 4000:40 --event 6000:41
# expect: cycles=7799
# expect: pru0.state=halted
# expect: pru0.instructions=3901
# expect: pru0.stalls=3898
# expect: pru0.r6=7790
# expect: pru0.r7=3897
# expect: pru0.cycle_counter=7796
# expect: pru0.stall_counter=3898
# expect: pru1.state=halted
# expect: pru1.instructions=7787
# expect: pru1.stalls=0
# expect: pru1.cycle_counter=0
# expect: intc.raw=0x30000000000

	.text
	.global	_start
_start:
	.if	PRU == 0
	ldi32	r1, 0x22000
	ldi	r2, 0xb			; SOFT_RST_N | EN | CTR_EN
	sbbo	&r2, r1, 0, 4
	ldi32	r4, 0x10000
poll:
	lbbo	&r5, r4, 0, 4
	qbeq	poll, r5, 0
	lbbo	&r6, r1, 0xc, 4		; CYCLE
	lbbo	&r7, r1, 0x10, 4	; STALL
	halt
	.else
wait:
	mov	r0, r31
	and	r0, r0, 4
	qbeq	wait, r0, 0
	ldi32	r4, 0x10000
	ldi	r5, 1
	sbbo	&r5, r4, 0, 4
	halt
	.endif
