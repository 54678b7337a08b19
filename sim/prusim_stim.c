// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim input stimulus: the parser of the text format and the value
 * lookup, shared by the prusim tool and the QEMU PRU-ICSS.
 *
 * The parser allocates nothing.  The embedder calls it twice: once without
 * a result to check the text and count its entries, then, with arrays of
 * that many entries, to fill them in.
 */

#include "prusim_stim.h"

/* U64 max = 10 * STIM_U64_MAX_DIV10 + STIM_U64_MAX_MOD10 (no 64-bit division) */
#define STIM_U64_MAX_DIV10	0x1999999999999999ull
#define STIM_U64_MAX_MOD10	5
/* At most this many characters of a bad token are quoted in an error */
#define STIM_QUOTE_MAX		24

/**
 * struct stim_parser - state of one prusim_stim_parse() call
 * @st: where entries go, or NULL when only counting
 * @err: error text buffer
 * @errlen: size of @err
 * @line: current line number, from 1
 * @count: entries seen so far
 * @first: cycle of the first entry
 * @last: cycle of the last entry
 * @period: period of a "repeat" line, 0 before one
 */
struct stim_parser {
	struct prusim_stim *st;
	char *err;
	size_t errlen;
	unsigned int line;
	size_t count;
	u64 first;
	u64 last;
	u64 period;
};

/**
 * struct stim_tok - one word of a line (not NUL terminated)
 * @p: first character
 * @len: number of characters
 */
struct stim_tok {
	const char *p;
	size_t len;
};

static __printf(3, 4) int stim_err(struct stim_parser *p, int ret, const char *fmt, ...)
{
	va_list ap;
	int n;

	if (!p->errlen)
		return ret;
	n = snprintf(p->err, p->errlen, "line %u: ", p->line);
	if (n >= 0 && (size_t)n < p->errlen) {
		va_start(ap, fmt);
		vsnprintf(p->err + n, p->errlen - n, fmt, ap);
		va_end(ap);
	}
	return ret;
}

/* Length of a token for "%.*s" in an error message */
static int stim_quote(const struct stim_tok *t)
{
	return t->len < STIM_QUOTE_MAX ? (int)t->len : STIM_QUOTE_MAX;
}

static bool stim_space(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* A decimal or 0x-prefixed hexadecimal number that fits in 64 bits */
static int stim_number(const struct stim_tok *t, u64 *v)
{
	const char *s = t->p, *end = t->p + t->len;
	bool hex = false;
	unsigned int digit;
	u64 x = 0;

	if (t->len > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
		hex = true;
		s += 2;
	}
	if (s == end)
		return -EINVAL;
	for (; s < end; s++) {
		if (*s >= '0' && *s <= '9')
			digit = *s - '0';
		else if (hex && *s >= 'a' && *s <= 'f')
			digit = *s - 'a' + 10;
		else if (hex && *s >= 'A' && *s <= 'F')
			digit = *s - 'A' + 10;
		else
			return -EINVAL;
		if (hex) {
			if (x >> 60)
				return -ERANGE;
			x = x << 4 | digit;
		} else {
			if (x > STIM_U64_MAX_DIV10 ||
			    (x == STIM_U64_MAX_DIV10 && digit > STIM_U64_MAX_MOD10))
				return -ERANGE;
			x = x * 10 + digit;
		}
	}
	*v = x;
	return 0;
}

/* Split @s (@n characters, comment removed) into at most 3 words */
static unsigned int stim_split(const char *s, size_t n, struct stim_tok *tok)
{
	unsigned int ntok = 0;
	size_t i = 0, start;

	while (ntok < 3) {
		while (i < n && stim_space(s[i]))
			i++;
		if (i == n)
			break;
		start = i;
		while (i < n && !stim_space(s[i]))
			i++;
		tok[ntok].p = s + start;
		tok[ntok].len = i - start;
		ntok++;
	}
	return ntok;
}

static int stim_repeat(struct stim_parser *p, const struct stim_tok *arg)
{
	u64 x;

	if (stim_number(arg, &x) || !x)
		return stim_err(p, -EINVAL, "bad period \"%.*s\"", stim_quote(arg), arg->p);
	if (!p->count || p->first || p->last >= x)
		return stim_err(p, -EINVAL,
				"a repeated pattern must start at cycle 0 and end before its period");
	p->period = x;
	return 0;
}

static int stim_entry(struct stim_parser *p, const struct stim_tok *tok)
{
	u64 cycle, value;

	if (stim_number(&tok[0], &cycle))
		return stim_err(p, -EINVAL, "bad cycle \"%.*s\"", stim_quote(&tok[0]), tok[0].p);
	if (stim_number(&tok[1], &value) || value > 0xffffffffull)
		return stim_err(p, -EINVAL, "bad value \"%.*s\" (32 bits at most)",
				stim_quote(&tok[1]), tok[1].p);
	if (p->count && cycle <= p->last)
		return stim_err(p, -EINVAL, "cycles must increase");
	if (p->count == PRUSIM_STIM_MAX_ENTRIES)
		return stim_err(p, -E2BIG, "more than %u entries", PRUSIM_STIM_MAX_ENTRIES);
	if (p->st) {
		if (p->count >= p->st->count)
			return stim_err(p, -ENOSPC, "more entries than the %zu counted",
					p->st->count);
		p->st->cycle[p->count] = cycle;
		p->st->value[p->count] = value;
	}
	if (!p->count)
		p->first = cycle;
	p->last = cycle;
	p->count++;
	return 0;
}

static int stim_line(struct stim_parser *p, const char *s, size_t n)
{
	struct stim_tok tok[3];
	unsigned int ntok;
	size_t i;

	for (i = 0; i < n && s[i] != '#'; i++)
		;
	ntok = stim_split(s, i, tok);
	if (!ntok)
		return 0;
	if (ntok != 2)
		return stim_err(p, -EINVAL, "expected \"CYCLE VALUE\" or \"repeat PERIOD\"");
	if (p->period)
		return stim_err(p, -EINVAL, "nothing may follow \"repeat\"");
	if (tok[0].len == 6 && !memcmp(tok[0].p, "repeat", 6))
		return stim_repeat(p, &tok[1]);
	return stim_entry(p, tok);
}

/**
 * prusim_stim_parse() - check a stimulus text, count or store its entries
 * @text: the text (need not be NUL terminated; the last line need not end
 *	with a newline); may be NULL when @len is 0
 * @len: its length in bytes
 * @st: NULL to only check the text and count its entries.  Otherwise
 *	@st->cycle and @st->value must have room for @st->count entries (the
 *	count returned by a first call); they are filled in and @st->count and
 *	@st->period are set to what the text says
 * @err: on failure, the reason with its line number ("line 3: cycles must
 *	increase"); "" on success.  May be NULL if @errlen is 0
 * @errlen: size of @err
 *
 * Allocates nothing and keeps no state: call it once with @st NULL, allocate
 * the arrays for the returned count, then call it again on the same text.
 * An empty text (or one of only comments) has 0 entries: the input reads 0.
 * On failure @st->count and @st->period are unchanged, the arrays may have
 * been partly written.
 *
 * Return: the number of entries (0..PRUSIM_STIM_MAX_ENTRIES), -EINVAL for a
 * malformed text, -E2BIG for more than PRUSIM_STIM_MAX_ENTRIES entries or
 * -ENOSPC when @st has room for fewer entries than the text holds.
 */
int prusim_stim_parse(const char *text, size_t len, struct prusim_stim *st,
		      char *err, size_t errlen)
{
	struct stim_parser p = { .st = st, .err = err, .errlen = errlen };
	size_t pos = 0, eol;
	int ret;

	if (errlen)
		err[0] = '\0';
	while (pos < len) {
		for (eol = pos; eol < len && text[eol] != '\n'; eol++)
			;
		p.line++;
		ret = stim_line(&p, text + pos, eol - pos);
		if (ret)
			return ret;
		pos = eol + 1;
	}
	if (st) {
		st->count = p.count;
		st->period = p.period;
	}
	return p.count;
}

/**
 * prusim_stim_value() - the value of a stimulus at a cycle
 * @st: the stimulus (as filled in by prusim_stim_parse())
 * @cycle: the cycle, counted from the stimulus' cycle 0
 * @next_change: set to the first cycle after @cycle at which the value may
 *	change (the next entry's cycle, or the start of the next period), or
 *	PRUSIM_NEVER when it never changes again
 *
 * Binary search: O(log @st->count).  Meant to be called from the input
 * callback of &struct prusim_ops, which then is called once per change.
 *
 * Return: the value (0 before the first entry and for an empty stimulus).
 */
u32 prusim_stim_value(const struct prusim_stim *st, u64 cycle, u64 *next_change)
{
	size_t lo = 0, hi = st->count, mid;
	u64 base = 0, t = cycle;

	if (st->period) {
		t = prusim_rem_u64(cycle, st->period);
		base = cycle - t;
	}
	/* the first entry after t */
	while (lo < hi) {
		mid = lo + (hi - lo) / 2;
		if (st->cycle[mid] <= t)
			lo = mid + 1;
		else
			hi = mid;
	}
	if (lo < st->count)
		*next_change = base + st->cycle[lo];
	else
		*next_change = st->period ? base + st->period : PRUSIM_NEVER;
	return lo ? st->value[lo - 1] : 0;
}
