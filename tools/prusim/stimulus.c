// SPDX-License-Identifier: GPL-2.0-only
/*
 * Input stimulus files: the file is read into memory and handed to the
 * simulator's parser twice, once to count the entries and once, with arrays
 * of that size, to store them.
 */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"
#include "stimulus.h"

/**
 * stimulus_load() - read a stimulus file
 * @st: result, zero-initialised by the caller; release with stimulus_free()
 * @path: file name
 * @err: error text ("FILE: line N: reason")
 * @errlen: size of @err
 *
 * Return: 0 or a negative errno.
 */
int stimulus_load(struct prusim_stim *st, const char *path, char *err, size_t errlen)
{
	char msg[160];
	size_t size = 0;
	char *text = read_file(path, &size);
	int n, ret;

	if (!text) {
		ret = -errno;
		snprintf(err, errlen, "%s: %s", path, strerror(errno));
		return ret;
	}
	n = prusim_stim_parse(text, size, NULL, msg, sizeof(msg));
	if (n >= 0) {
		/* one spare entry: malloc(0) may return NULL */
		st->cycle = calloc(n + 1, sizeof(*st->cycle));
		st->value = calloc(n + 1, sizeof(*st->value));
		st->count = n;
		if (!st->cycle || !st->value) {
			snprintf(msg, sizeof(msg), "out of memory");
			n = -ENOMEM;
		} else {
			n = prusim_stim_parse(text, size, st, msg, sizeof(msg));
		}
	}
	free(text);
	if (n < 0) {
		snprintf(err, errlen, "%s: %s", path, msg);
		stimulus_free(st);
		return n;
	}
	return 0;
}

/**
 * stimulus_free() - release a stimulus loaded by stimulus_load()
 * @st: stimulus
 */
void stimulus_free(struct prusim_stim *st)
{
	free(st->cycle);
	free(st->value);
	memset(st, 0, sizeof(*st));
}
