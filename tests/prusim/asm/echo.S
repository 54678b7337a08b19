# SPDX-License-Identifier: GPL-2.0-only
# Input echo (firmware/input-echo in assembly): copy R31 bits 0..15 to R30
# in a 4-cycle loop.  The stimulus repeats every 3000 cycles and holds its
# value across cycle 3000k, so skips end without the loop seeing a change
# and the loop is found idle again at once.  A skip must add what stepping
# adds: 10000 cycles are exactly 10000 one-cycle instructions (skips used
# to add their instructions to the next idle measurement, 748036 here).
#
#   0 ldi; reads (mov r0, r31) at 1 + 4k, r30 written at 3 + 4k
#   period 1: 0x1 from 1000 (read 1001 -> r30 1003), 0x3 from 1500 (1501
#   -> 1503), 0x2 from 1530 (1533 -> 1535), 0x8001 only in cycle 2000
#   (between the reads in 1997 and 2001: never seen), 0 from 2001 (2001 ->
#   2003); the same at 4000 + and 7000 +: 12 pin changes.
#
# args: --r31-0 {dir}/../stim/echo.txt --max-cycles 10000
# expect: cycles=10000
# expect: pin_changes=12
# expect: pru0.state=running
# expect: pru0.instructions=10000
# expect: pru0.stalls=0
# expect: pru0.pc=4
# edges: P9_31=1003,1535,4003,4535,7003,7535
# edges: P9_29=1503,2003,4503,5003,7503,8003
# edges: P8_11=

	.text
	.global	_start
_start:
	ldi	r1, 0xffff
loop:
	mov	r0, r31
	and	r0, r0, r1
	mov	r30, r0
	jmp	loop
