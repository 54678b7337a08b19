/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: <rsc_types.h> for PRU programs written against TI's PRU Software
 * Support Package (the PRU Cookbook's rpmsg examples): the remoteproc
 * resource table types under the names those programs use.
 *
 * Written by prukit from the resource table format that Linux's remoteproc
 * reads (include/linux/remoteproc.h documents it); prukit's own firmware uses
 * <prukit/resource_table.h> and <prukit/rpmsg.h> instead.  What is here:
 * the table header, carveout/devmem/trace entries, the vdev entry and its
 * vrings, the TYPE_* values, and the custom entry of the releases for TI's
 * 4.x kernels (struct fw_rsc_custom, TYPE_CUSTOM), which held their
 * interrupt map: no kernel since reads it, prukit_pru does (<pru_types.h>).
 * New programs put the map into the .pru_irq_map section instead.  See
 * Documentation/firmware-rpmsg.rst.
 */
#ifndef PRUKIT_COMPAT_RSC_TYPES_H
#define PRUKIT_COMPAT_RSC_TYPES_H

#include <assert.h>
#include <stdint.h>

#include <pru_types.h>

/* Resource entry types */
#define TYPE_CARVEOUT		0
#define TYPE_DEVMEM		1
#define TYPE_TRACE		2
#define TYPE_VDEV		3
#define TYPE_CUSTOM		5	/* TI's 4.x kernels only */

/* "Linux chooses": Linux writes the address it allocated over this */
#define FW_RSC_ADDR_ANY		0xffffffffu

/* The table header; num offsets (uint32_t, from the table start) follow it. */
struct resource_table {
	uint32_t ver;			/* 1 */
	uint32_t num;			/* number of entries */
	uint32_t reserved[2];		/* 0 */
};

/* Contiguous memory Linux allocates for the firmware. */
struct fw_rsc_carveout {
	uint32_t type;			/* TYPE_CARVEOUT */
	uint32_t da;			/* device address, or FW_RSC_ADDR_ANY */
	uint32_t pa;			/* physical address, written by Linux */
	uint32_t len;
	uint32_t flags;
	uint32_t reserved;
	uint8_t name[32];
};

/* A device memory region to map (for cores behind an IOMMU). */
struct fw_rsc_devmem {
	uint32_t type;			/* TYPE_DEVMEM */
	uint32_t da;
	uint32_t pa;
	uint32_t len;
	uint32_t flags;
	uint32_t reserved;
	uint8_t name[32];
};

/* A trace buffer in the core's memory that Linux shows in debugfs. */
struct fw_rsc_trace {
	uint32_t type;			/* TYPE_TRACE */
	uint32_t da;
	uint32_t len;
	uint32_t reserved;
	uint8_t name[32];
};

/* One vring of a vdev; Linux writes da (and notifyid). */
struct fw_rsc_vdev_vring {
	uint32_t da;			/* FW_RSC_ADDR_ANY: Linux allocates */
	uint32_t align;			/* alignment of the used ring */
	uint32_t num;			/* buffers, a power of two */
	uint32_t notifyid;
	union {
		uint32_t reserved;	/* the support package's name */
		uint32_t pa;		/* Linux's name for the same word */
	};
};

/*
 * A virtio device: for rpmsg, id 7 (VIRTIO_ID_RPMSG, <pru_virtio_ids.h>),
 * dfeatures bit 0 (name service) and two vrings, which follow this header
 * directly in the table.  Linux writes gfeatures and status; status has
 * VIRTIO_CONFIG_S_DRIVER_OK (4) set while the vrings may be used.
 */
struct fw_rsc_vdev {
	uint32_t type;			/* TYPE_VDEV */
	uint32_t id;
	uint32_t notifyid;
	uint32_t dfeatures;
	uint32_t gfeatures;
	uint32_t config_len;
	uint8_t status;
	uint8_t num_of_vrings;
	uint8_t reserved[2];
	struct fw_rsc_vdev_vring vring[0];
};

/* TI's 4.x kernels: a resource of a kind the sub type names (TYPE_PRU_INTS) */
union fw_custom {
	struct fw_rsc_custom_ints pru_ints;
};

struct fw_rsc_custom {
	uint32_t type;			/* TYPE_CUSTOM */
	uint32_t sub_type;		/* TYPE_PRU_INTS */
	uint32_t rsc_size;		/* sizeof the union's member */
	union fw_custom rsc;
};

static_assert(sizeof(struct fw_rsc_custom) == 32, "fw_rsc_custom is 32 bytes");
static_assert(sizeof(struct resource_table) == 16, "resource_table is 16 bytes");
static_assert(sizeof(struct fw_rsc_vdev_vring) == 20, "fw_rsc_vdev_vring is 20 bytes");
static_assert(sizeof(struct fw_rsc_vdev) == 28, "fw_rsc_vdev is 28 bytes");
static_assert(sizeof(struct fw_rsc_carveout) == 56, "fw_rsc_carveout is 56 bytes");
static_assert(sizeof(struct fw_rsc_trace) == 48, "fw_rsc_trace is 48 bytes");

#endif /* PRUKIT_COMPAT_RSC_TYPES_H */
