# SPDX-License-Identifier: GPL-2.0-only
# Interrupt path.  PRU0's .pru_irq_map section (applied by the loader) maps
# system event 17 -> channel 1 -> host 1 (R31 bit 31 of both cores) and
# event 18 -> channel 2 -> host 2 (an interrupt line to the ARM, reported
# to the embedder).  An R31 write (1 << 5) | (event - 16) strobes an event;
# it reaches the INTC one cycle later (event_latency), so R31 shows it to
# an instruction in the next cycle.
#
#   PRU0: 0 strobe 17, 1 strobe 18 (host 2 rises in cycle 2), 2 halt
#   PRU1: 0 wbs r31.31 (not yet), 1 wbs (set: falls through), 2 ldi,
#         3 sbco SICR (clears event 17, host 1 drops), 4 wbc r31.31 passes,
#         5 halt -> 6 cycles
#
# cores: 0 1
# expect: cycles=6
# expect: pru0.state=halted
# expect: pru1.state=halted
# expect: pru1.instructions=6
# expect: host_irq=2:2:1
# expect: intc.raw=0x40000
# expect: intc.pending=4
# expect: intc.enabled=0x60000

	.text
	.global	_start
_start:
	.if	PRU == 0
	ldi	r31, (1 << 5) | (17 - 16)
	ldi	r31, (1 << 5) | (18 - 16)
	halt

	.section .pru_irq_map, "", @progbits
	.byte	0, 2			; type 0, two events
	.byte	17, 1, 1		; event, channel, host
	.byte	18, 2, 2
	.else
	wbs	r31, 31
	ldi	r6, 17
	sbco	&r6, 0, 0x24, 4		; INTC SICR
	wbc	r31, 31
	halt
	.endif
