/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: minimal C runtime start-up for PRU firmware.
 *
 * The linker script puts .init0 first in IRAM, so _start is at address 0:
 * the core's reset value of the program counter and the ELF entry point.
 *
 *  - load the stack pointer (r2) with the top of data RAM from the linker
 *    script (__prukit_stack_top),
 *  - zero .bss: the loader already does, but this keeps a core that is
 *    restarted without reloading from seeing stale data there,
 *  - call main() (no arguments; constructors are rejected by the linker
 *    script, so there are none to run),
 *  - halt when main() returns; if the core is resumed, halt again.
 *
 * Cost before main(): 9 cycles + 4 per 32-bit word of .bss (each ldi32 is two
 * instructions, or one after linker relaxation when the value fits 16 bits,
 * which it always does in data RAM: then 6 + 4 per word).
 */

	.section .init0, "ax", @progbits
	.global	_start
	.type	_start, @function
_start:
	ldi32	r2, __prukit_stack_top
	ldi32	r0, __bss_start
	ldi32	r1, __bss_end
	ldi	r14, 0
.Lclear_bss:
	qbeq	.Lbss_done, r0, r1
	sbbo	&r14, r0, 0, 4
	add	r0, r0, 4
	qba	.Lclear_bss
.Lbss_done:
	call	main
.Lhalt:
	halt
	qba	.Lhalt
	.size	_start, . - _start
