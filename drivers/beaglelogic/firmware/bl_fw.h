/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * beaglelogic firmware: the assembler loops bl_main.c calls.
 */
#ifndef _BL_FW_H
#define _BL_FW_H

#include "beaglelogic_proto.h"

/* bl_store()'s results */
#define BL_STORE_DONE		0	/* one-shot: every buffer filled */
#define BL_STORE_COMMAND	1	/* a new command came */
#define BL_STORE_MISSED		2	/* a block was overwritten before it was stored */

#ifndef __ASSEMBLER__
#include <stdint.h>

/*
 * PRU1: sample until the storer sets the stop flag (bl_sample.S); @pad and
 * @rounds make the delay between two samples (bl_main.c, delay_params()).
 */
void bl_sample(volatile struct bl_ctrl *c, uint32_t pad, int32_t rounds);

/*
 * PRU0: answer START with @status, store blocks until the capture ends
 * (bl_store.S); returns a BL_STORE_* result.  The stop flag is set then,
 * @state is the caller's to set.
 */
uint32_t bl_store(volatile struct bl_ctrl *c, uint32_t status);

#endif /* __ASSEMBLER__ */

#endif /* _BL_FW_H */
