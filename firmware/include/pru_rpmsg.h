/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: <pru_rpmsg.h>, the rpmsg API of TI's PRU Software Support Package
 * (what the PRU Cookbook's rpmsg examples call), on top of prukit's own
 * rpmsg library.  Firmware that lists "pru_rpmsg.c ocp_copy.S" in its
 * fw-lib-srcs gets:
 *
 *	pru_rpmsg_init(&transport, &resourceTable.rpmsg_vring0,
 *		       &resourceTable.rpmsg_vring1, TO_ARM_HOST, FROM_ARM_HOST);
 *	while (pru_rpmsg_channel(RPMSG_NS_CREATE, &transport, CHAN_NAME,
 *				 CHAN_DESC, CHAN_PORT) != PRU_RPMSG_SUCCESS)
 *		;
 *	... pru_rpmsg_receive(&transport, &src, &dst, payload, &len) ...
 *	... pru_rpmsg_send(&transport, dst, src, payload, len) ...
 *
 * with the names, arguments and return values of the support package.  The
 * differences, all on purpose (Documentation/firmware-rpmsg.rst has them in
 * full, with the edits that port a Cookbook program to pru-gcc):
 *
 *  - pru_rpmsg_channel() announces the 40-byte name service message, which
 *    every kernel accepts; desc is not sent (the support package's older
 *    72-byte message, which carries it, is refused by mainline Linux,
 *    "malformed ns msg (72)", unless prukit_pru converts it).  The later
 *    form without desc, pru_rpmsg_channel(flags, transport, name, port),
 *    works too.
 *  - The events must be this core's: 16 (to the ARM) and 17 (from the ARM)
 *    on PRU0, 18 and 19 on PRU1; others give PRU_RPMSG_INVALID_EVENT.
 *  - pru_rpmsg_init() waits for VIRTIO_CONFIG_S_DRIVER_OK itself (programs
 *    that wait first lose nothing) and enables the OCP master port.
 *  - Malformed buffers from Linux are given back and skipped: receive
 *    returns the next good message, or PRU_RPMSG_NO_BUF_AVAILABLE.
 *  - If Linux resets the vdev (it does before it stops the core), nothing in
 *    ARM memory is touched any more; the call that sees it waits for Linux
 *    to set the vdev up again, re-announces the channel and returns
 *    PRU_RPMSG_LINK_RESET.
 */
#ifndef PRUKIT_COMPAT_PRU_RPMSG_H
#define PRUKIT_COMPAT_PRU_RPMSG_H

#include <stdint.h>

#include <prukit/rpmsg.h>
#include <pru_virtqueue.h>
#include <rsc_types.h>

#define PRU_RPMSG_NO_KICK		1
#define PRU_RPMSG_SUCCESS		0
#define PRU_RPMSG_NO_BUF_AVAILABLE	(-1)	/* nothing received / no buffer to send */
#define PRU_RPMSG_BUF_TOO_SMALL		(-2)	/* send: len > RPMSG_MESSAGE_SIZE */
#define PRU_RPMSG_INVALID_HEAD		(-3)	/* Linux's ring index is out of range */
#define PRU_RPMSG_INVALID_EVENT		(-4)	/* init: not this core's events */
/* prukit's additions */
#define PRU_RPMSG_LINK_RESET		(-5)	/* Linux reset the vdev; re-announced */
#define PRU_RPMSG_INVALID_VRING		(-6)	/* init: the table's vrings are unusable */

#define MIN_VALID_EVENT			16
#define MAX_VALID_EVENT			31

#define RPMSG_NAME_SIZE			32
#define RPMSG_BUF_SIZE			512	/* header included */
#define RPMSG_HEADER_SIZE		16
#define RPMSG_MESSAGE_SIZE		496	/* the largest payload */

enum pru_rpmsg_ns_flags {
	RPMSG_NS_CREATE = 0,
	RPMSG_NS_DESTROY = 1,
};

/*
 * What the support package keeps in it (two virtqueues), and prukit's
 * state: the rings, counters (struct prukit_rpmsg_stats) and the channel
 * announced, which is announced again after a reset.
 */
struct pru_rpmsg_transport {
	struct pru_virtqueue virtqueue0;	/* PRU -> ARM */
	struct pru_virtqueue virtqueue1;	/* ARM -> PRU */
	struct prukit_rpmsg rpmsg;
	struct prukit_rpmsg_ns_msg ns;
};

/*
 * Set up transport for the vdev whose two vrings are vring0 and vring1 (in
 * the program's resource table, where they follow the vdev entry).  Waits
 * for DRIVER_OK.  PRU_RPMSG_SUCCESS, PRU_RPMSG_INVALID_EVENT, or
 * PRU_RPMSG_INVALID_VRING; after either error every other call returns
 * PRU_RPMSG_INVALID_VRING without touching ARM memory.  (Vrings that turn
 * unusable after a later reset give PRU_RPMSG_LINK_RESET instead, on every
 * call, until Linux sets the vdev up anew.)
 */
int16_t pru_rpmsg_init(struct pru_rpmsg_transport *transport,
		       struct fw_rsc_vdev_vring *vring0,
		       struct fw_rsc_vdev_vring *vring1,
		       uint32_t to_arm_event, uint32_t from_arm_event);

/*
 * The next message: payload (at most RPMSG_MESSAGE_SIZE bytes) to data, its
 * sender, its destination and its length.  PRU_RPMSG_SUCCESS,
 * PRU_RPMSG_NO_BUF_AVAILABLE (none waiting), PRU_RPMSG_INVALID_HEAD or
 * PRU_RPMSG_LINK_RESET.
 */
int16_t pru_rpmsg_receive(struct pru_rpmsg_transport *transport, uint16_t *src,
			  uint16_t *dst, void *data, uint16_t *len);

/*
 * Send len bytes from src to dst.  PRU_RPMSG_SUCCESS,
 * PRU_RPMSG_NO_BUF_AVAILABLE (Linux has no free buffer: try again),
 * PRU_RPMSG_BUF_TOO_SMALL, PRU_RPMSG_INVALID_HEAD or PRU_RPMSG_LINK_RESET.
 */
int16_t pru_rpmsg_send(struct pru_rpmsg_transport *transport, uint32_t src,
		       uint32_t dst, const void *data, uint16_t len);

/*
 * Announce (RPMSG_NS_CREATE) or withdraw (RPMSG_NS_DESTROY) channel name at
 * address port, in the 40-byte form; desc is accepted and not sent.  The
 * same return values as pru_rpmsg_send().
 */
int16_t pru_rpmsg_channel(enum pru_rpmsg_ns_flags flags,
			  struct pru_rpmsg_transport *transport, const char *name,
			  const char *desc, int32_t port);

/* The support package's later pru_rpmsg_channel(flags, transport, name, port) */
static inline int16_t prukit_pru_rpmsg_channel4(enum pru_rpmsg_ns_flags flags,
						struct pru_rpmsg_transport *transport,
						const char *name, int32_t port)
{
	return pru_rpmsg_channel(flags, transport, name, "", port);
}

/* Either form: five arguments call the function, four the one above. */
#define PRUKIT_PRU_RPMSG_PICK(a, b, c, d, e, f, ...)	f
#define pru_rpmsg_channel(...)						\
	PRUKIT_PRU_RPMSG_PICK(__VA_ARGS__, pru_rpmsg_channel,		\
			      prukit_pru_rpmsg_channel4, 0)(__VA_ARGS__)

#endif /* PRUKIT_COMPAT_PRU_RPMSG_H */
