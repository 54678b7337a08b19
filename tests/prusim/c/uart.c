// SPDX-License-Identifier: GPL-2.0-only
/*
 * Bit-banged UART transmitter, 115200 baud 8N1 on PRU0 R30 bit 0 (P9_31).
 * run.sh decodes its VCD with sigrok's own UART decoder.  The bit time is
 * 1736 cycles (200 MHz / 115200) including the loop overhead, which
 * __delay_cycles() pads to the cycle.
 *
 * expect: pru0.state=halted
 */
#include <stdint.h>

#define CYCLES_PER_BIT	(200000000u / 115200u)
#define LOOP_CYCLES	5	/* and, mov r30, lsr, sub, qbne in tx() (pru-gcc -O2) */

static inline void write_r30(uint32_t v)
{
	asm volatile("mov r30, %0" : : "r"(v));
}

static void tx(uint8_t c)
{
	uint32_t frame = (uint32_t)c << 1 | 1u << 9;	/* start, 8 data LSB first, stop */
	int i;

	for (i = 0; i < 10; i++) {
		write_r30(frame & 1);
		frame >>= 1;
		__delay_cycles(CYCLES_PER_BIT - LOOP_CYCLES);
	}
}

int main(void)
{
	static const char msg[] = "Hello from prusim!\r\n";
	const char *p;

	write_r30(1);
	__delay_cycles(10 * CYCLES_PER_BIT);
	for (p = msg; *p; p++)
		tx(*p);
	__delay_cycles(10 * CYCLES_PER_BIT);
	return 0;
}
