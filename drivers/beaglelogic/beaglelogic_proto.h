/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * beaglelogic_proto.h - the beaglelogic driver's control blocks, shared
 * verbatim by the driver (drivers/beaglelogic/beaglelogic.c) and its PRU
 * firmware (firmware/bl_main.c, bl_sample.S, bl_store.S).
 *
 * Two cores capture together, as in the original BeagleLogic:
 *
 *  - PRU1, the sampler, copies R31 (bits 0..7, or 0..15) into r21..r28
 *    every 2 * @divisor cycles, without a gap: 100 MHz / @divisor samples
 *    per second.  Every 32 bytes make a block; the block goes to a
 *    scratchpad bank with its number in r29 (XOUT, one cycle): odd blocks
 *    to bank 11, even ones to bank 10, so the storer has two blocks' time
 *    to take each.  The sampler looks for a stop request (bank 12, r19)
 *    every other sample.
 *  - PRU0, the storer, takes the blocks in order (XIN), writes them to the
 *    capture's buffers in DDR (over the OCP master port), and after each
 *    full buffer counts it in @filled and strobes system event @event.
 *    One-shot: after the last buffer it asks the sampler to stop, and
 *    @state becomes BL_FW_DONE.  Continuous: it goes on with buffer 0.
 *    A block it finds overwritten before it took it (BL_ERR_MISSED) stops
 *    the capture with @state BL_FW_ERROR: no data is ever lost quietly.
 *
 * Each core has its own block of this layout at PRUKIT_CTRL_DA in its data
 * RAM.  Commands (struct prukit_ctrl_hdr):
 *  START (both cores; PRU0 first): PRU0 checks and copies @unit, @mode,
 *	@nbufs, @bufsize, @bufs and @event, clears the scratchpad banks and
 *	@filled, sets @state BL_FW_RUNNING, answers, and waits for blocks;
 *	PRU1 checks @unit and @divisor and that PRU0's @state is
 *	BL_FW_RUNNING (BL_ENOSTORER after about 0.5 s), answers, and
 *	samples.  On PRU1, @first_iep is the IEP counter at the first sample
 *	once the capture ended: it relates the samples to other PRU activity
 *	(the simulator's stimulus origins, in tests).
 *  STOP (PRU0): ends a capture; answered once PRU1 stopped too.  A STOP
 *	without a capture is answered at once.
 *
 * Triggers (PRU0, @trig_mode other than BL_TRIG_NONE; with @mode
 * BL_MODE_CONTINUOUS): the storer fills the ring round and round; after
 * @trig_pre blocks it looks at every block it stored for the trigger (an
 * edge of a channel, or a pattern: bl_store.S has the checks and what they
 * cost); the first block that holds one is @trig_block, and @trig_post
 * blocks later the capture ends (BL_FW_DONE, with one more event).  So the
 * ring holds, in capture order from block @trig_block - @trig_pre, every
 * block from @trig_pre before the trigger's to @trig_post after it.  The
 * driver finds the trigger's sample in block @trig_block.
 */
#ifndef _BEAGLELOGIC_PROTO_H
#define _BEAGLELOGIC_PROTO_H

#ifdef __KERNEL__
#include "prukit/pru_ctrl.h"
#elif !defined(__ASSEMBLER__)
#include <prukit/pru_ctrl.h>
#endif

#define BL_MAGIC		0x4c474c42u	/* "BLGL" */
#define BL_VERSION		3

#define BL_MAX_BUFS		128
#define BL_BLOCK_BYTES		32	/* a buffer is a multiple of this */
#define BL_MAX_DIVISOR		10000000u	/* 10 Hz */

/* The stop flag, in scratchpad bank 12, r19 (the sampler adds it to a count) */
#define BL_RUN_FLAG		1
#define BL_STOP_FLAG		0x80000000

/* @unit: the original's values */
#define BL_UNIT_16		0
#define BL_UNIT_8		1

/* @mode: the original's trigger flags */
#define BL_MODE_ONESHOT		0
#define BL_MODE_CONTINUOUS	1

/* @state */
#define BL_FW_IDLE		0
#define BL_FW_RUNNING		1
#define BL_FW_DONE		2	/* one-shot: every buffer filled */
#define BL_FW_ERROR		3	/* see @error */

/* @error */
#define BL_ERR_NONE		0
#define BL_ERR_MISSED		1	/* the storer fell two blocks behind */

/* Opcodes */
#define BL_CMD_START		1
#define BL_CMD_STOP		2

/* @trig_mode: what the storer looks for in each block */
#define BL_TRIG_NONE		0
#define BL_TRIG_RISING		1	/* channel bit @trig_bit goes 0 -> 1 */
#define BL_TRIG_FALLING		2	/* 1 -> 0 */
#define BL_TRIG_EDGE		3	/* either */
#define BL_TRIG_PATTERN8	4	/* (sample & mask) == value, every 8-bit sample */
#define BL_TRIG_PATTERN16	5	/* every 16-bit sample */
/* 16-bit samples 0, 1, 4, 5, 8, 9, 12, 13 of a block: 100 Msps leaves no time for all */
#define BL_TRIG_PATTERN16_HALF	6
#define BL_TRIG_MAX		BL_TRIG_PATTERN16_HALF

/* Results */
#define BL_OK			0
#define BL_EINVAL		1	/* a parameter out of range */
#define BL_EOPCODE		2	/* unknown opcode */
#define BL_EBUSY		3	/* START while capturing */
#define BL_ENOSTORER		4	/* PRU1's START: PRU0 takes no blocks */

#ifndef __ASSEMBLER__
/**
 * struct bl_ctrl - a core's control block, at PRUKIT_CTRL_DA in its RAM
 * @hdr: magic BL_MAGIC, version BL_VERSION, command and status
 * @unit: START: BL_UNIT_16 or BL_UNIT_8 (both cores)
 * @divisor: START (PRU1): a sample every 2 * @divisor cycles,
 *	1..BL_MAX_DIVISOR
 * @mode: START (PRU0): BL_MODE_ONESHOT or BL_MODE_CONTINUOUS
 * @nbufs: START (PRU0): buffers in @bufs, 1..BL_MAX_BUFS
 * @bufsize: START (PRU0): bytes of every buffer, a multiple of
 *	BL_BLOCK_BYTES
 * @event: START (PRU0): system event strobed per full buffer (16..31)
 * @state: BL_FW_*, written by the core
 * @error: BL_ERR_*, why @state is BL_FW_ERROR
 * @filled: PRU0: buffers filled since START
 * @first_iep: PRU1: the IEP counter at the first sample of the last capture
 *	(written when it ended)
 * @bufs: START (PRU0): bus addresses of the buffers, in capture order
 * @trig_mode: START (PRU0): BL_TRIG_*
 * @trig_lanes: START (PRU0): edges: the channel's bit in each sample of a
 *	32-bit word (8-bit units: 4 samples a word, 16-bit: 2); patterns: the
 *	mask, in each sample of a word
 * @trig_bit: START (PRU0): edges: the channel's bit in the last sample of
 *	a word (8-bit: channel + 24, 16-bit: channel + 16); patterns: the
 *	value (within the mask) in each sample of a word
 * @trig_pre: START (PRU0): blocks stored before the storer looks, >= 1
 * @trig_post: START (PRU0): blocks stored after the trigger's, >= 1
 * @trig_block: PRU0: the block (numbered from 1) that held the trigger, 0
 *	while none did
 * @ping: the driver's: any value, changed to ask the storer whether it
 *	runs
 * @pong: PRU0: the storer copies @ping here while it waits for a block:
 *	a capture whose storer leaves a new @ping unanswered is on a halted
 *	or faulted core, however slow its rate
 */
struct bl_ctrl {
	struct prukit_ctrl_hdr hdr;
	__u32 unit;
	__u32 divisor;
	__u32 mode;
	__u32 nbufs;
	__u32 bufsize;
	__u32 event;
	__u32 state;
	__u32 error;
	__u32 filled;
	__u32 first_iep;
	__u32 bufs[BL_MAX_BUFS];
	__u32 trig_mode;
	__u32 trig_lanes;
	__u32 trig_bit;
	__u32 trig_pre;
	__u32 trig_post;
	__u32 trig_block;
	__u16 ping;
	__u16 pong;
} __packed __aligned(4);
#endif

/* Offsets the assembler sources use (bl_main.c checks them) */
#define BL_CTRL_UNIT		16
#define BL_CTRL_DIVISOR		20
#define BL_CTRL_STATE		40
#define BL_CTRL_ERROR		44
#define BL_CTRL_FILLED		48
#define BL_CTRL_FIRST_IEP	52
#define BL_CTRL_BUFS		56
#define BL_CTRL_TRIG_MODE	(BL_CTRL_BUFS + 4 * BL_MAX_BUFS)	/* 568 */
#define BL_CTRL_TRIG_POST	(BL_CTRL_TRIG_MODE + 16)
#define BL_CTRL_TRIG_BLOCK	(BL_CTRL_TRIG_MODE + 20)
#define BL_CTRL_PING		(BL_CTRL_TRIG_MODE + 24)	/* pong at + 2 */

#endif /* _BEAGLELOGIC_PROTO_H */
