// SPDX-License-Identifier: GPL-2.0-only
/*
 * VCD output: one VCD time unit is one PRU cycle ("$timescale 5 ns"), so
 * sigrok-cli (200 MHz samplerate) and GTKWave show true time.  PRU R30 pins
 * that reach a BeagleBone header are named after the header pin.
 */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "prusim.h"
#include "vcd.h"

#define VCD_ID_FIRST	'!'
#define VCD_ID_CHARS	94

/* BeagleBone Black header pins of PRU0/PRU1 R30 bits (NULL: not on a header) */
static const char *const pru0_r30_pins[32] = {
	"P9_31", "P9_29", "P9_30", "P9_28", "P9_42", "P9_27", "P9_41", "P9_25",
	[14] = "P8_12", [15] = "P8_11",
};

static const char *const pru1_r30_pins[32] = {
	"P8_45", "P8_46", "P8_43", "P8_44", "P8_41", "P8_42", "P8_39", "P8_40",
	"P8_27", "P8_29", "P8_28", "P8_30", "P8_21", "P8_20",
};

/**
 * vcd_pin_name() - signal name of a pin
 * @pin: prusim pin id
 * @buf: buffer for generated names
 * @len: size of @buf
 *
 * Return: header pin name ("P9_31"), or "pru0_r30_8", or "gpio1_21".
 */
const char *vcd_pin_name(unsigned int pin, char *buf, size_t len)
{
	unsigned int bit = pin % 32;

	if (pin < PRUSIM_PIN_R30(1, 0) && pru0_r30_pins[bit])
		return pru0_r30_pins[bit];
	if (pin < PRUSIM_PIN_GPIO(0, 0) && pin >= PRUSIM_PIN_R30(1, 0) && pru1_r30_pins[bit])
		return pru1_r30_pins[bit];
	if (pin < PRUSIM_PIN_GPIO(0, 0))
		snprintf(buf, len, "pru%u_r30_%u", pin / 32, bit);
	else
		snprintf(buf, len, "gpio%u_%u", (pin - PRUSIM_PIN_GPIO(0, 0)) / 32, bit);
	return buf;
}

/**
 * vcd_record() - remember a pin change
 * @v: trace
 * @cycle: when (not earlier than the previous change)
 * @pin: prusim pin id
 * @level: new level
 *
 * Return: 0 or -ENOMEM.
 */
int vcd_record(struct vcd *v, uint64_t cycle, unsigned int pin, bool level)
{
	if (v->count == v->cap) {
		size_t n = v->cap ? 2 * v->cap : 4096;
		struct vcd_change *c = realloc(v->changes, n * sizeof(*c));

		if (!c)
			return -ENOMEM;
		v->changes = c;
		v->cap = n;
	}
	v->changes[v->count++] = (struct vcd_change){ cycle, pin, level };
	return 0;
}

static void vcd_id(char *id, unsigned int index)
{
	int n = 0;

	do {
		id[n++] = VCD_ID_FIRST + index % VCD_ID_CHARS;
		index /= VCD_ID_CHARS;
	} while (index);
	id[n] = '\0';
}

static void write_header(FILE *f, const int *slot, unsigned int declared)
{
	unsigned int pin;
	char id[4], name[32];

	fprintf(f, "$version prusim $end\n$timescale 5 ns $end\n$scope module prusim $end\n");
	for (pin = 0; pin < PRUSIM_NUM_PINS; pin++) {
		if (slot[pin] < 0)
			continue;
		vcd_id(id, slot[pin]);
		fprintf(f, "$var wire 1 %s %s $end\n", id, vcd_pin_name(pin, name, sizeof(name)));
	}
	fprintf(f, "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n");
	for (pin = 0; pin < declared; pin++) {
		vcd_id(id, pin);
		fprintf(f, "0%s\n", id);
	}
	fprintf(f, "$end\n");
}

/* Write the changes of one cycle: the last level of each pin, if it moved */
static size_t write_cycle(FILE *f, const struct vcd *v, size_t i, const int *slot, bool *level)
{
	uint64_t cycle = v->changes[i].cycle;
	bool before[PRUSIM_NUM_PINS], stamped = false;
	size_t j;
	char id[4];

	memcpy(before, level, sizeof(before));
	for (j = i; j < v->count && v->changes[j].cycle == cycle; j++)
		level[v->changes[j].pin] = v->changes[j].level;
	for (; i < j; i++) {
		unsigned int pin = v->changes[i].pin;

		if (level[pin] == before[pin])
			continue;
		if (!stamped)
			fprintf(f, "#%llu\n", (unsigned long long)cycle);
		stamped = true;
		before[pin] = level[pin];
		vcd_id(id, slot[pin]);
		fprintf(f, "%d%s\n", level[pin], id);
	}
	return j;
}

/**
 * vcd_write() - write the trace
 * @v: trace
 * @path: output file
 * @end: last cycle of the simulation, written as the final time stamp
 *
 * Return: 0 or a negative errno.
 */
int vcd_write(const struct vcd *v, const char *path, uint64_t end)
{
	bool level[PRUSIM_NUM_PINS] = { false };
	int slot[PRUSIM_NUM_PINS];
	unsigned int declared = 0, pin;
	size_t i;
	FILE *f;
	int ret;

	memset(slot, -1, sizeof(slot));
	for (i = 0; i < v->count; i++) {
		pin = v->changes[i].pin;
		if (slot[pin] < 0)
			slot[pin] = 0;
	}
	for (pin = 0; pin < PRUSIM_NUM_PINS; pin++) {
		if (!slot[pin])
			slot[pin] = declared++;
	}
	f = fopen(path, "w");
	if (!f)
		return -errno;
	write_header(f, slot, declared);
	for (i = 0; i < v->count;)
		i = write_cycle(f, v, i, slot, level);
	fprintf(f, "#%llu\n", (unsigned long long)end);
	ret = ferror(f) ? -EIO : 0;
	if (fclose(f))
		ret = -errno;
	return ret;
}

/**
 * vcd_free() - release a trace
 * @v: trace
 */
void vcd_free(struct vcd *v)
{
	free(v->changes);
	memset(v, 0, sizeof(*v));
}
