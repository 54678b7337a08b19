// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_sim - the simulated PRU-ICSS INTC as a Linux interrupt controller
 *
 * Cells as the TI PRUSS INTC binding: <system-event channel host-interrupt>.
 * Translating a specifier programs the simulated INTC the way the real
 * irqchip driver programs the hardware (event -> channel -> host, enables).
 * Host interrupts 2..9 are the ones wired to the ARM: after each slice the
 * simulation thread takes the events pending on them out of the INTC (as an
 * ARM handler clearing them through SICR would) and an irq_work delivers
 * them in hard interrupt context.  Marking an event pending with
 * irq_set_irqchip_state() raises it in the simulator: that is how a kick
 * reaches the PRU.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/irqdomain.h>
#include <linux/of.h>

#include "pru_sim.h"

/* INTC registers, offsets from the PRU-ICSS base (ARM view) */
#define PRU_SIM_INTC		0x20000
#define INTC_GER		(PRU_SIM_INTC + 0x010)
#define INTC_SICR		(PRU_SIM_INTC + 0x024)
#define INTC_EISR		(PRU_SIM_INTC + 0x028)
#define INTC_HIEISR		(PRU_SIM_INTC + 0x034)
#define INTC_CMR(ev)		(PRU_SIM_INTC + 0x400 + ((ev) & ~3))
#define INTC_HMR(ch)		(PRU_SIM_INTC + 0x800 + ((ch) & ~3))

#define PRU_SIM_FIRST_ARM_HOST	2

static void pru_sim_intc_write(struct pru_sim *sim, u32 reg, u32 val)
{
	prusim_host_write(sim->s, reg, &val, sizeof(val));
}

/* Set byte lane (n & 3) of the map register holding entry n. */
static void pru_sim_intc_set_lane(struct pru_sim *sim, u32 reg, unsigned int n, u8 val)
{
	unsigned int shift = (n & 3) * 8;
	u32 v = 0;

	prusim_host_read(sim->s, reg, &v, sizeof(v));
	v = (v & ~(0xffU << shift)) | (u32)val << shift;
	pru_sim_intc_write(sim, reg, v);
}

static void pru_sim_intc_map(struct pru_sim *sim, unsigned int ev, unsigned int ch,
			     unsigned int host)
{
	mutex_lock(&sim->lock);
	pru_sim_intc_set_lane(sim, INTC_CMR(ev), ev, ch);
	pru_sim_intc_set_lane(sim, INTC_HMR(ch), ch, host);
	pru_sim_intc_write(sim, INTC_EISR, ev);
	pru_sim_intc_write(sim, INTC_HIEISR, host);
	pru_sim_intc_write(sim, INTC_GER, 1);
	sim->mapped |= BIT_ULL(ev);
	mutex_unlock(&sim->lock);
}

/*
 * Called with the lock held after each slice: take every enabled event
 * pending on an ARM host interrupt out of the INTC and deliver it.
 */
void pru_sim_intc_collect(struct pru_sim *sim)
{
	const struct prusim_intc *intc = &sim->s->intc;
	u64 pending = intc->raw & intc->enabled;
	u64 taken = 0;

	lockdep_assert_held(&sim->lock);

	while (pending) {
		unsigned int ev = __ffs64(pending);
		unsigned int ch = intc->cmr[ev];

		pending &= pending - 1;
		if (ch < PRUSIM_NUM_CHANNELS && intc->hmr[ch] >= PRU_SIM_FIRST_ARM_HOST &&
		    intc->hmr[ch] < PRUSIM_NUM_HOSTS && (intc->hier & BIT(intc->hmr[ch])) &&
		    intc->ger) {
			pru_sim_intc_write(sim, INTC_SICR, ev);
			taken |= BIT_ULL(ev);
		}
	}
	if (taken) {
		atomic64_or(taken, &sim->to_arm);
		irq_work_queue(&sim->irq_work);
	}
}

static void pru_sim_intc_deliver(struct irq_work *work)
{
	struct pru_sim *sim = container_of(work, struct pru_sim, irq_work);
	u64 ev = atomic64_read(&sim->to_arm) & ~atomic64_read(&sim->masked);

	/* Masked events stay in to_arm until unmasked. */
	atomic64_andnot(ev, &sim->to_arm);
	while (ev) {
		unsigned int hwirq = __ffs64(ev);
		unsigned int virq = irq_find_mapping(sim->domain, hwirq);

		ev &= ev - 1;
		if (virq)
			generic_handle_irq(virq);
	}
}

static void pru_sim_irq_mask(struct irq_data *d)
{
	struct pru_sim *sim = irq_data_get_irq_chip_data(d);

	atomic64_or(BIT_ULL(d->hwirq), &sim->masked);
}

static void pru_sim_irq_unmask(struct irq_data *d)
{
	struct pru_sim *sim = irq_data_get_irq_chip_data(d);

	atomic64_andnot(BIT_ULL(d->hwirq), &sim->masked);
	if (atomic64_read(&sim->to_arm) & BIT_ULL(d->hwirq))
		irq_work_queue(&sim->irq_work);
}

static void pru_sim_irq_ack(struct irq_data *d)
{
	/* The event was cleared in the INTC when it was taken. */
}

static int pru_sim_irq_set_irqchip_state(struct irq_data *d, enum irqchip_irq_state which,
					 bool state)
{
	struct pru_sim *sim = irq_data_get_irq_chip_data(d);

	if (which != IRQCHIP_STATE_PENDING)
		return -EINVAL;
	if (state) {
		atomic64_or(BIT_ULL(d->hwirq), &sim->raise);
		pru_sim_kick_thread(sim);
	}
	return 0;
}

static struct irq_chip pru_sim_irq_chip = {
	.name = "pru_sim-intc",
	.irq_ack = pru_sim_irq_ack,
	.irq_mask = pru_sim_irq_mask,
	.irq_unmask = pru_sim_irq_unmask,
	.irq_set_irqchip_state = pru_sim_irq_set_irqchip_state,
};

static int pru_sim_intc_xlate(struct irq_domain *d, struct device_node *node,
			      const u32 *intspec, unsigned int intsize,
			      unsigned long *out_hwirq, unsigned int *out_type)
{
	struct pru_sim *sim = d->host_data;

	if (intsize != 3 || intspec[0] >= PRUSIM_NUM_EVENTS ||
	    intspec[1] >= PRUSIM_NUM_CHANNELS || intspec[2] >= PRUSIM_NUM_HOSTS) {
		dev_err(sim->dev, "bad interrupt specifier <%u %u %u>\n",
			intsize > 0 ? intspec[0] : 0, intsize > 1 ? intspec[1] : 0,
			intsize > 2 ? intspec[2] : 0);
		return -EINVAL;
	}
	pru_sim_intc_map(sim, intspec[0], intspec[1], intspec[2]);
	*out_hwirq = intspec[0];
	*out_type = IRQ_TYPE_EDGE_RISING;
	return 0;
}

static int pru_sim_intc_domain_map(struct irq_domain *d, unsigned int virq,
				   irq_hw_number_t hw)
{
	irq_set_chip_data(virq, d->host_data);
	irq_set_chip_and_handler(virq, &pru_sim_irq_chip, handle_edge_irq);
	irq_set_noprobe(virq);
	return 0;
}

static const struct irq_domain_ops pru_sim_intc_domain_ops = {
	.xlate = pru_sim_intc_xlate,
	.map = pru_sim_intc_domain_map,
};

static void pru_sim_intc_remove_domain(void *data)
{
	struct pru_sim *sim = data;
	irq_hw_number_t hw;

	irq_work_sync(&sim->irq_work);
	for (hw = 0; hw < PRUSIM_NUM_EVENTS; hw++)
		irq_dispose_mapping(irq_find_mapping(sim->domain, hw));
	irq_domain_remove(sim->domain);
}

int pru_sim_intc_init(struct pru_sim *sim, struct device_node *np)
{
	struct device_node *intc;

	intc = of_get_child_by_name(np, "interrupt-controller");
	if (!intc || !of_property_read_bool(intc, "interrupt-controller")) {
		of_node_put(intc);
		return dev_err_probe(sim->dev, -EINVAL, "no interrupt-controller child\n");
	}
	init_irq_work(&sim->irq_work, pru_sim_intc_deliver);
	sim->domain = irq_domain_add_linear(intc, PRUSIM_NUM_EVENTS, &pru_sim_intc_domain_ops,
					    sim);
	of_node_put(intc);
	if (!sim->domain)
		return -ENOMEM;
	return devm_add_action_or_reset(sim->dev, pru_sim_intc_remove_domain, sim);
}
