/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * ssp-v5-echo: a resource table in the form of the PRU Software Support
 * Package's releases for TI's 4.x kernels, which the PRU Cookbook's rpmsg
 * examples were built with: the rpmsg vdev and its two vrings, then a
 * TYPE_CUSTOM resource of sub type TYPE_PRU_INTS holding the INTC routing,
 * with the program's struct ch_map array; no .pru_irq_map section.  Names
 * as those programs use them (resourceTable.rpmsg_vdev.status, ...).
 *
 * Written by prukit from the format (<rsc_types.h>, <pru_types.h>).  The
 * including header defines, for its core:
 *   SSP_TO_ARM_EVT, SSP_TO_ARM_CH     PRU -> ARM event and its channel (host = channel)
 *   SSP_FROM_ARM_EVT, SSP_FROM_ARM_CH ARM -> PRU event and its channel (host 0 or 1)
 *   SSP_CHANNEL_HOST                  each channel's host, HOST_UNUSED for none
 * The pairs are listed PRU -> ARM first, as the support package's echo
 * example lists them: the resource has no order, and the kernel side must
 * not take the first pair for the kick.
 */
#ifndef SSP_V5_TABLE_H
#define SSP_V5_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include <prukit/resource_table.h>
#include <pru_types.h>
#include <pru_virtio_ids.h>
#include <rsc_types.h>

/* resourceTable (prukit's style check refuses CamelCase in its own sources) */
#define PRUKIT_SSP_PASTE(a, b, c)	a##b##c
#define PRUKIT_SSP_RESOURCE_TABLE	PRUKIT_SSP_PASTE(resource, T, able)

struct ch_map pru_intc_map[] = {
	{ SSP_TO_ARM_EVT, SSP_TO_ARM_CH },
	{ SSP_FROM_ARM_EVT, SSP_FROM_ARM_CH },
};

struct my_resource_table {
	struct resource_table base;
	uint32_t offset[2];
	struct fw_rsc_vdev rpmsg_vdev;
	struct fw_rsc_vdev_vring rpmsg_vring0;	/* PRU -> ARM */
	struct fw_rsc_vdev_vring rpmsg_vring1;	/* ARM -> PRU */
	struct fw_rsc_custom pru_ints;
};

struct my_resource_table PRUKIT_SSP_RESOURCE_TABLE PRUKIT_RSC_SECTION = {
	.base = { .ver = 1, .num = 2, .reserved = { 0, 0 } },
	.offset = {
		offsetof(struct my_resource_table, rpmsg_vdev),
		offsetof(struct my_resource_table, pru_ints),
	},
	.rpmsg_vdev = {
		.type = TYPE_VDEV,
		.id = VIRTIO_ID_RPMSG,
		.dfeatures = 1u << 0,		/* VIRTIO_RPMSG_F_NS: name service */
		.num_of_vrings = 2,
	},
	.rpmsg_vring0 = { .da = FW_RSC_ADDR_ANY, .align = 16, .num = 16, .notifyid = 0 },
	.rpmsg_vring1 = { .da = FW_RSC_ADDR_ANY, .align = 16, .num = 16, .notifyid = 1 },
	.pru_ints = {
		.type = TYPE_CUSTOM,
		.sub_type = TYPE_PRU_INTS,
		.rsc_size = sizeof(struct fw_rsc_custom_ints),
		.rsc.pru_ints = {
			.version = 0,
			.channel_host = SSP_CHANNEL_HOST,
			.num_evts = sizeof(pru_intc_map) / sizeof(struct ch_map),
			.event_channel = pru_intc_map,
		},
	},
};

#endif /* SSP_V5_TABLE_H */
