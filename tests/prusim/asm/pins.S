# SPDX-License-Identifier: GPL-2.0-only
# Many pins at once, on both cores and a GPIO bank: the pin naming of the
# VCD (header pins, pruN_r30_N, gpioB_N) and several changes in one cycle.
# run.sh also uses it for the binary trace round trip (--trace-out,
# --trace-in, --events).
#
#   PRU0: 0 nop, 1 ldi r30 0x00ff (bits 0-7 rise), 2 ldi r30 0xc00f (4-7
#         fall, 14/15 rise), 3 ldi r30 0 (0-3, 14, 15 fall), 4 set bit 16,
#         5-7 lbco SYSCFG, 8 clr, 9 sbco, 10-13 ldi32 x2, 14 ldi,
#         15 sbbo SETDATAOUT (gpio1_0 and gpio1_21 rise 17 cycles later,
#         at 32), 16 halt                    -> 15 instructions, 23 changes
#   PRU1: 0 nop, 1 ldi r30 0x3fff (bits 0-13 rise), 2 ldi r30 0x2aaa (even
#         bits 0-12 fall), 3 set bit 20, 4 halt -> 5 instructions, 22 changes
#   The run ends when the posted GPIO write has landed: 33 cycles.
#
# cores: 0 1
# expect: cycles=33
# expect: pin_changes=45
# expect: pru0.state=halted
# expect: pru1.state=halted
# expect: pru0.instructions=15
# expect: pru1.instructions=5
# edges: P9_31=1,3
# edges: P9_42=1,2
# edges: P8_12=2,3
# edges: P8_11=2,3
# edges: pru0_r30_16=4
# edges: gpio1_0=32
# edges: gpio1_21=32
# edges: P8_45=1,2
# edges: P8_46=1
# edges: P8_21=1,2
# edges: P8_20=1
# edges: pru1_r30_20=3

	.text
	.global	_start
_start:
	nop
.if PRU == 0
	ldi	r30, 0x00ff
	ldi	r30, 0xc00f
	ldi	r30, 0
	set	r30, r30, 16
	lbco	&r0, 4, 4, 4		; CFG SYSCFG
	clr	r0, r0, 4		; STANDBY_INIT = 0: OCP master port on
	sbco	&r0, 4, 4, 4
	ldi32	r1, 0x4804c000		; GPIO1
	ldi32	r2, (1 << 21) | 1
	ldi	r5, 0x194		; SETDATAOUT
	sbbo	&r2, r1, r5, 4
.else
	ldi	r30, 0x3fff
	ldi	r30, 0x2aaa
	set	r30, r30, 20
.endif
	halt
