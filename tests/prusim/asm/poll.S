# SPDX-License-Identifier: GPL-2.0-only
# Busy polling, skipped exactly.  PRU0 polls R31 bit 2 in a 3-cycle loop
# with the cycle counter on; the input rises at cycle 2000000.  PRU1 polls
# a flag in shared RAM in a 4-cycle loop (load 3 + branch 1) until PRU0 sets
# it.  While both only poll, the simulator jumps ahead in multiples of 12
# cycles; every count must equal the stepped run.
#
#   PRU0: 0-3 setup (CTR_EN from the store in cycle 3), polls at 4 + 3k;
#         the read in cycle 2000002 sees the bit; and, qbeq, lbbo CYCLE in
#         2000005 reads 2000005 (cycles 3..2000007: it samples at the start
#         of its last cycle, 2000008); ldi32, ldi, sbbo flag
#         in 2000012, halt 2000013.  2000011 instructions, 3 stalls.
#   PRU1: 0-1 ldi32, loads at 2 + 4k; the one in 2000014 sees the flag;
#         qbeq 2000017, halt 2000018.  1000011 instructions.
#
# cores: 0 1
# args: --r31-0 {dir}/../stim/poll.txt
# expect: cycles=2000019
# expect: pru0.r3=2000005
# expect: pru0.instructions=2000011
# expect: pru0.stalls=3
# expect: pru1.instructions=1000011
# expect: pru1.stalls=1000008
# expect: pru1.r5=1

	.text
	.global	_start
_start:
	.if	PRU == 0
	ldi32	r1, 0x22000
	ldi	r2, 0xb			; SOFT_RST_N | EN | CTR_EN
	sbbo	&r2, r1, 0, 4
wait:
	mov	r0, r31
	and	r0, r0, 4
	qbeq	wait, r0, 0
	lbbo	&r3, r1, 0xc, 4		; CYCLE
	ldi32	r4, 0x10000
	ldi	r5, 1
	sbbo	&r5, r4, 0, 4
	halt
	.else
	ldi32	r4, 0x10000
poll:
	lbbo	&r5, r4, 0, 4
	qbeq	poll, r5, 0
	halt
	.endif
