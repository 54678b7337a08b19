# SPDX-License-Identifier: GPL-2.0-only
# A jump beyond the 8 KiB IRAM stops the core there.
#
# exit: 3
# expect: pru0.state=stopped
# expect: pru0.reason~program counter 0x4000 is outside IRAM
# expect: pru0.pc=4096

	.text
	.global	_start
_start:
	ldi	r1, 4096
	jmp	r1
