// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_encoder - a quadrature encoder on the BeagleBone's PRU0, as a counter
 * device (Documentation/encoder.rst)
 *
 * The firmware (pru_encoder-pru0.elf, protocol in pru_encoder_proto.h)
 * decodes A and B x4, and an optional index, from three PRU0 R31 inputs and
 * keeps the count, its limits and counters of what happened in its control
 * block.  Here: one counter device (the kernel's counter subsystem, as the
 * mainline ti-eqep driver has), one count "position" with the quadrature x4
 * function and the signals A, B and (where the node names one) index, and
 * counter events for /dev/counterN's readers:
 *
 *   COUNTER_EVENT_OVERFLOW         channel 0  a step up from the ceiling
 *   COUNTER_EVENT_UNDERFLOW        channel 0  a step down from the floor
 *   COUNTER_EVENT_INDEX            channel 0  an index rising edge
 *   COUNTER_EVENT_CHANGE_OF_STATE  channel 0  the direction changed
 *   COUNTER_EVENT_CHANGE_OF_STATE  channel 1  a skipped state (A and B both
 *                                             changed between two samples)
 *
 *   COUNTER_EVENT_DIRECTION_CHANGE channel 0  the direction changed (kernels
 *                                             that have it, 6.15 on; pushed
 *                                             with the change of state)
 *
 * Each (event, channel) pair means one thing on every kernel: channel 1 of
 * COUNTER_EVENT_CHANGE_OF_STATE is the decoder's own state, which no event
 * of the counter subsystem names.  Skipped states are counted in the
 * count's extension "skipped_states".  The PRU strobes its event only while
 * the driver has armed it: a burst costs one interrupt
 * (pru_encoder_proto.h).  A core stopped behind the driver's back is told by
 * the layer (prukit_pru_notify_stop(): at once for a stop, within
 * PRUKIT_PRU_WATCH_MS for a crash report): every callback then fails with
 * -EPIPE, and every event is pushed once, so that a reader blocked on
 * /dev/counterN wakes and gets the events with the error of its watched
 * components.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/counter.h>
#include <linux/device.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/property.h>

#include "compat.h"
#include "prukit_pru.h"
#include "pru_encoder_proto.h"

#define PRU_ENC_EVENT_NAME	"encoder"

/* the counter's event channels */
#define PRU_ENC_CHAN_COUNT	0
#define PRU_ENC_CHAN_SKIP	1

enum pru_enc_signal_id { PRU_ENC_SIG_A, PRU_ENC_SIG_B, PRU_ENC_SIG_INDEX };

/**
 * struct pru_enc - one encoder
 * @dev: the platform device
 * @pru: PRU0
 * @ctrl: its control block
 * @counter: the counter device (its private data is this structure)
 * @lock: serialises commands and the cached settings
 * @enabled: counting (the firmware's state, as last commanded)
 * @stopped: the core stopped behind the driver's back: -EPIPE from now on
 * @seen: the firmware's overflows, underflows, indexes, reversals and
 *	skips when the interrupt handler last looked (handler only)
 * @signals: A, B and, with an index input, index
 * @synapses: one per signal
 * @count: the position
 */
struct pru_enc {
	struct device *dev;
	struct prukit_pru *pru;
	void __iomem *ctrl;
	struct counter_device *counter;
	struct mutex lock;	/* protects commands and @enabled */
	bool enabled;
	bool stopped;
	u32 seen[5];
	struct counter_signal signals[3];
	struct counter_synapse synapses[3];
	struct counter_count count;
};

#define CTRL(field)	offsetof(struct pru_enc_ctrl, field)

static u32 pru_enc_read(struct pru_enc *enc, size_t off)
{
	return readl(enc->ctrl + off);
}

/* The core still runs what the driver booted; else -EPIPE (once logged). */
static int pru_enc_alive(struct pru_enc *enc)
{
	if (!READ_ONCE(enc->stopped) && prukit_pru_running(enc->pru))
		return 0;
	if (!xchg(&enc->stopped, true))
		dev_err(enc->dev, "PRU0 stopped behind the driver's back: unbind and bind the driver to count again\n");
	return -EPIPE;
}

/* A command, with @lock held; the firmware's refusal is -EINVAL. */
static int pru_enc_command(struct pru_enc *enc, u16 opcode)
{
	int ret;

	lockdep_assert_held(&enc->lock);
	ret = pru_enc_alive(enc);
	if (ret)
		return ret;
	ret = prukit_pru_ctrl_command(enc->pru, enc->ctrl, opcode, PRUKIT_PRU_TIMEOUT_MS);
	if (ret > 0)
		return -EINVAL;
	return ret;
}

static const enum counter_function pru_enc_functions[] = {
	COUNTER_FUNCTION_QUADRATURE_X4,
};

static const enum counter_synapse_action pru_enc_ab_actions[] = {
	COUNTER_SYNAPSE_ACTION_BOTH_EDGES,
};

static const enum counter_synapse_action pru_enc_index_actions[] = {
	COUNTER_SYNAPSE_ACTION_NONE,
};

static int pru_enc_signal_read(struct counter_device *counter, struct counter_signal *signal,
			       enum counter_signal_level *level)
{
	struct pru_enc *enc = counter_priv(counter);
	u32 pins = pru_enc_read(enc, CTRL(pins)), bit;
	int ret = pru_enc_alive(enc);

	if (ret)
		return ret;
	switch (signal->id) {
	case PRU_ENC_SIG_A:
		bit = PRU_ENC_PIN_A(pins);
		break;
	case PRU_ENC_SIG_B:
		bit = PRU_ENC_PIN_B(pins);
		break;
	default:
		bit = PRU_ENC_PIN_I(pins);
		break;
	}
	*level = pru_enc_read(enc, CTRL(inputs)) & BIT(bit - PRU_ENC_WIN_FIRST) ?
		 COUNTER_SIGNAL_LEVEL_HIGH : COUNTER_SIGNAL_LEVEL_LOW;
	return 0;
}

static int pru_enc_count_read(struct counter_device *counter, struct counter_count *count,
			      u64 *val)
{
	struct pru_enc *enc = counter_priv(counter);
	int ret = pru_enc_alive(enc);

	if (ret)
		return ret;
	*val = pru_enc_read(enc, CTRL(count));
	return 0;
}

static int pru_enc_count_write(struct counter_device *counter, struct counter_count *count,
			       u64 val)
{
	struct pru_enc *enc = counter_priv(counter);
	int ret;

	mutex_lock(&enc->lock);
	if (val < pru_enc_read(enc, CTRL(floor)) || val > pru_enc_read(enc, CTRL(ceiling))) {
		ret = -EINVAL;
	} else {
		writel(val, enc->ctrl + CTRL(value));
		ret = pru_enc_command(enc, PRU_ENC_CMD_SET_COUNT);
	}
	mutex_unlock(&enc->lock);
	return ret;
}

static int pru_enc_function_read(struct counter_device *counter, struct counter_count *count,
				 enum counter_function *function)
{
	*function = COUNTER_FUNCTION_QUADRATURE_X4;
	return 0;
}

/* The one function: the core refuses the others (-EINVAL) before this. */
static int pru_enc_function_write(struct counter_device *counter, struct counter_count *count,
				  enum counter_function function)
{
	return function == COUNTER_FUNCTION_QUADRATURE_X4 ? 0 : -EINVAL;
}

static int pru_enc_action_read(struct counter_device *counter, struct counter_count *count,
			       struct counter_synapse *synapse,
			       enum counter_synapse_action *action)
{
	*action = synapse->signal->id == PRU_ENC_SIG_INDEX ? COUNTER_SYNAPSE_ACTION_NONE :
		  COUNTER_SYNAPSE_ACTION_BOTH_EDGES;
	return 0;
}

static int pru_enc_watch_validate(struct counter_device *counter,
				  const struct counter_watch *watch)
{
	struct pru_enc *enc = counter_priv(counter);

	switch (watch->event) {
	case COUNTER_EVENT_OVERFLOW:
	case COUNTER_EVENT_UNDERFLOW:
		return watch->channel == PRU_ENC_CHAN_COUNT ? 0 : -EINVAL;
	case COUNTER_EVENT_INDEX:
		return watch->channel == PRU_ENC_CHAN_COUNT &&
		       enc->count.num_synapses > PRU_ENC_SIG_INDEX ? 0 : -EINVAL;
	case COUNTER_EVENT_CHANGE_OF_STATE:
		return watch->channel <= PRU_ENC_CHAN_SKIP ? 0 : -EINVAL;
	default:
		if (PRUKIT_COUNTER_DIRECTION_CHANGE &&
		    watch->event == PRUKIT_COUNTER_EVENT_DIRECTION_CHANGE)
			return watch->channel == PRU_ENC_CHAN_COUNT ? 0 : -EINVAL;
		return -EINVAL;
	}
}

static const struct counter_ops pru_enc_ops = {
	.signal_read = pru_enc_signal_read,
	.count_read = pru_enc_count_read,
	.count_write = pru_enc_count_write,
	.function_read = pru_enc_function_read,
	.function_write = pru_enc_function_write,
	.action_read = pru_enc_action_read,
	.watch_validate = pru_enc_watch_validate,
};

static int pru_enc_limit_read(struct pru_enc *enc, size_t off, u64 *val)
{
	int ret = pru_enc_alive(enc);

	if (ret)
		return ret;
	*val = pru_enc_read(enc, off);
	return 0;
}

static int pru_enc_limits_write(struct pru_enc *enc, u64 ceiling, u64 floor)
{
	u32 count;
	int ret;

	lockdep_assert_held(&enc->lock);
	if (ceiling > U32_MAX || floor > ceiling)
		return -EINVAL;
	count = pru_enc_read(enc, CTRL(count));
	if (count < floor || count > ceiling)
		return -EINVAL;
	writel(ceiling, enc->ctrl + CTRL(set_ceiling));
	writel(floor, enc->ctrl + CTRL(set_floor));
	ret = pru_enc_command(enc, PRU_ENC_CMD_SET_LIMITS);
	return ret;
}

static int pru_enc_ceiling_read(struct counter_device *counter, struct counter_count *count,
				u64 *val)
{
	return pru_enc_limit_read(counter_priv(counter), CTRL(ceiling), val);
}

static int pru_enc_ceiling_write(struct counter_device *counter, struct counter_count *count,
				 u64 val)
{
	struct pru_enc *enc = counter_priv(counter);
	int ret;

	mutex_lock(&enc->lock);
	ret = pru_enc_limits_write(enc, val, pru_enc_read(enc, CTRL(floor)));
	mutex_unlock(&enc->lock);
	return ret;
}

static int pru_enc_floor_read(struct counter_device *counter, struct counter_count *count,
			      u64 *val)
{
	return pru_enc_limit_read(counter_priv(counter), CTRL(floor), val);
}

static int pru_enc_floor_write(struct counter_device *counter, struct counter_count *count,
			       u64 val)
{
	struct pru_enc *enc = counter_priv(counter);
	int ret;

	mutex_lock(&enc->lock);
	ret = pru_enc_limits_write(enc, pru_enc_read(enc, CTRL(ceiling)), val);
	mutex_unlock(&enc->lock);
	return ret;
}

static int pru_enc_enable_read(struct counter_device *counter, struct counter_count *count,
			       u8 *enable)
{
	struct pru_enc *enc = counter_priv(counter);
	int ret = pru_enc_alive(enc);

	if (ret)
		return ret;
	*enable = pru_enc_read(enc, CTRL(state)) == PRU_ENC_STATE_COUNTING;
	return 0;
}

static int pru_enc_enable_write(struct counter_device *counter, struct counter_count *count,
				u8 enable)
{
	struct pru_enc *enc = counter_priv(counter);
	int ret = pru_enc_alive(enc);

	if (ret)
		return ret;
	mutex_lock(&enc->lock);
	if (enable != enc->enabled) {
		ret = pru_enc_command(enc, enable ? PRU_ENC_CMD_ENABLE : PRU_ENC_CMD_DISABLE);
		if (!ret)
			enc->enabled = enable;
	}
	mutex_unlock(&enc->lock);
	return ret;
}

static int pru_enc_direction_read(struct counter_device *counter, struct counter_count *count,
				  u32 *direction)
{
	struct pru_enc *enc = counter_priv(counter);
	int ret = pru_enc_alive(enc);

	if (ret)
		return ret;
	*direction = pru_enc_read(enc, CTRL(direction)) ? COUNTER_COUNT_DIRECTION_BACKWARD :
			COUNTER_COUNT_DIRECTION_FORWARD;
	return 0;
}

static int pru_enc_skipped_read(struct counter_device *counter, struct counter_count *count,
				u64 *val)
{
	return pru_enc_limit_read(counter_priv(counter), CTRL(skips), val);
}

static struct counter_comp pru_enc_count_ext[] = {
	COUNTER_COMP_CEILING(pru_enc_ceiling_read, pru_enc_ceiling_write),
	COUNTER_COMP_FLOOR(pru_enc_floor_read, pru_enc_floor_write),
	COUNTER_COMP_ENABLE(pru_enc_enable_read, pru_enc_enable_write),
	COUNTER_COMP_DIRECTION(pru_enc_direction_read),
	COUNTER_COMP_COUNT_U64("skipped_states", pru_enc_skipped_read, NULL),
};

/* The firmware's counters, in the order of struct pru_enc's @seen */
#define PRU_ENC_EV_REVERSAL	3
static const struct {
	size_t off;
	u8 event;
	u8 channel;
} pru_enc_events[] = {
	{ CTRL(overflows), COUNTER_EVENT_OVERFLOW, PRU_ENC_CHAN_COUNT },
	{ CTRL(underflows), COUNTER_EVENT_UNDERFLOW, PRU_ENC_CHAN_COUNT },
	{ CTRL(indexes), COUNTER_EVENT_INDEX, PRU_ENC_CHAN_COUNT },
	{ CTRL(reversals), COUNTER_EVENT_CHANGE_OF_STATE, PRU_ENC_CHAN_COUNT },
	{ CTRL(skips), COUNTER_EVENT_CHANGE_OF_STATE, PRU_ENC_CHAN_SKIP },
};

/* Event @i of pru_enc_events, and a reversal's standard event where the kernel has it */
static void pru_enc_push(struct pru_enc *enc, unsigned int i)
{
	counter_push_event(enc->counter, pru_enc_events[i].event, pru_enc_events[i].channel);
	if (PRUKIT_COUNTER_DIRECTION_CHANGE && i == PRU_ENC_EV_REVERSAL)
		counter_push_event(enc->counter, PRUKIT_COUNTER_EVENT_DIRECTION_CHANGE,
				   PRU_ENC_CHAN_COUNT);
}

static irqreturn_t pru_enc_irq(int irq, void *data)
{
	struct pru_enc *enc = data;
	unsigned int i;

	/* arm first: what happens after the reads below strobes again */
	writel(1, enc->ctrl + CTRL(irq_armed));
	for (i = 0; i < ARRAY_SIZE(pru_enc_events); i++) {
		u32 now = pru_enc_read(enc, pru_enc_events[i].off);

		if (now == enc->seen[i])
			continue;
		enc->seen[i] = now;
		pru_enc_push(enc, i);
	}
	return IRQ_HANDLED;
}

/* The layer says the core stopped: it strobes nothing any more; tell the readers, with errors */
static void pru_enc_stopped(void *data)
{
	struct pru_enc *enc = data;
	unsigned int i;

	pru_enc_alive(enc);
	for (i = 0; i < ARRAY_SIZE(pru_enc_events); i++)
		pru_enc_push(enc, i);
}

/* "prukit,input-bits": A, B and optionally the index, R31 bits 14..16 */
static int pru_enc_pins(struct pru_enc *enc, u32 *pins)
{
	struct device *dev = enc->dev;
	u32 bits[3] = { 0, 0, PRU_ENC_PIN_NONE };
	int n, i;

	n = device_property_count_u32(dev, "prukit,input-bits");
	if (n != 2 && n != 3)
		return dev_err_probe(dev, -EINVAL,
				     "prukit,input-bits: want <A B> or <A B index>, R31 bits %u..%u\n",
				     PRU_ENC_WIN_FIRST, PRU_ENC_WIN_LAST);
	n = device_property_read_u32_array(dev, "prukit,input-bits", bits, n) ?: n;
	if (n < 0)
		return dev_err_probe(dev, n, "cannot read prukit,input-bits\n");
	for (i = 0; i < 3; i++) {
		if (i == 2 && bits[i] == PRU_ENC_PIN_NONE)
			break;
		if (bits[i] < PRU_ENC_WIN_FIRST || bits[i] > PRU_ENC_WIN_LAST ||
		    (i && bits[i] == bits[0]) || (i == 2 && bits[2] == bits[1]))
			return dev_err_probe(dev, -EINVAL,
					     "prukit,input-bits: %u: bits %u..%u, each once\n",
					     bits[i], PRU_ENC_WIN_FIRST, PRU_ENC_WIN_LAST);
	}
	*pins = PRU_ENC_PINS(bits[0], bits[1], bits[2]);
	return bits[2] == PRU_ENC_PIN_NONE ? 2 : 3;
}

static int pru_enc_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct counter_device *counter;
	struct pru_enc *enc;
	int nsig, event, ret, i;
	u32 pins;

	counter = devm_counter_alloc(dev, sizeof(*enc));
	if (!counter)
		return -ENOMEM;
	enc = counter_priv(counter);
	enc->dev = dev;
	enc->counter = counter;
	mutex_init(&enc->lock);

	nsig = pru_enc_pins(enc, &pins);
	if (nsig < 0)
		return nsig;
	event = prukit_pru_event(dev, PRU_ENC_EVENT_NAME);
	if (event < 0)
		return event;
	enc->pru = devm_prukit_pru_get(dev, 0);
	if (IS_ERR(enc->pru))
		return PTR_ERR(enc->pru);
	prukit_pru_notify_stop(enc->pru, pru_enc_stopped, enc);

	ret = prukit_pru_boot(enc->pru, NULL);
	if (ret)
		return ret;
	enc->ctrl = prukit_pru_map(enc->pru, PRUKIT_CTRL_DA, sizeof(struct pru_enc_ctrl));
	if (!enc->ctrl)
		return dev_err_probe(dev, -ENOMEM, "cannot map the control block\n");
	ret = prukit_pru_ctrl_check(enc->pru, enc->ctrl, PRU_ENC_MAGIC, PRU_ENC_VERSION,
				    sizeof(struct pru_enc_ctrl));
	if (ret)
		return ret;
	ret = prukit_pru_ctrl_wait_ready(enc->pru, enc->ctrl, PRUKIT_PRU_TIMEOUT_MS);
	if (ret)
		return ret;
	for (i = 0; i < ARRAY_SIZE(pru_enc_events); i++)
		enc->seen[i] = pru_enc_read(enc, pru_enc_events[i].off);
	writel(pins, enc->ctrl + CTRL(pins));
	writel(event, enc->ctrl + CTRL(event));
	mutex_lock(&enc->lock);
	ret = pru_enc_command(enc, PRU_ENC_CMD_CONFIG);
	mutex_unlock(&enc->lock);
	if (ret)
		return dev_err_probe(dev, ret, "the firmware refused the configuration\n");

	enc->signals[PRU_ENC_SIG_A] = (struct counter_signal){ .id = PRU_ENC_SIG_A, .name = "A" };
	enc->signals[PRU_ENC_SIG_B] = (struct counter_signal){ .id = PRU_ENC_SIG_B, .name = "B" };
	enc->signals[PRU_ENC_SIG_INDEX] =
		(struct counter_signal){ .id = PRU_ENC_SIG_INDEX, .name = "index" };
	for (i = 0; i < nsig; i++) {
		enc->synapses[i].signal = &enc->signals[i];
		enc->synapses[i].actions_list = i == PRU_ENC_SIG_INDEX ? pru_enc_index_actions :
						pru_enc_ab_actions;
		enc->synapses[i].num_actions = 1;
	}
	enc->count.id = 0;
	enc->count.name = "position";
	enc->count.functions_list = pru_enc_functions;
	enc->count.num_functions = ARRAY_SIZE(pru_enc_functions);
	enc->count.synapses = enc->synapses;
	enc->count.num_synapses = nsig;
	enc->count.ext = pru_enc_count_ext;
	enc->count.num_ext = ARRAY_SIZE(pru_enc_count_ext);

	counter->name = dev_name(dev);
	counter->parent = dev;
	counter->ops = &pru_enc_ops;
	counter->signals = enc->signals;
	counter->num_signals = nsig;
	counter->counts = &enc->count;
	counter->num_counts = 1;

	ret = devm_prukit_pru_request_irq(dev, PRU_ENC_EVENT_NAME, pru_enc_irq, NULL, 0, enc);
	if (ret < 0)
		return ret;
	writel(1, enc->ctrl + CTRL(irq_armed));

	ret = devm_counter_add(dev, counter);
	if (ret)
		return dev_err_probe(dev, ret, "cannot add the counter device\n");
	dev_info(dev, "%s: quadrature x4 on PRU0 R31 bits %u/%u%s, event %d\n",
		 dev_name(&counter->dev), PRU_ENC_PIN_A(pins), PRU_ENC_PIN_B(pins),
		 nsig == 3 ? ", index" : "", event);
	return 0;
}

static const struct of_device_id pru_enc_of_match[] = {
	{ .compatible = "prukit,pru-encoder" },
	{ }
};
MODULE_DEVICE_TABLE(of, pru_enc_of_match);

static struct platform_driver pru_enc_driver = {
	.probe = pru_enc_probe,
	.driver = {
		.name = "pru_encoder",
		.of_match_table = pru_enc_of_match,
	},
};
module_platform_driver(pru_enc_driver);

PRUKIT_IMPORT_NS();
PRUKIT_IMPORT_NS_COUNTER();
MODULE_DESCRIPTION("Quadrature encoder on the BeagleBone's PRU0 as a counter device");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
