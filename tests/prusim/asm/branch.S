# SPDX-License-Identifier: GPL-2.0-only
# Quick branches (every condition, taken and not taken, register and
# immediate operands, field selects), bit branches, backward branches,
# JMP/JAL by label and by register, call/ret.  Taken branches cost one
# cycle like any instruction: the success path below executes 58
# instructions (numbered in the comments), so the run takes 58 cycles.
# The return addresses are word addresses: call at word 54 leaves 55 in
# r3.w2, jal at word 56 leaves 57 in r5.w0.
#
# expect: pru0.state=halted
# expect: pru0.r29=0
# expect: pru0.r28=18
# expect: cycles=58
# expect: pru0.instructions=58
# expect: pru0.r5=0x39
# expect: pru0.r3=0x3701ff

	.text
	.global	_start
_start:
	ldi	r1, 5			; 1
	ldi	r2, 7			; 2
	qbgt	t1, r1, r2		; 3  7 > 5: taken
	jmp	fail
t1:	add	r28, r28, 1		; 4
	qbgt	fail, r2, r1		; 5  5 > 7: no
	qbgt	fail, r1, r1		; 6  5 > 5: no
	qbge	t2, r1, r1		; 7  5 >= 5: taken
	jmp	fail
t2:	add	r28, r28, 1		; 8
	qbge	fail, r2, r1		; 9  5 >= 7: no
	qblt	t3, r2, r1		; 10 5 < 7: taken
	jmp	fail
t3:	add	r28, r28, 1		; 11
	qblt	fail, r1, r1		; 12 5 < 5: no
	qble	t4, r1, r1		; 13 5 <= 5: taken
	jmp	fail
t4:	add	r28, r28, 1		; 14
	qble	fail, r1, r2		; 15 7 <= 5: no
	qbeq	t5, r1, 5		; 16 5 == 5: taken
	jmp	fail
t5:	add	r28, r28, 1		; 17
	qbeq	fail, r1, r2		; 18 no
	qbne	t6, r1, r2		; 19 taken
	jmp	fail
t6:	add	r28, r28, 1		; 20
	qbne	fail, r1, 5		; 21 no
	qba	t7			; 22
	jmp	fail
t7:	add	r28, r28, 1		; 23
	qbbs	t8, r2, 1		; 24 bit 1 of 7 is set: taken
	jmp	fail
t8:	add	r28, r28, 1		; 25
	qbbs	fail, r2, 3		; 26 bit 3 clear: no
	qbbc	t9, r2, 3		; 27 taken
	jmp	fail
t9:	add	r28, r28, 1		; 28
	qbbc	fail, r2.b0, 0		; 29 bit 0 set: no
	ldi	r3, 0x1ff		; 30
	qblt	t10, r3.b0, 0x80	; 31 0x80 < 0xff: taken
	jmp	fail
t10:	add	r28, r28, 1		; 32
	qbbs	t11, r3.w0, 8		; 33 bit 8 of 0x1ff: taken
	jmp	fail
t11:	add	r28, r28, 1		; 34
	qbbc	fail, r3.b1, 0		; 35 r3.b1 = 1: no
	qblt	fail, r3.w1, r3.b0	; 36 0xff < 0x0001: no
	qbgt	t12, r3.w1, r3.b0	; 37 0xff > 0x0001: taken
	jmp	fail
t12:	add	r28, r28, 1		; 38
	ldi	r4, 3			; 39
back:	sub	r4, r4, 1		; 40, 42, 44: backward branches
	qbne	back, r4, 0		; 41, 43, 45
	add	r28, r28, 1		; 46
	call	sub1			; 47 jal r3.w2 (word 54): sub1 48, 49
	add	r28, r28, 1		; 50
	jal	r5.w0, sub2		; 51 (word 56): sub2 52, 53
	add	r28, r28, 1		; 54
	ldi	r6, %pmem(t20)		; 55
	jmp	r6			; 56
	jmp	fail
t20:	add	r28, r28, 1		; 57
	halt				; 58

fail:
	ldi	r29, 0xdead
	halt

sub1:	add	r28, r28, 1
	ret
sub2:	add	r28, r28, 1
	jmp	r5.w0
