# SPDX-License-Identifier: GPL-2.0-only
# Hardware loops: LOOP costs one cycle, each iteration only its body
# (no per-iteration overhead).  Immediate and register (field) counts, a
# zero count skipping the body, the largest counts GNU as accepts (255) and
# the encoding holds (256, written as a .word), and an ILOOP left by a
# taken branch (after which the old body end no longer loops).
#
#   A: ldi, loop, 5 x 2                  = 12  (r1 = 15)
#   B: ldi, ldi, loop, 4 x 1             =  7  (r3 = 12)
#   C: ldi, loop (count 0)               =  2
#   D: ldi, iloop, 3 + 3 + 2, qba, add, qba = 13 (r4 = 3, r5 = 3)
#   E: ldi, loop, 255 x 1                = 257 (r7 = 255)
#   F: ldi, loop, 256 x 1                = 258 (r8 = 256)
#   halt                                 =  1      total 550
#
# expect: pru0.state=halted
# expect: cycles=550
# expect: pru0.instructions=550
# expect: pru0.r1=15
# expect: pru0.r3=12
# expect: pru0.r4=3
# expect: pru0.r5=3
# expect: pru0.r7=255
# expect: pru0.r8=256
# expect: pru0.r29=0

	.text
	.global	_start
_start:
	ldi	r1, 0
	loop	end1, 5
	add	r1, r1, 1
	add	r1, r1, 2
end1:
	ldi	r2.b1, 4
	ldi	r3, 0
	loop	end2, r2.b1
	add	r3, r3, 3
end2:
	ldi	r6, 0
	loop	end3, r6
	ldi	r29, 0xbad
end3:
	ldi	r4, 0
	iloop	end4, 100
	add	r4, r4, 1
	qbeq	out4, r4, 3		; leaves the loop in the third iteration
l4last:	add	r5, r5, 1
end4:
	qba	done4
out4:
	qba	l4last			; runs the old last body word once, falls through
done4:
	ldi	r7, 0
	loop	end5, 255
	add	r7, r7, 1
end5:
	ldi	r8, 0
	.word	0x31ff0002		; loop .+8, 256
	add	r8, r8, 1
	halt
