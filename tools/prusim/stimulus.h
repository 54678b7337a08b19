/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Input stimulus files for the prusim tool (format: Documentation/prusim.rst).
 */
#ifndef _PRUSIM_STIMULUS_H
#define _PRUSIM_STIMULUS_H

#include <stddef.h>
#include <stdint.h>

/**
 * struct stimulus - a piecewise constant input, optionally periodic
 * @cycle: cycles at which a new value starts, strictly increasing
 * @value: the values
 * @count: number of entries
 * @period: 0, or the period after which the entries repeat
 */
struct stimulus {
	uint64_t *cycle;
	uint32_t *value;
	size_t count;
	uint64_t period;
};

int stimulus_load(struct stimulus *st, const char *path, char *err, size_t errlen);
uint32_t stimulus_value(const struct stimulus *st, uint64_t cycle, uint64_t *next);
void stimulus_free(struct stimulus *st);

#endif /* _PRUSIM_STIMULUS_H */
