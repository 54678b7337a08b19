# SPDX-License-Identifier: GPL-2.0-only
# Carry rules: the carry of ADD/ADC/SUB/SUC/RSB/RSC is the bit above the
# destination field of the full (zero-extended) result; logic ops and
# shifts keep it.  After each case "adc rN, r0, 0" copies the carry to rN
# (and clears it).  26 instructions in 26 cycles.
#
# expect: pru0.state=halted
# expect: cycles=26
# expect: pru0.r10=0
# expect: pru0.r11=1
# expect: pru0.r12=0
# expect: pru0.r13=1
# expect: pru0.r14=0
# expect: pru0.r15=1
# expect: pru0.r16=1
# expect: pru0.r17=0
# expect: pru0.r18=1
# expect: pru0.r19=0
# expect: pru0.r2=0xffff

	.text
	.global	_start
_start:
	ldi	r1, 0xfff0
	ldi	r1.w2, 0xffff		; r1 = 0xfffffff0, r0 = 0
	add	r2.b0, r1, 0x20		; 0x1_0000_0010: bit 8 is 0
	adc	r10, r0, 0
	add	r2.b0, r1.b0, 0x20	; 0x110: bit 8 is 1
	adc	r11, r0, 0
	add	r2.w0, r1.b0, 0x20	; 0x110: bit 16 is 0
	adc	r12, r0, 0
	sub	r2.b0, r1.b0, 0xf1	; 0xf0 - 0xf1 borrows
	adc	r13, r0, 0
	sub	r2.b0, r1, 0xf1		; 0xfffffeff: bit 8 is 0
	adc	r14, r0, 0
	add	r2, r1, 0x20		; carry 1 ...
	lsl	r3, r1, 4
	and	r3, r1, r1
	xor	r3, r3, 1
	adc	r15, r0, 0		; ... kept by lsl/and/xor
	rsb	r2, r1, 0		; 0 - 0xfffffff0 borrows
	adc	r16, r0, 0
	rsc	r2, r0, 0		; 0 - 0 - 0: no borrow
	adc	r17, r0, 0
	suc	r2.w0, r0.w0, 0		; carry was cleared: 0 - 0 - 0 ... then:
	sub	r2.w0, r0.w0, 1		; 0 - 1 = 0xffff, borrow out of 16 bits
	adc	r18, r0, 0
	adc	r19, r0, 0		; the previous adc cleared the carry
	halt
