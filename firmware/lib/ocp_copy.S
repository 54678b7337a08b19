/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: void prukit_ocp_copy(uint32_t dst, uint32_t src, uint32_t len)
 *	   int prukit_ocp_copy_live(uint32_t dst, uint32_t src, uint32_t len,
 *				    const volatile uint8_t *status)
 *
 * Copy len bytes from src to dst, both addresses the core can reach: its data
 * RAM, the shared RAM or anything behind the OCP master port (DDR).  Moves 48
 * bytes per LBBO/SBBO pair through r18..r29, then the rest in one burst whose
 * length is in r0.b0.  A read from DDR costs its latency (~43 cycles) once
 * per burst instead of once per word; writes are posted.
 *
 * prukit_ocp_copy_live() is for writes into memory that Linux may take back
 * (rpmsg buffers): right before each burst's store it loads the byte at
 * status (a vdev status byte in data RAM, 3 cycles) and, if bit 2
 * (VIRTIO_CONFIG_S_DRIVER_OK) is clear, stops without storing and returns
 * 1; it returns 0 when everything was copied.  4 cycles per burst more.
 *
 * GCC's PRU ABI: arguments in r14, r15, r16, r17, the result in r14; r0, r1
 * and r14..r29 belong to the caller, so nothing needs saving.  Overlapping
 * ranges are not handled.
 */

#define COPY_CHUNK	48
#define DRIVER_OK_BIT	2		/* VIRTIO_CONFIG_S_DRIVER_OK */

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

	.section .text.prukit_ocp_copy_live, "ax", @progbits
	.global	prukit_ocp_copy_live
	.type	prukit_ocp_copy_live, @function
prukit_ocp_copy_live:
	qbgt	.Llive_tail, r16, COPY_CHUNK	/* len < 48 */
.Llive_chunk:
	lbbo	&r18, r15, 0, COPY_CHUNK
	lbbo	&r1.b0, r17, 0, 1		/* the status, right before the store */
	qbbc	.Llive_gone, r1.b0, DRIVER_OK_BIT
	sbbo	&r18, r14, 0, COPY_CHUNK
	add	r15, r15, COPY_CHUNK
	add	r14, r14, COPY_CHUNK
	sub	r16, r16, COPY_CHUNK
	qble	.Llive_chunk, r16, COPY_CHUNK	/* len >= 48 */
.Llive_tail:
	qbeq	.Llive_done, r16, 0
	mov	r0.b0, r16.b0
	lbbo	&r18, r15, 0, r0.b0
	lbbo	&r1.b0, r17, 0, 1
	qbbc	.Llive_gone, r1.b0, DRIVER_OK_BIT
	sbbo	&r18, r14, 0, r0.b0
.Llive_done:
	ldi	r14, 0
	ret
.Llive_gone:
	ldi	r14, 1
	ret
	.size	prukit_ocp_copy_live, . - prukit_ocp_copy_live
