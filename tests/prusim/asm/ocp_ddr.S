# SPDX-License-Identifier: GPL-2.0-only
# DDR behind the OCP master port (--ddr gives 4 KiB at 0x80000000 backed by
# host memory): a store is posted (1 cycle, 2 for 8 bytes), a load through
# C31 takes 43 cycles (+1 per further word); a load outside the DDR region
# fails in the embedder's callback and stops the core.
#
#   lbco 3, clr 1, sbco 1, ldi32 2, ldi32 2, sbco(8) 2, lbco(8) 44,
#   ldi32 2 = 57 cycles and 11 instructions; the lbbo in cycle 57 stops the
#   core (not counted as executed), so 58 cycles were simulated.
#
# args: --ddr 4K
# exit: 3
# expect: pru0.state=stopped
# expect: pru0.reason~OCP read of 4 bytes at 0x80001000 failed
# expect: pru0.r3=0xcafe0001
# expect: pru0.r4=0x12345678
# expect: pru0.r5=0xcafe0001
# expect: pru0.r6=0x12345678
# expect: pru0.instructions=11
# expect: pru0.pc=11
# expect: cycles=58

	.text
	.global	_start
_start:
	lbco	&r0, 4, 4, 4
	clr	r0, r0, 4
	sbco	&r0, 4, 4, 4
	ldi32	r3, 0xcafe0001
	ldi32	r4, 0x12345678
	sbco	&r3, 31, 0x10, 8	; C31 = 0x80000000
	lbco	&r5, 31, 0x10, 8
	ldi32	r1, 0x80001000
	lbbo	&r7, r1, 0, 4
	halt
