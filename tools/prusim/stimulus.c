// SPDX-License-Identifier: GPL-2.0-only
/*
 * Input stimulus files: one "CYCLE VALUE" pair per line (decimal or 0x hex),
 * the value holding from that cycle on; '#' starts a comment; a final
 * "repeat PERIOD" line makes the pattern periodic.
 */

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stimulus.h"

#define NEVER	UINT64_MAX

static int fail(char *err, size_t errlen, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(err, errlen, fmt, ap);
	va_end(ap);
	return -EINVAL;
}

static int parse_u64(const char *s, uint64_t *v)
{
	char *end;

	errno = 0;
	*v = strtoull(s, &end, 0);
	return errno || end == s || *end ? -EINVAL : 0;
}

static int add_entry(struct stimulus *st, size_t *cap, uint64_t cycle, uint32_t value)
{
	if (st->count == *cap) {
		size_t n = *cap ? 2 * *cap : 64;
		uint64_t *c = realloc(st->cycle, n * sizeof(*c));
		uint32_t *v;

		if (!c)
			return -ENOMEM;
		st->cycle = c;
		v = realloc(st->value, n * sizeof(*v));
		if (!v)
			return -ENOMEM;
		st->value = v;
		*cap = n;
	}
	st->cycle[st->count] = cycle;
	st->value[st->count++] = value;
	return 0;
}

static int parse_line(struct stimulus *st, size_t *cap, char *line, char *err, size_t errlen)
{
	char *a, *b, *extra;
	uint64_t x, y;

	line[strcspn(line, "#\n")] = '\0';
	a = strtok(line, " \t\r");
	if (!a)
		return 0;
	b = strtok(NULL, " \t\r");
	extra = strtok(NULL, " \t\r");
	if (!b || extra)
		return fail(err, errlen, "expected \"CYCLE VALUE\" or \"repeat PERIOD\"");
	if (st->period)
		return fail(err, errlen, "nothing may follow \"repeat\"");
	if (!strcmp(a, "repeat")) {
		if (parse_u64(b, &x) || !x)
			return fail(err, errlen, "bad period \"%s\"", b);
		if (!st->count || st->cycle[0] != 0 || st->cycle[st->count - 1] >= x)
			return fail(err, errlen,
				    "a repeated pattern starts at cycle 0 and ends before its period");
		st->period = x;
		return 0;
	}
	if (parse_u64(a, &x) || parse_u64(b, &y) || y > UINT32_MAX)
		return fail(err, errlen, "bad number in \"%s %s\"", a, b);
	if (st->count && x <= st->cycle[st->count - 1])
		return fail(err, errlen, "cycles must increase");
	return add_entry(st, cap, x, y) ? fail(err, errlen, "out of memory") : 0;
}

/**
 * stimulus_load() - read a stimulus file
 * @st: result, zero-initialised by the caller
 * @path: file name
 * @err: error text
 * @errlen: size of @err
 *
 * Return: 0 or a negative errno.
 */
int stimulus_load(struct stimulus *st, const char *path, char *err, size_t errlen)
{
	char line[256], msg[160];
	size_t cap = 0;
	unsigned int lineno = 0;
	FILE *f = fopen(path, "r");
	int ret = 0;

	if (!f)
		return fail(err, errlen, "%s: %s", path, strerror(errno));
	while (!ret && fgets(line, sizeof(line), f)) {
		lineno++;
		ret = parse_line(st, &cap, line, msg, sizeof(msg));
		if (ret)
			fail(err, errlen, "%s:%u: %s", path, lineno, msg);
	}
	fclose(f);
	return ret;
}

/**
 * stimulus_value() - value at a cycle
 * @st: stimulus
 * @cycle: cycle
 * @next: first later cycle at which the value may change
 *
 * Return: the value (0 before the first entry).
 */
uint32_t stimulus_value(const struct stimulus *st, uint64_t cycle, uint64_t *next)
{
	uint64_t base = 0, t = cycle;
	size_t lo = 0, hi = st->count;

	if (st->period) {
		t = cycle % st->period;
		base = cycle - t;
	}
	/* find the first entry after t */
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;

		if (st->cycle[mid] <= t)
			lo = mid + 1;
		else
			hi = mid;
	}
	if (lo < st->count)
		*next = base + st->cycle[lo];
	else
		*next = st->period ? base + st->period : NEVER;
	return lo ? st->value[lo - 1] : 0;
}

/**
 * stimulus_free() - release a stimulus
 * @st: stimulus
 */
void stimulus_free(struct stimulus *st)
{
	free(st->cycle);
	free(st->value);
	memset(st, 0, sizeof(*st));
}
