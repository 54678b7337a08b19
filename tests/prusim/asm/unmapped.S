# SPDX-License-Identifier: GPL-2.0-only
# A load from a PRU-ICSS block that is not modelled (the UART at 0x28000)
# stops the core with the address in the reason.
#
# exit: 3
# expect: pru0.state=stopped
# expect: pru0.reason~load of 4 bytes at unmapped or unmodelled address 0x28000

	.text
	.global	_start
_start:
	lbco	&r1, 7, 0, 4			; C7 = PRU-ICSS UART0
	halt
