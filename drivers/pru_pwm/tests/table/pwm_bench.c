// SPDX-License-Identifier: GPL-2.0-only
/*
 * pwm_bench - the ARM's work per duty update of pru_pwm: N tables built
 * by drivers/pru_pwm/pru_pwm_table.c (unchanged) for eight enabled
 * servo channels at 50 Hz, one channel's duty changing each time, as a
 * sweep does.  Run under callgrind by tests/bench.sh, which counts the
 * instructions of pru_pwm_table_build().
 *
 *   pwm_bench N
 */
#include <stdio.h>
#include <stdlib.h>

#include "pru_pwm_table.h"

int main(int argc, char **argv)
{
	static const u8 bit[PRU_PWM_CHANNELS] = { 8, 10, 9, 11, 6, 7, 4, 5 };
	struct pru_pwm_req req[PRU_PWM_CHANNELS];
	struct pru_pwm_table t;
	unsigned long n = argc > 1 ? strtoul(argv[1], NULL, 0) : 1000, i, sum = 0;
	unsigned int c;

	for (c = 0; c < PRU_PWM_CHANNELS; c++) {
		req[c].period = 4000000;		/* 20 ms */
		req[c].duty = 120000 + 30000 * c;	/* 600 .. 1650 us */
		req[c].enabled = true;
		req[c].inversed = false;
	}
	for (i = 0; i < n; i++) {
		req[i % PRU_PWM_CHANNELS].duty = 120000 + (i * 7919) % 360000;
		if (pru_pwm_table_build(req, bit, PRU_PWM_CHANNELS, &t))
			return 1;
		sum += t.steps;
	}
	printf("%lu updates, %lu steps\n", n, sum);
	return 0;
}
