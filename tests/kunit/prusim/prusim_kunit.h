/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The format of the data that tests/kunit/prusim/gen.py generates from the
 * prusim validation programs (the .S files of tests/prusim/asm, the .c files
 * of tests/prusim/c) and the expectations in their comments (see
 * tests/prusim/runner.py), for the KUnit suite in prusim_kunit.c.
 */
#ifndef _PRUSIM_KUNIT_H
#define _PRUSIM_KUNIT_H

#include "prusim.h"

/**
 * enum prusim_kunit_field - what an expectation compares
 * @PK_CYCLES: the simulator's clock at the end of the run
 * @PK_PIN_CHANGES: number of pin changes reported through &prusim_ops.pin
 * @PK_STATE: &enum prusim_state of a core
 * @PK_PC: program counter (word address)
 * @PK_INSNS: instructions executed
 * @PK_STALLS: stall cycles
 * @PK_CYCLE_CNT: CTRL CYCLE register
 * @PK_STALL_CNT: CTRL STALL register
 * @PK_REG: register @reg of a core
 * @PK_INTC_RAW: INTC raw event status
 * @PK_INTC_ENABLED: INTC event enables
 * @PK_INTC_PENDING: host interrupts pending
 * @PK_REASON_IS: the core's halt/stop reason equals @text
 * @PK_REASON_HAS: the core's halt/stop reason contains @text
 */
enum prusim_kunit_field {
	PK_CYCLES,
	PK_PIN_CHANGES,
	PK_STATE,
	PK_PC,
	PK_INSNS,
	PK_STALLS,
	PK_CYCLE_CNT,
	PK_STALL_CNT,
	PK_REG,
	PK_INTC_RAW,
	PK_INTC_ENABLED,
	PK_INTC_PENDING,
	PK_REASON_IS,
	PK_REASON_HAS,
};

/**
 * struct prusim_kunit_expect - one "expect:" line
 * @field: &enum prusim_kunit_field
 * @core: core of a per-core field
 * @reg: register of %PK_REG
 * @value: expected number (a state for %PK_STATE)
 * @text: expected text of %PK_REASON_IS and %PK_REASON_HAS
 * @line: the directive as written, for messages
 */
struct prusim_kunit_expect {
	u8 field;
	u8 core;
	u8 reg;
	u64 value;
	const char *text;
	const char *line;
};

/**
 * struct prusim_kunit_irq - one entry of an "expect: host_irq=" list
 * @cycle: when the line changed
 * @host: host interrupt 2..9
 * @level: new level
 */
struct prusim_kunit_irq {
	u64 cycle;
	u8 host;
	u8 level;
};

/**
 * enum prusim_kunit_signal_kind - checks on the VCD trace of one pin
 * @PK_EDGES: the cycles at which the pin changed ("edges:")
 * @PK_GAPS: the distances between those cycles ("gaps:")
 * @PK_PERIOD: every full period lasts values[0] cycles, high for values[1]
 *	("period:")
 */
enum prusim_kunit_signal_kind {
	PK_EDGES,
	PK_GAPS,
	PK_PERIOD,
};

/**
 * struct prusim_kunit_signal - an "edges:", "gaps:" or "period:" line
 * @kind: &enum prusim_kunit_signal_kind
 * @pin: prusim pin id of the VCD signal
 * @values: expected cycles, distances, or period and high time
 * @count: entries in @values
 * @line: the directive as written, for messages
 *
 * As in the VCD: a change in cycle 0 is not an edge, and several changes
 * of a pin in one cycle count once, if the level differs at its end.
 */
struct prusim_kunit_signal {
	u8 kind;
	u16 pin;
	const u64 *values;
	u32 count;
	const char *line;
};

/**
 * struct prusim_kunit_kick - an "--event CYCLE:EVENT" argument
 * @cycle: when the embedder raises it
 * @event: system event
 */
struct prusim_kunit_kick {
	u64 cycle;
	u8 event;
};

/* &struct prusim_kunit_cfg.param beyond the read latencies */
#define PK_CFG_READ_WORD_CYCLES		(PRUSIM_NUM_LAT + 0)
#define PK_CFG_WRITE_CYCLES		(PRUSIM_NUM_LAT + 1)
#define PK_CFG_WRITE_WORD_CYCLES	(PRUSIM_NUM_LAT + 2)
#define PK_CFG_GPIO_WRITE_LATENCY	(PRUSIM_NUM_LAT + 3)
#define PK_CFG_GPIO_WRITE_INTERVAL	(PRUSIM_NUM_LAT + 4)
#define PK_CFG_R31_SYNC_DELAY		(PRUSIM_NUM_LAT + 5)
#define PK_CFG_EVENT_LATENCY		(PRUSIM_NUM_LAT + 6)
#define PK_CFG_OCP_WRITE_DELAY		(PRUSIM_NUM_LAT + 7)
#define PK_CFG_DDR_JITTER		(PRUSIM_NUM_LAT + 8)
#define PK_CFG_JITTER_SEED		(PRUSIM_NUM_LAT + 9)

/**
 * struct prusim_kunit_cfg - a "-C NAME=VALUE" argument
 * @param: an &enum prusim_lat (read latency) or a PK_CFG_* value
 * @value: new value
 */
struct prusim_kunit_cfg {
	u8 param;
	u16 value;
};

/**
 * struct prusim_kunit_case - one validation program with its run and checks
 * @name: source file, relative to tests/prusim
 * @fw: the assembled ELF of each core, or NULL
 * @fw_size: their sizes
 * @stim: stimulus text of each input port (--r31-0, --r31-1, --gpio-in), or
 *	NULL
 * @stim_len: their lengths
 * @max_cycles: cycle budget (--max-cycles)
 * @ddr_size: bytes of memory behind OCP address 0x80000000 (--ddr), or 0
 * @until_halt: --until-halt: every loaded core must halt (exit status 2)
 * @kicks: events raised between runs (--event), sorted by cycle
 * @nkicks: entries in @kicks
 * @cfg: timing changes (-C)
 * @ncfg: entries in @cfg
 * @exit: expected exit status of the prusim tool: 0, 2 (not halted) or 3
 *	(a core was stopped by the simulator)
 * @expect: "expect:" lines
 * @nexpect: entries in @expect
 * @check_host_irq: an "expect: host_irq=" line was given
 * @host_irq: the host interrupt changes it lists
 * @nhost_irq: entries in @host_irq
 * @signals: "edges:", "gaps:" and "period:" lines
 * @nsignals: entries in @signals
 */
struct prusim_kunit_case {
	const char *name;
	const u8 *fw[PRUSIM_NUM_CORES];
	u32 fw_size[PRUSIM_NUM_CORES];
	const char *stim[PRUSIM_NUM_PORTS];
	u32 stim_len[PRUSIM_NUM_PORTS];
	u64 max_cycles;
	u32 ddr_size;
	bool until_halt;
	const struct prusim_kunit_kick *kicks;
	u32 nkicks;
	const struct prusim_kunit_cfg *cfg;
	u32 ncfg;
	u8 exit;
	const struct prusim_kunit_expect *expect;
	u32 nexpect;
	bool check_host_irq;
	const struct prusim_kunit_irq *host_irq;
	u32 nhost_irq;
	const struct prusim_kunit_signal *signals;
	u32 nsignals;
};

#endif /* _PRUSIM_KUNIT_H */
