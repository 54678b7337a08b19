/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * VCD trace of the simulated output pins.
 */
#ifndef _PRUSIM_VCD_H
#define _PRUSIM_VCD_H

#include "pinlog.h"

int vcd_write(const struct pin_log *log, const char *path);

#endif /* _PRUSIM_VCD_H */
