/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: <pru_virtqueue.h> for PRU programs written against TI's PRU
 * Software Support Package: the names of its virtqueue layer that the rpmsg
 * API (<pru_rpmsg.h>) uses - struct pru_virtqueue, the two members of
 * struct pru_rpmsg_transport, and the PRU_VIRTQUEUE_* return values.
 *
 * The rings themselves are run by prukit's library (<prukit/rpmsg.h>, kept
 * in pru_rpmsg_transport.rpmsg); a struct pru_virtqueue here only records
 * what pru_rpmsg_init() was given.  The support package's
 * pru_virtqueue_init/get_avail_buf/add_used_buf/kick() are not provided:
 * they hand out raw pointers into ARM memory, which prukit's library never
 * does (see Documentation/firmware-rpmsg.rst).
 */
#ifndef PRUKIT_COMPAT_PRU_VIRTQUEUE_H
#define PRUKIT_COMPAT_PRU_VIRTQUEUE_H

#include <stdint.h>

#include <rsc_types.h>

#define PRU_VIRTQUEUE_NO_KICK		1
#define PRU_VIRTQUEUE_SUCCESS		0
#define PRU_VIRTQUEUE_NO_BUF_AVAILABLE	(-1)
#define PRU_VIRTQUEUE_INVALID_HEAD	(-2)

struct pru_virtqueue {
	uint32_t id;			/* the vring's notifyid */
	uint32_t to_arm_event;		/* PRU -> ARM system event */
	uint32_t from_arm_event;	/* ARM -> PRU system event */
};

#endif /* PRUKIT_COMPAT_PRU_VIRTQUEUE_H */
