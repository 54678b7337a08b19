/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * pru_sim - a simulated AM335x PRU-ICSS (shared definitions of the driver)
 */
#ifndef PRU_SIM_H
#define PRU_SIM_H

#include <linux/atomic.h>
#include <linux/interrupt.h>
#include <linux/debugfs.h>
#include <linux/irq_work.h>
#include <linux/kthread.h>
#include <linux/mutex.h>
#include <linux/remoteproc.h>
#include <linux/spinlock.h>
#include <linux/wait.h>

#include "prusim.h"
#include "prusim_stim.h"
#include "prusim_trace.h"

/* Host interrupts 2..9 of the INTC are wired to the ARM. */
#define PRU_SIM_FIRST_ARM_HOST	2

/* The IEP's COUNT register, as prusim_host_read() maps the subsystem */
#define PRU_SIM_IEP_COUNT	0x2e00c

struct irq_domain;
struct pru_sim;

/**
 * struct pru_sim_core - one simulated PRU core, as a remote processor
 * @sim: the PRU-ICSS it belongs to
 * @dev: the core's platform device (parent of @rproc)
 * @rproc: the remote processor
 * @index: 0 for PRU0, 1 for PRU1
 * @vring_irq: Linux interrupt of the PRU -> ARM "vring" event, or 0
 * @kick_irq: Linux interrupt whose pending state is the ARM -> PRU "kick"
 *	event, or 0 (then the core has no kick, as with mainline pru_rproc)
 * @elf: what the loader found in the current firmware
 * @map_virq: Linux interrupts created for the firmware's .pru_irq_map while
 *	the core runs (disposed of when it stops)
 * @nr_map_virq: entries in @map_virq
 * @quiesce: subdevice that halts the core before remoteproc tears down the
 *	vdevs (registered while the core runs)
 */
struct pru_sim_core {
	struct pru_sim *sim;
	struct device *dev;
	struct rproc *rproc;
	unsigned int index;
	int vring_irq;
	int kick_irq;
	struct prusim_elf_info elf;
	unsigned int map_virq[PRUSIM_NUM_EVENTS];
	unsigned int nr_map_virq;
	struct rproc_subdev quiesce;
};

/**
 * struct pru_sim_input - stimulus of one input port
 * @sim: the PRU-ICSS
 * @port: PRUSIM_PORT_R31() or PRUSIM_PORT_GPIO() number
 * @stim: the pattern; @stim.count == 0 means the port reads 0
 * @origin: simulator cycle that the pattern's cycle 0 corresponds to
 * @pending_origin: the pattern starts at the next core start
 * @origin_iep: the IEP counter at @origin (firmware that reports IEP times,
 *	as beaglelogic's does, relates them to the pattern with it)
 */
struct pru_sim_input {
	struct pru_sim *sim;
	unsigned int port;
	struct prusim_stim stim;
	u64 origin;
	bool pending_origin;
	u32 origin_iep;
};

/**
 * struct pru_sim_trace - ring of recent output pin changes
 * @rec: PRU_SIM_TRACE_LEN records
 * @head: index of the next record to write
 * @count: valid records (at most PRU_SIM_TRACE_LEN)
 * @dropped: records overwritten since the last clear
 * @origin: cycle of the last core start
 * @until: changes from this cycle on are not recorded (0: no limit); set
 *	by "clear N", so that a reader slower than the simulation still gets
 *	exactly the N cycles it asked for
 */
struct pru_sim_trace {
	struct prusim_trace_rec *rec;
	unsigned int head;
	unsigned int count;
	u64 dropped;
	u64 origin;
	u64 until;
};

#define PRU_SIM_TRACE_LEN	BIT(18)

/* Pad registers of the AM335x control module: conf_* at 0x800..0xa34 */
#define PRU_SIM_NUM_PADS	142

/**
 * struct pru_sim - one simulated PRU-ICSS
 * @dev: the "prukit,pruss-sim" platform device
 * @lock: serialises every use of @s and the state below it
 * @s: the simulator (vmalloc'ed)
 * @core: the two PRU cores; NULL until their devices probe
 * @thread: runs the simulation in slices
 * @wq: @thread sleeps here while no core runs or all only wait
 * @work: set (and @wq woken) when there may be something to run
 * @raise: system events to raise in the simulator before the next slice
 *	(kicks; set from any context)
 * @domain: interrupt domain of the INTC (hwirq = system event)
 * @irq_work: delivers @to_arm events to Linux in hard interrupt context
 * @to_arm: system events for the ARM, taken from the INTC, not yet delivered
 * @masked: system events whose Linux interrupt is masked
 * @mapped: system events that have a Linux interrupt
 * @routed: system events given a route by an interrupt specifier
 * @route_ch: channel of each routed event
 * @route_host: host interrupt of each routed event
 * @cycle: simulator cycle at the end of the last slice, for readers that
 *	cannot take @lock
 * @irq_since: cycle of the R31 strobe of the oldest event not yet taken
 *	for the ARM, or 0 (under @lock)
 * @stat_lock: protects the latency statistics below
 * @taken_since: @irq_since of the events handed to @irq_work
 * @lat_last: PRU cycles from the strobe of the last event delivered to the
 *	ARM until its Linux handler ran
 * @lat_max: largest @lat_last
 * @lat_sum: sum of all @lat_last
 * @lat_count: number of deliveries measured
 * @ram_bus: PRU bus address at which the ARM's RAM appears (dma-ranges)
 * @ram_phys: CPU physical address of that RAM
 * @ram_size: its size
 * @ocp_err: the reason of the last refused OCP access
 * @ocp_free_writes: OCP writes that landed in a page the page allocator held
 *	free (a buffer freed under the firmware)
 * @ocp_write_pause_us: debugfs knob: after every OCP write the slice ends
 *	and the thread sleeps this long (0: off; read with READ_ONCE())
 * @ocp_pause: the slice ended at an OCP write, pause before the next one
 * @stop_delay_us: debugfs knob: a core's ->stop sleeps this long before it
 *	halts the core (0: off; read with READ_ONCE())
 * @input: stimulus per input port (PRUSIM_PORT_*)
 * @trace: pin trace
 * @pad: pad registers of the simulated board (pru_sim_board.c), offset
 *	0x800 + 4 * index; written under @lock, read with READ_ONCE() too
 * @pads_live: a simulated pin controller is bound: PRU outputs reach the
 *	trace only through pads muxed to them
 * @r30: the level of every PRU output (bit PRUSIM_PIN_R30())
 * @r30_shown: the level each output's pad shows, as last traced
 * @unmuxed_writes: output changes that reached no pad
 * @unmuxed_warned: outputs already reported in the kernel log
 * @slice_cycles: cycles simulated per slice (module parameter slice_cycles)
 * @host_ns: host time spent simulating, for the statistics
 * @debugfs: debugfs directory
 */
struct pru_sim {
	struct device *dev;
	struct mutex lock;		/* protects @s and everything below it */
	struct prusim *s;
	struct pru_sim_core *core[PRUSIM_NUM_CORES];
	struct task_struct *thread;
	wait_queue_head_t wq;
	atomic_t work;
	atomic64_t raise;
	struct irq_domain *domain;
	struct irq_work irq_work;
	atomic64_t to_arm;
	atomic64_t masked;
	u64 mapped;
	u64 routed;
	u8 route_ch[PRUSIM_NUM_EVENTS];
	u8 route_host[PRUSIM_NUM_EVENTS];
	atomic64_t cycle;
	u64 irq_since;
	spinlock_t stat_lock;		/* protects the lat_* statistics */
	u64 taken_since;
	u64 lat_last;
	u64 lat_max;
	u64 lat_sum;
	u64 lat_count;
	u64 ram_bus;
	phys_addr_t ram_phys;
	u64 ram_size;
	char ocp_err[PRUSIM_REASON_LEN];
	u64 ocp_free_writes;
	u32 ocp_write_pause_us;
	bool ocp_pause;
	u32 stop_delay_us;
	struct pru_sim_input input[PRUSIM_NUM_PORTS];
	struct pru_sim_trace trace;
	u32 pad[PRU_SIM_NUM_PADS];
	bool pads_live;
	u64 r30;
	u64 r30_shown;
	u64 unmuxed_writes;
	u64 unmuxed_warned;
	u64 slice_cycles;
	u64 host_ns;
	struct dentry *debugfs;
};

void pru_sim_kick_thread(struct pru_sim *sim);

int pru_sim_intc_init(struct pru_sim *sim, struct device_node *np);
void pru_sim_intc_exit(struct pru_sim *sim);
void pru_sim_intc_collect(struct pru_sim *sim);
int pru_sim_intc_map_firmware(struct pru_sim_core *pc);
void pru_sim_intc_unmap_firmware(struct pru_sim_core *pc);

void pru_sim_debugfs_init(struct pru_sim *sim, struct dentry *root);
void pru_sim_trace_pin(struct pru_sim *sim, u64 cycle, unsigned int pin, bool level);
u32 pru_sim_input(struct pru_sim *sim, unsigned int port, u64 cycle, u64 *next_change);
bool pru_sim_inputs_pending(struct pru_sim *sim);
void pru_sim_core_started(struct pru_sim *sim);
void pru_sim_inputs_free(struct pru_sim *sim);

void pru_sim_r30_changed(struct pru_sim *sim, u64 cycle, unsigned int pin, bool level);

extern struct platform_driver pru_sim_core_driver;
extern struct platform_driver pru_sim_pinmux_driver;
extern struct platform_driver pru_sim_gpio_driver;

#endif /* PRU_SIM_H */
