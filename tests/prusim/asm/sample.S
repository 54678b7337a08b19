# SPDX-License-Identifier: GPL-2.0-only
# The 100 Msps R31 sampling loop of BeagleLogic (MOV + NOP per sample):
# every sample sees the stimulus value of its own cycle.  The stimulus
# (stim/pattern64.txt) changes every cycle: (cycle * 37 + 11) mod 256,
# repeated every 64 cycles.  Samples at cycles 0, 2, .., 30 go to r1..r4,
# samples at cycles 129, 131, .., 159 (in the repeated pattern) to r5..r8.
#
#   0..31 16 x (mov, nop), 32 loop, 33..128 96 nops, 129..160 16 x (mov,
#   nop), 161 halt
#
# args: --r31-0 {dir}/../stim/pattern64.txt
# expect: cycles=162
# expect: pru0.r1=0xe99f550b
# expect: pru0.r2=0x11c77d33
# expect: pru0.r3=0x39efa55b
# expect: pru0.r4=0x6117cd83
# expect: pru0.r5=0x0ec47a30
# expect: pru0.r6=0x36eca258
# expect: pru0.r7=0x5e14ca80
# expect: pru0.r8=0x863cf2a8

	.macro	sample4 reg
	.irp	byte, b0, b1, b2, b3
	mov	\reg\().\byte, r31.b0
	nop
	.endr
	.endm

	.text
	.global	_start
_start:
	sample4	r1
	sample4	r2
	sample4	r3
	sample4	r4
	loop	wait, 96
	nop
wait:
	sample4	r5
	sample4	r6
	sample4	r7
	sample4	r8
	halt
