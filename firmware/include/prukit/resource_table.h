/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * prukit: remoteproc resource table for PRU firmware.
 *
 * Linux's remoteproc ELF loader requires a section named ".resource_table"
 * (struct resource_table: ver = 1, num entries, two reserved words that must
 * be 0, then num offsets to the entries from the start of the table).  The
 * linker script keeps it in data RAM, 8-byte aligned, and refuses to link
 * firmware without one.
 *
 * Firmware that needs no resources (the usual case for prukit drivers, which
 * use a control block and DMA buffers instead of a vdev) writes
 *
 *	PRUKIT_RESOURCE_TABLE_EMPTY();
 *
 * once at file scope.  Firmware with entries (rpmsg vdev) defines its own
 * struct that starts with struct prukit_rsc_table_hdr and puts it in
 * PRUKIT_RSC_SECTION.
 */
#ifndef _PRUKIT_RESOURCE_TABLE_H
#define _PRUKIT_RESOURCE_TABLE_H

#include <assert.h>
#include <stdint.h>

#define PRUKIT_RSC_TABLE_VERSION	1

/* Resource entry types (include/linux/remoteproc.h) */
#define PRUKIT_RSC_CARVEOUT	0
#define PRUKIT_RSC_DEVMEM	1
#define PRUKIT_RSC_TRACE	2
#define PRUKIT_RSC_VDEV		3

/* Not referenced by the firmware's code but read (and written) by Linux. */
#define PRUKIT_RSC_SECTION						\
	__attribute__((section(".resource_table"), used, aligned(4)))

struct prukit_rsc_table_hdr {
	uint32_t ver;
	uint32_t num;
	uint32_t reserved[2];
};

struct prukit_rsc_table_empty {
	struct prukit_rsc_table_hdr hdr;
};

static_assert(sizeof(struct prukit_rsc_table_empty) == 16,
	      "empty resource table must be 16 bytes");

#define PRUKIT_RESOURCE_TABLE_EMPTY()					\
	struct prukit_rsc_table_empty prukit_resource_table PRUKIT_RSC_SECTION = { \
		.hdr = {						\
			.ver = PRUKIT_RSC_TABLE_VERSION,		\
			.num = 0,					\
			.reserved = { 0, 0 },				\
		},							\
	}

#endif /* _PRUKIT_RESOURCE_TABLE_H */
