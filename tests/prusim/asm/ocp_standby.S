# SPDX-License-Identifier: GPL-2.0-only
# An OCP master access while CFG SYSCFG.STANDBY_INIT is still 1 (its reset
# value) never completes on hardware; prusim stops the core with a reason.
#
# exit: 3
# expect: pru0.state=stopped
# expect: pru0.reason~STANDBY_INIT
# expect: pru0.pc=2

	.text
	.global	_start
_start:
	ldi32	r1, 0x4804c000
	sbbo	&r2, r1, 0, 4
	halt
