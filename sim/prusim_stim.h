/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prusim input stimulus: the text format of the prusim tool's --r31-0,
 * --r31-1 and --gpio-in files and of the QEMU PRU-ICSS's input files, parsed
 * without allocating, and the lookup of the value at a cycle.
 *
 * Format (Documentation/prusim.rst): one "CYCLE VALUE" pair per line
 * (decimal or 0x hex), the value holding from CYCLE on, cycles strictly
 * increasing and 0 before the first one; '#' starts a comment; an optional
 * last line "repeat PERIOD" makes the pattern periodic (it must then start
 * at cycle 0 and end before PERIOD).
 */
#ifndef _PRUSIM_STIM_H
#define _PRUSIM_STIM_H

#include "prusim_platform.h"

/* Most entries one stimulus may have, 2^28 (the count must fit in an int) */
#define PRUSIM_STIM_MAX_ENTRIES	0x10000000u

/**
 * struct prusim_stim - a piecewise constant input value, optionally periodic
 * @cycle: cycles at which a new value starts, strictly increasing
 * @value: @value[i] holds from @cycle[i] on (0 before @cycle[0])
 * @count: number of entries; on input to prusim_stim_parse() the number of
 *	entries @cycle and @value have room for
 * @period: 0, or the period in cycles after which the pattern repeats (then
 *	@cycle[0] is 0 and @cycle[@count - 1] is below @period)
 *
 * The arrays belong to the embedder; the simulator never allocates or frees
 * them.
 */
struct prusim_stim {
	u64 *cycle;
	u32 *value;
	size_t count;
	u64 period;
};

int prusim_stim_parse(const char *text, size_t len, struct prusim_stim *st,
		      char *err, size_t errlen);
u32 prusim_stim_value(const struct prusim_stim *st, u64 cycle, u64 *next_change);

#endif /* _PRUSIM_STIM_H */
