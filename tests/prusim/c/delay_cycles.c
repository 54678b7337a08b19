// SPDX-License-Identifier: GPL-2.0-only
/*
 * __delay_cycles(n) between two R30 writes: the edges are exactly n + 1
 * cycles apart (the delay plus the write itself), for short NOP fills, the
 * 16-bit LDI/SUB/QBNE loop and the 32-bit loop GCC uses for long delays.
 * R30 is written through asm volatile (a volatile register variable does
 * not make GCC write r30 every time) and both levels are held in registers
 * before the first write, so nothing else runs between the writes.
 *
 * expect: pru0.state=halted
 * gaps: P9_31=2,3,4,6,11,101,1001,65537,100001,1000001
 */
#include <stdint.h>

static inline void write_r30(uint32_t v)
{
	asm volatile("mov r30, %0" : : "r"(v));
}

int main(void)
{
	uint32_t hi = 1, lo = 0;

	asm volatile("" : "+r"(hi), "+r"(lo));
	write_r30(hi);
	__delay_cycles(1);
	write_r30(lo);
	__delay_cycles(2);
	write_r30(hi);
	__delay_cycles(3);
	write_r30(lo);
	__delay_cycles(5);
	write_r30(hi);
	__delay_cycles(10);
	write_r30(lo);
	__delay_cycles(100);
	write_r30(hi);
	__delay_cycles(1000);
	write_r30(lo);
	__delay_cycles(65536);
	write_r30(hi);
	__delay_cycles(100000);
	write_r30(lo);
	__delay_cycles(1000000);
	write_r30(hi);
	return 0;
}
