/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * ssp-v5-echo: PRU0's table in the older support package's form
 * (ssp_v5_table.h): 16 -> channel 2 -> host 2 (to the ARM), 17 -> channel 0
 * -> host 0 (from the ARM).
 */
#if !defined(PRUKIT_PRU_CORE) || PRUKIT_PRU_CORE != 0
#error "resource_table_0.h is for PRU0"
#endif
#define SSP_TO_ARM_EVT		16
#define SSP_TO_ARM_CH		2
#define SSP_FROM_ARM_EVT	17
#define SSP_FROM_ARM_CH		0
#define SSP_CHANNEL_HOST	{ 0, HOST_UNUSED, 2, HOST_UNUSED, HOST_UNUSED, HOST_UNUSED, \
			  HOST_UNUSED, HOST_UNUSED, HOST_UNUSED, HOST_UNUSED }
#include "ssp_v5_table.h"
