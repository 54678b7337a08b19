# SPDX-License-Identifier: GPL-2.0-only
# Programmable constant table entries: CTBIR0 sets the 256-byte block of
# C24 (bits 7:0) and C25 (bits 23:16), CTPPR1 the 256-byte pointer of C30
# (bits 15:0) and C31 (bits 31:16).  The CT_REG debug registers (CTRL +
# 0x480) read back the resulting table; C4 is a fixed entry.
#
#   CTBIR0 = 0x00020001: C24 = 0x00000100, C25 = 0x00002200
#   CTPPR1 = 0x00100003: C30 = 0x40000300, C31 = 0x80001000
#
# expect: pru0.state=halted
# expect: pru0.r4=0x100
# expect: pru0.r5=0x2200
# expect: pru0.r6=0x40000300
# expect: pru0.r7=0x80001000
# expect: pru0.r8=0x26000
# expect: pru0.r9=0xaabbccdd
# expect: pru0.r10=0x11223344

	.section .data.atzero, "aw"
	.word	0x11223344		; DRAM0 offset 0
	.fill	0x100 - 4, 1, 0
	.word	0xaabbccdd		; DRAM0 offset 0x100

	.text
	.global	_start
_start:
	ldi32	r1, 0x22000
	ldi32	r2, 0x00020001
	sbbo	&r2, r1, 0x20, 4	; CTBIR0
	ldi32	r3, 0x00100003
	sbbo	&r3, r1, 0x2c, 4	; CTPPR1
	ldi32	r11, 0x22480		; CT_REG0
	lbbo	&r4, r11, 24 * 4, 8	; C24, C25
	lbbo	&r6, r11, 30 * 4, 8	; C30, C31
	lbbo	&r8, r11, 4 * 4, 4	; C4
	lbco	&r9, 24, 0, 4		; DRAM0 0x100
	ldi	r2, 0
	sbbo	&r2, r1, 0x20, 4	; CTBIR0 = 0: C24 = 0
	lbco	&r10, 24, 0, 4		; DRAM0 0
	halt
