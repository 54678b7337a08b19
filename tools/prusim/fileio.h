/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Whole-file reading for the prusim tool.
 */
#ifndef _PRUSIM_FILEIO_H
#define _PRUSIM_FILEIO_H

#include <stddef.h>

void *read_file(const char *path, size_t *size);

#endif /* _PRUSIM_FILEIO_H */
