/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: <pru_virtio_ids.h> for PRU programs written against TI's PRU
 * Software Support Package, whose resource tables include it for
 * VIRTIO_ID_RPMSG.  Device IDs as the virtio specification assigns them.
 */
#ifndef PRUKIT_COMPAT_PRU_VIRTIO_IDS_H
#define PRUKIT_COMPAT_PRU_VIRTIO_IDS_H

#define VIRTIO_ID_NET		1
#define VIRTIO_ID_BLOCK		2
#define VIRTIO_ID_CONSOLE	3
#define VIRTIO_ID_RNG		4
#define VIRTIO_ID_BALLOON	5
#define VIRTIO_ID_RPMSG		7
#define VIRTIO_ID_SCSI		8
#define VIRTIO_ID_9P		9
#define VIRTIO_ID_RPROC_SERIAL	11
#define VIRTIO_ID_CAIF		12

#endif /* PRUKIT_COMPAT_PRU_VIRTIO_IDS_H */
