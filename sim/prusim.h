/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prusim - cycle-accurate model of the AM335x PRU-ICSS (two PRU v3 cores,
 * their memories, INTC, CTRL, CFG, IEP counter and the OCP master port with
 * the AM335x GPIO banks).
 *
 * The same sources build in userspace and in the kernel.  The embedder owns
 * the memory of struct prusim (about 180 KiB; vzalloc it in the kernel), fills
 * in a struct prusim_config and struct prusim_ops, calls prusim_init(), loads
 * firmware with prusim_load_elf(), enables cores with prusim_core_enable() and
 * then calls prusim_run() as often as it likes.  The core never allocates,
 * never sleeps and keeps no state outside struct prusim.
 *
 * Time is counted in PRU cycles of 5 ns (200 MHz) from prusim_init().
 */
#ifndef _PRUSIM_H
#define _PRUSIM_H

#include "prusim_platform.h"

#define PRUSIM_NUM_CORES	2
#define PRUSIM_IRAM_SIZE	0x2000
#define PRUSIM_IRAM_WORDS	(PRUSIM_IRAM_SIZE / 4)
#define PRUSIM_DRAM_SIZE	0x2000
#define PRUSIM_SHARED_SIZE	0x3000
#define PRUSIM_SPAD_BANKS	3
#define PRUSIM_SPAD_BYTES	(30 * 4)	/* r0..r29 of each scratchpad bank */
#define PRUSIM_NUM_EVENTS	64
#define PRUSIM_NUM_CHANNELS	10
#define PRUSIM_NUM_HOSTS	10
#define PRUSIM_GPIO_BANKS	4
#define PRUSIM_QUEUE_LEN	64
#define PRUSIM_POSTED_LEN	8	/* OCP stores on their way at once */
#define PRUSIM_MAX_BURST	124	/* bytes of one LBBO/SBBO */
#define PRUSIM_REASON_LEN	96

/*
 * Pin ids used by prusim_ops.pin: PRU0 R30 bits are 0..31, PRU1 R30 bits are
 * 32..63, AM335x GPIO bank b bit n (DATAOUT) is 64 + 32 * b + n.
 */
#define PRUSIM_PIN_R30(core, bit)	((core) * 32 + (bit))
#define PRUSIM_PIN_GPIO(bank, bit)	(64 + (bank) * 32 + (bit))
#define PRUSIM_NUM_PINS			PRUSIM_PIN_GPIO(PRUSIM_GPIO_BANKS, 0)

/*
 * Input ports used by prusim_ops.input: the R31 inputs of each core (bits
 * 0..29 are used) and the DATAIN register of each GPIO bank.
 */
#define PRUSIM_PORT_R31(core)		(core)
#define PRUSIM_PORT_GPIO(bank)		(2 + (bank))
#define PRUSIM_NUM_PORTS		PRUSIM_PORT_GPIO(PRUSIM_GPIO_BANKS)

/* AM335x GPIO bank registers the simulator models (offsets in a bank) */
#define PRUSIM_GPIO_OE			0x134u
#define PRUSIM_GPIO_DATAIN		0x138u
#define PRUSIM_GPIO_DATAOUT		0x13cu
#define PRUSIM_GPIO_CLEARDATAOUT	0x190u
#define PRUSIM_GPIO_SETDATAOUT		0x194u

/* The local address of the OCP master port; lower addresses stay inside. */
#define PRUSIM_OCP_BASE		0x80000u
/* Where the GNU toolchain links code: ELF addresses with this bit are IRAM. */
#define PRUSIM_ELF_IRAM_TAG	0x20000000u

/**
 * enum prusim_lat - memory regions with their own read latency
 * @PRUSIM_LAT_DRAM: own or other PRU data RAM
 * @PRUSIM_LAT_SHARED: 12 KiB shared RAM
 * @PRUSIM_LAT_INTC: PRU-ICSS interrupt controller
 * @PRUSIM_LAT_CTRL: PRU0/PRU1 control and debug registers
 * @PRUSIM_LAT_CFG: PRU-ICSS CFG registers
 * @PRUSIM_LAT_IEP: industrial ethernet peripheral (timer)
 * @PRUSIM_LAT_GPIO0: GPIO bank 0 (L4_WKUP) over the OCP master port
 * @PRUSIM_LAT_GPIO: GPIO banks 1..3 (L4_PER) over the OCP master port
 * @PRUSIM_LAT_OCMC: L3 on-chip RAM 0x40300000..0x4030ffff
 * @PRUSIM_LAT_DDR: EMIF (DDR) 0x80000000..0xbfffffff
 * @PRUSIM_LAT_PRCM: PRCM 0x44e00000..0x44e03fff
 * @PRUSIM_LAT_OCP: any other address behind the OCP master port
 * @PRUSIM_NUM_LAT: number of entries
 */
enum prusim_lat {
	PRUSIM_LAT_DRAM,
	PRUSIM_LAT_SHARED,
	PRUSIM_LAT_INTC,
	PRUSIM_LAT_CTRL,
	PRUSIM_LAT_CFG,
	PRUSIM_LAT_IEP,
	PRUSIM_LAT_GPIO0,
	PRUSIM_LAT_GPIO,
	PRUSIM_LAT_OCMC,
	PRUSIM_LAT_DDR,
	PRUSIM_LAT_PRCM,
	PRUSIM_LAT_OCP,
	PRUSIM_NUM_LAT
};

/**
 * struct prusim_config - timing parameters (prusim_default_config() fills in
 * the documented defaults; every value may be changed before prusim_init())
 * @read_latency: cycles of a load of 1..4 bytes from each &enum prusim_lat
 *	region, including the issue cycle
 * @read_word_cycles: extra cycles per further 32-bit word of a burst load
 * @write_cycles: cycles of a store of 1..4 bytes (posted)
 * @write_word_cycles: extra cycles per further 32-bit word of a burst store
 * @gpio_write_latency: cycles from the issue of a store to a GPIO bank until
 *	the output changes
 * @gpio_write_interval: minimum distance in cycles between two 32-bit writes
 *	accepted by the GPIO banks; a store to a busy bank stalls the core
 * @r31_sync_delay: age in cycles of the R31 input value a core reads
 * @event_latency: cycles from an R31 event strobe until the event is seen in
 *	the INTC (and in R31 bits 30/31 of a reader); 1..16
 * @ocp_write_delay: cycles from the issue of a store over the OCP master
 *	port (not to a GPIO bank) until it lands (&prusim_ops.ocp_write); 0:
 *	it lands as it issues.  Stores land in order; at most
 *	%PRUSIM_POSTED_LEN are on their way (another stalls the core).  A
 *	load over the port travels behind them: it sees them and completes
 *	no earlier than the cycle after the last one landed.  An event strobed
 *	after a store can reach the INTC (and the ARM) before it lands.
 * @ddr_jitter: up to this many cycles more for each load from DDR and each
 *	store's way there (0: none), the same for the same @jitter_seed,
 *	cycle and address
 * @jitter_seed: seed of @ddr_jitter
 * @no_skip: never skip idle cycles (for instruction tracing)
 * @stop_when_idle: when every core waits for something only the outside
 *	can bring (a waiting loop, SLP, HALT, no queued action, no announced
 *	input change), prusim_run() returns there and sets &prusim.waiting
 *	instead of skipping to the end of its budget: simulated time then
 *	passes only while something happens (an embedder that sleeps until the
 *	outside acts)
 * @irq_map_by_embedder: prusim_load_elf() only reports the .pru_irq_map
 *	entries in &prusim_elf_info; the embedder routes them (a remoteproc
 *	driver does so when the core starts, and undoes it when it stops)
 */
struct prusim_config {
	u16 read_latency[PRUSIM_NUM_LAT];
	u16 read_word_cycles;
	u16 write_cycles;
	u16 write_word_cycles;
	u16 gpio_write_latency;
	u16 gpio_write_interval;
	u16 r31_sync_delay;
	u16 event_latency;
	u32 ocp_write_delay;
	u16 ddr_jitter;
	u32 jitter_seed;
	bool no_skip;
	bool stop_when_idle;
	bool irq_map_by_embedder;
};

/**
 * struct prusim_ops - callbacks into the embedder; all are optional
 * @pin: an output pin (see PRUSIM_PIN_R30()/PRUSIM_PIN_GPIO()) changed to
 *	@level at @cycle.  Called in cycle order.
 * @input: return the value of input port @port (PRUSIM_PORT_R31() or
 *	PRUSIM_PORT_GPIO()) at @cycle and store in @next_change the first later
 *	cycle at which it may differ (PRUSIM_NEVER if it never will).  The
 *	simulator caches the value until then, so a source that announces its
 *	changes is called once per change, not once per read; a source that
 *	changes otherwise must be followed by prusim_input_changed().  Without
 *	this callback all inputs read 0.
 * @gpio_oe: the OE register of GPIO bank @bank changed to @oe (1 = input)
 *	at @cycle, by the ARM or by a PRU store landing; with DATAOUT (@pin)
 *	it says which lines drive their pad
 * @host_irq: host interrupt line @host (2..9, the ones that go to the ARM)
 *	changed to @level at @cycle
 * @ocp_read: read @len bytes at OCP address @addr (not a GPIO bank) into
 *	@buf; return 0 or a negative errno, which stops the core
 * @ocp_write: write @len bytes to OCP address @addr; as @ocp_read
 * @trace: called before each instruction is executed
 */
struct prusim_ops {
	void (*pin)(void *ctx, u64 cycle, unsigned int pin, bool level);
	u32 (*input)(void *ctx, unsigned int port, u64 cycle, u64 *next_change);
	void (*gpio_oe)(void *ctx, u64 cycle, unsigned int bank, u32 oe);
	void (*host_irq)(void *ctx, u64 cycle, unsigned int host, bool level);
	int (*ocp_read)(void *ctx, u32 addr, void *buf, unsigned int len);
	int (*ocp_write)(void *ctx, u32 addr, const void *buf, unsigned int len);
	void (*trace)(void *ctx, u64 cycle, unsigned int core, u32 pc, u32 insn);
};

/**
 * enum prusim_state - run state of one core
 * @PRUSIM_DISABLED: CONTROL.EN is clear (after reset, load or a host stop)
 * @PRUSIM_RUNNING: executing (possibly stalled)
 * @PRUSIM_SLEEPING: in SLP; woken by a WAKEUP_EN status bit (SLP 1) or by
 *	clearing CONTROL.SLEEPING
 * @PRUSIM_HALTED: executed HALT; the pc stays on the HALT instruction
 * @PRUSIM_STOPPED: the simulator stopped the core; see the reason string
 */
enum prusim_state {
	PRUSIM_DISABLED,
	PRUSIM_RUNNING,
	PRUSIM_SLEEPING,
	PRUSIM_HALTED,
	PRUSIM_STOPPED,
};

/**
 * struct prusim_insn - one predecoded IRAM word (private to the core)
 * @op: dispatch code: the operation, or a generic code for instructions that
 *	touch r28..r31
 * @kind: the operation
 * @flags: decode flags (operands or destination with side effects)
 * @rd: destination register; first register of a burst or XFR
 * @rd_shift: bit position of the destination field
 * @rd_width: width in bits of the destination field
 * @rs1: first source register (constant table entry for LBCO/SBCO)
 * @rs1_shift: bit position of the first source field
 * @rs2: second source register, 32 (always zero) for an immediate
 * @rs2_shift: bit position of the second source field
 * @aux: operation specific: ALU sub-opcode, branch condition, XFR device,
 *	register-file byte offset of a burst
 * @len: burst/XFR length code: 0..123 for 1..124 bytes, 124..127 for the
 *	count in R0.b0..b3
 * @target: branch target or hardware loop end (IRAM word address)
 * @rd_mask: destination field mask (unshifted)
 * @rs1_mask: first source field mask (unshifted)
 * @rs2_mask: second source field mask (unshifted), 0 for an immediate
 * @imm: immediate operand or absolute branch target (word address)
 */
struct prusim_insn {
	u8 op;
	u8 kind;
	u8 flags;
	u8 rd;
	u8 rd_shift;
	u8 rd_width;
	u8 rs1;
	u8 rs1_shift;
	u8 rs2;
	u8 rs2_shift;
	u8 aux;
	u8 len;
	u16 target;
	u32 rd_mask;
	u32 rs1_mask;
	u32 rs2_mask;
	u32 imm;
};

/**
 * struct prusim_watch - observation of a candidate idle loop (private)
 * @pc: loop head (target of the backward branch that armed the watch)
 * @cycle: issue cycle of the first instruction of the observed iteration
 * @insns: instruction count at that point
 * @stalls: stall count at that point
 * @epoch: &prusim.epoch at that point
 */
struct prusim_watch {
	u32 pc;
	u64 cycle;
	u64 insns;
	u64 stalls;
	u64 epoch;
};

/**
 * struct prusim_idle - a loop found to repeat without any effect (private)
 * @epoch: &prusim.epoch when it was found; stale once the epoch moves
 * @period: cycles per iteration
 * @insns: instructions per iteration
 * @stalls: stall cycles per iteration
 */
struct prusim_idle {
	u64 epoch;
	u32 period;
	u32 insns;
	u32 stalls;
};

/**
 * struct prusim_core - one PRU core
 * @r: registers r0..r31; r[32] is always 0 and serves immediate operands
 * @pc: program counter (IRAM word address)
 * @carry: ALU carry/borrow
 * @state: &enum prusim_state
 * @index: 0 for PRU0, 1 for PRU1
 * @dirty: state changed since the idle watch was armed
 * @wake_on_status: the current SLP may be ended by a WAKEUP_EN bit
 * @next: cycle at which the next instruction issues, or PRUSIM_NEVER
 * @loop_start: first word of the active hardware loop body
 * @loop_end: word after the loop body, 0xffffffff when no loop is active
 * @loop_left: iterations still to run, including the current one
 * @control: CONTROL bits SOFT_RST_N, CTR_EN, SINGLE_STEP, PCOUNTER_RST_VAL
 * @wakeup_en: WAKEUP_EN register
 * @cycle_cnt: CYCLE register
 * @stall_cnt: STALL register
 * @ctr_from: first cycle counted into @cycle_cnt and @stall_cnt after a
 *	store to CYCLE (the store's value lands at the end of the cycle after
 *	the store, so neither cycle is counted); 0 when nothing is held back
 * @ctbir: CTBIR0/1 registers
 * @ctppr: CTPPR0/1 registers
 * @ctable: constant table C0..C31 as currently programmed
 * @insns: executed instructions since prusim_init()
 * @stalls: stall cycles since prusim_init()
 * @skipped_insns: how many of @insns idle skipping accounted for instead of
 *	executing them
 * @r31_in: cached R31 input value (bits 0..29)
 * @r31_until: first cycle at which @r31_in may be stale
 * @xfr_wait: waiting in XIN 14 (1) or XOUT 14 (2) for the other core
 * @xfr_since: issue cycle of the waiting XFR
 * @mpy_prev: r28/r29 before their last write (multiplier operand history)
 * @mpy_written: cycle of the last write to r28 or r29
 * @mac_acc: multiply-accumulate accumulator
 * @mac_mode: multiplier in accumulate mode
 * @mac_carry: accumulator overflowed
 * @watch: idle-loop observation
 * @idle: idle-loop result, valid while @idle.epoch equals &prusim.epoch
 * @reason: why the core is halted or stopped
 * @iram: instruction RAM
 * @code: predecoded @iram
 * @dram: this core's data RAM (DRAM0 for PRU0, DRAM1 for PRU1)
 */
struct prusim_core {
	u32 r[33];
	u32 pc;
	u8 carry;
	u8 state;
	u8 index;
	bool dirty;
	bool wake_on_status;
	u64 next;
	u32 loop_start;
	u32 loop_end;
	u32 loop_left;
	u32 control;
	u32 wakeup_en;
	u32 cycle_cnt;
	u32 stall_cnt;
	u64 ctr_from;
	u32 ctbir[2];
	u32 ctppr[2];
	u32 ctable[32];
	u64 insns;
	u64 stalls;
	u64 skipped_insns;
	u32 r31_in;
	u64 r31_until;
	u8 xfr_wait;
	u64 xfr_since;
	u32 mpy_prev[2];
	u64 mpy_written;
	u64 mac_acc;
	bool mac_mode;
	bool mac_carry;
	struct prusim_watch watch;
	struct prusim_idle idle;
	char reason[PRUSIM_REASON_LEN];
	u32 iram[PRUSIM_IRAM_WORDS];
	struct prusim_insn code[PRUSIM_IRAM_WORDS];
	u8 dram[PRUSIM_DRAM_SIZE];
};

/**
 * struct prusim_intc - PRU-ICSS interrupt controller state
 * @raw: raw status of system events 0..63 (SRSR)
 * @enabled: event enables (ESR/ECR)
 * @cmr: channel of each event (CMR0..15)
 * @hmr: host interrupt of each channel (HMR0..2)
 * @hier: host interrupt enables (HIER)
 * @ger: global enable (GER)
 * @cr: control register (stored)
 * @gnlr: global nesting level (stored)
 * @sipr: polarity registers (stored; events are always active high)
 * @sitr: type registers (stored; events are always pulses)
 * @hinlr: host nesting levels (stored)
 * @pending: host interrupts 0..9 currently pending
 */
struct prusim_intc {
	u64 raw;
	u64 enabled;
	u8 cmr[PRUSIM_NUM_EVENTS];
	u8 hmr[PRUSIM_NUM_CHANNELS];
	u32 hier;
	u32 ger;
	u32 cr;
	u32 gnlr;
	u32 sipr[2];
	u32 sitr[2];
	u32 hinlr[PRUSIM_NUM_HOSTS];
	u32 pending;
};

/**
 * struct prusim_iep - IEP counter, computed lazily from the cycle number
 * @global_cfg: GLOBAL_CFG (CNT_ENABLE, DEFAULT_INC)
 * @overflow: GLOBAL_STATUS.CNT_OVF
 * @count: COUNT at cycle @since
 * @since: cycle of the last update of @count
 * @compen: COMPEN (stored)
 *
 * The compare block is not modelled (prusim_host_modelled()).
 */
struct prusim_iep {
	u32 global_cfg;
	bool overflow;
	u32 count;
	u64 since;
	u32 compen;
};

/**
 * struct prusim_gpio - one AM335x GPIO bank
 * @oe: OE register (1 = input; 0xffffffff at reset, as on a board); every
 *	change is reported through &prusim_ops.gpio_oe
 * @dataout: DATAOUT register; every change is reported as pin events
 * @gated: the bank's clocks are off (prusim_gpio_set_gated(), the
 *	embedder's PRCM): a core's load from it stops the core; false at reset
 */
struct prusim_gpio {
	u32 oe;
	u32 dataout;
	bool gated;
};

/**
 * struct prusim_timed - an action scheduled for a later cycle (private)
 * @cycle: when it takes effect
 * @kind: PRUSIM_TIMED_EVENT, PRUSIM_TIMED_GPIO or PRUSIM_TIMED_OCP (the
 *	oldest of &prusim.posted lands)
 * @bank: GPIO bank
 * @reg: GPIO register offset
 * @value: system event number or register value
 * @mask: bits of @value that were written
 */
struct prusim_timed {
	u64 cycle;
	u8 kind;
	u8 bank;
	u16 reg;
	u32 value;
	u32 mask;
};

/**
 * struct prusim_posted - a store over the OCP master port on its way (private)
 * @addr: OCP address
 * @len: bytes
 * @core: the core that stored it (stopped if it cannot land)
 * @data: the bytes
 */
struct prusim_posted {
	u32 addr;
	u8 len;
	u8 core;
	u8 data[PRUSIM_MAX_BURST];
};

/**
 * struct prusim - one simulated PRU-ICSS
 * @cfg: timing parameters
 * @ops: embedder callbacks
 * @ctx: first argument of every callback
 * @now: next cycle to be simulated
 * @next_event: cycle of the earliest @queue entry, or PRUSIM_NEVER
 * @attention: first cycle at which prusim_run() must look at @queue,
 *	@skip_pending, @stop_run or its end (0: at once)
 * @epoch: bumped whenever state that an idle loop might read changes
 * @skip_pending: a core found an idle loop; try to skip ahead
 * @in_step: a core instruction is executing (its effects show next cycle)
 * @stop_run: a core was stopped; prusim_run() returns
 * @waiting: the last prusim_run() returned because every core waits for the
 *	outside (&prusim_config.stop_when_idle)
 * @core: the two PRU cores
 * @shared: shared RAM
 * @spad: scratchpad banks 0..2 (XFR devices 10..12)
 * @spad_xout: cycle of PRU0's last XOUT to each bank (collision stall)
 * @intc: interrupt controller
 * @syscfg: CFG SYSCFG
 * @gpcfg: CFG GPCFG0/1 (stored)
 * @cfg_regs: other CFG registers 0x10..0x40, stored
 * @iep: IEP counter
 * @gpio: GPIO banks 0..3
 * @gpio_free: first cycle at which the GPIO banks accept another write
 * @queue: scheduled actions sorted by cycle
 * @queued: entries in @queue
 * @posted: OCP stores on their way, oldest at @posted_head
 * @posted_head: index of the oldest entry of @posted
 * @posted_n: entries in @posted
 * @posted_due: the cycle at which the newest of them lands
 */
struct prusim {
	struct prusim_config cfg;
	struct prusim_ops ops;
	void *ctx;
	u64 now;
	u64 next_event;
	u64 attention;
	u64 epoch;
	bool skip_pending;
	bool in_step;
	bool stop_run;
	bool waiting;
	struct prusim_core core[PRUSIM_NUM_CORES];
	u8 shared[PRUSIM_SHARED_SIZE];
	u8 spad[PRUSIM_SPAD_BANKS][PRUSIM_SPAD_BYTES];
	u64 spad_xout[PRUSIM_SPAD_BANKS];
	struct prusim_intc intc;
	u32 syscfg;
	u32 gpcfg[PRUSIM_NUM_CORES];
	u32 cfg_regs[13];
	struct prusim_iep iep;
	struct prusim_gpio gpio[PRUSIM_GPIO_BANKS];
	u64 gpio_free;
	struct prusim_timed queue[PRUSIM_QUEUE_LEN];
	unsigned int queued;
	struct prusim_posted posted[PRUSIM_POSTED_LEN];
	unsigned int posted_head;
	unsigned int posted_n;
	u64 posted_due;
};

/**
 * struct prusim_status - snapshot of one core for the embedder
 * @state: &enum prusim_state
 * @pc: program counter (word address)
 * @insns: instructions executed (including those idle skipping accounted for)
 * @stalls: stall cycles
 * @skipped_insns: how many of @insns idle skipping accounted for without
 *	executing them (always 0 with &prusim_config.no_skip)
 * @cycle_cnt: CTRL CYCLE register
 * @stall_cnt: CTRL STALL register
 * @regs: r0..r31 (r31 as last read by the core)
 * @reason: why the core halted or stopped ("" otherwise)
 */
struct prusim_status {
	enum prusim_state state;
	u32 pc;
	u64 insns;
	u64 stalls;
	u64 skipped_insns;
	u32 cycle_cnt;
	u32 stall_cnt;
	u32 regs[32];
	const char *reason;
};

/**
 * struct prusim_elf_info - what prusim_load_elf() found
 * @entry: entry point (IRAM byte address)
 * @rsc_offset: file offset of the .resource_table section (0: none)
 * @rsc_size: its size in bytes
 * @rsc_addr: its address in the core's data memory map
 * @irq_map_events: number of .pru_irq_map entries
 * @irq_map: the entries: system event, channel, host interrupt (applied to
 *	the INTC unless &prusim_config.irq_map_by_embedder)
 * @err: human readable reason when loading failed
 */
struct prusim_elf_info {
	u32 entry;
	u32 rsc_offset;
	u32 rsc_size;
	u32 rsc_addr;
	unsigned int irq_map_events;
	u8 irq_map[PRUSIM_NUM_EVENTS][3];
	char err[PRUSIM_REASON_LEN];
};

/* Setup (prusim_core.c) */
void prusim_default_config(struct prusim_config *cfg);
void prusim_init(struct prusim *s, const struct prusim_config *cfg,
		 const struct prusim_ops *ops, void *ctx);
void prusim_core_reset(struct prusim *s, unsigned int core, u32 pc);
void prusim_icss_reset(struct prusim *s);
void prusim_core_enable(struct prusim *s, unsigned int core, bool enable);
int prusim_write_iram(struct prusim *s, unsigned int core, u32 offset,
		      const void *buf, size_t len);

/* Running (prusim_core.c) */
u64 prusim_run(struct prusim *s, u64 max_cycles);
bool prusim_active(const struct prusim *s);
void prusim_set_ocp_write_delay(struct prusim *s, u32 cycles);
unsigned int prusim_ocp_drain(struct prusim *s);
void prusim_set_ddr_jitter(struct prusim *s, u16 cycles, u32 seed);
void prusim_get_status(const struct prusim *s, unsigned int core,
		       struct prusim_status *st);
void prusim_input_changed(struct prusim *s, unsigned int port);
void prusim_memory_written(struct prusim *s);
void prusim_yield(struct prusim *s);
void prusim_gpio_write(struct prusim *s, unsigned int bank, u32 reg, u32 value);
u32 prusim_gpio_read(struct prusim *s, unsigned int bank, u32 reg);
void prusim_gpio_set_gated(struct prusim *s, unsigned int bank, bool gated);
int prusim_gpio_bank(u32 addr);

/* Peripherals as seen from outside the subsystem (prusim_mem.c) */
void prusim_raise_event(struct prusim *s, unsigned int event);
bool prusim_host_pending(const struct prusim *s, unsigned int host);
int prusim_host_read(struct prusim *s, u32 offset, void *buf, size_t len);
int prusim_host_write(struct prusim *s, u32 offset, const void *buf, size_t len);
bool prusim_host_modelled(u32 offset, size_t len, bool write);
bool prusim_store_modelled(u32 offset, const void *buf, size_t len);
void *prusim_da_to_va(struct prusim *s, unsigned int core, u32 da, size_t len);

/* Firmware (prusim_elf.c) */
int prusim_load_elf(struct prusim *s, unsigned int core, const void *image,
		    size_t size, struct prusim_elf_info *info);

/* Disassembler (prusim_disasm.c) */
int prusim_disasm(char *buf, size_t size, u32 insn, u32 addr);

#endif /* _PRUSIM_H */
