// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_pwm_table.c - the table of one period of every channel
 * (Documentation/pru_pwm.rst, "Timing").
 *
 * Every enabled channel is active from the period's start to its duty
 * cycle and inactive for the rest (active is high, or low for inversed
 * polarity); a disabled channel stays at its inactive level.  The table
 * has a step at 0 and one at each distinct time a channel goes inactive.
 * The firmware writes a step exactly at its time when it comes at least
 * PRU_PWM_MIN_GAP cycles after the step before it and PRU_PWM_END_GAP
 * cycles before the period's end; so, in time order, a channel's end that
 * would break that is rounded down, as the PWM core asks of drivers: to
 * the step before it (the two channels' ends are then one write), or to
 * PRU_PWM_END_GAP cycles before the period's end.  Ends in the same cycle
 * are one write and need no rounding.  The table records what each
 * channel then does (struct pru_pwm_chan), which is what the driver
 * reports.
 */
#include <linux/errno.h>
#include <linux/minmax.h>
#include <linux/string.h>

#include "pru_pwm_table.h"

/* The channel's level at time @at of a period with its duty @duty */
static u32 pru_pwm_level(const struct pru_pwm_req *req, u32 duty, u32 at)
{
	bool active = req->enabled && at < duty;

	return active != req->inversed;
}

/**
 * pru_pwm_table_build() - the table for the channels' states
 * @req: the state of each channel
 * @r30_bit: each channel's R30 bit (0..31)
 * @nchan: channels, 1..PRU_PWM_CHANNELS
 * @t: the table (every field written)
 *
 * Every enabled channel must have the same period,
 * PRU_PWM_MIN_PERIOD..PRU_PWM_MAX_PERIOD; with none enabled the table has
 * PRU_PWM_IDLE_PERIOD.
 *
 * Return: 0, or -EINVAL for channels that break these rules.
 */
int pru_pwm_table_build(const struct pru_pwm_req *req, const u8 *r30_bit,
			unsigned int nchan, struct pru_pwm_table *t)
{
	u32 ends[PRU_PWM_CHANNELS], rounded[PRU_PWM_CHANNELS], duty[PRU_PWM_CHANNELS];
	u32 period = 0, last = 0, limit;
	unsigned int i, j, nends = 0;

	if (!nchan || nchan > PRU_PWM_CHANNELS)
		return -EINVAL;
	for (i = 0; i < nchan; i++) {
		if (!req[i].enabled)
			continue;
		if (req[i].period < PRU_PWM_MIN_PERIOD || req[i].period > PRU_PWM_MAX_PERIOD ||
		    req[i].duty > req[i].period || (period && req[i].period != period))
			return -EINVAL;
		period = req[i].period;
	}
	if (!period)
		period = PRU_PWM_IDLE_PERIOD;
	limit = period - PRU_PWM_END_GAP;

	/* the ends inside the period, in time order (insertion: 8 at most) */
	for (i = 0; i < nchan; i++) {
		u32 d = req[i].duty;

		if (!req[i].enabled || !d || d >= period)
			continue;
		for (j = nends; j > 0 && ends[j - 1] > d; j--)
			ends[j] = ends[j - 1];
		ends[j] = d;
		nends++;
	}
	/* each rounded down: MIN_GAP after the one before, END_GAP before the end */
	for (j = 0; j < nends; j++) {
		u32 e = min(ends[j], limit);

		if (e != last && e - last < PRU_PWM_MIN_GAP)
			e = last;
		rounded[j] = e;
		last = e;
	}
	for (i = 0; i < nchan; i++) {
		duty[i] = req[i].enabled ? req[i].duty : 0;
		if (!duty[i] || duty[i] >= period)
			continue;
		for (j = 0; ends[j] != duty[i]; j++)
			;
		duty[i] = rounded[j];
	}

	memset(t, 0, sizeof(*t));
	t->period = period;
	/* step 0, then one per distinct rounded end (rounded[] is sorted) */
	for (j = 0; j <= nends; j++) {
		u32 at = j ? rounded[j - 1] : 0, r30 = 0;

		if (j && at == t->step[t->steps - 1].at)
			continue;
		for (i = 0; i < nchan; i++)
			r30 |= pru_pwm_level(&req[i], duty[i], at) << r30_bit[i];
		t->step[t->steps].at = at;
		t->step[t->steps].r30 = r30;
		t->steps++;
	}
	for (i = 0; i < nchan; i++) {
		t->chan[i].duty = duty[i];
		t->chan[i].flags = (req[i].enabled ? PRU_PWM_CHAN_ENABLED : 0) |
				   (req[i].inversed ? PRU_PWM_CHAN_INVERSED : 0);
		t->chan[i].period = req[i].enabled ? period : req[i].period;
	}
	return 0;
}
