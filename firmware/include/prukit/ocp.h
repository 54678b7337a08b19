/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: copying to and from memory behind the OCP master port (the ARM's
 * RAM: DMA buffers, vrings).  The port must be enabled first:
 * pruss_ocp_master_enable() in <am335x/pruss_cfg.h>.  Implemented in
 * lib/ocp_copy.S (fw-lib-srcs := ocp_copy.S).
 */
#ifndef _PRUKIT_OCP_H
#define _PRUKIT_OCP_H

#include <stdint.h>

/*
 * Copy len bytes between any two addresses the core can reach (data RAM,
 * shared RAM, OCP) in bursts of 48 bytes through r18..r29 (lib/ocp_copy.S).
 * A load from DDR costs its latency once per burst rather than once per word.
 * Prefer the two wrappers, which tell GCC which local object is written or
 * read (it cannot see through an address passed as an integer).
 */
void prukit_ocp_copy(uint32_t dst, uint32_t src, uint32_t len);

/*
 * The same, for writes into ARM memory that Linux may free at any time:
 * before each burst's store, the byte at status (a vdev status in data RAM)
 * is read, and if PRUKIT_VIRTIO_S_DRIVER_OK is clear the copy stops there.
 * Returns 0 if everything was copied, nonzero if it stopped.
 */
int prukit_ocp_copy_live(uint32_t dst, uint32_t src, uint32_t len,
			 const volatile uint8_t *status);

/* OCP (or any) address src -> local object dst */
static inline void prukit_ocp_read(void *dst, uint32_t src, uint32_t len)
{
	/* dst escapes here: the call below may change what it points to */
	__asm__ __volatile__("" : : "r"(dst) : "memory");
	prukit_ocp_copy((uint32_t)(uintptr_t)dst, src, len);
}

/* local object src -> OCP (or any) address dst */
static inline void prukit_ocp_write(uint32_t dst, const void *src, uint32_t len)
{
	/* src escapes here: stores to it must be done before the call */
	__asm__ __volatile__("" : : "r"(src) : "memory");
	prukit_ocp_copy(dst, (uint32_t)(uintptr_t)src, len);
}

/*
 * Return only once every store this core made over the OCP master port has
 * landed.  Stores there are posted: the core goes on at once, and an event
 * it strobes next can reach the ARM before the data does.  A load from the
 * same memory travels behind the stores and returns only after them, so
 * this reads back one word at addr (best the last one written).  Costs one
 * load from there (DDR: 43 cycles or more).  Call it before the event (or
 * the status word in the core's own RAM) that tells Linux the data is there.
 */
static inline void prukit_ocp_flush(uint32_t addr)
{
	(void)*(volatile uint32_t *)(uintptr_t)addr;
}

#endif /* _PRUKIT_OCP_H */
