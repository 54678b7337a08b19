/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * VCD trace of the simulated output pins.
 */
#ifndef _PRUSIM_VCD_H
#define _PRUSIM_VCD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/**
 * struct vcd_change - one recorded pin change
 * @cycle: when
 * @pin: prusim pin id
 * @level: new level
 */
struct vcd_change {
	uint64_t cycle;
	uint16_t pin;
	bool level;
};

/**
 * struct vcd - pin changes collected during a run, written at the end so
 * that only pins that ever changed are declared
 * @changes: the changes in cycle order
 * @count: number of changes
 * @cap: allocated entries
 */
struct vcd {
	struct vcd_change *changes;
	size_t count;
	size_t cap;
};

int vcd_record(struct vcd *v, uint64_t cycle, unsigned int pin, bool level);
int vcd_write(const struct vcd *v, const char *path, uint64_t end);
const char *vcd_pin_name(unsigned int pin, char *buf, size_t len);
void vcd_free(struct vcd *v);

#endif /* _PRUSIM_VCD_H */
