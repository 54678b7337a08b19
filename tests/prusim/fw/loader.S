# SPDX-License-Identifier: GPL-2.0-only
# Firmware for the loader unit test: a resource table, a .pru_irq_map
# (17 -> channel 1 -> host 1, 18 -> channel 2 -> host 2), data and code.

	.section .resource_table, "a"
	.word	1, 0, 0, 0		; version 1, no entries, reserved

	.section .pru_irq_map, "", @progbits
	.byte	0, 2
	.byte	17, 1, 1
	.byte	18, 2, 2

	.data
	.word	0x11223344

	.text
	.global	_start
_start:
	ldi	r1, 1
	halt
