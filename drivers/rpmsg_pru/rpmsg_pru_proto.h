/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * What rpmsg_pru and PRU firmware agree on.
 *
 * Shared verbatim by the kernel driver and the PRU firmware library.  The
 * transport itself is virtio-rpmsg, whose layout the kernel defines; this
 * header holds only the conventions layered on top of it.
 */
#ifndef RPMSG_PRU_PROTO_H
#define RPMSG_PRU_PROTO_H

/* Channel name the firmware announces; the driver binds only this one. */
#define RPMSG_PRU_CHAN_NAME		"rpmsg-pru"

/* virtio-rpmsg buffers are 512 bytes including the 16-byte message header. */
#define RPMSG_PRU_BUF_SIZE		512
#define RPMSG_PRU_HDR_SIZE		16
#define RPMSG_PRU_MAX_PAYLOAD		(RPMSG_PRU_BUF_SIZE - RPMSG_PRU_HDR_SIZE)

/*
 * Conventional firmware addresses: the device node is /dev/rpmsg_pru<port>.
 * System events: PRU -> ARM (vring kick) and ARM -> PRU, as TI's support
 * package and the PRU Cookbook use them.
 */
#define RPMSG_PRU0_PORT			30
#define RPMSG_PRU0_EVT_TO_ARM		16
#define RPMSG_PRU0_EVT_FROM_ARM		17
#define RPMSG_PRU1_PORT			31
#define RPMSG_PRU1_EVT_TO_ARM		18
#define RPMSG_PRU1_EVT_FROM_ARM		19

#endif /* RPMSG_PRU_PROTO_H */
