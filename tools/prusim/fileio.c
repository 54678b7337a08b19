// SPDX-License-Identifier: GPL-2.0-only
/*
 * Whole-file reading for the prusim tool.  Reads until end of file, so
 * pipes and files whose size is not known in advance (debugfs) work too.
 */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "fileio.h"

/**
 * read_file() - read a whole file into memory
 * @path: file name
 * @size: set to the number of bytes read
 *
 * Return: a malloc()ed buffer with one spare byte after the contents (so an
 * empty file gives a valid pointer), or NULL with errno set.
 */
void *read_file(const char *path, size_t *size)
{
	FILE *f = fopen(path, "rb");
	size_t cap = 0, len = 0, n;
	char *buf = NULL, *p;
	int saved;

	if (!f)
		return NULL;
	do {
		if (cap - len < 2) {
			cap = cap ? 2 * cap : 65536;
			p = realloc(buf, cap);
			if (!p) {
				errno = ENOMEM;
				goto fail;
			}
			buf = p;
		}
		n = fread(buf + len, 1, cap - len - 1, f);
		len += n;
	} while (n);
	if (ferror(f)) {
		errno = errno ? errno : EIO;
		goto fail;
	}
	fclose(f);
	buf[len] = '\0';
	*size = len;
	return buf;

fail:
	saved = errno;
	free(buf);
	fclose(f);
	errno = saved;
	return NULL;
}
