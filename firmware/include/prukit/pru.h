/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: access to the PRU's R30 (direct outputs) and R31 (direct inputs,
 * host interrupt status, event strobe).
 *
 * Always go through these accessors.  A global
 *	volatile register uint32_t __R30 asm("r30");
 * does not make GCC perform every access: volatile has no effect on register
 * variables, and pru-gcc 12 -O2 was seen to compute "__R30 |= 1" into another
 * register and never write r30.  Each accessor below is one asm volatile
 * statement, so every call is exactly one instruction (write_r30() is one
 * "mov r30, rX"), in program order with respect to other volatile asm
 * (__delay_cycles() included) and volatile memory accesses.
 */
#ifndef _PRUKIT_PRU_H
#define _PRUKIT_PRU_H

#include <stdint.h>

#ifndef ARRAY_SIZE
#define ARRAY_SIZE(a)		(sizeof(a) / sizeof((a)[0]))
#endif

/* Bits of R31 when read */
#define PRU_R31_GPI_MASK	0x3fffffffu	/* direct inputs (pins 0..29) */
#define PRU_R31_HOST0		(1u << 30)	/* INTC host interrupt 0 pending */
#define PRU_R31_HOST1		(1u << 31)	/* INTC host interrupt 1 pending */

/* Writing R31: strobe system event 16..31 */
#define PRU_R31_VEC_VALID	(1u << 5)
#define PRU_R31_VEC_MASK	0x0fu
#define PRU_R31_EVENT_FIRST	16
#define PRU_R31_EVENT_LAST	31

static inline uint32_t read_r31(void)
{
	uint32_t val;

	__asm__ __volatile__("mov %0, r31" : "=r"(val));
	return val;
}

static inline uint32_t read_r30(void)
{
	uint32_t val;

	__asm__ __volatile__("mov %0, r30" : "=r"(val));
	return val;
}

static inline void write_r30(uint32_t val)
{
	__asm__ __volatile__("mov r30, %0" : : "r"(val));
}

/*
 * Raise INTC system event ev (16..31) towards whatever channel/host the
 * .pru_irq_map (or the host driver) mapped it to.
 */
static inline void r31_strobe_event(unsigned int ev)
{
	uint32_t val = PRU_R31_VEC_VALID | ((ev - PRU_R31_EVENT_FIRST) & PRU_R31_VEC_MASK);

	__asm__ __volatile__("mov r31, %0" : : "r"(val));
}

/*
 * Stop the core (HALT).  If it is ever resumed, halt again.  Plain asm rather
 * than GCC's __halt() builtin, so that older pru-gcc releases work too.
 */
static inline void __attribute__((noreturn)) pru_halt(void)
{
	__asm__ __volatile__("1:\thalt\n\tqba\t1b");
	__builtin_unreachable();
}

#endif /* _PRUKIT_PRU_H */
