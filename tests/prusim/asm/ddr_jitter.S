# SPDX-License-Identifier: GPL-2.0-only
# DDR latency jitter (-C ddr_jitter=20 -C jitter_seed=7): each load from
# DDR takes 43 to 63 cycles, the same in every run with the same seed.  The
# cycle counter (CTRL CYCLE, read last) counts 346 cycles from its reset to
# that read without it (8 x 43 for the loads), 346 + 104 with seed 7 (and
# 346 + 55 with seed 8): within 0..8 x 20 more.
#
# args: --ddr 4K -C ddr_jitter=20 -C jitter_seed=7
# expect: pru0.state=halted
# expect: pru0.r10=450

	.text
	.global	_start
_start:
	lbco	&r0, 4, 4, 4		; C4 = CFG: SYSCFG.STANDBY_INIT off
	clr	r0, r0, 4
	sbco	&r0, 4, 4, 4
	ldi32	r1, 0x22000		; PRU0 CTRL
	lbbo	&r2, r1, 0, 4
	set	r2, r2, 3		; COUNTER_ENABLE
	sbbo	&r2, r1, 0, 4
	ldi	r4, 0
	sbbo	&r4, r1, 0xc, 4		; CYCLE = 0
	lbco	&r5, 31, 0x00, 4
	lbco	&r5, 31, 0x20, 4
	lbco	&r5, 31, 0x40, 4
	lbco	&r5, 31, 0x60, 4
	lbco	&r5, 31, 0x80, 4
	lbco	&r5, 31, 0xa0, 4
	lbco	&r5, 31, 0xc0, 4
	lbco	&r5, 31, 0xe0, 4
	lbbo	&r10, r1, 0xc, 4	; CYCLE
	halt
