// SPDX-License-Identifier: GPL-2.0-only
/*
 * Binary pin traces (the format of sim/prusim_trace.h, written by the QEMU PRU-ICSS
 * and by --trace-out, read by --trace-in) and the text event list of
 * --events: one "CYCLE PIN_NAME LEVEL" line per change, CYCLE relative to
 * the origin, so that lists from different places compare with diff.
 */

#include <assert.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"
#include "prusim.h"
#include "prusim_trace.h"
#include "trace.h"

#define HDR_SIZE	sizeof(struct prusim_trace_hdr)
#define REC_SIZE	sizeof(struct prusim_trace_rec)
#define HDR(field)	offsetof(struct prusim_trace_hdr, field)
#define REC(field)	offsetof(struct prusim_trace_rec, field)

static_assert(HDR_SIZE == 48 && REC_SIZE == 16, "binary trace layout");

static uint64_t get_le64(const uint8_t *p)
{
	return prusim_get_le32(p) | (uint64_t)prusim_get_le32(p + 4) << 32;
}

static void put_le64(uint8_t *p, uint64_t v)
{
	prusim_put_le32(p, v);
	prusim_put_le32(p + 4, v >> 32);
}

static int fail(char *err, size_t errlen, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(err, errlen, fmt, ap);
	va_end(ap);
	return -EINVAL;
}

/**
 * trace_write() - write a pin log as a binary pin trace
 * @log: the changes, with their origin and end
 * @path: output file
 *
 * Return: 0 or a negative errno.
 */
int trace_write(const struct pin_log *log, const char *path)
{
	uint8_t hdr[HDR_SIZE] = { 0 }, rec[REC_SIZE];
	FILE *f = fopen(path, "wb");
	size_t i;
	int ret;

	if (!f)
		return -errno;
	memcpy(hdr + HDR(magic), PRUSIM_TRACE_MAGIC, sizeof(((struct prusim_trace_hdr *)0)->magic));
	prusim_put_le32(hdr + HDR(version), PRUSIM_TRACE_VERSION);
	prusim_put_le32(hdr + HDR(rec_size), REC_SIZE);
	put_le64(hdr + HDR(origin), log->origin);
	put_le64(hdr + HDR(count), log->count);
	put_le64(hdr + HDR(dropped), log->dropped);
	put_le64(hdr + HDR(end), log->end);
	fwrite(hdr, sizeof(hdr), 1, f);
	for (i = 0; i < log->count; i++) {
		memset(rec, 0, sizeof(rec));
		put_le64(rec + REC(cycle), log->changes[i].cycle);
		rec[REC(pin)] = log->changes[i].pin;
		rec[REC(pin) + 1] = log->changes[i].pin >> 8;
		rec[REC(level)] = log->changes[i].level;
		fwrite(rec, sizeof(rec), 1, f);
	}
	ret = ferror(f) ? -EIO : 0;
	if (fclose(f))
		ret = -errno;
	return ret;
}

/* Check the header of a trace of @size bytes; the record count on success */
static int check_header(const uint8_t *img, size_t size, uint64_t *count, char *err,
			size_t errlen)
{
	uint32_t version, rec_size;
	uint64_t n;

	if (size < 8 || memcmp(img, PRUSIM_TRACE_MAGIC, 8))
		return fail(err, errlen, "not a prusim pin trace (no \"%s\" magic)",
			    PRUSIM_TRACE_MAGIC);
	if (size < HDR_SIZE)
		return fail(err, errlen, "truncated header (%zu of %zu bytes)", size, HDR_SIZE);
	version = prusim_get_le32(img + HDR(version));
	if (version != PRUSIM_TRACE_VERSION)
		return fail(err, errlen, "trace format version %u, this prusim reads version %u",
			    version, PRUSIM_TRACE_VERSION);
	rec_size = prusim_get_le32(img + HDR(rec_size));
	if (rec_size != REC_SIZE)
		return fail(err, errlen, "record size %u, expected %zu", rec_size, REC_SIZE);
	n = get_le64(img + HDR(count));
	if (n != (size - HDR_SIZE) / REC_SIZE || (size - HDR_SIZE) % REC_SIZE)
		return fail(err, errlen,
			    "the header announces %llu records but the file holds %zu bytes of records (%s)",
			    (unsigned long long)n, size - HDR_SIZE,
			    n > (size - HDR_SIZE) / REC_SIZE ? "truncated" : "extra data");
	*count = n;
	return 0;
}

/* Check record @i and append it to @log (origin and end already set) */
static int add_record(struct pin_log *log, const uint8_t *r, uint64_t i, char *err,
		      size_t errlen)
{
	static const uint8_t zero[sizeof(((struct prusim_trace_rec *)0)->reserved)];
	uint64_t cycle = get_le64(r + REC(cycle));
	unsigned int pin = prusim_get_le16(r + REC(pin));
	unsigned int level = r[REC(level)];

	if (pin >= PRUSIM_NUM_PINS)
		return fail(err, errlen, "record %llu: pin %u out of range (0..%u)",
			    (unsigned long long)i, pin, PRUSIM_NUM_PINS - 1);
	if (level > 1)
		return fail(err, errlen, "record %llu: level %u is not 0 or 1",
			    (unsigned long long)i, level);
	if (memcmp(r + REC(reserved), zero, sizeof(zero)))
		return fail(err, errlen, "record %llu: reserved bytes are not zero",
			    (unsigned long long)i);
	if (log->count && cycle < log->changes[log->count - 1].cycle)
		return fail(err, errlen, "record %llu: cycle %llu is before the previous one",
			    (unsigned long long)i, (unsigned long long)cycle);
	if (cycle > log->end)
		return fail(err, errlen, "record %llu: cycle %llu is after the end (%llu)",
			    (unsigned long long)i, (unsigned long long)cycle,
			    (unsigned long long)log->end);
	if (pin_log_add(log, cycle, pin, level)) {
		snprintf(err, errlen, "out of memory");
		return -ENOMEM;
	}
	return 0;
}

/**
 * trace_read() - read and check a binary pin trace
 * @log: result, zero-initialised by the caller; release with pin_log_free()
 * @path: file name
 * @err: error text
 * @errlen: size of @err
 *
 * Rejects a file with a wrong magic, version or record size, whose record
 * count does not match its size, whose end is before its origin, or with a
 * record that is out of cycle order, after the end, for a pin that does not
 * exist, with a level other than 0 or 1 or with reserved bytes set.
 *
 * Return: 0 or a negative errno.
 */
int trace_read(struct pin_log *log, const char *path, char *err, size_t errlen)
{
	size_t size = 0;
	uint8_t *img = read_file(path, &size);
	uint64_t count = 0, i;
	char msg[160];
	int ret;

	if (!img) {
		ret = -errno;
		snprintf(err, errlen, "%s: %s", path, strerror(errno));
		return ret;
	}
	ret = check_header(img, size, &count, msg, sizeof(msg));
	if (!ret) {
		log->origin = get_le64(img + HDR(origin));
		log->dropped = get_le64(img + HDR(dropped));
		log->end = get_le64(img + HDR(end));
		if (log->end < log->origin)
			ret = fail(msg, sizeof(msg), "end cycle %llu is before the origin %llu",
				   (unsigned long long)log->end,
				   (unsigned long long)log->origin);
	}
	for (i = 0; !ret && i < count; i++)
		ret = add_record(log, img + HDR_SIZE + i * REC_SIZE, i, msg, sizeof(msg));
	free(img);
	if (ret) {
		snprintf(err, errlen, "%s: %s", path, msg);
		pin_log_free(log);
	}
	return ret;
}

/**
 * events_write() - write a pin log as a text event list
 * @log: the changes
 * @path: output file
 *
 * One line per change: "CYCLE PIN_NAME LEVEL", CYCLE relative to the origin
 * (negative for changes before it).
 *
 * Return: 0 or a negative errno.
 */
int events_write(const struct pin_log *log, const char *path)
{
	FILE *f = fopen(path, "w");
	char name[32];
	size_t i;
	int ret;

	if (!f)
		return -errno;
	for (i = 0; i < log->count; i++) {
		const struct pin_change *c = &log->changes[i];

		fprintf(f, "%lld %s %d\n", (long long)(c->cycle - log->origin),
			pin_name(c->pin, name, sizeof(name)), c->level);
	}
	ret = ferror(f) ? -EIO : 0;
	if (fclose(f))
		ret = -errno;
	return ret;
}
