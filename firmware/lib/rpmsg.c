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
 *
 * Linux can take the rings away at any moment: when it stops the core,
 * remoteproc first resets the vdev (status byte 0) and frees the buffers and
 * rings, and only then halts the core.  So the vdev's status byte (in our data
 * RAM, 3 cycles to read) is read again right before a buffer is claimed and
 * right before every write into ARM memory; once DRIVER_OK is gone nothing
 * there is touched again until Linux has set the vdev up anew.
 *
 * Built on its own (fw-lib-srcs := rpmsg.c) this file also defines the
 * resource table and the .pru_irq_map.  pru_rpmsg.c (the support package's
 * API) includes it with PRUKIT_RPMSG_EXTERNAL_TABLE defined instead: then the
 * program brings its own table, and struct prukit_rpmsg's vdev points into it.
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

#ifdef PRUKIT_RPMSG_EXTERNAL_TABLE
/* The program's own table: rp->vdev points into it. */
#define RP_VDEV(rp)	((rp)->vdev)
#else
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

/* Our table, at an address the linker knows: no pointer to load. */
#define RP_VDEV(rp)							\
	((void)(rp), (volatile struct prukit_rsc_vdev *)&prukit_resource_table.vdev)
#endif

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

/*
 * Is DRIVER_OK still set?  Read right before a buffer is claimed and right
 * before every write into ARM memory: once Linux has reset the vdev it frees
 * the buffers and the rings, and nothing there may be touched any more.
 */
#define DRIVER_OK_BIT	2	/* PRUKIT_VIRTIO_S_DRIVER_OK */
static_assert(PRUKIT_VIRTIO_S_DRIVER_OK == 1u << DRIVER_OK_BIT, "DRIVER_OK is bit 2");

/*
 * One load of the word that starts with the status byte (then num_of_vrings
 * and two reserved bytes; little endian) and one QBBC, which the caller's
 * "if (!vdev_ok(rp)) goto ..." becomes once inlined - GCC 12 would test the
 * bit with AND and QBEQ.
 */
static inline __attribute__((always_inline)) int vdev_ok(struct prukit_rpmsg *rp)
{
	uint32_t st = *(volatile uint32_t *)&RP_VDEV(rp)->status;

	__asm__ goto("qbbc %l[gone], %0, %1" : : "r"(st), "i"(DRIVER_OK_BIT) : : gone);
	return 1;
gone:
	return 0;
}

/*
 * Have these values in registers before the next check: GCC would otherwise
 * compute addresses (and load from data RAM) between the check and the
 * stores it guards, widening the window.
 */
static inline void in_regs(uint32_t a, uint32_t b)
{
	__asm__ __volatile__("" : : "r"(a), "r"(b));
}

/*
 * ... and is it still the session we set the rings up for?  Checked when a
 * call starts: a reset and a new session may both have happened while the
 * firmware was busy elsewhere, and then DRIVER_OK alone would not tell.
 */
static inline int session_ok(struct prukit_rpmsg *rp)
{
	if (!(RP_VDEV(rp)->gfeatures & PRUKIT_RPMSG_GF_SESSION))
		return 0;
	return vdev_ok(rp);
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

/* vq_take() besides a descriptor index 0..num - 1 (one compare for both) */
#define VQ_BAD_HEAD	PRUKIT_VRING_NUM
#define VQ_LOST		(PRUKIT_VRING_NUM + 1)

/*
 * Take the next available entry and read its descriptor into *d.  Returns
 * the descriptor index; VQ_BAD_HEAD if the entry held an index >= num
 * (counted; the entry is used up, the descriptor table is not read); VQ_LOST
 * if DRIVER_OK is gone (nothing read, nothing taken).
 */
static unsigned int vq_take(struct prukit_rpmsg *rp, struct prukit_vring *vq,
			    struct prukit_vring_desc *d)
{
	uint16_t head;

	if (!vdev_ok(rp))
		goto gone;
	head = ocp_read16(vq->base + PRUKIT_VRING_AVAIL_RING(vq->last_avail & VRING_MASK));
	vq->last_avail++;
	if (head >= PRUKIT_VRING_NUM) {
		note(rp, &rp->stats.err_desc_idx, PRUKIT_RPMSG_ST_DESC_IDX);
		return VQ_BAD_HEAD;
	}
	prukit_ocp_read(d, vq->base + PRUKIT_VRING_DESC_OFF + 16 * head, sizeof(*d));
	return head;
gone:
	return VQ_LOST;
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
 * same memory, the ARM cannot see the kick before the used entry.  Returns
 * 0, or 1 if DRIVER_OK is gone (nothing written).
 */
static int vq_put(struct prukit_rpmsg *rp, struct prukit_vring *vq, uint32_t head,
		  uint32_t len)
{
	uint32_t base = vq->base;
	uint32_t elem = base + PRUKIT_VRING_USED_RING(vq->used_idx & VRING_MASK);

	in_regs(base, elem);
	if (!vdev_ok(rp))
		goto gone;
	ocp_write32(elem, head);
	ocp_write32(elem + 4, len);
	vq->used_idx++;
	ocp_write16(base + PRUKIT_VRING_USED_IDX, vq->used_idx);
	vq_read_avail(vq);
	if (!(vq->avail_flags & PRUKIT_VRING_AVAIL_F_NO_INTERRUPT)) {
		r31_strobe_event(PRUKIT_RPMSG_EVT_TO_ARM);
		rp->stats.kicks_out++;
	}
	return 0;
gone:
	return 1;
}

/* Start-up and recovery are rare: cold (GCC optimises them for size). */
static __attribute__((cold)) int rpmsg_start(struct prukit_rpmsg *rp);

/*
 * The session is gone: count it, and unless we are starting already, start
 * again (wait for DRIVER_OK, set the rings up, re-announce).  Nothing of the
 * old session is touched any more.  Returns -ECONNRESET for the caller.
 */
static __attribute__((noinline, cold)) int rpmsg_lost(struct prukit_rpmsg *rp)
{
	rp->stats.resets++;
	rp->stats.status = (rp->stats.status | PRUKIT_RPMSG_ST_RESET) &
			   ~(PRUKIT_RPMSG_ST_READY | PRUKIT_RPMSG_ST_ANNOUNCED);
	if (!rp->starting)
		rpmsg_start(rp);
	return -ECONNRESET;
}

int prukit_rpmsg_kicked(struct prukit_rpmsg *rp)
{
	if (!(read_r31() & PRUKIT_RPMSG_R31_KICK))
		return 0;
	pru_intc_clear_event(PRUKIT_RPMSG_EVT_FROM_ARM);
	rp->stats.kicks_in++;
	return 1;
}

int prukit_rpmsg_wait(struct prukit_rpmsg *rp)
{
	while (!prukit_rpmsg_kicked(rp)) {
		if (!session_ok(rp))
			return rpmsg_lost(rp);
	}
	return 0;
}

int prukit_rpmsg_recv(struct prukit_rpmsg *rp, void *data, uint16_t *len, uint32_t *src)
{
	struct prukit_vring *vq = &rp->vq[PRUKIT_RPMSG_VQ_RX];
	struct prukit_vring_desc d;
	struct prukit_rpmsg_hdr hdr;
	unsigned int head;
	int ret;

	if (!session_ok(rp))
		goto lost;
	ret = vq_pending(rp, vq);
	if (ret <= 0)
		return ret ? ret : -EAGAIN;
	head = vq_take(rp, vq, &d);
	if (head >= PRUKIT_VRING_NUM) {
		if (head == VQ_LOST)
			goto lost;
		return -EBADMSG;
	}

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
			rp->dst = hdr.dst;
			if (rp->peer == PRUKIT_RPMSG_ADDR_ANY)
				rp->peer = hdr.src;
			ret = 0;
		}
	}
	/* Linux's transmit buffers are read-only to us: 0 bytes written */
	if (vq_put(rp, vq, head, 0))
		goto lost;
	if (!ret)
		rp->stats.rx_msgs++;
	return ret;
lost:
	/* nothing received: the message went with the session */
	return rpmsg_lost(rp);
}

__attribute__((noinline))
int prukit_rpmsg_send(struct prukit_rpmsg *rp, uint32_t dst, const void *data, uint16_t len)
{
	struct prukit_vring *vq = &rp->vq[PRUKIT_RPMSG_VQ_TX];
	uint32_t need = sizeof(struct prukit_rpmsg_hdr) + len;
	struct prukit_vring_desc d;
	unsigned int tries, head;
	uint32_t buf, port;
	int ret;

	if (len > RPMSG_PRU_MAX_PAYLOAD)
		return -EMSGSIZE;
	if (!session_ok(rp))
		goto lost;

	/* At most num entries: each one taken is either used or skipped. */
	for (tries = 0; tries < PRUKIT_VRING_NUM; tries++) {
		ret = vq_pending(rp, vq);
		if (ret <= 0)
			return ret ? ret : -EAGAIN;
		head = vq_take(rp, vq, &d);
		if (head >= PRUKIT_VRING_NUM) {
			if (head == VQ_LOST)
				goto lost;
			continue;
		}
		if (!buf_ok(&d, need)) {
			/*
			 * Not given back: Linux would read a stale header
			 * from a buffer returned with fewer than 16 bytes.
			 */
			note(rp, &rp->stats.err_desc, PRUKIT_RPMSG_ST_DESC);
			continue;
		}
		/* in a register: d's copy may change with every store below */
		buf = d.addr_lo;
		port = rp->port;
		in_regs(buf, port);
		if (!vdev_ok(rp))
			goto lost;
		ocp_write32(buf + offsetof(struct prukit_rpmsg_hdr, src), port);
		ocp_write32(buf + offsetof(struct prukit_rpmsg_hdr, dst), dst);
		ocp_write32(buf + offsetof(struct prukit_rpmsg_hdr, reserved), 0);
		/* len (bits 15:0) and flags (bits 31:16, 0) */
		ocp_write32(buf + offsetof(struct prukit_rpmsg_hdr, len), len);
		/* data escapes here: stores to it must be done before the call */
		__asm__ __volatile__("" : : "r"(data) : "memory");
		/* the payload, each burst stored right after a look at the status */
		if (prukit_ocp_copy_live(buf + sizeof(struct prukit_rpmsg_hdr),
					 (uint32_t)(uintptr_t)data, len, &RP_VDEV(rp)->status))
			goto lost;
		if (vq_put(rp, vq, head, need))
			goto lost;
		rp->stats.tx_msgs++;
		return 0;
	}
	return -EAGAIN;
lost:
	/* not sent: the buffer (if one was taken) went with the session */
	return rpmsg_lost(rp);
}

/*
 * The vrings as Linux wrote them into the loaded resource table (da,
 * notifyid): 1 if both are usable.  Our indices start from 0.
 */
static __attribute__((cold)) int vrings_setup(struct prukit_rpmsg *rp)
{
	volatile struct prukit_rsc_vdev *vdev = RP_VDEV(rp);
	int ok = vdev->num_of_vrings == 2;
	unsigned int i;

	for (i = 0; i < 2; i++) {
		volatile struct prukit_rsc_vdev_vring *vr = &vdev->vring[i];
		struct prukit_vring *vq = &rp->vq[i];
		uint32_t da = vr->da;

		vq->base = da;
		vq->last_avail = 0;
		vq->avail_idx = 0;
		vq->used_idx = 0;
		vq->avail_flags = 0;
		ok &= vr->num == PRUKIT_VRING_NUM && vr->align == PRUKIT_VRING_ALIGN &&
		      da >= PRUKIT_RPMSG_OCP_MIN && da <= 0u - PRUKIT_VRING_SIZE;
	}
	return ok;
}

/*
 * Wait until Linux has set DRIVER_OK (reading only our data RAM), mark the
 * session as ours, check the vrings and send rp->ns, waiting for a kick
 * whenever there is no buffer (or the ring index is out of range) - and if
 * the session ends meanwhile, all of it again.  Returns 0, or -EINVAL if the
 * vrings are unusable: then the session is left unmarked, so that every
 * later call comes back here (touching nothing in ARM memory) until Linux
 * sets the vdev up anew.
 */
static __attribute__((cold)) int rpmsg_start(struct prukit_rpmsg *rp)
{
	volatile struct prukit_rsc_vdev *vdev = RP_VDEV(rp);
	int ret;

	rp->starting = 1;
	do {
		while (!vdev_ok(rp))
			;
		/* ours: a session Linux starts after this clears the bit */
		vdev->gfeatures |= PRUKIT_RPMSG_GF_SESSION;
		rp->peer = PRUKIT_RPMSG_ADDR_ANY;
		if (!vrings_setup(rp)) {
			vdev->gfeatures &= ~PRUKIT_RPMSG_GF_SESSION;
			rp->stats.status |= PRUKIT_RPMSG_ST_BAD_RSC;
			ret = -EINVAL;
			break;
		}
		rp->stats.status |= PRUKIT_RPMSG_ST_READY;
		ret = 0;
		if (rp->ns) {
			rp->port = rp->ns->addr;
			do {
				ret = prukit_rpmsg_send(rp, PRUKIT_RPMSG_NS_ADDR, rp->ns,
							sizeof(*rp->ns));
				/* no buffer yet: wait for a kick (or -ECONNRESET) */
			} while ((ret == -EAGAIN || ret == -EIO) &&
				 !(ret = prukit_rpmsg_wait(rp)));
			if (!ret)
				rp->stats.status |= PRUKIT_RPMSG_ST_ANNOUNCED;
		}
	} while (ret == -ECONNRESET);
	rp->starting = 0;
	return ret;
}

/*
 * Use the vdev at vdev (whose vrings follow it, as in every resource table),
 * wait for Linux and announce ns (if not NULL): the start-up of
 * prukit_rpmsg_init() and of pru_rpmsg_init().
 */
static __attribute__((cold)) int rpmsg_attach(struct prukit_rpmsg *rp,
					      volatile struct prukit_rsc_vdev *vdev,
					      const struct prukit_rpmsg_ns_msg *ns)
{
	/* peer and starting: rpmsg_start() sets them, port too if ns */
	rp->stats = (struct prukit_rpmsg_stats){ 0 };
	rp->port = PRUKIT_RPMSG_PORT;
	rp->vdev = vdev;
	rp->ns = ns;

	pruss_ocp_master_enable();
	return rpmsg_start(rp);
}

#ifndef PRUKIT_RPMSG_EXTERNAL_TABLE
__attribute__((cold))
int prukit_rpmsg_init(struct prukit_rpmsg *rp)
{
	return rpmsg_attach(rp, RP_VDEV(rp), &prukit_rpmsg_ns);
}
#endif
