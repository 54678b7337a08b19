/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The output pin changes of a run (or of a binary trace), and what the
 * prusim tool writes from them: VCD (vcd.c), the binary pin trace and the
 * text event list (trace.c).
 */
#ifndef _PRUSIM_PINLOG_H
#define _PRUSIM_PINLOG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/**
 * struct pin_change - one output pin change
 * @cycle: absolute simulator cycle
 * @pin: prusim pin id (PRUSIM_PIN_R30(), PRUSIM_PIN_GPIO())
 * @level: new level
 */
struct pin_change {
	uint64_t cycle;
	uint16_t pin;
	bool level;
};

/**
 * struct pin_log - pin changes in cycle order
 * @changes: the changes
 * @count: number of changes
 * @cap: allocated entries
 * @origin: reference cycle: outputs show times as cycle - @origin; changes
 *	before it only set the levels at time 0 of a VCD
 * @end: last cycle covered (the end of the run), not before @origin or the
 *	last change
 * @dropped: older changes lost before the first one (from a binary trace)
 */
struct pin_log {
	struct pin_change *changes;
	size_t count;
	size_t cap;
	uint64_t origin;
	uint64_t end;
	uint64_t dropped;
};

int pin_log_add(struct pin_log *log, uint64_t cycle, unsigned int pin, bool level);
void pin_log_free(struct pin_log *log);
const char *pin_name(unsigned int pin, char *buf, size_t len);

#endif /* _PRUSIM_PINLOG_H */
