/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prukit_pru - how every prukit driver takes and uses a PRU core
 *
 * See Documentation/writing-a-driver.rst.  The symbols are exported in the
 * PRUKIT module namespace; a driver says PRUKIT_IMPORT_NS() (compat.h's
 * MODULE_IMPORT_NS(PRUKIT), whose form changed in v6.13).
 */
#ifndef _PRUKIT_PRU_H
#define _PRUKIT_PRU_H

#include <linux/interrupt.h>
#include <linux/iopoll.h>
#include <linux/remoteproc.h>
#include <linux/types.h>
#include <linux/workqueue.h>

#include "prukit/pru_ctrl.h"

struct device;
struct device_node;

/* AM335x GPIO banks a PRU can drive over OCP (prukit_pru_gpio_bank()) */
#define PRUKIT_PRU_GPIO_BANKS		4

/* remoteproc sysfs files the layer makes read-only while it holds a core */
#define PRUKIT_PRU_RPROC_FILES		4

/* How often the layer looks for a crash report (remoteproc tells no one) */
#define PRUKIT_PRU_WATCH_MS		250

/* Default for firmware answers: generous, for emulated PRUs too. */
#define PRUKIT_PRU_TIMEOUT_MS		5000

/**
 * struct prukit_pru - one PRU core held by a prukit driver
 * @dev: the consumer device (the driver's)
 * @rproc: the core's remote processor
 * @index: position of the core in the consumer's "ti,prus"
 * @firmware: the consumer's "firmware-name" entry for it, or NULL
 * @via_pru_rproc: taken with pru_rproc_get() (the kernel's PRU remoteproc
 *	driver owns the core), not with rproc_get_by_phandle()
 * @booted: prukit_pru_boot() succeeded and no shutdown followed: the
 *	driver holds a reference on the core's power
 * @subdev: how remoteproc tells the layer of each start and stop of the core
 * @gen: starts and stops of the core seen by @subdev (under rproc->lock)
 * @boot_gen: @gen right after the driver's boot; while the two agree, the
 *	core runs what the driver booted
 * @sysfs_mode: the modes of remoteproc's sysfs files before the layer made
 *	them read-only (0: no such file)
 * @seq: sequence number of the last command sent
 * @on_stop: called when the core stops running the driver's firmware behind
 *	its back (prukit_pru_notify_stop()), or NULL
 * @on_stop_data: its argument
 * @stop_work: calls @on_stop, out of remoteproc's lock
 * @crash_watch: looks for a crash report every PRUKIT_PRU_WATCH_MS while the
 *	driver's boot runs and @on_stop is set
 * @stop_told: @on_stop was called for the current boot
 *
 * Drivers read @rproc and @dev; the rest belongs to the layer.
 */
struct prukit_pru {
	struct device *dev;
	struct rproc *rproc;
	unsigned int index;
	const char *firmware;
	bool via_pru_rproc;
	bool booted;
	struct rproc_subdev subdev;
	unsigned int gen;
	unsigned int boot_gen;
	umode_t sysfs_mode[PRUKIT_PRU_RPROC_FILES];
	u16 seq;
	void (*on_stop)(void *data);
	void *on_stop_data;
	struct work_struct stop_work;
	struct delayed_work crash_watch;
	bool stop_told;
};

struct prukit_pru *devm_prukit_pru_get(struct device *dev, unsigned int index);
int prukit_pru_boot(struct prukit_pru *pru, const char *firmware);
void prukit_pru_notify_stop(struct prukit_pru *pru, void (*fn)(void *data), void *data);
void prukit_pru_shutdown(struct prukit_pru *pru);
bool prukit_pru_running(struct prukit_pru *pru);
void __iomem *prukit_pru_map(struct prukit_pru *pru, u32 da, size_t len);
int prukit_pru_ctrl_check(struct prukit_pru *pru, void __iomem *ctrl, u32 magic,
			  u16 version, u16 size);
int prukit_pru_ctrl_wait_ready(struct prukit_pru *pru, void __iomem *ctrl,
			       unsigned int timeout_ms);
int prukit_pru_ctrl_command(struct prukit_pru *pru, void __iomem *ctrl, u16 opcode,
			    unsigned int timeout_ms);
int prukit_pru_ctrl_post(struct prukit_pru *pru, void __iomem *ctrl, u16 opcode);
int prukit_pru_ctrl_wait(struct prukit_pru *pru, void __iomem *ctrl, u16 seq,
			 unsigned int timeout_ms);
int prukit_pru_ctrl_answer(void __iomem *ctrl, u16 seq);
int prukit_pru_gpio_bank(struct device_node *np);
int prukit_pru_event(struct device *dev, const char *name);

/**
 * prukit_pru_poll_timeout() - wait, polling, for what the firmware does
 * @pru: the core whose firmware makes @cond true
 * @cond: what to wait for (evaluated after each sleep: MMIO reads, say)
 * @sleep_us: the longest sleep between two looks
 * @timeout_ms: how long at most
 *
 * The one way prukit drivers poll their firmware: the kernel's
 * read_poll_timeout(), plus what a PRU adds: a core stopped behind the
 * driver's back (a crash report, say) ends the wait at once.  May sleep.
 *
 * Return: 0 once @cond held, -EPIPE if the core stopped before it did,
 * -ETIMEDOUT.
 */
#define prukit_pru_poll_timeout(pru, cond, sleep_us, timeout_ms)			\
({											\
	bool __running, __done = false;							\
	int __ret;									\
											\
	__ret = read_poll_timeout(prukit_pru_running, __running,			\
				  (__done = (cond)) || !__running, sleep_us,		\
				  (u64)(timeout_ms) * USEC_PER_MSEC, false, pru);	\
	__done ? 0 : __running ? __ret : -EPIPE;					\
})

int devm_prukit_pru_request_irq(struct device *dev, const char *name,
				irq_handler_t handler, irq_handler_t thread_fn,
				unsigned long flags, void *data);

#endif /* _PRUKIT_PRU_H */
