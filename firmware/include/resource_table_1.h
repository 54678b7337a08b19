/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: resource_table_1.h for PRU1 programs written against TI's PRU
 * Software Support Package's rpmsg API (the PRU Cookbook's rpmsg examples
 * include a file of this name): defines resourceTable with one rpmsg vdev
 * (two vrings of 16 buffers, Linux chooses their addresses) under the names
 * those programs use - resourceTable.rpmsg_vdev.status,
 * &resourceTable.rpmsg_vring0, &resourceTable.rpmsg_vring1 - and, through
 * intc_map_1.h, the .pru_irq_map.  Include it once, from the file with main().
 *
 * Written by prukit.  A program folder that still has the support package's
 * own resource_table_1.h uses that one instead ("..." looks there first).
 */
#ifndef PRUKIT_COMPAT_RESOURCE_TABLE_1_H
#define PRUKIT_COMPAT_RESOURCE_TABLE_1_H

#if !defined(PRUKIT_PRU_CORE) || PRUKIT_PRU_CORE != 1
#error "resource_table_1.h is for PRU1: build this firmware for core 1 only (fw-cores := 1)"
#endif

#include <stddef.h>
#include <stdint.h>

#include <prukit/resource_table.h>
#include <pru_virtio_ids.h>
#include <rsc_types.h>

#include "intc_map_1.h"

struct my_resource_table {
	struct resource_table base;
	uint32_t offset[1];
	struct fw_rsc_vdev rpmsg_vdev;
	struct fw_rsc_vdev_vring rpmsg_vring0;	/* PRU1 -> ARM */
	struct fw_rsc_vdev_vring rpmsg_vring1;	/* ARM -> PRU1 */
};

/*
 * resourceTable, the support package's name, which its programs use: pasted
 * together here only because prukit's own sources follow the kernel's style
 * check, which refuses CamelCase (programs simply write resourceTable).
 */
#define PRUKIT_SSP_PASTE(a, b, c)	a##b##c
#define PRUKIT_SSP_RESOURCE_TABLE	PRUKIT_SSP_PASTE(resource, T, able)

struct my_resource_table PRUKIT_SSP_RESOURCE_TABLE PRUKIT_RSC_SECTION = {
	.base = { .ver = 1, .num = 1, .reserved = { 0, 0 } },
	.offset = { offsetof(struct my_resource_table, rpmsg_vdev) },
	.rpmsg_vdev = {
		.type = TYPE_VDEV,
		.id = VIRTIO_ID_RPMSG,
		.notifyid = 0,
		.dfeatures = 1u << 0,		/* VIRTIO_RPMSG_F_NS: name service */
		.gfeatures = 0,
		.config_len = 0,
		.status = 0,
		.num_of_vrings = 2,
		.reserved = { 0, 0 },
	},
	.rpmsg_vring0 = { .da = FW_RSC_ADDR_ANY, .align = 16, .num = 16, .notifyid = 0 },
	.rpmsg_vring1 = { .da = FW_RSC_ADDR_ANY, .align = 16, .num = 16, .notifyid = 1 },
};

#endif /* PRUKIT_COMPAT_RESOURCE_TABLE_1_H */
