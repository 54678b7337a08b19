/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: the PRU side of rpmsg (virtio-rpmsg over remoteproc).
 *
 * Firmware that lists rpmsg.c in fw-lib-srcs gets:
 *
 *  - the resource table (one rpmsg vdev with two vrings of 16 buffers) as
 *    prukit_resource_table: do not use PRUKIT_RESOURCE_TABLE_EMPTY() too (the
 *    symbol would be defined twice and the link fails, as it should);
 *  - the .pru_irq_map of its core, ARM -> PRU event first (PRU0: 17 ->
 *    channel 0 -> host 0 = R31 bit 30, then 16 -> channel 2 -> host 2 to the
 *    ARM; PRU1: 19 -> 1 -> 1 = R31 bit 31, then 18 -> 3 -> 3);
 *  - the functions below.  Everything is polled: no interrupts, no
 *    allocation, bounded work per call.
 *
 * Usage:
 *
 *	static struct prukit_rpmsg rpmsg;
 *	static uint8_t buf[RPMSG_PRU_MAX_PAYLOAD];
 *
 *	if (prukit_rpmsg_init(&rpmsg))		// waits for Linux, announces
 *		pru_halt();			// "rpmsg-pru" at our port
 *	for (;;) {
 *		uint16_t len;
 *		uint32_t src;
 *		int ret = prukit_rpmsg_recv(&rpmsg, buf, &len, &src);
 *
 *		if (ret == -EAGAIN)
 *			prukit_rpmsg_wait(&rpmsg);	// until the ARM kicks
 *		else if (!ret)
 *			...use buf[0..len)...
 *	}
 *
 * The vrings live in the ARM's RAM; the core reaches them through the OCP
 * master port at the DMA addresses Linux wrote into the loaded copy of the
 * resource table (which is in this core's data RAM, hence volatile).
 * Nothing a buffer descriptor or message header says is followed unless it
 * is in range: see Documentation/firmware-rpmsg.rst for the exact rules.
 *
 * Linux may take the rings away at any time: remoteproc resets the vdev
 * (its status byte in the resource table goes to 0) and frees the buffers
 * and rings before it stops the core.  The library reads the status byte
 * right before it claims a buffer and right before every write into ARM
 * memory, and touches nothing there once DRIVER_OK is gone; it then waits
 * for Linux to come back, sets the rings up again and re-announces, as at
 * start (the call that saw it returns -ECONNRESET).
 * Layouts are the virtio legacy split ring (little endian) and the remoteproc
 * resource table format of include/linux/remoteproc.h; the names here are
 * our own.
 */
#ifndef _PRUKIT_RPMSG_H
#define _PRUKIT_RPMSG_H

#include <assert.h>
#include <stdint.h>

#include <prukit/ocp.h>

#include <rpmsg_pru_proto.h>

/* Resource table (remoteproc) */
#define PRUKIT_RSC_ADDR_ANY		0xffffffffu	/* FW_RSC_ADDR_ANY */
#define PRUKIT_VIRTIO_ID_RPMSG		7
#define PRUKIT_VIRTIO_RPMSG_F_NS	0		/* feature bit: name service */
#define PRUKIT_VIRTIO_S_ACKNOWLEDGE	1
#define PRUKIT_VIRTIO_S_DRIVER		2
#define PRUKIT_VIRTIO_S_DRIVER_OK	4

/*
 * Set by the firmware in the vdev's gfeatures once it has set the rings up
 * for the session Linux started.  Linux writes gfeatures (without this bit)
 * whenever a virtio driver binds to the vdev and never reads it back, so a
 * clear bit means a session the firmware did not set up: one that began
 * while it was not looking, after a reset it did not see.
 */
#define PRUKIT_RPMSG_GF_SESSION		(1u << 31)

/* Split virtqueue */
#define PRUKIT_VRING_NUM		16	/* buffers per vring, a power of two */
#define PRUKIT_VRING_ALIGN		16	/* alignment of the used ring */
#define PRUKIT_VRING_DESC_F_NEXT	1
#define PRUKIT_VRING_DESC_F_WRITE	2
#define PRUKIT_VRING_AVAIL_F_NO_INTERRUPT 1
#define PRUKIT_VRING_USED_F_NO_NOTIFY	1

/* vring 0 carries PRU -> ARM messages, vring 1 ARM -> PRU */
#define PRUKIT_RPMSG_VQ_TX		0
#define PRUKIT_RPMSG_VQ_RX		1

/* rpmsg */
#define PRUKIT_RPMSG_NS_ADDR		53	/* Linux's name service endpoint */
#define PRUKIT_RPMSG_NS_CREATE		0
#define PRUKIT_RPMSG_NS_DESTROY		1
#define PRUKIT_RPMSG_NAME_SIZE		32
#define PRUKIT_RPMSG_ADDR_ANY		0xffffffffu

/* Anything the core addresses below this stays inside the PRU-ICSS. */
#define PRUKIT_RPMSG_OCP_MIN		0x00080000u

/*
 * This core's conventions (rpmsg_pru_proto.h) and INTC routing, which must
 * match the device tree: PRU0 16 -> channel 2 -> host 2, 17 -> 0 -> 0;
 * PRU1 18 -> 3 -> 3, 19 -> 1 -> 1.
 */
#if defined(PRUKIT_PRU_CORE) && PRUKIT_PRU_CORE == 1
#define PRUKIT_RPMSG_PORT		RPMSG_PRU1_PORT
#define PRUKIT_RPMSG_EVT_TO_ARM		RPMSG_PRU1_EVT_TO_ARM
#define PRUKIT_RPMSG_EVT_FROM_ARM	RPMSG_PRU1_EVT_FROM_ARM
#define PRUKIT_RPMSG_CHAN_TO_ARM	3
#define PRUKIT_RPMSG_HOST_TO_ARM	3
#define PRUKIT_RPMSG_CHAN_FROM_ARM	1
#define PRUKIT_RPMSG_HOST_FROM_ARM	1
#define PRUKIT_RPMSG_R31_KICK		(1u << 31)
#elif defined(PRUKIT_PRU_CORE) && PRUKIT_PRU_CORE == 0
#define PRUKIT_RPMSG_PORT		RPMSG_PRU0_PORT
#define PRUKIT_RPMSG_EVT_TO_ARM		RPMSG_PRU0_EVT_TO_ARM
#define PRUKIT_RPMSG_EVT_FROM_ARM	RPMSG_PRU0_EVT_FROM_ARM
#define PRUKIT_RPMSG_CHAN_TO_ARM	2
#define PRUKIT_RPMSG_HOST_TO_ARM	2
#define PRUKIT_RPMSG_CHAN_FROM_ARM	0
#define PRUKIT_RPMSG_HOST_FROM_ARM	0
#define PRUKIT_RPMSG_R31_KICK		(1u << 30)
#endif

struct prukit_rsc_vdev_vring {
	uint32_t da;		/* DMA address, written by Linux */
	uint32_t align;
	uint32_t num;
	uint32_t notifyid;	/* written by Linux */
	uint32_t pa;
};

struct prukit_rsc_vdev {
	uint32_t type;		/* PRUKIT_RSC_VDEV */
	uint32_t id;		/* PRUKIT_VIRTIO_ID_RPMSG */
	uint32_t notifyid;
	uint32_t dfeatures;
	uint32_t gfeatures;	/* written by Linux */
	uint32_t config_len;
	uint8_t status;		/* written by Linux */
	uint8_t num_of_vrings;
	uint8_t reserved[2];
	struct prukit_rsc_vdev_vring vring[2];
};

/* The table of a firmware with rpmsg: header, one offset, the vdev. */
struct prukit_rpmsg_rsc_table {
	uint32_t ver;
	uint32_t num;
	uint32_t reserved[2];
	uint32_t offset[1];
	struct prukit_rsc_vdev vdev;
};

struct prukit_vring_desc {
	uint32_t addr_lo;	/* u64 addr, little endian */
	uint32_t addr_hi;
	uint32_t len;
	uint16_t flags;
	uint16_t next;
};

struct prukit_vring_used_elem {
	uint32_t id;
	uint32_t len;
};

/* Byte offsets inside a vring of PRUKIT_VRING_NUM entries */
#define PRUKIT_VRING_DESC_OFF		0
#define PRUKIT_VRING_AVAIL_OFF		(16 * PRUKIT_VRING_NUM)
#define PRUKIT_VRING_AVAIL_FLAGS	(PRUKIT_VRING_AVAIL_OFF + 0)
#define PRUKIT_VRING_AVAIL_IDX		(PRUKIT_VRING_AVAIL_OFF + 2)
#define PRUKIT_VRING_AVAIL_RING(i)	(PRUKIT_VRING_AVAIL_OFF + 4 + 2 * (i))
#define PRUKIT_VRING_USED_OFF						\
	((PRUKIT_VRING_AVAIL_OFF + 2 * (3 + PRUKIT_VRING_NUM) + PRUKIT_VRING_ALIGN - 1) & \
	 ~(PRUKIT_VRING_ALIGN - 1))
#define PRUKIT_VRING_USED_FLAGS		(PRUKIT_VRING_USED_OFF + 0)
#define PRUKIT_VRING_USED_IDX		(PRUKIT_VRING_USED_OFF + 2)
#define PRUKIT_VRING_USED_RING(i)	(PRUKIT_VRING_USED_OFF + 4 + 8 * (i))
#define PRUKIT_VRING_SIZE		(PRUKIT_VRING_USED_RING(PRUKIT_VRING_NUM) + 2)

struct prukit_rpmsg_hdr {
	uint32_t src;
	uint32_t dst;
	uint32_t reserved;
	uint16_t len;
	uint16_t flags;
};

struct prukit_rpmsg_ns_msg {
	char name[PRUKIT_RPMSG_NAME_SIZE];
	uint32_t addr;
	uint32_t flags;
};

static_assert(sizeof(struct prukit_rsc_vdev) == 68, "fw_rsc_vdev with two vrings is 68 bytes");
static_assert(sizeof(struct prukit_rpmsg_rsc_table) == 88, "rpmsg resource table is 88 bytes");
static_assert(sizeof(struct prukit_vring_desc) == 16, "vring_desc is 16 bytes");
static_assert(sizeof(struct prukit_rpmsg_hdr) == RPMSG_PRU_HDR_SIZE, "rpmsg header size");
static_assert(sizeof(struct prukit_rpmsg_ns_msg) == 40, "name service message is 40 bytes");
static_assert(PRUKIT_VRING_USED_OFF == 304, "vring layout for num 16, align 16");

/* prukit_rpmsg_stats.status bits: what went wrong at least once */
#define PRUKIT_RPMSG_ST_BAD_RSC		(1u << 0)	/* unusable resource table */
#define PRUKIT_RPMSG_ST_RING_IDX	(1u << 1)	/* avail idx ran > num ahead */
#define PRUKIT_RPMSG_ST_DESC_IDX	(1u << 2)	/* descriptor index >= num */
#define PRUKIT_RPMSG_ST_DESC		(1u << 3)	/* buffer address/length unusable */
#define PRUKIT_RPMSG_ST_MSG_LEN		(1u << 4)	/* header len > buffer or 496 */
#define PRUKIT_RPMSG_ST_RESET		(1u << 5)	/* Linux reset the vdev */
#define PRUKIT_RPMSG_ST_READY		(1u << 8)	/* DRIVER_OK seen, rings valid */
#define PRUKIT_RPMSG_ST_ANNOUNCED	(1u << 9)	/* name service message sent */

/*
 * Counters, first in struct prukit_rpmsg so that a debugger (or a test)
 * finds them at the address of the firmware's variable.  Each err_* counts
 * refusals: a ring index refused stays refused (and is counted again) on
 * every call until Linux fixes it.
 */
struct prukit_rpmsg_stats {
	uint32_t status;	/* PRUKIT_RPMSG_ST_* */
	uint32_t rx_msgs;	/* messages received and returned to Linux */
	uint32_t tx_msgs;	/* messages sent, name service included */
	uint32_t kicks_in;	/* ARM -> PRU events taken */
	uint32_t kicks_out;	/* PRU -> ARM events strobed */
	uint32_t err_ring_idx;	/* avail->idx more than num ahead of us */
	uint32_t err_desc_idx;	/* avail ring entry >= num */
	uint32_t err_desc;	/* buffer not in OCP space, wraps, too short */
	uint32_t err_msg_len;	/* received header len > buffer or > 496 */
	uint32_t resets;	/* sessions lost: DRIVER_OK gone, or a new session */
};

struct prukit_vring {
	uint32_t base;		/* da of the ring (OCP address) */
	uint16_t last_avail;	/* next avail entry to take */
	uint16_t avail_idx;	/* avail->idx as last read */
	uint16_t used_idx;	/* our used->idx */
	uint16_t avail_flags;	/* avail->flags as last read */
};

struct prukit_rpmsg {
	struct prukit_rpmsg_stats stats;
	struct prukit_vring vq[2];	/* PRUKIT_RPMSG_VQ_TX, _RX */
	uint32_t port;			/* our address: the src of what we send */
	uint32_t peer;			/* src of the first received message */
	uint32_t dst;			/* dst of the last received message */
	/* the vdev served: status, gfeatures and vrings in the resource table */
	volatile struct prukit_rsc_vdev *vdev;
	/* announced at start and again after a reset; NULL: nothing */
	const struct prukit_rpmsg_ns_msg *ns;
	uint32_t starting;		/* inside the start-up sequence */
};

/*
 * The resource table is rpmsg.c's prukit_resource_table (a struct
 * prukit_rpmsg_rsc_table in .resource_table); it is not declared here, so
 * that firmware which includes this header but not the library can have
 * PRUKIT_RESOURCE_TABLE_EMPTY().
 */

/*
 * Enable the OCP master port, wait until Linux has set DRIVER_OK, mark the
 * session (PRUKIT_RPMSG_GF_SESSION), check the vrings and announce
 * "rpmsg-pru" at this core's port (waiting for a kick while Linux has no
 * buffer, or its ring index is out of range).  Returns 0, or -EINVAL (and
 * PRUKIT_RPMSG_ST_BAD_RSC) if the table holds unusable vrings: then nothing
 * else must be called.
 *
 * After a reset (DRIVER_OK gone, or a session not marked, see above) recv,
 * send and wait do the same again themselves - wait for DRIVER_OK, set the
 * rings up, announce - and only then return -ECONNRESET.  If the vrings have
 * become unusable, every such call finds that out again and returns
 * -ECONNRESET, touching nothing in ARM memory, until Linux sets the vdev up
 * anew.
 */
int prukit_rpmsg_init(struct prukit_rpmsg *rp);

/*
 * If the ARM has kicked (R31 host bit), clear the event in the INTC and
 * return 1, else 0.  Clearing before looking at the rings means that a kick
 * arriving meanwhile stays pending: nothing is lost.
 */
int prukit_rpmsg_kicked(struct prukit_rpmsg *rp);

/*
 * Busy-wait for a kick (prukit_rpmsg_kicked() in a loop), watching the vdev
 * meanwhile: if Linux resets it, wait for it to come back, set the rings up
 * again, re-announce and return -ECONNRESET; else 0.
 */
int prukit_rpmsg_wait(struct prukit_rpmsg *rp);

/*
 * Take the next message from vring 1: copy its payload (at most
 * RPMSG_PRU_MAX_PAYLOAD bytes) to data, its length to *len and its sender
 * to *src, give the buffer back to Linux and kick the ARM unless it asked not
 * to be.  Returns 0; -EAGAIN if there is none; -EBADMSG if the buffer was
 * malformed (given back unread, counted; call again for the next one);
 * -EIO if the ring's index is out of range (nothing taken, counted);
 * -ECONNRESET if Linux had reset the vdev (nothing received; the rings have
 * been set up again and the channel re-announced, rp->peer forgotten).
 */
int prukit_rpmsg_recv(struct prukit_rpmsg *rp, void *data, uint16_t *len, uint32_t *src);

/*
 * Send len bytes (1..RPMSG_PRU_MAX_PAYLOAD; 0 is allowed too) from data to
 * address dst, from this core's port, in the next free buffer of vring 0,
 * and kick the ARM unless it asked not to be.  Malformed buffers on the way
 * are skipped and counted.  Returns 0; -EAGAIN if Linux has no free buffer
 * (wait for a kick, try again); -EMSGSIZE; -EIO and -ECONNRESET as
 * prukit_rpmsg_recv() (after -ECONNRESET the message was not sent, and dst
 * belonged to the session that is gone).
 */
int prukit_rpmsg_send(struct prukit_rpmsg *rp, uint32_t dst, const void *data, uint16_t len);

#endif /* _PRUKIT_RPMSG_H */
