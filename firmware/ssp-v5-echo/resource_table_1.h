/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * ssp-v5-echo: PRU1's table in the older support package's form
 * (ssp_v5_table.h): 18 -> channel 3 -> host 3 (to the ARM), 19 -> channel 1
 * -> host 1 (from the ARM).
 */
#if !defined(PRUKIT_PRU_CORE) || PRUKIT_PRU_CORE != 1
#error "resource_table_1.h is for PRU1"
#endif
#define SSP_TO_ARM_EVT		18
#define SSP_TO_ARM_CH		3
#define SSP_FROM_ARM_EVT	19
#define SSP_FROM_ARM_CH		1
#define SSP_CHANNEL_HOST	{ HOST_UNUSED, 1, HOST_UNUSED, 3, HOST_UNUSED, HOST_UNUSED, \
			  HOST_UNUSED, HOST_UNUSED, HOST_UNUSED, HOST_UNUSED }
#include "ssp_v5_table.h"
