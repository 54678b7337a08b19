# SPDX-License-Identifier: GPL-2.0-only
# An undefined encoding (NOT with a register operand: the assembler never
# emits it) stops the core with a reason and the pc at the bad word.
#
# exit: 3
# expect: pru0.state=stopped
# expect: pru0.reason~illegal instruction 0x16000000 at 0x0004
# expect: pru0.pc=1
# expect: pru0.instructions=1
# expect: cycles=2

	.text
	.global	_start
_start:
	nop
	.word	0x16000000
	halt
