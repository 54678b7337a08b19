// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * prukit: the rpmsg API of TI's PRU Software Support Package (<pru_rpmsg.h>)
 * on top of prukit's own library, for programs such as the PRU Cookbook's
 * rpmsg examples.  A firmware lists "pru_rpmsg.c ocp_copy.S" in its
 * fw-lib-srcs (not rpmsg.c: this file builds it) and brings its own resource
 * table and .pru_irq_map, as those programs do (resource_table_0.h).
 *
 * Written from the API's documented names, arguments and return values; no
 * code from the support package.  Everything below only translates: the
 * rings, the checks and the name service message are prukit's, so such a
 * program announces the 40-byte name service message every kernel accepts,
 * and stops touching ARM memory the moment Linux resets the vdev.
 */

/* The program brings its own resource table and interrupt map. */
#define PRUKIT_RPMSG_EXTERNAL_TABLE 1
#include "rpmsg.c"

#include <string.h>

#include <pru_rpmsg.h>

/* The program's table and prukit's view of it must be the same bytes. */
static_assert(sizeof(struct fw_rsc_vdev_vring) == sizeof(struct prukit_rsc_vdev_vring),
	      "vring entry layout");
static_assert(offsetof(struct fw_rsc_vdev_vring, notifyid) ==
	      offsetof(struct prukit_rsc_vdev_vring, notifyid), "vring entry layout");
static_assert(offsetof(struct fw_rsc_vdev, status) == offsetof(struct prukit_rsc_vdev, status),
	      "vdev entry layout");
static_assert(offsetof(struct fw_rsc_vdev, gfeatures) ==
	      offsetof(struct prukit_rsc_vdev, gfeatures), "vdev entry layout");
static_assert(offsetof(struct fw_rsc_vdev, vring) == offsetof(struct prukit_rsc_vdev, vring),
	      "vdev entry layout");
static_assert(sizeof(((struct pru_rpmsg_transport *)0)->ns) == 40,
	      "the name service message prukit sends is 40 bytes");

static int16_t pru_rpmsg_ret(int ret)
{
	switch (ret) {
	case 0:
		return PRU_RPMSG_SUCCESS;
	case -EAGAIN:
		return PRU_RPMSG_NO_BUF_AVAILABLE;
	case -EMSGSIZE:
		return PRU_RPMSG_BUF_TOO_SMALL;
	case -ECONNRESET:
		return PRU_RPMSG_LINK_RESET;
	case -EINVAL:
		return PRU_RPMSG_INVALID_VRING;
	default:		/* -EIO: Linux's ring index is out of range */
		return PRU_RPMSG_INVALID_HEAD;
	}
}

/*
 * Did pru_rpmsg_init() succeed?  If not (rpmsg.vdev left NULL), nothing may
 * be touched.  Vrings that turn unusable after a reset are the library's
 * business: it finds that out again on every call, touching nothing.
 */
static int transport_ready(struct pru_rpmsg_transport *transport)
{
	return !!transport->rpmsg.vdev;
}

int16_t pru_rpmsg_init(struct pru_rpmsg_transport *transport,
		       struct fw_rsc_vdev_vring *vring0,
		       struct fw_rsc_vdev_vring *vring1,
		       uint32_t to_arm_event, uint32_t from_arm_event)
{
	/* In every resource table the vrings follow their vdev entry. */
	struct prukit_rsc_vdev *vdev = (struct prukit_rsc_vdev *)
		((char *)vring0 - offsetof(struct prukit_rsc_vdev, vring));
	int ret;

	memset(transport, 0, sizeof(*transport));
	transport->virtqueue0.id = vring0->notifyid;
	transport->virtqueue0.to_arm_event = to_arm_event;
	transport->virtqueue0.from_arm_event = from_arm_event;
	transport->virtqueue1.id = vring1->notifyid;
	transport->virtqueue1.to_arm_event = to_arm_event;
	transport->virtqueue1.from_arm_event = from_arm_event;
	/*
	 * The events are fixed by the device tree and prukit's interrupt map
	 * for this core (PRUKIT_RPMSG_EVT_*); the library kicks and polls
	 * those.
	 */
	if (to_arm_event != PRUKIT_RPMSG_EVT_TO_ARM ||
	    from_arm_event != PRUKIT_RPMSG_EVT_FROM_ARM)
		return PRU_RPMSG_INVALID_EVENT;
	if (vring1 != vring0 + 1 || vdev->type != PRUKIT_RSC_VDEV ||
	    vdev->id != PRUKIT_VIRTIO_ID_RPMSG) {
		transport->rpmsg.stats.status |= PRUKIT_RPMSG_ST_BAD_RSC;
		return PRU_RPMSG_INVALID_VRING;
	}
	/* no announcement yet: that is pru_rpmsg_channel()'s */
	ret = rpmsg_attach(&transport->rpmsg, vdev, NULL);
	if (ret)
		transport->rpmsg.vdev = NULL;
	return pru_rpmsg_ret(ret);
}

int16_t pru_rpmsg_receive(struct pru_rpmsg_transport *transport, uint16_t *src,
			  uint16_t *dst, void *data, uint16_t *len)
{
	unsigned int tries;
	uint32_t from;
	int ret;

	if (!transport_ready(transport))
		return PRU_RPMSG_INVALID_VRING;
	/* Malformed buffers are given back by recv; skip to the next message. */
	for (tries = 0; tries <= PRUKIT_VRING_NUM; tries++) {
		ret = prukit_rpmsg_recv(&transport->rpmsg, data, len, &from);
		if (ret != -EBADMSG)
			break;
	}
	if (ret == -EBADMSG)
		ret = -EAGAIN;
	if (!ret) {
		*src = from;
		*dst = transport->rpmsg.dst;
	}
	return pru_rpmsg_ret(ret);
}

int16_t pru_rpmsg_send(struct pru_rpmsg_transport *transport, uint32_t src,
		       uint32_t dst, const void *data, uint16_t len)
{
	if (!transport_ready(transport))
		return PRU_RPMSG_INVALID_VRING;
	/* prukit_rpmsg_send() sends from rpmsg.port */
	transport->rpmsg.port = src;
	return pru_rpmsg_ret(prukit_rpmsg_send(&transport->rpmsg, dst, data, len));
}

#ifdef PRUKIT_SSP_NS_DESC
/*
 * Built with -DPRUKIT_SSP_NS_DESC (prukit's test firmware only): announce
 * with the 72-byte message of the support package's releases for TI's 4.x
 * kernels, desc included, as firmware built with them does, so that the
 * kernel side can be tested with it.  It is not announced again after a
 * vdev reset: neither was it by that library.
 */
struct prukit_ssp_ns_desc_msg {
	char name[PRUKIT_RPMSG_NAME_SIZE];
	char desc[PRUKIT_RPMSG_NAME_SIZE];
	uint32_t addr;
	uint32_t flags;
};

static_assert(sizeof(struct prukit_ssp_ns_desc_msg) == 72, "the 72-byte name service message");

static int ssp_ns_desc_send(struct prukit_rpmsg *rp, const char *name, const char *desc,
			    uint32_t port, uint32_t flags)
{
	struct prukit_ssp_ns_desc_msg msg;

	memset(&msg, 0, sizeof(msg));
	strncpy(msg.name, name, sizeof(msg.name) - 1);
	strncpy(msg.desc, desc, sizeof(msg.desc) - 1);
	msg.addr = port;
	msg.flags = flags;
	rp->port = port;
	rp->ns = NULL;
	return prukit_rpmsg_send(rp, PRUKIT_RPMSG_NS_ADDR, &msg, sizeof(msg));
}
#endif

/* Parenthesised: pru_rpmsg_channel is also a macro (both argument lists). */
int16_t (pru_rpmsg_channel)(enum pru_rpmsg_ns_flags flags,
			    struct pru_rpmsg_transport *transport, const char *name,
			    const char *desc, int32_t port)
{
	struct prukit_rpmsg *rp = &transport->rpmsg;
	struct prukit_rpmsg_ns_msg msg;
	unsigned int i;
	int ret;

	if (!transport_ready(transport))
		return PRU_RPMSG_INVALID_VRING;
#ifdef PRUKIT_SSP_NS_DESC
	return pru_rpmsg_ret(ssp_ns_desc_send(rp, name, desc, port, flags));
#endif
	(void)desc;		/* only the 72-byte form carries it */
	/* at most 32 bytes, the rest zero (no terminator if it is 32 long) */
	for (i = 0; i < sizeof(msg.name); i++) {
		msg.name[i] = *name;
		if (*name)
			name++;
	}
	msg.addr = port;
	msg.flags = flags;
	rp->port = port;
	ret = prukit_rpmsg_send(rp, PRUKIT_RPMSG_NS_ADDR, &msg, sizeof(msg));
	if (!ret) {
		/* What is announced again after a reset, if anything */
		if (flags == RPMSG_NS_CREATE) {
			transport->ns = msg;
			rp->ns = &transport->ns;
			rp->stats.status |= PRUKIT_RPMSG_ST_ANNOUNCED;
		} else {
			rp->ns = NULL;
			rp->stats.status &= ~PRUKIT_RPMSG_ST_ANNOUNCED;
		}
	}
	return pru_rpmsg_ret(ret);
}
