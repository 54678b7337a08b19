# SPDX-License-Identifier: GPL-2.0-only
# GPIO over the OCP master port: SYSCFG.STANDBY_INIT cleared first; stores
# to SETDATAOUT/CLEARDATAOUT are accepted at most every 8 cycles (a store
# to a busy path stalls) and change the pin 17 cycles after acceptance.
# A set/clear loop therefore toggles gpio1_21 with an 80 ns (16 cycle)
# period, 40 ns high, as the PRU cookbook measured.
#
#   t=0 lbco SYSCFG (3), 3 clr, 4 sbco, 5-12 ldi32 x2 + 4 ldi
#   iter 1: SET 13 (accepted 13, lands 30), CLR 14 (accepted 21 -> stalls
#           to 22, lands 38), sub 22, qbne 23
#   iter 2: SET 24 (acc. 29, lands 46), CLR 30 (acc. 37, lands 54), 38, 39
#   iter 3: SET 40 (acc. 45, lands 62), CLR 46 (acc. 53, lands 70), 54, 55
#   SET 56 (acc. 61, lands 78); lbbo DATAOUT at 62 sees the set that lands
#   in the same cycle (34 cycles); ldi32, ldi; lbbo GPIO0 OE at 99
#   (38 cycles: its reset value, every line an input); halt at 137.
#
# expect: cycles=138
# expect: pru0.state=halted
# expect: pru0.instructions=30
# expect: pru0.stalls=108
# expect: pru0.r8=0x200000
# expect: pru0.r12=0xffffffff
# edges: gpio1_21=30,38,46,54,62,70,78
# period: gpio1_21=16,8

	.text
	.global	_start
_start:
	lbco	&r0, 4, 4, 4		; CFG SYSCFG
	clr	r0, r0, 4		; STANDBY_INIT = 0: OCP master port on
	sbco	&r0, 4, 4, 4
	ldi32	r1, 0x4804c000		; GPIO1
	ldi32	r2, 1 << 21
	ldi	r5, 0x194		; SETDATAOUT
	ldi	r6, 0x190		; CLEARDATAOUT
	ldi	r7, 0x13c		; DATAOUT
	ldi	r3, 3
loop:
	sbbo	&r2, r1, r5, 4
	sbbo	&r2, r1, r6, 4
	sub	r3, r3, 1
	qbne	loop, r3, 0
	sbbo	&r2, r1, r5, 4
	lbbo	&r8, r1, r7, 4
	ldi32	r10, 0x44e07000		; GPIO0
	ldi	r11, 0x134		; OE
	lbbo	&r12, r10, r11, 4
	halt
