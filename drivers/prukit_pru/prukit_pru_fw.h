/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prukit_pru - what the layer reads from a PRU firmware file itself
 */
#ifndef _PRUKIT_PRU_FW_H
#define _PRUKIT_PRU_FW_H

#include <linux/types.h>

int prukit_pru_fw_irq_events(const u8 *elf, size_t size, u64 *events);

#endif /* _PRUKIT_PRU_FW_H */
