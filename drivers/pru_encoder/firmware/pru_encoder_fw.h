/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/* pru_encoder firmware: the sampling loop (pru_encoder_loop.S) */
#ifndef _PRU_ENCODER_FW_H
#define _PRU_ENCODER_FW_H

#include <stdint.h>

#include "pru_encoder_proto.h"

/*
 * Decode until the command word differs from @last_cmd; return it.  @table
 * is indexed by (previous window << 3 | window), @strobe is written to R31
 * to raise the driver's event (0: none).
 */
uint32_t pru_enc_loop(volatile struct pru_enc_ctrl *c, const uint32_t *table,
		      uint32_t last_cmd, uint32_t strobe);

#endif /* _PRU_ENCODER_FW_H */
