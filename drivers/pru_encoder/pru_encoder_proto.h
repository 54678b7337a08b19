/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * pru_encoder: the protocol between the pru_encoder driver and its PRU0
 * firmware (pru_encoder-pru0.elf), shared verbatim by both.
 *
 * The firmware decodes one quadrature encoder, x4 (every edge of A and B
 * counts), from three adjacent PRU0 R31 inputs, bits 14..16 (PRU_ENC_WIN_*):
 * A, B and an optional index, in an order the driver gives (the
 * BeagleBone Black and the PocketBeagle route them differently).  It keeps
 * the count between @floor and @ceiling (a step up from @ceiling wraps to
 * @floor: an overflow; a step down from @floor wraps to @ceiling: an
 * underflow), the direction of the last step, and counts what the driver
 * reports: overflows, underflows, index pulses (rising edges), reversals
 * (a step against the previous one) and skipped states (A and B both
 * changed between two samples: a step of unknown sign, not counted).
 *
 * Every field is written by one side only, so no update is ever lost: the
 * ARM writes the parameters and @command (and sets @irq_armed), the PRU
 * everything else.  The PRU strobes system event @event (16..31; 0: none)
 * after an overflow, underflow, index pulse, reversal or skipped state,
 * but only while @irq_armed is non-zero, which it clears when it strobes:
 * the driver sets @irq_armed again, then reads the counters.  A burst of
 * events thus costs the ARM one interrupt, and none is missed: an event
 * after the driver's read finds @irq_armed set and strobes again.
 *
 * Timing: pru_encoder_loop.S (its header comment has the cycle counts).
 */
#ifndef _PRU_ENCODER_PROTO_H
#define _PRU_ENCODER_PROTO_H

#ifdef __KERNEL__
#include "prukit/pru_ctrl.h"
#elif !defined(__ASSEMBLER__)
#include <prukit/pru_ctrl.h>
#endif

#define PRU_ENC_MAGIC		0x434e4550u	/* "PENC" */
#define PRU_ENC_VERSION		1

/* The R31 window the firmware samples: bits 14, 15 and 16 */
#define PRU_ENC_WIN_SHIFT	14
#define PRU_ENC_WIN_BITS	3
#define PRU_ENC_WIN_FIRST	14
#define PRU_ENC_WIN_LAST	16

/* @pins: R31 bit numbers of A (bits 0..7), B (8..15), index (16..23) */
#define PRU_ENC_PINS(a, b, i)	((__u32)(a) | (__u32)(b) << 8 | (__u32)(i) << 16)
#define PRU_ENC_PIN_A(p)	((p) & 0xff)
#define PRU_ENC_PIN_B(p)	(((p) >> 8) & 0xff)
#define PRU_ENC_PIN_I(p)	(((p) >> 16) & 0xff)
#define PRU_ENC_PIN_NONE	0xff	/* no index input */

/* Opcodes (with @command) */
#define PRU_ENC_CMD_CONFIG	1	/* @pins, @event; disables counting */
#define PRU_ENC_CMD_ENABLE	2	/* start counting from the inputs' state now */
#define PRU_ENC_CMD_DISABLE	3	/* stop counting; the count stays */
#define PRU_ENC_CMD_SET_COUNT	4	/* @count = @value: @floor <= @value <= @ceiling */
#define PRU_ENC_CMD_SET_LIMITS	5	/* @ceiling, @floor = @set_ceiling, @set_floor */

/* Results */
#define PRU_ENC_OK		0
#define PRU_ENC_EINVAL		1	/* a parameter out of range */
#define PRU_ENC_EOPCODE		2	/* unknown opcode */

/* @state */
#define PRU_ENC_STATE_IDLE	0
#define PRU_ENC_STATE_COUNTING	1

/* Byte offsets in the control block, for pru_encoder_loop.S */
#define PRU_ENC_OFF_COMMAND	0x08	/* hdr.command */
#define PRU_ENC_OFF_COUNT	0x28
#define PRU_ENC_OFF_DIRECTION	0x2c
#define PRU_ENC_OFF_INPUTS	0x30
#define PRU_ENC_OFF_OVERFLOWS	0x34
#define PRU_ENC_OFF_UNDERFLOWS	0x38
#define PRU_ENC_OFF_INDEXES	0x3c
#define PRU_ENC_OFF_REVERSALS	0x40
#define PRU_ENC_OFF_SKIPS	0x44
#define PRU_ENC_OFF_IRQ_ARMED	0x48
#define PRU_ENC_OFF_CEILING	0x4c
#define PRU_ENC_OFF_FLOOR	0x50

/*
 * The transition table (firmware only): entry (previous window << 3 |
 * window), one word each, says what a change of the three inputs is.
 */
#define PRU_ENC_T_UP		0x1	/* one step forward (A leads B) */
#define PRU_ENC_T_DOWN		0x2	/* one step backward */
#define PRU_ENC_T_INDEX		0x4	/* index rising edge */
#define PRU_ENC_T_SKIP		0x8	/* A and B both changed */

#ifndef __ASSEMBLER__
/**
 * struct pru_enc_ctrl - the pru_encoder control block, at PRUKIT_CTRL_DA
 * @hdr: the common header (magic PRU_ENC_MAGIC, version PRU_ENC_VERSION)
 * @pins: ARM -> PRU, for CONFIG: PRU_ENC_PINS() of the inputs, each one of
 *	bits PRU_ENC_WIN_FIRST..PRU_ENC_WIN_LAST, the index PRU_ENC_PIN_NONE
 *	where there is none
 * @event: ARM -> PRU, for CONFIG: system event strobed (16..31), 0 for none
 * @value: ARM -> PRU, for SET_COUNT
 * @set_ceiling: ARM -> PRU, for SET_LIMITS
 * @set_floor: ARM -> PRU, for SET_LIMITS (@set_floor <= @count <=
 *	@set_ceiling, else PRU_ENC_EINVAL and nothing changes)
 * @state: PRU -> ARM: PRU_ENC_STATE_*
 * @count: PRU -> ARM: the position
 * @direction: PRU -> ARM: 0 after a step forward, 1 after one backward
 * @inputs: PRU -> ARM: the window (R31 >> 14, 3 bits) as last sampled
 * @overflows: PRU -> ARM: steps from @ceiling up to @floor
 * @underflows: PRU -> ARM: steps from @floor down to @ceiling
 * @indexes: PRU -> ARM: index rising edges
 * @reversals: PRU -> ARM: steps against the previous step's direction
 * @skips: PRU -> ARM: skipped states (both A and B changed between two
 *	samples; not counted)
 * @irq_armed: ARM sets it non-zero, the PRU clears it when it strobes
 *	@event (so only the ARM ever sets it, only the PRU clears it)
 * @ceiling: PRU -> ARM: the limits in force
 * @floor: PRU -> ARM
 *
 * The counters wrap at 2^32; the driver adds their differences.
 */
struct pru_enc_ctrl {
	struct prukit_ctrl_hdr hdr;
	__u32 pins;
	__u32 event;
	__u32 value;
	__u32 set_ceiling;
	__u32 set_floor;
	__u32 state;
	__u32 count;
	__u32 direction;
	__u32 inputs;
	__u32 overflows;
	__u32 underflows;
	__u32 indexes;
	__u32 reversals;
	__u32 skips;
	__u32 irq_armed;
	__u32 ceiling;
	__u32 floor;
} __packed __aligned(4);
#endif

#endif /* _PRU_ENCODER_PROTO_H */
