// SPDX-License-Identifier: GPL-2.0-only
/*
 * pwm_table - drivers/pru_pwm/pru_pwm_table.c, unchanged, on the host: the
 * table the driver would give the firmware for some channels' states.
 *
 *   pwm_table OUT CHANNEL...
 *
 * CHANNEL is BIT:PERIOD:DUTY:FLAGS, cycles, FLAGS a combination of e
 * (enabled) and i (inversed) or "-".  Writes the struct pru_pwm_table to
 * OUT and prints one line per step and per channel; exit status 1 (and
 * "EINVAL") where the driver would refuse the states.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pru_pwm_table.h"

int main(int argc, char **argv)
{
	struct pru_pwm_req req[PRU_PWM_CHANNELS];
	u8 bit[PRU_PWM_CHANNELS];
	struct pru_pwm_table t;
	unsigned int n = argc - 2, i;
	FILE *f;

	if (argc < 3 || n > PRU_PWM_CHANNELS) {
		fprintf(stderr, "usage: pwm_table OUT BIT:PERIOD:DUTY:FLAGS... (1..%d)\n",
			PRU_PWM_CHANNELS);
		return 2;
	}
	for (i = 0; i < n; i++) {
		unsigned int b, p, d;
		char flags[8];

		if (sscanf(argv[i + 2], "%u:%u:%u:%7s", &b, &p, &d, flags) != 4 || b > 31) {
			fprintf(stderr, "pwm_table: bad channel '%s'\n", argv[i + 2]);
			return 2;
		}
		bit[i] = b;
		req[i].period = p;
		req[i].duty = d;
		req[i].enabled = strchr(flags, 'e');
		req[i].inversed = strchr(flags, 'i');
	}
	if (pru_pwm_table_build(req, bit, n, &t)) {
		puts("EINVAL");
		return 1;
	}
	f = fopen(argv[1], "wb");
	if (!f || fwrite(&t, sizeof(t), 1, f) != 1 || fclose(f)) {
		perror(argv[1]);
		return 2;
	}
	printf("period %u steps %u\n", t.period, t.steps);
	for (i = 0; i < t.steps; i++)
		printf("step %u at %u r30 0x%x\n", i, t.step[i].at, t.step[i].r30);
	for (i = 0; i < n; i++)
		printf("chan %u duty %u period %u flags %u\n", i, t.chan[i].duty,
		       t.chan[i].period, t.chan[i].flags);
	return 0;
}
