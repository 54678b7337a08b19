/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: void prukit_ocp_copy(uint32_t dst, uint32_t src, uint32_t len)
 *
 * Copy len bytes from src to dst, both addresses the core can reach: its data
 * RAM, the shared RAM or anything behind the OCP master port (DDR).  Moves 48
 * bytes per LBBO/SBBO pair through r18..r29, then the rest in one burst whose
 * length is in r0.b0.  A read from DDR costs its latency (~43 cycles) once
 * per burst instead of once per word; writes are posted.
 *
 * GCC's PRU ABI: arguments in r14, r15, r16; r0, r1 and r14..r29 belong to
 * the caller, so nothing needs saving.  Overlapping ranges are not handled.
 */

#define COPY_CHUNK	48

	.section .text.prukit_ocp_copy, "ax", @progbits
	.global	prukit_ocp_copy
	.type	prukit_ocp_copy, @function
prukit_ocp_copy:
	qbgt	.Ltail, r16, COPY_CHUNK		/* len < 48 */
.Lchunk:
	lbbo	&r18, r15, 0, COPY_CHUNK
	sbbo	&r18, r14, 0, COPY_CHUNK
	add	r15, r15, COPY_CHUNK
	add	r14, r14, COPY_CHUNK
	sub	r16, r16, COPY_CHUNK
	qble	.Lchunk, r16, COPY_CHUNK	/* len >= 48 */
.Ltail:
	qbeq	.Ldone, r16, 0
	mov	r0.b0, r16.b0
	lbbo	&r18, r15, 0, r0.b0
	sbbo	&r18, r14, 0, r0.b0
.Ldone:
	ret
	.size	prukit_ocp_copy, . - prukit_ocp_copy
