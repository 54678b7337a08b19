// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_pwm - PWM channels on a BeagleBone PRU, as a PWM chip
 *
 * One "prukit,pru-pwm" node: the core in "ti,prus", the R30 bit of each
 * channel in "prukit,r30-bits" (up to 8; the PRU Cookbook's servo pins are
 * PRU1's bits 8, 10, 9, 11, 6, 7, 4, 5).  The firmware (pru_pwm_proto.h)
 * plays one period of every channel from a table, each R30 write in its
 * cycle of 5 ns; the driver builds the table (pru_pwm_table.c) whenever a
 * channel's state changes, in the table the firmware does not play, and
 * asks for it: the firmware switches at the end of a period, so that a
 * change takes effect at the next period and no pulse is cut short.
 *
 * The channels share one period (the table's): a channel is enabled with
 * another period only while no other one is enabled (-EBUSY otherwise).
 * Periods and duty cycles are rounded down to whole cycles of 5 ns, and an
 * end of a pulse too close to another one, or to the end of the period, is
 * rounded down as Documentation/pru_pwm.rst says; .get_state() reads the
 * table the firmware plays, so it reports what the pins do.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#define PRUKIT_COMPAT_PWM

#include <linux/device.h>
#include <linux/io.h>
#include <linux/math64.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/pwm.h>

#include "compat.h"
#include "prukit_pru.h"
#include "pru_pwm_proto.h"
#include "pru_pwm_table.h"

#define PRU_PWM_NS_PER_CYCLE	5

/**
 * struct pru_pwm - one PRU's PWM channels
 * @dev: the platform device
 * @pru: the core
 * @ctrl: its control block
 * @lock: serialises changes and reads of the tables (the table the
 *	firmware does not play is the driver's while it holds the lock)
 * @req: what each channel was last asked, in cycles
 * @pending_seq: a SET the firmware did not answer in time (0: none); its
 *	table is the firmware's to take until it answers
 * @pending_req: what that SET asked, @req once the firmware took it
 * @r30_bit: each channel's R30 bit
 * @nchan: channels
 */
struct pru_pwm {
	struct device *dev;
	struct prukit_pru *pru;
	struct pru_pwm_ctrl __iomem *ctrl;
	struct mutex lock;	/* see above */
	struct pru_pwm_req req[PRU_PWM_CHANNELS];
	u16 pending_seq;
	struct pru_pwm_req pending_req[PRU_PWM_CHANNELS];
	u8 r30_bit[PRU_PWM_CHANNELS];
	unsigned int nchan;
};

static struct pru_pwm *to_pru_pwm(struct pwm_chip *chip)
{
	return prukit_pwmchip_priv(chip);
}

/* The table the firmware plays: 0, 1, or -EPIPE when it plays none */
static int pru_pwm_active(struct pru_pwm *pp)
{
	u32 active = readl(&pp->ctrl->active);

	return active < 2 ? active : -EPIPE;
}

/*
 * A SET that timed out is still the firmware's: it may take that table at
 * the end of any later period.  Until it answers, the driver writes neither
 * that table nor another command (-EBUSY); once it answered, what that SET
 * asked is what the channels do.
 */
static int pru_pwm_settle(struct pru_pwm *pp)
{
	int ret;

	lockdep_assert_held(&pp->lock);
	if (!pp->pending_seq)
		return 0;
	if (!prukit_pru_running(pp->pru))
		return -EPIPE;
	ret = prukit_pru_ctrl_answer(pp->ctrl, pp->pending_seq);
	if (ret == -EAGAIN) {
		dev_err_ratelimited(pp->dev,
				    "the firmware has not taken the table it was sent yet: changes refused until it does\n");
		return -EBUSY;
	}
	pp->pending_seq = 0;
	if (ret) {
		dev_err(pp->dev, "the firmware refused a table, late: %d\n", ret);
		return 0;
	}
	memcpy(pp->req, pp->pending_req, sizeof(pp->req));
	dev_info(pp->dev, "the firmware took the table it was sent late: the channels play it\n");
	return 0;
}

/*
 * Build the table for @req in the table the firmware does not play and
 * switch to it; waits for the switch (at most a period).  No SET may be
 * pending (pru_pwm_settle()).
 */
static int pru_pwm_commit(struct pru_pwm *pp, const struct pru_pwm_req *req)
{
	struct pru_pwm_table t;
	int active, seq, ret;
	u32 next, period;

	lockdep_assert_held(&pp->lock);
	if (!prukit_pru_running(pp->pru))
		return -EPIPE;
	if (WARN_ON_ONCE(pp->pending_seq))	/* callers settle first */
		return -EBUSY;
	ret = pru_pwm_table_build(req, pp->r30_bit, pp->nchan, &t);
	if (ret)
		return ret;
	active = pru_pwm_active(pp);
	next = active == 0 ? 1 : 0;
	memcpy_toio(&pp->ctrl->table[next], &t, sizeof(t));
	writel(next, &pp->ctrl->next);
	seq = prukit_pru_ctrl_post(pp->pru, pp->ctrl, PRU_PWM_CMD_SET);
	if (seq < 0)
		return seq;
	/* the firmware answers at the end of the period it plays (200000 cycles a ms) */
	period = active < 0 ? 0 : readl(&pp->ctrl->table[active].period);
	ret = prukit_pru_ctrl_wait(pp->pru, pp->ctrl, seq,
				   PRUKIT_PRU_TIMEOUT_MS + DIV_ROUND_UP(period, 200000));
	if (ret == -ETIMEDOUT) {
		pp->pending_seq = seq;
		memcpy(pp->pending_req, req, sizeof(pp->pending_req));
	} else if (ret > 0) {
		dev_err(pp->dev, "the firmware refused table %u: %d\n", next, ret);
		return -EPROTO;
	}
	return ret;
}

static int pru_pwm_apply(struct pwm_chip *chip, struct pwm_device *pwm,
			 const struct pwm_state *state)
{
	struct pru_pwm *pp = to_pru_pwm(chip);
	struct pru_pwm_req req[PRU_PWM_CHANNELS];
	struct pru_pwm_req *r = &req[pwm->hwpwm];
	u64 period = div_u64(state->period, PRU_PWM_NS_PER_CYCLE);
	u64 duty = div_u64(state->duty_cycle, PRU_PWM_NS_PER_CYCLE);
	unsigned int i;
	int ret;

	/* rounded down, as the PWM core asks */
	period = min_t(u64, period, PRU_PWM_MAX_PERIOD);
	duty = min(duty, period);
	if (state->enabled && period < PRU_PWM_MIN_PERIOD)
		return -EINVAL;

	mutex_lock(&pp->lock);
	ret = pru_pwm_settle(pp);
	if (ret) {
		mutex_unlock(&pp->lock);
		return ret;
	}
	memcpy(req, pp->req, sizeof(req));
	r->period = period;
	r->duty = duty;
	r->enabled = state->enabled;
	r->inversed = state->polarity == PWM_POLARITY_INVERSED;
	ret = 0;
	for (i = 0; i < pp->nchan && r->enabled; i++)
		if (i != pwm->hwpwm && req[i].enabled && req[i].period != r->period)
			ret = -EBUSY;	/* one period for every enabled channel */
	if (!ret)
		ret = pru_pwm_commit(pp, req);
	if (!ret)
		pp->req[pwm->hwpwm] = *r;
	mutex_unlock(&pp->lock);
	return ret;
}

static int pru_pwm_get_state(struct pwm_chip *chip, struct pwm_device *pwm,
			     struct pwm_state *state)
{
	struct pru_pwm *pp = to_pru_pwm(chip);
	struct pru_pwm_chan __iomem *c;
	int active;
	u32 flags;

	mutex_lock(&pp->lock);
	active = pru_pwm_active(pp);
	if (active < 0) {
		mutex_unlock(&pp->lock);
		state->enabled = false;
		return 0;
	}
	c = &pp->ctrl->table[active].chan[pwm->hwpwm];
	flags = readl(&c->flags);
	state->period = (u64)readl(&c->period) * PRU_PWM_NS_PER_CYCLE;
	state->duty_cycle = (u64)readl(&c->duty) * PRU_PWM_NS_PER_CYCLE;
	state->enabled = flags & PRU_PWM_CHAN_ENABLED;
	state->polarity = flags & PRU_PWM_CHAN_INVERSED ? PWM_POLARITY_INVERSED :
			  PWM_POLARITY_NORMAL;
	mutex_unlock(&pp->lock);
	return 0;
}

PRUKIT_PWM_DEFINE_GET_STATE(pru_pwm_get_state)

static const struct pwm_ops pru_pwm_ops = {
	.apply = pru_pwm_apply,
	PRUKIT_PWM_GET_STATE(pru_pwm_get_state),
	PRUKIT_PWM_OPS_OWNER
};

static int pru_pwm_start(struct pru_pwm *pp)
{
	struct pru_pwm_ctrl __iomem *ctrl;
	int ret;

	ret = prukit_pru_boot(pp->pru, NULL);
	if (ret)
		return ret;
	ctrl = prukit_pru_map(pp->pru, PRUKIT_CTRL_DA, sizeof(*ctrl));
	if (!ctrl)
		return -EPROTO;
	ret = prukit_pru_ctrl_check(pp->pru, ctrl, PRU_PWM_MAGIC, PRU_PWM_VERSION,
				    sizeof(*ctrl));
	if (ret)
		return ret;
	ret = prukit_pru_ctrl_wait_ready(pp->pru, ctrl, PRUKIT_PRU_TIMEOUT_MS);
	if (ret)
		return ret;
	pp->ctrl = ctrl;
	/* every channel disabled, at its inactive level (low) */
	mutex_lock(&pp->lock);
	ret = pru_pwm_commit(pp, pp->req);
	mutex_unlock(&pp->lock);
	return ret;
}

/*
 * Before the core stops (the driver's unbind): every channel disabled, so
 * that the pins are left at their inactive levels, not wherever the last
 * period left R30 (bounded wait; nothing to do for a core stopped already).
 */
static void pru_pwm_quiet(void *data)
{
	struct pru_pwm *pp = data;
	unsigned int i;

	mutex_lock(&pp->lock);
	if (!pru_pwm_settle(pp)) {
		for (i = 0; i < pp->nchan; i++)
			pp->req[i].enabled = false;
		pru_pwm_commit(pp, pp->req);
	}
	mutex_unlock(&pp->lock);
}

static int pru_pwm_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct pwm_chip *chip;
	struct pru_pwm *pp;
	u32 bits[PRU_PWM_CHANNELS];
	int n, i, ret;

	n = of_property_count_u32_elems(dev->of_node, "prukit,r30-bits");
	if (n < 1 || n > PRU_PWM_CHANNELS)
		return dev_err_probe(dev, -EINVAL,
				     "prukit,r30-bits: 1 to %d R30 bits, one per channel\n",
				     PRU_PWM_CHANNELS);
	ret = of_property_read_u32_array(dev->of_node, "prukit,r30-bits", bits, n);
	if (ret)
		return dev_err_probe(dev, ret, "prukit,r30-bits\n");

	chip = prukit_devm_pwmchip_alloc(dev, n, sizeof(*pp));
	if (IS_ERR(chip))
		return PTR_ERR(chip);
	pp = to_pru_pwm(chip);
	pp->dev = dev;
	pp->nchan = n;
	mutex_init(&pp->lock);
	for (i = 0; i < n; i++) {
		int j;

		if (bits[i] > 15)
			return dev_err_probe(dev, -EINVAL,
					     "channel %d: R30 bit %u is no output pin (0..15)\n",
					     i, bits[i]);
		for (j = 0; j < i; j++)
			if (bits[j] == bits[i])
				return dev_err_probe(dev, -EINVAL,
						     "channels %d and %d: the same R30 bit %u\n",
						     j, i, bits[i]);
		pp->r30_bit[i] = bits[i];
		pp->req[i].period = PRU_PWM_IDLE_PERIOD;
	}

	pp->pru = devm_prukit_pru_get(dev, 0);
	if (IS_ERR(pp->pru))
		return PTR_ERR(pp->pru);
	ret = pru_pwm_start(pp);
	if (ret)
		return dev_err_probe(dev, ret, "starting the PRU's firmware\n");
	ret = devm_add_action_or_reset(dev, pru_pwm_quiet, pp);
	if (ret)
		return ret;

	chip->ops = &pru_pwm_ops;
	prukit_pwmchip_of_cells(chip);
	ret = prukit_devm_pwmchip_add(dev, chip);
	if (ret)
		return dev_err_probe(dev, ret, "adding the PWM chip\n");
	dev_info(dev, "%d PWM channels on R30 of %s, 5 ns steps, periods %u ns to %u s\n",
		 n, dev_name(&pp->pru->rproc->dev), PRU_PWM_MIN_PERIOD * PRU_PWM_NS_PER_CYCLE,
		 PRU_PWM_MAX_PERIOD / (1000000000 / PRU_PWM_NS_PER_CYCLE));
	return 0;
}

static const struct of_device_id pru_pwm_of_match[] = {
	{ .compatible = "prukit,pru-pwm" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_pwm_of_match);

static struct platform_driver pru_pwm_driver = {
	.probe = pru_pwm_probe,
	.driver = {
		.name = "pru_pwm",
		.of_match_table = pru_pwm_of_match,
	},
};
module_platform_driver(pru_pwm_driver);

PRUKIT_IMPORT_NS();
MODULE_DESCRIPTION("PWM channels on the BeagleBone's PRUs");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
