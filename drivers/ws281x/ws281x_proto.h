/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * ws281x_proto.h - the ws281x driver's control block, shared verbatim by the
 * driver (drivers/ws281x/ws281x_main.c, ws281x_conv.c) and its PRU firmware
 * (firmware/ws281x.c, firmware/ws281x_send.S).
 *
 * The driver turns a frame into bit slots: one struct ws281x_slot per bit
 * sent, in wire order (the first LED's first bit first), each saying which of
 * the core's outputs carry a 1 in that bit.  Every string a core drives is
 * sent at once, one bit slot of WS281X_SLOT_CYCLES for every string: all its
 * outputs rise at the start of the slot, those sending 0 fall after
 * WS281X_T0H_CYCLES, the rest after WS281X_T1H_CYCLES.  Shorter strings are
 * padded by the driver (their outputs carry 0s after their last LED, which
 * they ignore: a WS281x passes on only what it does not keep).
 *
 * Outputs are R30 bits of the core, and AM335x GPIO bank bits written
 * through the banks' SETDATAOUT/CLEARDATAOUT registers over the OCP master
 * port.  With GPIO outputs the firmware writes all four banks at each edge,
 * in bank order (a write of 0 changes nothing), so that each bank's edges
 * keep the same distance from the slot's start in every slot.
 *
 * Commands (struct prukit_ctrl_hdr):
 *  SHOW: send the frame described by @frame, @slots, @r30_mask,
 *	@gpio_mask, then hold every output low for @reset cycles, then count
 *	it in @frames and strobe system event @event.  The firmware takes
 *	the command (answers it, status READY | result | seq << 16, after
 *	copying its parameters) only between frames: a SHOW posted while a
 *	frame is being sent is queued, and taken when that frame's reset is
 *	over, before its event is strobed.  So at each event the driver sees
 *	whether the frame it queued was taken, and may queue the next one:
 *	one frame is sent while at most one waits.  A frame's slots are free
 *	again once its event came (the next frame uses the other buffer).
 *
 * Two cores with GPIO outputs share the PRU-ICSS's one OCP master port: each
 * edge's four bank writes of one core would delay the other's.  The driver
 * then sets @sync: PRU0 leads, PRU1 follows, and both time their slots on
 * the IEP counter (one per PRU cycle, enabled by the leader) instead of
 * their own CYCLE.  For every frame the follower takes its SHOW, loads its
 * first slot and sets its @ready to its frame count + 1; the leader, having
 * taken its SHOW, waits for that, sets its @start_at (slot 0's IEP deadline,
 * WS281X_SYNC_LEAD cycles ahead) and then its @started to its frame count +
 * 1; the follower, seeing that, starts WS281X_SYNC_PHASE cycles after the
 * leader, so that each core's bank writes fall between the other's.  Either
 * side gives up waiting after about WS281X_SYNC_WAIT cycles and sends the
 * frame alone (counted in @unsynced): a core stopped behind the driver's
 * back stalls nothing.
 */
#ifndef _WS281X_PROTO_H
#define _WS281X_PROTO_H

#ifdef __KERNEL__
#include "prukit/pru_ctrl.h"
#else
#include <prukit/pru_ctrl.h>
#endif

#define WS281X_MAGIC		0x78313832u	/* "281x" */
#define WS281X_VERSION		2

/* Timing, in PRU cycles of 5 ns */
#define WS281X_SLOT_CYCLES	250	/* 1250 ns per bit */
#define WS281X_T0H_CYCLES	70	/* 350 ns high for a 0 (T0L 900 ns) */
#define WS281X_T1H_CYCLES	140	/* 700 ns high for a 1 (T1L 550 ns) */
#define WS281X_RESET_DEFAULT	60000	/* 300 us: newer WS2812B latch after 280 us */
#define WS281X_RESET_MIN	10000	/* 50 us: the datasheets' minimum */

#define WS281X_GPIO_BANKS	4
#define WS281X_MAX_SLOTS	0x100000u	/* 32768 RGBW LEDs per string */

/* Two cores in step (@sync), in PRU cycles */
#define WS281X_SYNC_NONE	0	/* time slots on the core's own CYCLE */
#define WS281X_SYNC_LEADER	1	/* PRU0: on the IEP counter, PRU1 follows */
#define WS281X_SYNC_FOLLOWER	2	/* PRU1: on the IEP counter, after PRU0 */
#define WS281X_SYNC_LEAD	400	/* leader's slot 0 this far after @start_at is set */
#define WS281X_SYNC_PHASE	35	/* follower's slots this much after the leader's */
#define WS281X_SYNC_WAIT	2000000	/* 10 ms */

/* Opcodes */
#define WS281X_CMD_SHOW		1

/* Results */
#define WS281X_OK		0
#define WS281X_EINVAL		1	/* a parameter out of range */
#define WS281X_EOPCODE		2	/* unknown opcode */

/**
 * struct ws281x_slot - one bit sent on every string of a core
 * @r30: R30 bits whose string sends a 1 (a subset of the frame's @r30_mask)
 * @gpio: per GPIO bank, the bits whose string sends a 1
 */
struct ws281x_slot {
	__u32 r30;
	__u32 gpio[WS281X_GPIO_BANKS];
} __packed __aligned(4);

/**
 * struct ws281x_ctrl - the control block, at PRUKIT_CTRL_DA in the core's RAM
 * @hdr: magic WS281X_MAGIC, version WS281X_VERSION, command and status
 * @frame: SHOW: bus address of the frame's first struct ws281x_slot
 * @slots: SHOW: bit slots in the frame, 1..WS281X_MAX_SLOTS
 * @r30_mask: SHOW: the R30 bits that drive strings
 * @gpio_mask: SHOW: per GPIO bank (0..3), the bits that drive strings
 * @reset: SHOW: cycles every output stays low after the frame, at least
 *	WS281X_RESET_MIN
 * @event: SHOW: the system event strobed when a frame is done (16..31; the
 *	driver's device tree maps it, "interrupts-extended")
 * @frames: frames sent, reset and event included (the firmware counts)
 * @first_cycle: the core's CYCLE counter (the IEP counter with @sync) when
 *	the last frame's first slot started (the firmware enables the
 *	counter), for tests
 * @sync: SHOW: WS281X_SYNC_NONE, _LEADER (PRU0) or _FOLLOWER (PRU1)
 * @ready: follower: the frame count + 1 of the frame it is ready to send
 * @started: leader: the frame count + 1 of the frame whose @start_at is set
 * @start_at: leader: the IEP deadline of that frame's slot 0
 * @unsynced: frames sent alone because the other core did not answer
 */
struct ws281x_ctrl {
	struct prukit_ctrl_hdr hdr;
	__u32 frame;
	__u32 slots;
	__u32 r30_mask;
	__u32 gpio_mask[WS281X_GPIO_BANKS];
	__u32 reset;
	__u32 event;
	__u32 frames;
	__u32 first_cycle;
	__u32 sync;
	__u32 ready;
	__u32 started;
	__u32 start_at;
	__u32 unsynced;
} __packed __aligned(4);

#endif /* _WS281X_PROTO_H */
