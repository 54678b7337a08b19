/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Input stimulus files for the prusim tool: read a file and parse it with the
 * simulator's own parser (sim/prusim_stim.c; format: Documentation/prusim.rst).
 */
#ifndef _PRUSIM_STIMULUS_H
#define _PRUSIM_STIMULUS_H

#include <stddef.h>

#include "prusim_stim.h"

int stimulus_load(struct prusim_stim *st, const char *path, char *err, size_t errlen);
void stimulus_free(struct prusim_stim *st);

#endif /* _PRUSIM_STIMULUS_H */
