// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_sim - the simulated PRU-ICSS INTC as a Linux interrupt controller
 *
 * Cells as the TI PRUSS INTC binding: <system-event channel host-interrupt>.
 * Mapping a specifier programs the simulated INTC the way the real irqchip
 * driver programs the hardware (event -> channel -> host, enables), and
 * refuses, as it does, an event or channel already routed elsewhere;
 * disposing of the mapping disables the event again.  A firmware's
 * .pru_irq_map is mapped the same way while its core runs.
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
#define INTC_EICR		(PRU_SIM_INTC + 0x02c)
#define INTC_HIEISR		(PRU_SIM_INTC + 0x034)
#define INTC_CMR(ev)		(PRU_SIM_INTC + 0x400 + ((ev) & ~3))
#define INTC_HMR(ch)		(PRU_SIM_INTC + 0x800 + ((ch) & ~3))

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

/*
 * Record the route of event @ev, refusing one that disagrees with a route
 * in use: an event goes to one channel, a channel to one host interrupt.
 */
static int pru_sim_intc_route(struct pru_sim *sim, unsigned int ev, unsigned int ch,
			      unsigned int host)
{
	u64 others;
	int ret = 0;

	mutex_lock(&sim->lock);
	if ((sim->routed & BIT_ULL(ev)) &&
	    (sim->route_ch[ev] != ch || sim->route_host[ev] != host)) {
		dev_err(sim->dev, "event %u -> channel %u -> host %u: the event already goes to channel %u, host %u\n",
			ev, ch, host, sim->route_ch[ev], sim->route_host[ev]);
		ret = -EBUSY;
		goto unlock;
	}
	others = sim->routed & ~BIT_ULL(ev);
	while (others) {
		unsigned int o = __ffs64(others);

		others &= others - 1;
		if (sim->route_ch[o] == ch && sim->route_host[o] != host) {
			dev_err(sim->dev, "event %u -> channel %u -> host %u: channel %u already goes to host %u (event %u)\n",
				ev, ch, host, ch, sim->route_host[o], o);
			ret = -EBUSY;
			goto unlock;
		}
	}
	sim->routed |= BIT_ULL(ev);
	sim->route_ch[ev] = ch;
	sim->route_host[ev] = host;
unlock:
	mutex_unlock(&sim->lock);
	return ret;
}

/* Program the INTC with the recorded route of @ev and enable it. */
static void pru_sim_intc_enable(struct pru_sim *sim, unsigned int ev)
{
	unsigned int ch = sim->route_ch[ev], host = sim->route_host[ev];

	mutex_lock(&sim->lock);
	pru_sim_intc_set_lane(sim, INTC_CMR(ev), ev, ch);
	pru_sim_intc_set_lane(sim, INTC_HMR(ch), ch, host);
	pru_sim_intc_write(sim, INTC_EISR, ev);
	pru_sim_intc_write(sim, INTC_HIEISR, host);
	pru_sim_intc_write(sim, INTC_GER, 1);
	sim->mapped |= BIT_ULL(ev);
	mutex_unlock(&sim->lock);
}

/* The mapping of @ev is gone: disable the event and forget its route. */
static void pru_sim_intc_disable(struct pru_sim *sim, unsigned int ev)
{
	mutex_lock(&sim->lock);
	pru_sim_intc_write(sim, INTC_EICR, ev);
	pru_sim_intc_write(sim, INTC_SICR, ev);
	sim->mapped &= ~BIT_ULL(ev);
	sim->routed &= ~BIT_ULL(ev);
	atomic64_andnot(BIT_ULL(ev), &sim->to_arm);
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
		spin_lock_irq(&sim->stat_lock);
		if (!sim->taken_since)
			sim->taken_since = sim->irq_since;
		spin_unlock_irq(&sim->stat_lock);
		atomic64_or(taken, &sim->to_arm);
		irq_work_queue(&sim->irq_work);
	}
	sim->irq_since = 0;
}

/*
 * The latency of a PRU -> ARM event: PRU cycles simulated from the R31
 * strobe until the Linux handler runs, which is right after this.
 */
static void pru_sim_intc_account(struct pru_sim *sim)
{
	u64 now = atomic64_read(&sim->cycle), lat;

	spin_lock(&sim->stat_lock);
	if (sim->taken_since) {
		lat = now - min(now, sim->taken_since);
		sim->taken_since = 0;
		sim->lat_last = lat;
		sim->lat_max = max(sim->lat_max, lat);
		sim->lat_sum += lat;
		sim->lat_count++;
	}
	spin_unlock(&sim->stat_lock);
}

static void pru_sim_intc_deliver(struct irq_work *work)
{
	struct pru_sim *sim = container_of(work, struct pru_sim, irq_work);
	u64 ev = atomic64_read(&sim->to_arm) & ~atomic64_read(&sim->masked);

	/* Masked events stay in to_arm until unmasked. */
	atomic64_andnot(ev, &sim->to_arm);
	if (ev)
		pru_sim_intc_account(sim);
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

	int ret;

	if (intsize != 3 || intspec[0] >= PRUSIM_NUM_EVENTS ||
	    intspec[1] >= PRUSIM_NUM_CHANNELS || intspec[2] >= PRUSIM_NUM_HOSTS) {
		dev_err(sim->dev, "bad interrupt specifier <%u %u %u>\n",
			intsize > 0 ? intspec[0] : 0, intsize > 1 ? intspec[1] : 0,
			intsize > 2 ? intspec[2] : 0);
		return -EINVAL;
	}
	ret = pru_sim_intc_route(sim, intspec[0], intspec[1], intspec[2]);
	if (ret)
		return ret;
	*out_hwirq = intspec[0];
	*out_type = IRQ_TYPE_EDGE_RISING;
	return 0;
}

static int pru_sim_intc_domain_map(struct irq_domain *d, unsigned int virq,
				   irq_hw_number_t hw)
{
	struct pru_sim *sim = d->host_data;

	irq_set_chip_data(virq, sim);
	irq_set_chip_and_handler(virq, &pru_sim_irq_chip, handle_edge_irq);
	irq_set_noprobe(virq);
	pru_sim_intc_enable(sim, hw);
	return 0;
}

static void pru_sim_intc_domain_unmap(struct irq_domain *d, unsigned int virq)
{
	struct pru_sim *sim = d->host_data;
	irq_hw_number_t hw = irqd_to_hwirq(irq_get_irq_data(virq));

	pru_sim_intc_disable(sim, hw);
	irq_set_chip_and_handler(virq, NULL, NULL);
	irq_set_chip_data(virq, NULL);
}

static const struct irq_domain_ops pru_sim_intc_domain_ops = {
	.xlate = pru_sim_intc_xlate,
	.map = pru_sim_intc_domain_map,
	.unmap = pru_sim_intc_domain_unmap,
};

/*
 * Route the firmware's .pru_irq_map while its core runs, as the PRU
 * remoteproc driver does: each entry becomes a mapping in the INTC's domain,
 * and one that conflicts with a route in use fails the start.  An entry
 * that is already mapped (the core's own vring/kick interrupts, or a
 * consumer's) is used as it is and left alone at stop: the real driver
 * would dispose of it then, which is why consumers take their events from
 * their own device tree node, never from a firmware's .pru_irq_map.
 */
int pru_sim_intc_map_firmware(struct pru_sim_core *pc)
{
	struct pru_sim *sim = pc->sim;
	struct irq_fwspec spec = {
		.fwnode = sim->domain->fwnode,
		.param_count = 3,
	};
	unsigned int i, virq;

	pc->nr_map_virq = 0;
	for (i = 0; i < pc->elf.irq_map_events; i++) {
		const u8 *e = pc->elf.irq_map[i];
		unsigned int existing = irq_find_mapping(sim->domain, e[0]);

		spec.param[0] = e[0];
		spec.param[1] = e[1];
		spec.param[2] = e[2];
		virq = irq_create_fwspec_mapping(&spec);
		if (!virq) {
			dev_err(pc->dev, "%s: .pru_irq_map entry %u (event %u -> channel %u -> host %u) conflicts with a route in use\n",
				pc->rproc->firmware, i, e[0], e[1], e[2]);
			pru_sim_intc_unmap_firmware(pc);
			return -EBUSY;
		}
		if (existing) {
			if (existing != pc->vring_irq && existing != pc->kick_irq)
				dev_warn(pc->dev, "%s: .pru_irq_map maps event %u, which a device tree node maps too; the PRU remoteproc driver would dispose of it when PRU%u stops\n",
					 pc->rproc->firmware, e[0], pc->index);
			continue;
		}
		pc->map_virq[pc->nr_map_virq++] = virq;
	}
	return 0;
}

/* The core stopped: dispose of what its .pru_irq_map created. */
void pru_sim_intc_unmap_firmware(struct pru_sim_core *pc)
{
	while (pc->nr_map_virq)
		irq_dispose_mapping(pc->map_virq[--pc->nr_map_virq]);
}

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
