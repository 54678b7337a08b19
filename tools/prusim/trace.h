/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Binary pin traces (sim/prusim_trace.h) and text event lists of the
 * prusim tool.
 */
#ifndef _PRUSIM_TOOL_TRACE_H
#define _PRUSIM_TOOL_TRACE_H

#include <stddef.h>

#include "pinlog.h"

int trace_write(const struct pin_log *log, const char *path);
int trace_read(struct pin_log *log, const char *path, char *err, size_t errlen);
int events_write(const struct pin_log *log, const char *path);

#endif /* _PRUSIM_TOOL_TRACE_H */
