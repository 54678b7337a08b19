# SPDX-License-Identifier: GPL-2.0-only
# Read latencies of every local region and burst lengths, store costs, the
# C24/C25/C28 constant table entries (CTPPR0 programmed to 0x0100) and the
# swapped DRAM view of PRU1.  Both cores run this; cycle budget per core:
#
#   ldi32, ldi, sbbo CTPPR0, ldi32, sbbo shared        2+1+1+2+1 =  7
#   own DRAM 3, other DRAM 3, shared 3, INTC 3, CFG 3            = 15
#   CTRL 4, IEP 4                                                 =  8
#   bursts 1/2/8/12/16/3 bytes: 3, 3, 4, 5, 6, 3                  = 24
#   ldi r0.b1, 6-byte burst from r0.b1: 1 + 4                     =  5
#   stores of 4/8/16/124 bytes: 1, 2, 4, 31                       = 38
#   halt                                                          =  1
#   total 98 cycles, 27 instructions (ldi32 is two), 71 stall cycles
#
# cores: 0 1
# expect: cycles=98
# expect: pru0.state=halted
# expect: pru1.state=halted
# expect: pru0.instructions=27
# expect: pru0.stalls=71
# expect: pru1.stalls=71
# expect: pru0.r3=0xa0a0a0a0
# expect: pru0.r4=0xa0a0a0a1
# expect: pru1.r3=0xa0a0a0a1
# expect: pru1.r4=0xa0a0a0a0
# expect: pru0.r5=0x22000
# expect: pru1.r5=0x24000
# expect: pru0.r6=0x4e82a900
# expect: pru0.r7=0x47000000
# expect: pru0.r8=0x100
# expect: pru1.r8=0x100
# expect: pru0.r10=0
# expect: pru0.r11=0xb4
# expect: pru0.r12=0xb3b4
# expect: pru0.r13=0xb1b2b3b4
# expect: pru0.r14=0xc1c2c3c4
# expect: pru0.r15=0xb1b2b3b4
# expect: pru0.r16=0xc1c2c3c4
# expect: pru0.r17=0xd1d2d3d4
# expect: pru0.r18=0xa0a0a0a0
# expect: pru1.r18=0xa0a0a0a1
# expect: pru0.r21=0xd1d2d3d4
# expect: pru0.r22=0xb2b3b400
# expect: pru0.r23=0xb1b2b3b4
# expect: pru0.r24=0xc3c4

	.section .data.atzero, "aw"	; placed at DRAM offset 0
	.word	0xa0a0a0a0 + PRU, 0xb1b2b3b4, 0xc1c2c3c4, 0xd1d2d3d4, 0xe1e2e3e4

	.text
	.global	_start
_start:
	ldi32	r1, 0x22000 + 0x2000 * PRU	; this core's CTRL
	ldi	r2, 0x100
	sbbo	&r2, r1, 0x28, 4		; CTPPR0: C28 = 0x00010000
	ldi32	r9, 0x10000
	sbbo	&r1, r9, 4 * PRU, 4		; shared RAM, absolute
	lbco	&r3, 24, 0, 4			; own DRAM
	lbco	&r4, 25, 0, 4			; other DRAM
	lbco	&r5, 28, 4 * PRU, 4		; shared RAM through C28
	lbco	&r6, 0, 0, 4			; INTC REVID
	lbco	&r7, 4, 0, 4			; CFG REVID
	lbbo	&r8, r1, 0x28, 4		; CTRL CTPPR0
	lbco	&r10, 26, 0, 4			; IEP GLOBAL_CFG
	lbco	&r11, 24, 4, 1
	lbco	&r12, 24, 4, 2
	lbco	&r13, 24, 4, 8
	lbco	&r15, 24, 4, 12
	lbco	&r18, 24, 0, 16
	lbco	&r22.b1, 24, 4, 3
	ldi	r0.b1, 6
	lbco	&r23, 24, 4, r0.b1
	sbco	&r3, 24, 0x80, 4
	sbco	&r3, 24, 0x80, 8
	sbco	&r3, 24, 0x80, 16
	sbco	&r0, 24, 0x80, 124
	halt
