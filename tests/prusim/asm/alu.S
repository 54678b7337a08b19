# SPDX-License-Identifier: GPL-2.0-only
# Every format 1 ALU operation, with byte and half-word field selects, and
# LDI/LMBD.  Each instruction takes one cycle: 35 instructions, the last
# (HALT) issues in cycle 34, so the run ends after 35 cycles.
#
# expect: pru0.state=halted
# expect: cycles=35
# expect: pru0.instructions=35
# expect: pru0.stalls=0
# expect: pru0.r1=0xfffffff0
# expect: pru0.r2=0x10
# expect: pru0.r3=0x16
# expect: pru0.r4=0x15
# expect: pru0.r5=0x111000
# expect: pru0.r6=0xffffffff
# expect: pru0.r7=0
# expect: pru0.r8=1
# expect: pru0.r9=0x20
# expect: pru0.r10=0xffff
# expect: pru0.r11=0x1f
# expect: pru0.r12=0x80000000
# expect: pru0.r13=0x0fffffff
# expect: pru0.r14=0
# expect: pru0.r15=0xff00
# expect: pru0.r16=0x0ffffff0
# expect: pru0.r17=0x80000010
# expect: pru0.r18=0xf000000f
# expect: pru0.r19=0xffffffef
# expect: pru0.r20=0xef000000
# expect: pru0.r21=0x0fffffff
# expect: pru0.r22=0xfffffff0
# expect: pru0.r23=0x80
# expect: pru0.r24=0x7ffffff0
# expect: pru0.r25=0x11
# expect: pru0.r26=0x1200
# expect: pru0.r27=31
# expect: pru0.r28=31
# expect: pru0.r29=3
# expect: pru0.r0=32

	.text
	.global	_start
_start:
	ldi	r1, 0xfff0		; r1 = 0x0000fff0
	ldi	r1.w2, 0xffff		; r1 = 0xfffffff0
	add	r2, r1, 0x20		; 0x1_0000_0010: r2 = 0x10, carry 1
	adc	r3, r2, 5		; 0x10 + 5 + 1 = 0x16, carry 0
	adc	r4, r2, 5		; 0x15
	add	r5.b1, r1.b0, 0x20	; 0xf0 + 0x20 = 0x110: r5.b1 = 0x10, carry 1
	adc	r5.b2, r5.b1, 0		; 0x10 + 1 = 0x11: r5 = 0x111000
	sub	r6, r2, 0x11		; 0x10 - 0x11 = 0xffffffff, borrow 1
	suc	r7, r2, 0x0f		; 0x10 - 0xf - 1 = 0, borrow 0
	suc	r8, r2, 0x0f		; 0x10 - 0xf - 0 = 1
	rsb	r9, r2, 0x30		; 0x30 - 0x10 = 0x20
	rsb	r10.w0, r2.w0, 0x0f	; 0xf - 0x10 = 0xffff (16 bits), borrow 1
	rsc	r11, r2, 0x30		; 0x30 - 0x10 - 1 = 0x1f
	lsl	r12, r2, 27		; 0x80000000
	lsr	r13, r1, 4		; 0x0fffffff
	lsl	r14.b0, r2.b0, 4	; 0x100 truncated to 8 bits: 0
	lsr	r15.w1, r1.w2, 8	; 0xffff >> 8 = 0xff into bits 23:8
	and	r16, r1, r13		; 0x0ffffff0
	or	r17, r2, r12		; 0x80000010
	xor	r18, r1, r13		; 0xf000000f
	not	r19, r2			; 0xffffffef
	not	r20.b3, r2.b0		; 0xef into bits 31:24
	min	r21, r1, r13		; 0x0fffffff
	max	r22, r1, r13		; 0xfffffff0
	min	r23.w0, r1.w2, 0x80	; min(0xffff, 0x80)
	clr	r24, r1, 31		; 0x7ffffff0
	set	r25, r2, 0		; 0x11
	set	r26.b1, r2.b0, 33	; bit 33 & 31 = 1: 0x12 into bits 15:8
	lmbd	r27, r12, 1		; leftmost 1 of 0x80000000: 31
	lmbd	r28, r2, 0		; leftmost 0 of 0x00000010: 31
	lmbd	r29.b0, r1.b0, 0	; leftmost 0 of the byte 0xf0: 3
	lmbd	r0, r14, 1		; no 1 in 0: 32
	ldi	r30.b2, 0		; r30 stays 0: no pin change
	nop
	halt
