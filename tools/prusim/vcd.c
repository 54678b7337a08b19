// SPDX-License-Identifier: GPL-2.0-only
/*
 * VCD output: one VCD time unit is one PRU cycle ("$timescale 5 ns"), so
 * sigrok-cli (200 MHz samplerate) and GTKWave show true time.  Times are
 * relative to the log's origin; changes before it give the initial levels.
 */

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "prusim.h"
#include "vcd.h"

#define VCD_ID_FIRST	'!'
#define VCD_ID_CHARS	94

static void vcd_id(char *id, unsigned int index)
{
	int n = 0;

	do {
		id[n++] = VCD_ID_FIRST + index % VCD_ID_CHARS;
		index /= VCD_ID_CHARS;
	} while (index);
	id[n] = '\0';
}

static void write_header(FILE *f, const int *slot, const bool *level)
{
	unsigned int pin;
	char id[4], name[32];

	fprintf(f, "$version prusim $end\n$timescale 5 ns $end\n$scope module prusim $end\n");
	for (pin = 0; pin < PRUSIM_NUM_PINS; pin++) {
		if (slot[pin] < 0)
			continue;
		vcd_id(id, slot[pin]);
		fprintf(f, "$var wire 1 %s %s $end\n", id, pin_name(pin, name, sizeof(name)));
	}
	fprintf(f, "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n");
	for (pin = 0; pin < PRUSIM_NUM_PINS; pin++) {
		if (slot[pin] < 0)
			continue;
		vcd_id(id, slot[pin]);
		fprintf(f, "%d%s\n", level[pin], id);
	}
	fprintf(f, "$end\n");
}

/* Write the changes of one cycle: the last level of each pin, if it moved */
static size_t write_cycle(FILE *f, const struct pin_log *log, size_t i, const int *slot,
			  bool *level)
{
	uint64_t cycle = log->changes[i].cycle;
	bool before[PRUSIM_NUM_PINS], stamped = false;
	size_t j;
	char id[4];

	memcpy(before, level, sizeof(before));
	for (j = i; j < log->count && log->changes[j].cycle == cycle; j++)
		level[log->changes[j].pin] = log->changes[j].level;
	for (; i < j; i++) {
		unsigned int pin = log->changes[i].pin;

		if (level[pin] == before[pin])
			continue;
		if (!stamped)
			fprintf(f, "#%llu\n", (unsigned long long)(cycle - log->origin));
		stamped = true;
		before[pin] = level[pin];
		vcd_id(id, slot[pin]);
		fprintf(f, "%d%s\n", level[pin], id);
	}
	return j;
}

/**
 * vcd_write() - write a pin log as VCD
 * @log: the changes (pin ids below PRUSIM_NUM_PINS, cycles in order); only
 *	pins that appear in it are declared.  Changes before @log->origin set
 *	the levels at time 0 (all 0 otherwise); @log->end - @log->origin is
 *	written as the final time stamp.
 * @path: output file
 *
 * Return: 0 or a negative errno.
 */
int vcd_write(const struct pin_log *log, const char *path)
{
	bool level[PRUSIM_NUM_PINS] = { false };
	int slot[PRUSIM_NUM_PINS];
	unsigned int declared = 0, pin;
	size_t i;
	FILE *f;
	int ret;

	memset(slot, -1, sizeof(slot));
	for (i = 0; i < log->count; i++) {
		pin = log->changes[i].pin;
		if (slot[pin] < 0)
			slot[pin] = 0;
	}
	for (pin = 0; pin < PRUSIM_NUM_PINS; pin++) {
		if (!slot[pin])
			slot[pin] = declared++;
	}
	for (i = 0; i < log->count && log->changes[i].cycle < log->origin; i++)
		level[log->changes[i].pin] = log->changes[i].level;
	f = fopen(path, "w");
	if (!f)
		return -errno;
	write_header(f, slot, level);
	while (i < log->count)
		i = write_cycle(f, log, i, slot, level);
	fprintf(f, "#%llu\n", (unsigned long long)(log->end - log->origin));
	ret = ferror(f) ? -EIO : 0;
	if (fclose(f))
		ret = -errno;
	return ret;
}
