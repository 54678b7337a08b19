/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * hub75 firmware: the refresh loop hub75_main.c calls.
 */
#ifndef _HUB75_FW_H
#define _HUB75_FW_H

#include "hub75_proto.h"

#ifndef __ASSEMBLER__
#include <stdint.h>

/*
 * Refresh the panel from the frame buffers (hub75_scan.S) until
 * c->hdr.command differs from @command; returns with OE high.
 */
void hub75_scan(volatile struct hub75_ctrl *c, uint32_t command);

/* The same with every line on GPIO banks (HUB75_DATA_BANKS, hub75_banks.S) */
void hub75_scan_banks(volatile struct hub75_ctrl *c, uint32_t command);

#endif /* __ASSEMBLER__ */

#endif /* _HUB75_FW_H */
