// SPDX-License-Identifier: GPL-2.0-only
/*
 * The output pin changes of a run, and the names of the pins.  PRU R30 pins
 * that reach a BeagleBone header are named after the header pin.
 */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pinlog.h"
#include "prusim.h"

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
 * pin_name() - signal name of a pin
 * @pin: prusim pin id, below PRUSIM_NUM_PINS
 * @buf: buffer for generated names
 * @len: size of @buf
 *
 * Return: header pin name ("P9_31"), or "pru0_r30_8", or "gpio1_21".
 */
const char *pin_name(unsigned int pin, char *buf, size_t len)
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
 * pin_log_add() - remember a pin change
 * @log: the log
 * @cycle: when (not earlier than the previous change)
 * @pin: prusim pin id
 * @level: new level
 *
 * Return: 0 or -ENOMEM.
 */
int pin_log_add(struct pin_log *log, uint64_t cycle, unsigned int pin, bool level)
{
	if (log->count == log->cap) {
		size_t n = log->cap ? 2 * log->cap : 4096;
		struct pin_change *c = realloc(log->changes, n * sizeof(*c));

		if (!c)
			return -ENOMEM;
		log->changes = c;
		log->cap = n;
	}
	log->changes[log->count++] = (struct pin_change){ cycle, pin, level };
	return 0;
}

/**
 * pin_log_free() - release a log
 * @log: the log
 */
void pin_log_free(struct pin_log *log)
{
	free(log->changes);
	memset(log, 0, sizeof(*log));
}
