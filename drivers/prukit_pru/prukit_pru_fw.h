/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prukit_pru - what the layer reads from a PRU firmware file itself
 */
#ifndef _PRUKIT_PRU_FW_H
#define _PRUKIT_PRU_FW_H

#include <linux/types.h>

/*
 * The INTC of the PRU-ICSS prukit drives: the AM335x's (the same on the
 * AM437x, AM57xx and 66AK2G: mainline's pruss_intc has one match data for
 * them), 64 system events, 10 channels, 10 host interrupts: hosts 0 and 1
 * reach the PRUs' R31, hosts 2..9 the ARM (PRU_EVTOUT0..7).  The K3
 * ICSSG's INTC (160 events, 20 hosts) is not one prukit drives.
 */
#define PRUKIT_INTC_EVENTS		64
#define PRUKIT_INTC_CHANNELS		10
#define PRUKIT_INTC_HOST_ARM_FIRST	2
#define PRUKIT_INTC_HOST_LAST		9

/**
 * struct prukit_pru_fw_irq - one entry of a firmware's .pru_irq_map
 * @event: the system event (below PRUKIT_INTC_EVENTS), -1 for none
 * @channel: the INTC channel it is routed to
 * @host: the host interrupt that channel is routed to (0, 1: the PRUs'
 *	R31; 2..9: the ARM's PRU_EVTOUT0..7)
 */
struct prukit_pru_fw_irq {
	int event;
	u8 channel;
	u8 host;
};

int prukit_pru_fw_irq_map(const u8 *elf, size_t size, const u8 **entries,
			  unsigned int *count);
/* The longest .pru_irq_map prukit_pru_fw_ssp_irq_map() makes: every event */
#define PRUKIT_PRU_FW_IRQ_MAP_MAX	(2 + 3 * PRUKIT_INTC_EVENTS)

int prukit_pru_fw_ssp_irq_map(const u8 *elf, size_t size, u8 *map, size_t *len);
u8 *prukit_pru_fw_add_irq_map(const u8 *elf, size_t size, const u8 *map, size_t map_len,
			      size_t *copy_size);
int prukit_pru_fw_irq_events(const u8 *elf, size_t size, u64 *events);
int prukit_pru_fw_rpmsg_events(const u8 *map, unsigned int count,
			       struct prukit_pru_fw_irq *kick,
			       struct prukit_pru_fw_irq *vring);

struct rproc_ops;

/**
 * enum prukit_pru_kick_choice - what prukit_pru_kick does with a PRU
 *	remote processor
 * @PRUKIT_PRU_KICK_GIVE: its driver has no kick (mainline's pru_rproc):
 *	prukit gives it one, and the vring interrupt
 * @PRUKIT_PRU_KICK_ASIDE: its driver kicks (TI's pru_rproc): prukit stays out
 */
enum prukit_pru_kick_choice {
	PRUKIT_PRU_KICK_GIVE,
	PRUKIT_PRU_KICK_ASIDE,
};

enum prukit_pru_kick_choice prukit_pru_kick_choose(const struct rproc_ops *ops);

#endif /* _PRUKIT_PRU_FW_H */
