# SPDX-License-Identifier: GPL-2.0-only
# The PRU cookbook's fastest toggle, "set r30; clr r30; jmp" (what TI's
# compiler makes of while (1) { __R30 |= g; __R30 &= ~g; }): the scope
# showed a 15 ns period, high for 5 ns.  That is 3 cycles, 1 high.
#
# args: --max-cycles 40
# expect: cycles=40
# expect: pru0.state=running
# edges: P9_31=1,2,4,5,7,8,10,11,13,14,16,17,19,20,22,23,25,26,28,29,31,32,34,35,37,38
# period: P9_31=3,1

	.text
	.global	_start
_start:
	nop
loop:
	set	r30, r30, 0
	clr	r30, r30, 0
	jmp	loop
