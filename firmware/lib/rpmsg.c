// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * prukit: the PRU side of rpmsg (see <prukit/rpmsg.h> and
 * Documentation/firmware-rpmsg.rst).
 *
 * Written from the virtio legacy split ring layout, the remoteproc resource
 * table format and the rpmsg message and name service formats; no code from
 * TI's PRU Software Support Package.
 *
 * The rings are in the ARM's RAM, behind the OCP master port: every load
 * from there costs ~43 cycles, stores are posted.  So the code reads as
 * little as it can (avail flags and idx in one 32-bit load, the descriptor
 * and the message header in one 16-byte burst each, payloads in 48-byte
 * bursts) and never reads the used ring, which only we write.
 */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>

#include <am335x/pruss_cfg.h>
#include <am335x/pruss_intc.h>
#include <prukit/irq_map.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>
#include <prukit/rpmsg.h>

#ifndef PRUKIT_RPMSG_PORT
#error "rpmsg.c is built per core: PRUKIT_PRU_CORE must be 0 or 1"
#endif

#define VRING_MASK	(PRUKIT_VRING_NUM - 1)

struct prukit_rpmsg_rsc_table prukit_resource_table PRUKIT_RSC_SECTION = {
	.ver = PRUKIT_RSC_TABLE_VERSION,
	.num = 1,
	.reserved = { 0, 0 },
	.offset = { offsetof(struct prukit_rpmsg_rsc_table, vdev) },
	.vdev = {
		.type = PRUKIT_RSC_VDEV,
		.id = PRUKIT_VIRTIO_ID_RPMSG,
		.notifyid = 0,
		.dfeatures = 1u << PRUKIT_VIRTIO_RPMSG_F_NS,
		.gfeatures = 0,
		.config_len = 0,
		.status = 0,
		.num_of_vrings = 2,
		.reserved = { 0, 0 },
		.vring = {
			[PRUKIT_RPMSG_VQ_TX] = {
				.da = PRUKIT_RSC_ADDR_ANY,
				.align = PRUKIT_VRING_ALIGN,
				.num = PRUKIT_VRING_NUM,
				.notifyid = 0,
				.pa = 0,
			},
			[PRUKIT_RPMSG_VQ_RX] = {
				.da = PRUKIT_RSC_ADDR_ANY,
				.align = PRUKIT_VRING_ALIGN,
				.num = PRUKIT_VRING_NUM,
				.notifyid = 1,
				.pa = 0,
			},
		},
	},
};

/*
 * The ARM -> PRU event comes first: TI's 5.10 kernels kick by raising the
 * first event of this map.
 */
PRUKIT_IRQ_MAP(PRUKIT_IRQ_EVT(PRUKIT_RPMSG_EVT_FROM_ARM, PRUKIT_RPMSG_CHAN_FROM_ARM,
			      PRUKIT_RPMSG_HOST_FROM_ARM),
	       PRUKIT_IRQ_EVT(PRUKIT_RPMSG_EVT_TO_ARM, PRUKIT_RPMSG_CHAN_TO_ARM,
			      PRUKIT_RPMSG_HOST_TO_ARM));

static const struct prukit_rpmsg_ns_msg prukit_rpmsg_ns = {
	.name = RPMSG_PRU_CHAN_NAME,
	.addr = PRUKIT_RPMSG_PORT,
	.flags = PRUKIT_RPMSG_NS_CREATE,
};

static inline uint32_t ocp_read32(uint32_t addr)
{
	return *(volatile uint32_t *)(uintptr_t)addr;
}

static inline uint16_t ocp_read16(uint32_t addr)
{
	return *(volatile uint16_t *)(uintptr_t)addr;
}

static inline void ocp_write32(uint32_t addr, uint32_t val)
{
	*(volatile uint32_t *)(uintptr_t)addr = val;
}

static inline void ocp_write16(uint32_t addr, uint16_t val)
{
	*(volatile uint16_t *)(uintptr_t)addr = val;
}

static void note(struct prukit_rpmsg *rp, uint32_t *counter, uint32_t status)
{
	(*counter)++;
	rp->stats.status |= status;
}

/* avail->flags (bits 15:0) and avail->idx (bits 31:16) in one load */
static void vq_read_avail(struct prukit_vring *vq)
{
	uint32_t w = ocp_read32(vq->base + PRUKIT_VRING_AVAIL_FLAGS);

	vq->avail_flags = w & 0xffff;
	vq->avail_idx = w >> 16;
}

/*
 * Number of buffers Linux has made available and we have not taken (0..num),
 * or -EIO if its index is more than num ahead of ours: then the ring is not
 * followed, and the index is read again next time.
 */
static int vq_pending(struct prukit_rpmsg *rp, struct prukit_vring *vq)
{
	uint16_t n = vq->avail_idx - vq->last_avail;

	if (!n) {
		vq_read_avail(vq);
		n = vq->avail_idx - vq->last_avail;
	}
	if (n > PRUKIT_VRING_NUM) {
		vq->avail_idx = vq->last_avail;
		note(rp, &rp->stats.err_ring_idx, PRUKIT_RPMSG_ST_RING_IDX);
		return -EIO;
	}
	return n;
}

/*
 * Take the next available entry and read its descriptor into *d.  Returns
 * the descriptor index, or -1 if the entry held an index >= num (counted;
 * the entry is used up, the descriptor table is not read).
 */
static int vq_take(struct prukit_rpmsg *rp, struct prukit_vring *vq,
		   struct prukit_vring_desc *d)
{
	uint16_t head = ocp_read16(vq->base + PRUKIT_VRING_AVAIL_RING(vq->last_avail & VRING_MASK));

	vq->last_avail++;
	if (head >= PRUKIT_VRING_NUM) {
		note(rp, &rp->stats.err_desc_idx, PRUKIT_RPMSG_ST_DESC_IDX);
		return -1;
	}
	prukit_ocp_read(d, vq->base + PRUKIT_VRING_DESC_OFF + 16 * head, sizeof(*d));
	return head;
}

/*
 * May the core access [addr, addr + need) of this buffer?  Only if the
 * address is a 32-bit OCP address (not the core's own memories or
 * registers), the range does not wrap and the buffer is at least that long.
 */
static int buf_ok(const struct prukit_vring_desc *d, uint32_t need)
{
	return !d->addr_hi && d->addr_lo >= PRUKIT_RPMSG_OCP_MIN && d->len >= need &&
	       (uint32_t)(0u - d->addr_lo) >= need;
}

/*
 * Give descriptor head back to Linux with len bytes written, then kick the
 * ARM unless avail->flags says not to.  The flags are read after used->idx
 * is written (a kick cannot be lost when Linux re-enables interrupts at the
 * same time), and since the read travels behind the posted writes to the
 * same memory, the ARM cannot see the kick before the used entry.
 */
static void vq_put(struct prukit_rpmsg *rp, struct prukit_vring *vq, uint32_t head,
		   uint32_t len)
{
	uint32_t elem = vq->base + PRUKIT_VRING_USED_RING(vq->used_idx & VRING_MASK);

	ocp_write32(elem, head);
	ocp_write32(elem + 4, len);
	vq->used_idx++;
	ocp_write16(vq->base + PRUKIT_VRING_USED_IDX, vq->used_idx);
	vq_read_avail(vq);
	if (!(vq->avail_flags & PRUKIT_VRING_AVAIL_F_NO_INTERRUPT)) {
		r31_strobe_event(PRUKIT_RPMSG_EVT_TO_ARM);
		rp->stats.kicks_out++;
	}
}

int prukit_rpmsg_kicked(struct prukit_rpmsg *rp)
{
	if (!(read_r31() & PRUKIT_RPMSG_R31_KICK))
		return 0;
	pru_intc_clear_event(PRUKIT_RPMSG_EVT_FROM_ARM);
	rp->stats.kicks_in++;
	return 1;
}

void prukit_rpmsg_wait(struct prukit_rpmsg *rp)
{
	while (!prukit_rpmsg_kicked(rp))
		;
}

int prukit_rpmsg_recv(struct prukit_rpmsg *rp, void *data, uint16_t *len, uint32_t *src)
{
	struct prukit_vring *vq = &rp->vq[PRUKIT_RPMSG_VQ_RX];
	struct prukit_vring_desc d;
	struct prukit_rpmsg_hdr hdr;
	int head, ret;

	ret = vq_pending(rp, vq);
	if (ret <= 0)
		return ret ? ret : -EAGAIN;
	head = vq_take(rp, vq, &d);
	if (head < 0)
		return -EBADMSG;

	ret = -EBADMSG;
	if (!buf_ok(&d, sizeof(hdr))) {
		note(rp, &rp->stats.err_desc, PRUKIT_RPMSG_ST_DESC);
	} else {
		prukit_ocp_read(&hdr, d.addr_lo, sizeof(hdr));
		if (hdr.len > RPMSG_PRU_MAX_PAYLOAD || hdr.len > d.len - sizeof(hdr)) {
			note(rp, &rp->stats.err_msg_len, PRUKIT_RPMSG_ST_MSG_LEN);
		} else {
			prukit_ocp_read(data, d.addr_lo + sizeof(hdr), hdr.len);
			*len = hdr.len;
			*src = hdr.src;
			if (rp->peer == PRUKIT_RPMSG_ADDR_ANY)
				rp->peer = hdr.src;
			rp->stats.rx_msgs++;
			ret = 0;
		}
	}
	/* Linux's transmit buffers are read-only to us: 0 bytes written */
	vq_put(rp, vq, head, 0);
	return ret;
}

__attribute__((noinline))
int prukit_rpmsg_send(struct prukit_rpmsg *rp, uint32_t dst, const void *data, uint16_t len)
{
	struct prukit_vring *vq = &rp->vq[PRUKIT_RPMSG_VQ_TX];
	uint32_t need = sizeof(struct prukit_rpmsg_hdr) + len;
	struct prukit_vring_desc d;
	unsigned int tries;
	int head, ret;

	if (len > RPMSG_PRU_MAX_PAYLOAD)
		return -EMSGSIZE;

	/* At most num entries: each one taken is either used or skipped. */
	for (tries = 0; tries < PRUKIT_VRING_NUM; tries++) {
		ret = vq_pending(rp, vq);
		if (ret <= 0)
			return ret ? ret : -EAGAIN;
		head = vq_take(rp, vq, &d);
		if (head < 0)
			continue;
		if (!buf_ok(&d, need)) {
			/*
			 * Not given back: Linux would read a stale header
			 * from a buffer returned with fewer than 16 bytes.
			 */
			note(rp, &rp->stats.err_desc, PRUKIT_RPMSG_ST_DESC);
			continue;
		}
		ocp_write32(d.addr_lo + offsetof(struct prukit_rpmsg_hdr, src), rp->port);
		ocp_write32(d.addr_lo + offsetof(struct prukit_rpmsg_hdr, dst), dst);
		ocp_write32(d.addr_lo + offsetof(struct prukit_rpmsg_hdr, reserved), 0);
		/* len (bits 15:0) and flags (bits 31:16, 0) */
		ocp_write32(d.addr_lo + offsetof(struct prukit_rpmsg_hdr, len), len);
		prukit_ocp_write(d.addr_lo + sizeof(struct prukit_rpmsg_hdr), data, len);
		vq_put(rp, vq, head, need);
		rp->stats.tx_msgs++;
		return 0;
	}
	return -EAGAIN;
}

/* The loaded resource table: Linux writes da, notifyid and status. */
static int vring_setup(struct prukit_rpmsg *rp, unsigned int i)
{
	volatile struct prukit_rsc_vdev_vring *vr = &prukit_resource_table.vdev.vring[i];
	struct prukit_vring *vq = &rp->vq[i];
	uint32_t da = vr->da;

	vq->base = da;
	vq->last_avail = 0;
	vq->avail_idx = 0;
	vq->used_idx = 0;
	vq->avail_flags = 0;
	return vr->num == PRUKIT_VRING_NUM && vr->align == PRUKIT_VRING_ALIGN &&
	       da >= PRUKIT_RPMSG_OCP_MIN && da <= 0u - PRUKIT_VRING_SIZE;
}

int prukit_rpmsg_init(struct prukit_rpmsg *rp)
{
	volatile struct prukit_rsc_vdev *vdev = &prukit_resource_table.vdev;
	int ret, ok;

	rp->stats = (struct prukit_rpmsg_stats){ 0 };
	rp->port = PRUKIT_RPMSG_PORT;
	rp->peer = PRUKIT_RPMSG_ADDR_ANY;

	pruss_ocp_master_enable();
	while (!(vdev->status & PRUKIT_VIRTIO_S_DRIVER_OK))
		;

	ok = vdev->num_of_vrings == 2;
	ok &= vring_setup(rp, PRUKIT_RPMSG_VQ_TX);
	ok &= vring_setup(rp, PRUKIT_RPMSG_VQ_RX);
	if (!ok) {
		rp->stats.status |= PRUKIT_RPMSG_ST_BAD_RSC;
		return -EINVAL;
	}
	rp->stats.status |= PRUKIT_RPMSG_ST_READY;

	while ((ret = prukit_rpmsg_send(rp, PRUKIT_RPMSG_NS_ADDR, &prukit_rpmsg_ns,
					sizeof(prukit_rpmsg_ns))) == -EAGAIN)
		prukit_rpmsg_wait(rp);
	if (ret)
		return ret;
	rp->stats.status |= PRUKIT_RPMSG_ST_ANNOUNCED;
	return 0;
}
