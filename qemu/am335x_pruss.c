/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS, and the parts of the SoC a PRU and its Linux drivers
 * touch, for prukit's test VM (Documentation/qemu-pruss.rst in prukit)
 *
 * The two PRU cores, their memories, INTC, CTRL/DEBUG, CFG, IEP and the OCP
 * master port are prukit's cycle-accurate simulator, sim/ (the same sources
 * as the prusim host tool, compiled here unchanged and used only through
 * prusim.h); this file puts it at the AM335x's addresses, so that Linux's
 * own pruss, pruss_intc and pru_rproc drivers run against it as on a board:
 *
 *   0x4a300000  PRU-ICSS (512 KiB): prusim_host_read()/prusim_host_write()
 *   0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000
 *               GPIO banks 0..3 (gpio-omap): OE and the data registers are
 *               the simulator's, the rest is stored here
 *   0x44e10800  control module pad registers (pinctrl-single): a PRU output
 *               or a GPIO output reaches the pin trace only through a pad
 *               in its mode, an input R31 or DATAIN only through one that
 *               also has its receiver on
 *   0x5f000000  prukit's test port: pin trace, input stimulus, statistics
 *               and timing knobs, for tests inside the guest (registers:
 *               sim/prusim_port.h; a guest driver, prukit's
 *               tests/kmod/prusim_port.c, shows them in debugfs)
 *
 * Accesses to the rest of L4_WKUP, L4_PER and L4_FAST, and to registers of
 * the blocks above that are not modelled, are logged (-d unimp) and counted
 * in the test port's "stats": a test that makes one fails.
 *
 * Outputs: interrupts host_intr0..7 (INTC host interrupts 2..9) and one per
 * GPIO bank (never raised: GPIO interrupts are not modelled).
 *
 * The simulation runs in a thread of its own.  Lock order: the BQL before
 * the device lock, everywhere.  MMIO handlers run under the BQL and take
 * the device lock; the thread runs a slice under the device lock only,
 * drops it between slices (and waits there while an MMIO handler wants it),
 * and takes the BQL, then the device lock, to change interrupt lines.
 * The thread parks while the VM is stopped.
 *
 * Register values are handled as host integers: little-endian hosts only.
 *
 * Emulation policy (not a property of the board): while a host interrupt
 * towards the ARM is pending (until the ARM's handler has taken its event:
 * read HIPIR, masked and acknowledged it), simulated time stands still, up
 * to hold-cap-ms of host time; the handler and its thread then run while
 * the PRU runs on.  The knob hold_mode makes the hold last until the ARM
 * unmasks the event (serviced) or turns it off (none): the emulated ARM is
 * far slower than a real one relative to the PRU, and a test that counts
 * every event of a fast burst needs the longer hold.
 */

#include "qemu/osdep.h"
#include "qemu/atomic.h"
#include "qemu/cutils.h"
#include "qemu/log.h"
#include "qemu/main-loop.h"
#include "qemu/module.h"
#include "qemu/rcu.h"
#include "qemu/thread.h"
#include "qemu/timer.h"
#include "qapi/error.h"
#include "exec/address-spaces.h"
#include "exec/memory.h"
#include "hw/irq.h"
#include "hw/qdev-properties.h"
#include "hw/sysbus.h"
#include "migration/vmstate.h"
#include "qom/object.h"
#include "sysemu/runstate.h"
#include "trace.h"

#include "hw/misc/am335x_pruss.h"
#include "prusim/prusim.h"
#include "prusim/prusim_port.h"
#include "prusim/prusim_stim.h"
#include "prusim/prusim_trace.h"
#include "prusim/am335x_pins.h"

QEMU_BUILD_BUG_MSG(HOST_BIG_ENDIAN,
                   "am335x-pruss supports little-endian hosts only");

OBJECT_DECLARE_SIMPLE_TYPE(AM335xPrussState, AM335X_PRUSS)

/* The AM335x memory map (SPRUH73 chapter 2) */
#define PRUSS_BASE              0x4a300000
#define PRUSS_SIZE              0x80000
#define PADS_BASE               0x44e10800
#define PADS_NUM                142             /* conf_* at 0x800..0xa34 */
#define PADS_SIZE               (4 * PADS_NUM)
#define GPIO_SIZE               0x1000

static const hwaddr gpio_base[PRUSIM_GPIO_BANKS] = {
    0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000,
};

/* Unmodelled rest of the L4 interconnects, at a lower priority */
static const struct {
    hwaddr base;
    hwaddr size;
    const char *name;
} catch_regions[] = {
    { 0x44c00000, 0x00400000, "L4_WKUP" },
    { 0x48000000, 0x01000000, "L4_PER" },
    { 0x4a000000, 0x01000000, "L4_FAST" },
};
#define NUM_CATCH               ARRAY_SIZE(catch_regions)

/* prukit's test port: registers, and a buffer both sides read and write */
#define PORT_BASE               0x5f000000
#define PORT_SIZE               0x1000
#define PORT_BUF_BASE           0x5f800000
#define PORT_BUF_SIZE           (8 << 20)
#define PORT_HANDLES            16
#define STIM_MAX                (64 << 20)  /* staged text, all handles */

/* GPIO bank registers (SPRUH73 chapter 25) */
#define GPIO_REVISION           0x000
#define GPIO_SYSCONFIG          0x010
#define GPIO_EOI                0x020
#define GPIO_IRQSTATUS_RAW(n)   (0x024 + 4 * (n))
#define GPIO_IRQSTATUS(n)       (0x02c + 4 * (n))
#define GPIO_IRQSTATUS_SET(n)   (0x034 + 4 * (n))
#define GPIO_IRQSTATUS_CLR(n)   (0x03c + 4 * (n))
#define GPIO_IRQWAKEN(n)        (0x044 + 4 * (n))
#define GPIO_SYSSTATUS          0x114
#define GPIO_CTRL               0x130
#define GPIO_CTRL_DISABLEMODULE 0x1     /* the module's clocks are gated */
#define GPIO_LEVELDETECT(n)     (0x140 + 4 * (n))
#define GPIO_RISINGDETECT       0x148
#define GPIO_FALLINGDETECT      0x14c
#define GPIO_DEBOUNCENABLE      0x150
#define GPIO_DEBOUNCINGTIME     0x154
#define GPIO_REVISION_VALUE     0x50600801
#define GPIO_NUM_STORED         (0x160 / 4)

/* PRU-ICSS offsets the device itself looks at */
#define ICSS_INTC               0x20000
#define ICSS_INTC_SICR          (ICSS_INTC + 0x024)
#define ICSS_INTC_EISR          (ICSS_INTC + 0x028)
#define ICSS_INTC_EICR          (ICSS_INTC + 0x02c)
#define ICSS_INTC_ESR(n)        (ICSS_INTC + 0x300 + 4 * (n))
#define ICSS_INTC_ECR(n)        (ICSS_INTC + 0x380 + 4 * (n))
#define ICSS_INTC_SRSR(n)       (ICSS_INTC + 0x200 + 4 * (n))
#define ICSS_INTC_CMR(n)        (ICSS_INTC + 0x400 + 4 * (n))
#define ICSS_INTC_HMR(n)        (ICSS_INTC + 0x800 + 4 * (n))
#define ICSS_INTC_HIPIR(n)      (ICSS_INTC + 0x900 + 4 * (n))
#define ICSS_INTC_HIER          (ICSS_INTC + 0x1500)
#define ICSS_CTRL(core)         (0x22000 + 0x2000 * (core))
#define ICSS_CTRL_EN            (1u << 1)
#define ICSS_IEP_COUNT          0x2e00c

#define FIRST_ARM_HOST          2       /* host interrupts 2..9 go to the ARM */
/* as many records as the port's buffer carries after the header: 524285 */
#define TRACE_LEN               ((PORT_BUF_SIZE - \
                                  sizeof(struct prusim_trace_hdr)) / \
                                 sizeof(struct prusim_trace_rec))
#define PAD_RESET               0x27    /* mode 7, pull-down, receiver on */
#define PAD_MASK                0x7f
#define PAD_MODE                0x07    /* MUXMODE */
#define PAD_RXACTIVE            0x20    /* the pad's receiver is on */
#define UNIMP_LAST_LEN          160
#define KNOB_MAX_US             1000000
/* hold_mode: simulated time stands still for an interrupt ... */
#define HOLD_SERVICED           0       /* until the ARM unmasked its event */
#define HOLD_TAKEN              1       /* until the ARM took it (to SICR) */
#define HOLD_NONE               2       /* never */
#define OCP_WRITE_DELAY_MAX     10000000 /* cycles: 50 ms */
#define DDR_JITTER_MAX          10000   /* cycles */
#define JITTER_PAUSE_ONE_IN     64      /* a slice in 64 is followed by ... */
#define JITTER_PAUSE_MAX_US     200     /* ... a pause of up to 200 us */

/* A PRU's store to RAM the knob ocp_write_flight_us holds back */
typedef struct PrussFlight {
    uint32_t addr;
    uint32_t len;
    uint8_t data[PRUSIM_MAX_BURST];
} PrussFlight;

typedef struct PrussInput {
    struct prusim_stim stim;
    uint64_t origin;
    bool pending_origin;
    uint32_t origin_iep;
} PrussInput;

typedef struct PrussStage {
    bool used;
    unsigned int port;
    char *text;
    size_t len;
    size_t cap;
    size_t checked;
} PrussStage;

struct AM335xPrussState {
    SysBusDevice parent_obj;

    MemoryRegion pruss_mr;
    MemoryRegion gpio_mr[PRUSIM_GPIO_BANKS];
    MemoryRegion pads_mr;
    MemoryRegion port_mr;
    MemoryRegion port_buf;
    MemoryRegion catch_mr[NUM_CATCH];
    qemu_irq host_irq[AM335X_PRUSS_NUM_HOST_IRQS];
    qemu_irq gpio_irq[AM335X_PRUSS_NUM_GPIO_IRQS];
    uint8_t *buf;                   /* port_buf's memory */

    /* properties */
    uint32_t slice_cycles;
    uint32_t hold_cap_ms;
    uint32_t jitter_seed;
    uint32_t hold_mode_reset;
    uint32_t ocp_write_delay_reset;
    uint32_t ddr_jitter_reset;

    /* Under the BQL */
    bool host_level[AM335X_PRUSS_NUM_HOST_IRQS];
    uint32_t port_status;
    uint32_t port_len;
    uint32_t port_handle;

    QemuThread thread;
    QemuMutex lock;                 /* everything below; after the BQL */
    QemuCond wake;                  /* the thread waits for work here */
    QemuCond turn;                  /* ... and here for MMIO handlers */
    int waiters;                    /* MMIO handlers waiting for the lock */
    bool quit;
    bool runnable;                  /* the last slice did not end idle */
    bool irq_dirty;                 /* a host interrupt line may have changed */
    bool vm_running;
    uint32_t ocp_pauses;            /* OCP writes that ended the slice */
    VMChangeStateEntry *vmstate_entry;

    struct prusim *s;
    bool stopped_reported[PRUSIM_NUM_CORES];
    char ocp_err[PRUSIM_REASON_LEN];
    uint64_t ocp_errors;
    uint64_t ocp_writes;            /* OCP stores landed in RAM */
    uint64_t ocp_drained;           /* ... of them early, for an ARM access */

    /* pin trace */
    struct prusim_trace_rec *trace;
    uint32_t trace_head;
    uint32_t trace_count;
    uint64_t trace_dropped;
    uint64_t trace_origin;
    uint64_t trace_until;
    bool trace_first;           /* keep the first records, not the last */

    /* pads */
    uint32_t pad[PADS_NUM];
    uint64_t r30;                   /* every PRU output's level */
    uint64_t r30_shown;             /* what its pads show */
    uint64_t unmuxed_writes;
    uint64_t unmuxed_seen;          /* outputs written while unmuxed */
    uint64_t pad_writes;
    /* what reaches a pin, from the pads (pads_changed()) */
    uint64_t r30_pad_mask;          /* R30 bits on a pad in their mode */
    uint32_t r31_pad_mask[PRUSIM_NUM_CORES]; /* R31 bits a pad feeds */
    uint32_t gpio_pad_mask[PRUSIM_GPIO_BANKS]; /* lines on a pad in mode 7 */
    uint32_t gpio_in_mask[PRUSIM_GPIO_BANKS];  /* ... with its receiver on */
    /* GPIO lines: DATAOUT and OE as they land, what the pads show */
    uint32_t gpio_out[PRUSIM_GPIO_BANKS];
    uint32_t gpio_oe[PRUSIM_GPIO_BANKS];
    uint32_t gpio_shown[PRUSIM_GPIO_BANKS];
    uint32_t gpio_unmuxed_seen[PRUSIM_GPIO_BANKS];
    uint64_t gpio_unpinned;         /* GPIO output stores that reached no pin */
    uint64_t gpio_gated;            /* ... of them, to a bank gpio-omap gated */
    bool arm_gpio;                  /* in an ARM store to a GPIO bank */

    /* GPIO registers the simulator does not keep */
    uint32_t gpio_reg[PRUSIM_GPIO_BANKS][GPIO_NUM_STORED];

    PrussInput input[PRUSIM_NUM_PORTS];
    PrussStage stage[PORT_HANDLES];

    /* interrupt hold (emulation policy, see above) */
    uint64_t taken;         /* events the ARM read from HIPIR */
    uint64_t in_service;    /* ... and masked (EICR) or acked masked (SICR) */
    uint32_t expired_lines; /* held past the cap: ignored until they clear */
    uint64_t expired_events;
    int64_t hold_since;     /* host ns, 0 while not holding */
    uint64_t holds;
    uint64_t hold_ns;
    uint64_t hold_max_ns;
    uint64_t hold_expired;
    uint64_t strobe[PRUSIM_NUM_HOSTS]; /* R31 strobe that raised a host line */
    uint16_t event_latency; /* strobe to INTC, in cycles (the config's) */

    /* statistics */
    uint64_t host_ns;
    uint64_t lat_last;
    uint64_t lat_max;
    uint64_t lat_sum;
    uint64_t lat_count;
    uint64_t unimp;
    char unimp_last[UNIMP_LAST_LEN];

    /* knobs (microseconds; freeze: 0 or 1; jitter: a seed, 0 = off) */
    uint32_t ocp_write_pause_us;
    uint32_t freeze;
    uint32_t jitter;
    uint32_t hold_mode;             /* HOLD_*: how long an interrupt holds */
    uint32_t ocp_write_delay;       /* cycles from a PRU's store to RAM */
    uint32_t ocp_write_flight_us;   /* knob: and host time before it lands */
    uint32_t ddr_jitter;            /* knob: DDR accesses up to this longer */
    PrussFlight flight[PRUSIM_POSTED_LEN];  /* stores held back */
    unsigned int flight_n;
    GRand *rng;                     /* jitter's, seeded with it */
    uint64_t jitter_slices;
    uint64_t jitter_pauses;
    uint64_t jitter_pause_ns;
};

static int64_t now_ns(void)
{
    return qemu_clock_get_ns(QEMU_CLOCK_REALTIME);
}

/* ------------------------------------------------------------------ */
/* Unmodelled accesses                                                 */

static void G_GNUC_PRINTF(2, 3) pruss_unimp(AM335xPrussState *p,
                                            const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(p->unimp_last, sizeof(p->unimp_last), fmt, ap);
    va_end(ap);
    p->unimp++;
    qemu_log_mask(LOG_UNIMP, "am335x-pruss: %s\n", p->unimp_last);
}

/* ------------------------------------------------------------------ */
/* Pin trace and pads                                                  */

static void trace_pin(AM335xPrussState *p, uint64_t cycle, unsigned int pin,
                      bool level)
{
    struct prusim_trace_rec *r = &p->trace[p->trace_head];

    if (p->trace_until && cycle >= p->trace_until) {
        return;
    }
    if (p->trace_first && p->trace_count == TRACE_LEN) {
        /* full: the trace is whole up to here, and ends here */
        p->trace_until = cycle;
        p->trace_dropped++;
        return;
    }
    memset(r, 0, sizeof(*r));
    r->cycle = cycle;
    r->pin = pin;
    r->level = level;
    p->trace_head = (p->trace_head + 1) % TRACE_LEN;
    if (p->trace_count < TRACE_LEN) {
        p->trace_count++;
    } else {
        p->trace_dropped++;
    }
}

static uint32_t pad_of(AM335xPrussState *p, const struct am335x_pin_row *row)
{
    return p->pad[(row->offset - 0x800) / 4];
}

/* Is PRU output @pin (PRUSIM_PIN_R30()) on a pad muxed to it? */
static bool r30_muxed(AM335xPrussState *p, unsigned int pin)
{
    return (p->r30_pad_mask >> pin) & 1;
}

static void r30_show(AM335xPrussState *p, uint64_t cycle, unsigned int pin)
{
    uint64_t bit = 1ull << pin;
    bool level = (p->r30 & bit) && r30_muxed(p, pin);

    if (!!(p->r30_shown & bit) == level) {
        return;
    }
    p->r30_shown ^= bit;
    trace_pin(p, cycle, pin, level);
}

/*
 * gpio-omap disables a bank's module (GPIO_CTRL.DISABLEMODULE: its clocks
 * are gated) when the bank's last requested line is freed, and enables it
 * when one is requested again.
 */
static bool gpio_gated(AM335xPrussState *p, unsigned int bank)
{
    return p->gpio_reg[bank][GPIO_CTRL / 4] & GPIO_CTRL_DISABLEMODULE;
}

/*
 * A GPIO line reaches its pad while it is an output (OE bit 0) and the pad
 * is in mode 7; otherwise the trace shows it low (pulls are not modelled).
 * A gated bank's pins keep what they showed until it is enabled again.
 */
static void gpio_show(AM335xPrussState *p, uint64_t cycle, unsigned int bank)
{
    uint32_t shown = p->gpio_out[bank] & ~p->gpio_oe[bank] &
                     p->gpio_pad_mask[bank];
    uint32_t diff = shown ^ p->gpio_shown[bank];
    unsigned int bit;

    if (gpio_gated(p, bank)) {
        return;
    }
    p->gpio_shown[bank] = shown;
    for (bit = 0; diff; bit++, diff >>= 1) {
        if (diff & 1) {
            trace_pin(p, cycle, PRUSIM_PIN_GPIO(bank, bit), (shown >> bit) & 1);
        }
    }
}

/* The pads' modes and receivers, as masks of what reaches a pin */
static void pads_masks(AM335xPrussState *p)
{
    unsigned int i;

    p->r30_pad_mask = 0;
    memset(p->r31_pad_mask, 0, sizeof(p->r31_pad_mask));
    memset(p->gpio_pad_mask, 0, sizeof(p->gpio_pad_mask));
    memset(p->gpio_in_mask, 0, sizeof(p->gpio_in_mask));
    for (i = 0; i < ARRAY_SIZE(am335x_r30_pads); i++) {
        const struct am335x_pin_row *row = &am335x_r30_pads[i];

        if ((pad_of(p, row) & PAD_MODE) == row->mode) {
            p->r30_pad_mask |= 1ull << PRUSIM_PIN_R30(row->unit, row->bit);
        }
    }
    for (i = 0; i < ARRAY_SIZE(am335x_r31_pads); i++) {
        const struct am335x_pin_row *row = &am335x_r31_pads[i];
        uint32_t pad = pad_of(p, row);

        if ((pad & PAD_MODE) == row->mode && (pad & PAD_RXACTIVE)) {
            p->r31_pad_mask[row->unit] |= 1u << row->bit;
        }
    }
    for (i = 0; i < ARRAY_SIZE(am335x_gpio_pads); i++) {
        const struct am335x_pin_row *row = &am335x_gpio_pads[i];
        uint32_t pad = pad_of(p, row);

        if ((pad & PAD_MODE) == row->mode) {
            p->gpio_pad_mask[row->unit] |= 1u << row->bit;
            if (pad & PAD_RXACTIVE) {
                p->gpio_in_mask[row->unit] |= 1u << row->bit;
            }
        }
    }
}

static void pads_changed(AM335xPrussState *p)
{
    unsigned int pin, i;

    pads_masks(p);
    for (pin = 0; pin < 64; pin++) {
        r30_show(p, p->s->now, pin);
    }
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        gpio_show(p, p->s->now, i);
    }
    /* what the inputs read may have changed with a receiver or a mode */
    for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
        prusim_input_changed(p->s, i);
    }
}

/* ------------------------------------------------------------------ */
/* Input stimulus                                                      */

static uint32_t iep_count(AM335xPrussState *p)
{
    uint32_t v = 0;

    prusim_host_read(p->s, ICSS_IEP_COUNT, &v, sizeof(v));
    return v;
}

/* A core started: the origin of traces and of stimuli waiting for it. */
static void core_started(AM335xPrussState *p)
{
    unsigned int i;

    p->trace_origin = p->s->now;
    for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
        PrussInput *in = &p->input[i];

        if (in->pending_origin) {
            in->origin = p->s->now;
            in->origin_iep = iep_count(p);
            in->pending_origin = false;
        }
    }
}

static bool inputs_pending(AM335xPrussState *p)
{
    unsigned int i;

    for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
        PrussInput *in = &p->input[i];
        uint64_t next;

        if (!in->stim.count || in->pending_origin) {
            continue;
        }
        if (p->s->now < in->origin) {
            return true;
        }
        prusim_stim_value(&in->stim, p->s->now - in->origin, &next);
        if (next != PRUSIM_NEVER) {
            return true;
        }
    }
    return false;
}

static void stim_free(struct prusim_stim *st)
{
    g_free(st->cycle);
    g_free(st->value);
    memset(st, 0, sizeof(*st));
}

/* ------------------------------------------------------------------ */
/* prusim callbacks (under the device lock)                            */

/*
 * A PRU's store to DATAOUT of a line that drives no pad (an input, or its
 * pad in another mode) reaches no pin: counted apart from R30's unmuxed
 * bits, since such a store has no other purpose than a pin (the test
 * runner fails the test that made one).  The ARM's count only for an
 * output line: gpio-omap sets DATAOUT before it clears OE, as drivers do
 * on a board.  A PRU's store to a gated bank reaches no pin, and is
 * counted as such (on a board it is lost).  The ARM's are not: gpio-omap
 * restores a bank's registers on runtime resume before it enables the
 * module, and the pins show them once it does.
 */
static void cb_gpio_pin(AM335xPrussState *p, u64 cycle, unsigned int pin,
                        bool level)
{
    unsigned int bank = (pin - PRUSIM_PIN_GPIO(0, 0)) / 32;
    uint32_t bit = 1u << (pin % 32);
    bool output = !(p->gpio_oe[bank] & bit);

    if (level) {
        p->gpio_out[bank] |= bit;
    } else {
        p->gpio_out[bank] &= ~bit;
    }
    if (gpio_gated(p, bank) && !p->arm_gpio) {
        p->gpio_gated++;
        p->gpio_unpinned++;
        p->gpio_unmuxed_seen[bank] |= bit;
    } else if (!(output && (p->gpio_pad_mask[bank] & bit)) &&
               (output || !p->arm_gpio)) {
        p->gpio_unpinned++;
        p->gpio_unmuxed_seen[bank] |= bit;
    }
    gpio_show(p, cycle, bank);
}

static void cb_gpio_oe(void *ctx, u64 cycle, unsigned int bank, u32 oe)
{
    AM335xPrussState *p = ctx;

    p->gpio_oe[bank] = oe;
    gpio_show(p, cycle, bank);
}

static void cb_pin(void *ctx, u64 cycle, unsigned int pin, bool level)
{
    AM335xPrussState *p = ctx;
    uint64_t bit;

    if (pin >= PRUSIM_PIN_GPIO(0, 0)) {
        cb_gpio_pin(p, cycle, pin, level);
        return;
    }
    bit = 1ull << pin;
    if (level) {
        p->r30 |= bit;
    } else {
        p->r30 &= ~bit;
    }
    if (!r30_muxed(p, pin)) {
        p->unmuxed_writes++;
        p->unmuxed_seen |= bit;
    }
    r30_show(p, cycle, pin);
}

static u32 cb_input(void *ctx, unsigned int port, u64 cycle, u64 *next_change)
{
    AM335xPrussState *p = ctx;
    PrussInput *in = &p->input[port];
    uint64_t next;
    uint32_t v;

    if (!in->stim.count || in->pending_origin || cycle < in->origin) {
        *next_change = in->stim.count && !in->pending_origin ?
                       in->origin : PRUSIM_NEVER;
        return 0;
    }
    v = prusim_stim_value(&in->stim, cycle - in->origin, &next);
    *next_change = next == PRUSIM_NEVER ? PRUSIM_NEVER : next + in->origin;
    /* a signal reaches R31 or DATAIN through a pad in its mode, receiving */
    if (port >= PRUSIM_PORT_GPIO(0)) {
        return v & p->gpio_in_mask[port - PRUSIM_PORT_GPIO(0)];
    }
    return v & p->r31_pad_mask[port];
}

static void cb_host_irq(void *ctx, u64 cycle, unsigned int host, bool level)
{
    AM335xPrussState *p = ctx;

    if (host < FIRST_ARM_HOST) {
        return;
    }
    if (level) {
        p->strobe[host] = cycle - MIN(cycle, (u64)p->event_latency);
    }
    p->irq_dirty = true;
    /* the slice ends here: the line is delivered before time goes on */
    prusim_yield(p->s);
}

/* Is [@addr, @addr + @len) guest RAM? */
static bool ocp_is_ram(uint32_t addr, unsigned int len, bool write)
{
    MemoryRegion *mr;
    hwaddr xlat, l = len;

    RCU_READ_LOCK_GUARD();
    mr = address_space_translate(&address_space_memory, addr, &xlat, &l, write,
                                 MEMTXATTRS_UNSPECIFIED);
    return memory_region_is_ram(mr) && !memory_region_is_romd(mr) && l >= len;
}

/*
 * The stores the knob ocp_write_flight_us held back land in order: each after
 * its own wait in the thread (knob_waits()), or all at once when the ARM
 * stops a core (a stop takes longer on a board than any store's way to RAM).
 */
static void flight_land_one(AM335xPrussState *p)
{
    PrussFlight *f = &p->flight[0];

    if (!p->flight_n) {
        return;
    }
    if (address_space_rw(&address_space_memory, f->addr,
                         MEMTXATTRS_UNSPECIFIED, f->data, f->len,
                         true) != MEMTX_OK) {
        snprintf(p->ocp_err, sizeof(p->ocp_err),
                 "OCP write at 0x%08x failed", f->addr);
        p->ocp_errors++;
        qemu_log_mask(LOG_GUEST_ERROR, "am335x-pruss: %s\n", p->ocp_err);
    } else {
        p->ocp_writes++;
    }
    p->flight_n--;
    memmove(&p->flight[0], &p->flight[1], p->flight_n * sizeof(p->flight[0]));
}

static void flight_land(AM335xPrussState *p)
{
    while (p->flight_n) {
        flight_land_one(p);
    }
}

/* A PRU's load sees the stores held back (they landed for the simulation) */
static void flight_seen(AM335xPrussState *p, uint32_t addr, uint8_t *buf,
                        uint32_t len)
{
    unsigned int i;

    for (i = 0; i < p->flight_n; i++) {
        const PrussFlight *f = &p->flight[i];
        uint64_t lo = MAX(f->addr, addr);
        uint64_t hi = MIN((uint64_t)f->addr + f->len, (uint64_t)addr + len);

        if (lo < hi) {
            memcpy(buf + (lo - addr), f->data + (lo - f->addr), hi - lo);
        }
    }
}

/*
 * OCP master port: the AM335x EMIF window 0x80000000..0xbfffffff, where the
 * guest's RAM is (as an AM335x's DDR is).  Only RAM: a device behind the
 * port would need the BQL, which this lock must not wait for.  The check
 * and the access translate the address apart; that is safe because the
 * board maps its RAM once and never moves it.
 */
static int cb_ocp(AM335xPrussState *p, u32 addr, void *buf, unsigned int len,
                  bool write)
{
    const char *what = write ? "write" : "read";

    if (addr < 0x80000000u || (uint64_t)addr + len > 0xc0000000ull) {
        snprintf(p->ocp_err, sizeof(p->ocp_err),
                 "OCP %s of %u bytes at 0x%08x: not modelled (only DDR)",
                 what, len, addr);
        goto fail;
    }
    if (!ocp_is_ram(addr, len, write)) {
        snprintf(p->ocp_err, sizeof(p->ocp_err),
                 "OCP %s of %u bytes at 0x%08x: no RAM there",
                 what, len, addr);
        goto fail;
    }
    if (write && p->ocp_write_flight_us) {
        /* knob: the store lands once the thread has waited (flight_land()) */
        PrussFlight *f;

        if (p->flight_n == ARRAY_SIZE(p->flight)) {
            flight_land(p);
        }
        f = &p->flight[p->flight_n++];
        f->addr = addr;
        f->len = len;
        memcpy(f->data, buf, len);
        prusim_yield(p->s);
        return 0;
    }
    if (address_space_rw(&address_space_memory, addr, MEMTXATTRS_UNSPECIFIED,
                         buf, len, write) != MEMTX_OK) {
        snprintf(p->ocp_err, sizeof(p->ocp_err),
                 "OCP %s at 0x%08x failed", what, addr);
        goto fail;
    }
    if (write) {
        p->ocp_writes++;
    } else {
        flight_seen(p, addr, buf, len);
    }
    if (write && p->ocp_write_pause_us) {
        /* knob: the thread pauses after this store (pruss_thread()) */
        p->ocp_pauses++;
        prusim_yield(p->s);
    }
    return 0;
fail:
    p->ocp_errors++;
    qemu_log_mask(LOG_GUEST_ERROR, "am335x-pruss: %s\n", p->ocp_err);
    return -EFAULT;
}

static int cb_ocp_read(void *ctx, u32 addr, void *buf, unsigned int len)
{
    return cb_ocp(ctx, addr, buf, len, false);
}

static int cb_ocp_write(void *ctx, u32 addr, const void *buf, unsigned int len)
{
    return cb_ocp(ctx, addr, (void *)buf, len, true);
}

static const struct prusim_ops pruss_sim_ops = {
    .pin = cb_pin,
    .input = cb_input,
    .gpio_oe = cb_gpio_oe,
    .host_irq = cb_host_irq,
    .ocp_read = cb_ocp_read,
    .ocp_write = cb_ocp_write,
};

/* ------------------------------------------------------------------ */
/* Interrupt lines and the hold                                        */

static uint32_t icss_read32(AM335xPrussState *p, uint32_t off)
{
    uint32_t v = 0;

    prusim_host_read(p->s, off, &v, sizeof(v));
    return v;
}

/* Events routed to a host interrupt towards the ARM that is enabled */
static uint64_t arm_routed(AM335xPrussState *p)
{
    uint32_t hier = icss_read32(p, ICSS_INTC_HIER);
    uint8_t cmr[PRUSIM_NUM_EVENTS], hmr[12];
    uint64_t mask = 0;
    unsigned int ev;

    prusim_host_read(p->s, ICSS_INTC_CMR(0), cmr, sizeof(cmr));
    prusim_host_read(p->s, ICSS_INTC_HMR(0), hmr, sizeof(hmr));
    for (ev = 0; ev < PRUSIM_NUM_EVENTS; ev++) {
        unsigned int ch = cmr[ev] & 0xf, host;

        if (ch >= PRUSIM_NUM_CHANNELS) {
            continue;
        }
        host = hmr[ch] & 0xf;
        if (host >= FIRST_ARM_HOST && host < PRUSIM_NUM_HOSTS &&
            (hier >> host) & 1) {
            mask |= 1ull << ev;
        }
    }
    return mask;
}

static uint32_t arm_lines(AM335xPrussState *p)
{
    uint32_t lines = 0;
    unsigned int host;

    for (host = FIRST_ARM_HOST; host < PRUSIM_NUM_HOSTS; host++) {
        if (prusim_host_pending(p->s, host)) {
            lines |= 1u << host;
        }
    }
    return lines;
}

/*
 * Whether simulated time must stand still now (see the top of the file),
 * with the accounting of holds and of the cap.  Sets *@wait_ms to how long
 * the cap still allows.
 */
static bool pruss_held(AM335xPrussState *p, int *wait_ms)
{
    uint32_t lines = p->hold_mode == HOLD_NONE ? 0 : arm_lines(p);
    uint64_t events = 0;
    int64_t now = now_ns(), held;

    /*
     * taken: from its read from HIPIR until acknowledged (SICR);
     * serviced: also from the mask (EICR) to the unmask (EISR)
     */
    if (p->hold_mode != HOLD_NONE && p->taken) {
        events = p->taken;
    }
    if (p->hold_mode == HOLD_SERVICED) {
        events |= p->in_service;
    }
    if (events) {
        events &= arm_routed(p);
    }

    p->expired_lines &= lines;
    p->expired_events &= events;
    lines &= ~p->expired_lines;
    events &= ~p->expired_events;
    if (!lines && !events) {
        if (p->hold_since) {
            held = now - p->hold_since;
            p->hold_ns += held;
            p->hold_max_ns = MAX(p->hold_max_ns, (uint64_t)held);
            p->hold_since = 0;
        }
        return false;
    }
    if (!p->hold_since) {
        p->hold_since = now;
        p->holds++;
    }
    held = now - p->hold_since;
    if (held >= (int64_t)p->hold_cap_ms * SCALE_MS) {
        p->expired_lines |= lines;
        p->expired_events |= events;
        p->hold_expired++;
        p->hold_ns += held;
        p->hold_max_ns = MAX(p->hold_max_ns, (uint64_t)held);
        p->hold_since = 0;
        return false;
    }
    *wait_ms = MAX(1, (int)(((int64_t)p->hold_cap_ms * SCALE_MS - held) /
                            SCALE_MS));
    return true;
}

/* Drive the host interrupt lines as the INTC says.  BQL and lock held. */
static void pruss_update_irqs(AM335xPrussState *p)
{
    unsigned int i;

    p->irq_dirty = false;
    for (i = 0; i < AM335X_PRUSS_NUM_HOST_IRQS; i++) {
        bool level = prusim_host_pending(p->s, FIRST_ARM_HOST + i);

        if (level != p->host_level[i]) {
            p->host_level[i] = level;
            trace_am335x_pruss_irq(i, level);
            qemu_set_irq(p->host_irq[i], level);
        }
    }
}

/*
 * The ARM takes, masks, acknowledges and unmasks events through the INTC:
 * follow what it does to the events of its host interrupts (the hold), and
 * time the deliveries.  pruss-intc's chained handler reads HIPIR, then
 * handle_level_irq() masks the event (EICR) and acknowledges it (SICR), runs
 * the handler (or wakes its thread) and unmasks it (EISR): from the mask to
 * the unmask the ARM is servicing the event.  Called before the write @off
 * = @val is made.
 */
static void intc_write_seen(AM335xPrussState *p, uint32_t off, uint32_t val)
{
    unsigned int ev = val & 0x3ff, host;
    uint64_t bit = ev < PRUSIM_NUM_EVENTS ? 1ull << ev : 0;
    uint8_t cmr[PRUSIM_NUM_EVENTS], hmr[12];

    switch (off) {
    case ICSS_INTC_EICR:
        if (p->taken & bit) {
            p->in_service |= bit;
        }
        break;
    case ICSS_INTC_SICR:
        if (!(p->taken & bit)) {
            break;
        }
        p->taken &= ~bit;
        if (!((icss_read32(p, ICSS_INTC_ESR(ev / 32)) >> (ev % 32)) & 1)) {
            p->in_service |= bit;
        }
        if (!((icss_read32(p, ICSS_INTC_SRSR(ev / 32)) >> (ev % 32)) & 1)) {
            break;
        }
        /* the delivery's latency, from the R31 strobe to this ack */
        prusim_host_read(p->s, ICSS_INTC_CMR(0), cmr, sizeof(cmr));
        prusim_host_read(p->s, ICSS_INTC_HMR(0), hmr, sizeof(hmr));
        if ((cmr[ev] & 0xf) >= PRUSIM_NUM_CHANNELS) {
            break;
        }
        host = hmr[cmr[ev] & 0xf] & 0xf;
        if (host < PRUSIM_NUM_HOSTS && p->strobe[host] &&
            p->s->now >= p->strobe[host]) {
            p->lat_last = p->s->now - p->strobe[host];
            p->lat_max = MAX(p->lat_max, p->lat_last);
            p->lat_sum += p->lat_last;
            p->lat_count++;
        }
        break;
    case ICSS_INTC_EISR:
        p->in_service &= ~bit;
        break;
    case ICSS_INTC_ESR(0):
    case ICSS_INTC_ECR(0):
        p->in_service &= ~(uint64_t)val;
        p->taken &= ~(uint64_t)val;
        break;
    case ICSS_INTC_ESR(1):
    case ICSS_INTC_ECR(1):
        p->in_service &= ~((uint64_t)val << 32);
        p->taken &= ~((uint64_t)val << 32);
        break;
    }
}

/* ------------------------------------------------------------------ */
/* Taking the lock from an MMIO handler (BQL held)                      */

static void pruss_lock(AM335xPrussState *p)
{
    qatomic_inc(&p->waiters);
    qemu_mutex_lock(&p->lock);
    qatomic_dec(&p->waiters);
}

static void pruss_unlock(AM335xPrussState *p, bool kick)
{
    if (kick) {
        qemu_cond_signal(&p->wake);
    }
    qemu_cond_signal(&p->turn);
    qemu_mutex_unlock(&p->lock);
}

/* ------------------------------------------------------------------ */
/* PRU-ICSS                                                            */

/*
 * Every ARM access to the PRU-ICSS first lands the PRUs' stores on their way
 * to RAM (prusim_ocp_drain()).  On a board a store reaches DDR within a
 * fraction of a microsecond, sooner than Linux reacts to anything the PRU
 * did after it (an interrupt's HIPIR read, a status word's load); here the
 * simulation's thread may get no host CPU while the emulated ARM runs on,
 * and a store could wait for milliseconds.  The knob ocp_write_flight_us
 * holds stores back past this on purpose.
 */
static uint64_t pruss_read(void *opaque, hwaddr addr, unsigned int size)
{
    AM335xPrussState *p = opaque;
    uint32_t v = 0;

    pruss_lock(p);
    p->ocp_drained += prusim_ocp_drain(p->s);
    if (!prusim_host_modelled(addr, size, false)) {
        pruss_unimp(p, "PRU-ICSS read of %u bytes at 0x%05" HWADDR_PRIx,
                    size, addr);
    }
    prusim_host_read(p->s, addr, &v, size);
    /* the ARM's interrupt handler takes the event HIPIR names */
    if (addr >= ICSS_INTC_HIPIR(FIRST_ARM_HOST) &&
        addr < ICSS_INTC_HIPIR(PRUSIM_NUM_HOSTS) &&
        size == 4 && v < PRUSIM_NUM_EVENTS) {
        p->taken |= 1ull << v;
    }
    /* stores the drain left to the knobs are the thread's to land */
    pruss_unlock(p, p->flight_n || p->ocp_pauses);
    trace_am335x_pruss_read(addr, size, v);
    return v;
}

static void pruss_write(void *opaque, hwaddr addr, uint64_t val,
                        unsigned int size)
{
    AM335xPrussState *p = opaque;
    uint32_t v = val;
    bool was_running[PRUSIM_NUM_CORES];
    unsigned int i;

    trace_am335x_pruss_write(addr, size, v);
    pruss_lock(p);
    p->ocp_drained += prusim_ocp_drain(p->s);
    if (!prusim_host_modelled(addr, size, true)) {
        pruss_unimp(p,
                    "PRU-ICSS write of %u bytes at 0x%05" HWADDR_PRIx " (0x%x)",
                    size, addr, v);
    } else if (!prusim_store_modelled(addr, &v, size)) {
        pruss_unimp(p, "PRU-ICSS write of 0x%x (%u bytes) at 0x%05" HWADDR_PRIx
                    ": a setting not modelled", v, size, addr);
    }
    for (i = 0; i < PRUSIM_NUM_CORES; i++) {
        struct prusim_status st;

        prusim_get_status(p->s, i, &st);
        was_running[i] = st.state == PRUSIM_RUNNING ||
                         st.state == PRUSIM_SLEEPING;
    }
    if (addr >= ICSS_INTC && addr < ICSS_INTC + 0x2000 && size == 4) {
        intc_write_seen(p, addr, v);
    }
    if (addr == ICSS_CTRL(0) || addr == ICSS_CTRL(1)) {
        /* a core's CONTROL: even the knob's stores land before it stops */
        flight_land(p);
    }
    prusim_host_write(p->s, addr, &v, size);
    for (i = 0; i < PRUSIM_NUM_CORES; i++) {
        struct prusim_status st;

        prusim_get_status(p->s, i, &st);
        if (!was_running[i] && st.state == PRUSIM_RUNNING) {
            core_started(p);
            p->stopped_reported[i] = false;
        }
    }
    p->runnable = true;
    pruss_update_irqs(p);
    pruss_unlock(p, true);
}

static const MemoryRegionOps pruss_ops = {
    .read = pruss_read,
    .write = pruss_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};

/* ------------------------------------------------------------------ */
/* GPIO banks                                                          */

static bool gpio_sim_reg(hwaddr off)
{
    return off == PRUSIM_GPIO_OE || off == PRUSIM_GPIO_DATAIN ||
           off == PRUSIM_GPIO_DATAOUT || off == PRUSIM_GPIO_CLEARDATAOUT ||
           off == PRUSIM_GPIO_SETDATAOUT;
}

static bool gpio_stored_reg(hwaddr off)
{
    switch (off) {
    case GPIO_SYSCONFIG:
    case GPIO_IRQSTATUS_RAW(0):
    case GPIO_IRQSTATUS_RAW(1):
    case GPIO_IRQSTATUS(0):
    case GPIO_IRQSTATUS(1):
    case GPIO_IRQSTATUS_SET(0):
    case GPIO_IRQSTATUS_SET(1):
    case GPIO_IRQSTATUS_CLR(0):
    case GPIO_IRQSTATUS_CLR(1):
    case GPIO_IRQWAKEN(0):
    case GPIO_IRQWAKEN(1):
    case GPIO_CTRL:
    case GPIO_LEVELDETECT(0):
    case GPIO_LEVELDETECT(1):
    case GPIO_RISINGDETECT:
    case GPIO_FALLINGDETECT:
    case GPIO_DEBOUNCENABLE:
    case GPIO_DEBOUNCINGTIME:
        return true;
    }
    return false;
}

static uint64_t gpio_read(void *opaque, hwaddr off, unsigned int size,
                          unsigned int bank)
{
    AM335xPrussState *p = opaque;
    unsigned int shift;
    uint32_t v = 0;

    /*
     * a narrower read (gpio-omap reads REVISION as 16 bits) takes part of the
     * word
     */
    if ((off & 3) + size > 4) {
        pruss_lock(p);
        pruss_unimp(p, "GPIO%u read of %u bytes at 0x%03" HWADDR_PRIx,
                    bank, size, off);
        pruss_unlock(p, false);
        return 0;
    }
    shift = 8 * (off & 3);
    off &= ~(hwaddr)3;
    pruss_lock(p);
    if (gpio_sim_reg(off)) {
        v = prusim_gpio_read(p->s, bank,
                             off == PRUSIM_GPIO_OE ||
                             off == PRUSIM_GPIO_DATAIN ?
                             off : PRUSIM_GPIO_DATAOUT);
    } else if (off == GPIO_REVISION) {
        v = GPIO_REVISION_VALUE;
    } else if (off == GPIO_SYSSTATUS) {
        v = 1;          /* RESETDONE */
    } else if (off == GPIO_IRQSTATUS_CLR(0) || off == GPIO_IRQSTATUS_CLR(1)) {
        v = p->gpio_reg[bank][(off - GPIO_IRQSTATUS_CLR(0) +
                               GPIO_IRQSTATUS_SET(0)) / 4];
    } else if (gpio_stored_reg(off)) {
        v = p->gpio_reg[bank][off / 4];
    } else {
        pruss_unimp(p, "GPIO%u read at 0x%03" HWADDR_PRIx, bank, off);
    }
    pruss_unlock(p, false);
    trace_am335x_pruss_gpio_read(bank, off, v);
    return extract32(v, shift, 8 * size);
}

static void gpio_write(void *opaque, hwaddr off, uint64_t val,
                       unsigned int size, unsigned int bank)
{
    AM335xPrussState *p = opaque;
    uint32_t v = val, *reg;

    trace_am335x_pruss_gpio_write(bank, off, v);
    pruss_lock(p);
    if (size != 4 || off & 3) {
        pruss_unimp(p, "GPIO%u write of %u bytes at 0x%03" HWADDR_PRIx,
                    bank, size, off);
    } else if (gpio_sim_reg(off) && off != PRUSIM_GPIO_DATAIN) {
        p->arm_gpio = true;
        prusim_gpio_write(p->s, bank, off, v);
        p->arm_gpio = false;
    } else if (gpio_stored_reg(off)) {
        reg = &p->gpio_reg[bank][off / 4];
        switch (off) {
        case GPIO_IRQSTATUS(0):
        case GPIO_IRQSTATUS(1):
            *reg &= ~v;             /* write 1 to clear; never set */
            break;
        case GPIO_IRQSTATUS_SET(0):
        case GPIO_IRQSTATUS_SET(1):
            if (v) {
                pruss_unimp(p, "GPIO%u interrupts (IRQSTATUS_SET 0x%08x)",
                            bank, v);
            }
            *reg |= v;
            break;
        case GPIO_IRQSTATUS_CLR(0):
        case GPIO_IRQSTATUS_CLR(1):
            p->gpio_reg[bank][(off - GPIO_IRQSTATUS_CLR(0) +
                               GPIO_IRQSTATUS_SET(0)) / 4] &= ~v;
            break;
        case GPIO_IRQSTATUS_RAW(0):
        case GPIO_IRQSTATUS_RAW(1):
            if (v) {
                pruss_unimp(p, "GPIO%u IRQSTATUS_RAW set 0x%08x", bank, v);
            }
            break;
        case GPIO_CTRL:
            *reg = v;
            gpio_show(p, p->s->now, bank);  /* enabled: the pins catch up */
            break;
        default:
            *reg = v;
            break;
        }
    } else if (off != GPIO_EOI) {
        pruss_unimp(p, "GPIO%u write at 0x%03" HWADDR_PRIx " (0x%x)",
                    bank, off, v);
    }
    p->runnable = true;
    pruss_unlock(p, true);
}

#define GPIO_OPS(n)                                                     \
static uint64_t gpio##n##_read(void *opaque, hwaddr off, unsigned int size) \
{                                                                       \
    return gpio_read(opaque, off, size, n);                             \
}                                                                       \
static void gpio##n##_write(void *opaque, hwaddr off, uint64_t v,       \
                            unsigned int size)                          \
{                                                                       \
    gpio_write(opaque, off, v, size, n);                                \
}
GPIO_OPS(0)
GPIO_OPS(1)
GPIO_OPS(2)
GPIO_OPS(3)

static const MemoryRegionOps gpio_ops[PRUSIM_GPIO_BANKS] = {
#define GPIO_OPS_ENTRY(n)                                               \
    [n] = {                                                             \
        .read = gpio##n##_read,                                         \
        .write = gpio##n##_write,                                       \
        .endianness = DEVICE_LITTLE_ENDIAN,                             \
        .valid = { .min_access_size = 1, .max_access_size = 4 },        \
        .impl = { .min_access_size = 1, .max_access_size = 4 },         \
    }
    GPIO_OPS_ENTRY(0), GPIO_OPS_ENTRY(1), GPIO_OPS_ENTRY(2), GPIO_OPS_ENTRY(3),
};

/* ------------------------------------------------------------------ */
/* Pad registers                                                       */

static uint64_t pads_read(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPrussState *p = opaque;
    uint32_t v = 0;

    pruss_lock(p);
    if (size != 4 || off & 3) {
        pruss_unimp(p, "pad read of %u bytes at 0x%03" HWADDR_PRIx,
                    size, 0x800 + off);
    } else {
        v = p->pad[off / 4];
    }
    pruss_unlock(p, false);
    return v;
}

static void pads_write(void *opaque, hwaddr off, uint64_t val,
                       unsigned int size)
{
    AM335xPrussState *p = opaque;

    trace_am335x_pruss_pad_write(0x800 + off, val);
    pruss_lock(p);
    if (size != 4 || off & 3) {
        pruss_unimp(p, "pad write of %u bytes at 0x%03" HWADDR_PRIx,
                    size, 0x800 + off);
    } else {
        p->pad[off / 4] = val & PAD_MASK;
        p->pad_writes++;
        pads_changed(p);
    }
    pruss_unlock(p, false);
}

static const MemoryRegionOps pads_ops = {
    .read = pads_read,
    .write = pads_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};

/* ------------------------------------------------------------------ */
/* The rest of the L4 interconnects: not modelled                      */

static uint64_t catch_read(void *opaque, hwaddr off, unsigned int size)
{
    MemoryRegion *mr = opaque;
    AM335xPrussState *p = AM335X_PRUSS(mr->owner);

    pruss_lock(p);
    pruss_unimp(p, "read of %u bytes at 0x%08" HWADDR_PRIx " (not modelled)",
                size, mr->addr + off);
    pruss_unlock(p, false);
    return 0;
}

static void catch_write(void *opaque, hwaddr off, uint64_t val,
                        unsigned int size)
{
    MemoryRegion *mr = opaque;
    AM335xPrussState *p = AM335X_PRUSS(mr->owner);

    pruss_lock(p);
    pruss_unimp(p, "write of %u bytes at 0x%08" HWADDR_PRIx
                " (0x%" PRIx64 ", not modelled)",
                size, mr->addr + off, val);
    pruss_unlock(p, false);
}

static const MemoryRegionOps catch_ops = {
    .read = catch_read,
    .write = catch_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 8 },
};

/* ------------------------------------------------------------------ */
/* Test port: files                                                    */

enum port_file {
    PF_TRACE,
    PF_STATS,
    PF_PADS,
    PF_OCP_WRITE_PAUSE_US,
    PF_FREEZE,
    PF_JITTER,
    PF_HOLD_MODE,
    PF_OCP_WRITE_DELAY,
    PF_OCP_WRITE_FLIGHT_US,
    PF_DDR_JITTER,
    PF_INPUT,               /* PF_INPUT + port: input/<name> */
    PF_NUM = PF_INPUT + PRUSIM_NUM_PORTS,
};

static const char *const port_file_name[PF_NUM] = {
    [PF_TRACE] = "trace",
    [PF_STATS] = "stats",
    [PF_PADS] = "pads",
    [PF_OCP_WRITE_PAUSE_US] = "ocp_write_pause_us",
    [PF_FREEZE] = "freeze",
    [PF_JITTER] = "jitter",
    [PF_HOLD_MODE] = "hold_mode",
    [PF_OCP_WRITE_DELAY] = "ocp_write_delay",
    [PF_OCP_WRITE_FLIGHT_US] = "ocp_write_flight_us",
    [PF_DDR_JITTER] = "ddr_jitter",
    [PF_INPUT + PRUSIM_PORT_R31(0)] = "input/r31-0",
    [PF_INPUT + PRUSIM_PORT_R31(1)] = "input/r31-1",
    [PF_INPUT + PRUSIM_PORT_GPIO(0)] = "input/gpio0",
    [PF_INPUT + PRUSIM_PORT_GPIO(1)] = "input/gpio1",
    [PF_INPUT + PRUSIM_PORT_GPIO(2)] = "input/gpio2",
    [PF_INPUT + PRUSIM_PORT_GPIO(3)] = "input/gpio3",
};

/* Reply text; returns its length (truncated to the buffer) */
static uint32_t G_GNUC_PRINTF(2, 3) port_reply(AM335xPrussState *p,
                                               const char *fmt, ...)
{
    va_list ap;
    int n;

    va_start(ap, fmt);
    n = vsnprintf((char *)p->buf, PORT_BUF_SIZE, fmt, ap);
    va_end(ap);
    return MIN((uint32_t)MAX(n, 0), PORT_BUF_SIZE - 1);
}

/* Appends to the reply being built at *@len */
static void G_GNUC_PRINTF(3, 4) port_add(AM335xPrussState *p, uint32_t *len,
                                         const char *fmt, ...)
{
    va_list ap;
    int n;

    if (*len >= PORT_BUF_SIZE - 1) {
        return;
    }
    va_start(ap, fmt);
    n = vsnprintf((char *)p->buf + *len, PORT_BUF_SIZE - *len, fmt, ap);
    va_end(ap);
    *len = MIN(*len + MAX(n, 0), PORT_BUF_SIZE - 1);
}

static uint32_t port_trace(AM335xPrussState *p)
{
    struct prusim_trace_hdr hdr;
    uint32_t first, n;
    uint8_t *rec = p->buf + sizeof(hdr);

    memset(&hdr, 0, sizeof(hdr));
    memcpy(hdr.magic, PRUSIM_TRACE_MAGIC, sizeof(hdr.magic));
    hdr.version = PRUSIM_TRACE_VERSION;
    hdr.rec_size = sizeof(struct prusim_trace_rec);
    hdr.origin = p->trace_origin;
    hdr.count = p->trace_count;
    hdr.dropped = p->trace_dropped;
    hdr.end = p->trace_until ? MIN(p->s->now, p->trace_until) : p->s->now;
    memcpy(p->buf, &hdr, sizeof(hdr));
    first = (p->trace_head + TRACE_LEN - p->trace_count) % TRACE_LEN;
    n = MIN(p->trace_count, TRACE_LEN - first);
    memcpy(rec, &p->trace[first], n * sizeof(*p->trace));
    memcpy(rec + n * sizeof(*p->trace), p->trace,
           (p->trace_count - n) * sizeof(*p->trace));
    return sizeof(hdr) + p->trace_count * sizeof(*p->trace);
}

static const char *const state_name[] = {
    [PRUSIM_DISABLED] = "disabled",
    [PRUSIM_RUNNING] = "running",
    [PRUSIM_SLEEPING] = "sleeping",
    [PRUSIM_HALTED] = "halted",
    [PRUSIM_STOPPED] = "stopped",
};

static uint32_t port_stats(AM335xPrussState *p)
{
    uint64_t enabled = (uint64_t)icss_read32(p, ICSS_INTC_ESR(1)) << 32 |
                       icss_read32(p, ICSS_INTC_ESR(0));
    uint8_t cmr[PRUSIM_NUM_EVENTS], hmr[12];
    uint32_t len = 0;
    unsigned int i;
    int64_t held = p->hold_since ? now_ns() - p->hold_since : 0;

    prusim_host_read(p->s, ICSS_INTC_CMR(0), cmr, sizeof(cmr));
    prusim_host_read(p->s, ICSS_INTC_HMR(0), hmr, sizeof(hmr));
    port_add(p, &len, "cycles %" PRIu64 "\n", p->s->now);
    port_add(p, &len, "host_ns %" PRIu64 "\n", p->host_ns);
    for (i = 0; i < PRUSIM_NUM_CORES; i++) {
        struct prusim_status st;

        prusim_get_status(p->s, i, &st);
        port_add(p, &len, "pru%u state %s pc 0x%x instructions %" PRIu64
                 " stalls %" PRIu64 " reason %s\n", i, state_name[st.state],
                 st.pc * 4, st.insns, st.stalls,
                 st.reason[0] ? st.reason : "-");
    }
    port_add(p, &len, "trace_events %u trace_dropped %" PRIu64
             " trace_origin %" PRIu64
             " trace_until %" PRIu64 "\n", p->trace_count, p->trace_dropped,
             p->trace_origin, p->trace_until);
    port_add(p, &len, "pads checked unmuxed_writes %" PRIu64 "\n",
             p->unmuxed_writes);
    port_add(p, &len, "gpio_unpinned_writes %" PRIu64 "\n", p->gpio_unpinned);
    port_add(p, &len, "gpio_gated_writes %" PRIu64 " gated_banks",
             p->gpio_gated);
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        if (gpio_gated(p, i)) {
            port_add(p, &len, " gpio%u", i);
        }
    }
    port_add(p, &len, "\n");
    port_add(p, &len, "unmuxed_outputs");
    for (i = 0; i < 64; i++) {
        if ((p->unmuxed_seen >> i) & 1) {
            port_add(p, &len, " pru%u_r30_%u", i / 32, i % 32);
        }
    }
    for (i = 0; i < 32 * PRUSIM_GPIO_BANKS; i++) {
        if ((p->gpio_unmuxed_seen[i / 32] >> (i % 32)) & 1) {
            port_add(p, &len, " gpio%u_%u", i / 32, i % 32);
        }
    }
    port_add(p, &len, "\n");
    port_add(p, &len, "routes");
    for (i = 0; i < PRUSIM_NUM_EVENTS; i++) {
        unsigned int ch = cmr[i] & 0xf;

        if (((enabled | p->in_service) >> i) & 1) {
            port_add(p, &len, " %u:%u:%u", i, ch,
                     ch < PRUSIM_NUM_CHANNELS ? hmr[ch] & 0xf : 0);
        }
    }
    port_add(p, &len, "\n");
    port_add(p, &len, "irq_latency last %" PRIu64 " max %" PRIu64
             " mean %" PRIu64
             " count %" PRIu64 "\n", p->lat_last, p->lat_max,
             p->lat_count ? p->lat_sum / p->lat_count : 0, p->lat_count);
    port_add(p, &len, "holds %" PRIu64 " held_ns %" PRIu64
             " held_max_ns %" PRIu64
             " hold_expired %" PRIu64 " hold_cap_ms %u hold_mode %u\n",
             p->holds, p->hold_ns + held,
             MAX(p->hold_max_ns, (uint64_t)held), p->hold_expired,
             p->hold_cap_ms, p->hold_mode);
    port_add(p, &len, "ocp_writes %" PRIu64 " ocp_write_delay %u"
             " ocp_write_flight_us %u ddr_jitter %u"
             " ocp_drained %" PRIu64 "\n",
             p->ocp_writes, p->ocp_write_delay, p->ocp_write_flight_us,
             p->jitter ? p->ddr_jitter : 0, p->ocp_drained);
    port_add(p, &len, "ocp_errors %" PRIu64 "%s%s\n", p->ocp_errors,
             p->ocp_errors ? " last " : "", p->ocp_errors ? p->ocp_err : "");
    port_add(p, &len, "jitter %u slices %" PRIu64 " pauses %" PRIu64
             " pause_ns %" PRIu64 "\n", p->jitter, p->jitter_slices,
             p->jitter_pauses, p->jitter_pause_ns);
    port_add(p, &len, "unmodelled %" PRIu64 "\n", p->unimp);
    port_add(p, &len, "unmodelled_last %s\n", p->unimp ? p->unimp_last : "-");
    return len;
}

/* "pads": every pad not at its reset value and every pad of a PRU output */
static uint32_t port_pads(AM335xPrussState *p)
{
    uint32_t len = 0;
    unsigned int i, r;

    for (i = 0; i < PADS_NUM; i++) {
        uint32_t off = 0x800 + 4 * i;
        bool listed = p->pad[i] != PAD_RESET;

        for (r = 0; r < ARRAY_SIZE(am335x_r30_pads); r++) {
            listed |= am335x_r30_pads[r].offset == off;
        }
        if (!listed) {
            continue;
        }
        port_add(p, &len, "0x%03x 0x%02x", off, p->pad[i]);
        for (r = 0; r < ARRAY_SIZE(am335x_r30_pads); r++) {
            const struct am335x_pin_row *row = &am335x_r30_pads[r];

            if (row->offset == off) {
                port_add(p, &len, " pru%u_r30_%u %s", row->unit, row->bit,
                         (p->pad[i] & 7) == row->mode ? "muxed" : "unmuxed");
            }
        }
        port_add(p, &len, "\n");
    }
    return len;
}

static uint32_t port_input_info(AM335xPrussState *p, unsigned int port)
{
    PrussInput *in = &p->input[port];

    return port_reply(p, "entries %zu period %" PRIu64 " origin %" PRIu64
                      " iep %u%s\n",
                      in->stim.count, in->stim.period, in->origin,
                      in->origin_iep,
                      in->pending_origin ? " (next start)" : "");
}

static int port_read(AM335xPrussState *p, unsigned int file, uint32_t *len)
{
    switch (file) {
    case PF_TRACE:
        *len = port_trace(p);
        return 0;
    case PF_STATS:
        *len = port_stats(p);
        return 0;
    case PF_PADS:
        *len = port_pads(p);
        return 0;
    case PF_OCP_WRITE_PAUSE_US:
        *len = port_reply(p, "%u\n", p->ocp_write_pause_us);
        return 0;
    case PF_FREEZE:
        *len = port_reply(p, "%u\n", p->freeze);
        return 0;
    case PF_JITTER:
        *len = port_reply(p, "%u\n", p->jitter);
        return 0;
    case PF_HOLD_MODE:
        *len = port_reply(p, "%u\n", p->hold_mode);
        return 0;
    case PF_OCP_WRITE_DELAY:
        *len = port_reply(p, "%u\n", p->ocp_write_delay);
        return 0;
    case PF_OCP_WRITE_FLIGHT_US:
        *len = port_reply(p, "%u\n", p->ocp_write_flight_us);
        return 0;
    case PF_DDR_JITTER:
        *len = port_reply(p, "%u\n", p->ddr_jitter);
        return 0;
    }
    if (file >= PF_INPUT && file < PF_NUM) {
        *len = port_input_info(p, file - PF_INPUT);
        return 0;
    }
    return -EINVAL;
}

/* The written text, NUL terminated, trimmed; NULL if it holds a NUL */
static char *port_text(AM335xPrussState *p, uint32_t len, char *dst,
                       size_t size)
{
    if (len >= size || memchr(p->buf, 0, len)) {
        return NULL;
    }
    memcpy(dst, p->buf, len);
    dst[len] = 0;
    return g_strstrip(dst);
}

static int port_write_trace(AM335xPrussState *p, uint32_t len, uint32_t *reply)
{
    char text[64], *arg;
    uint64_t window = 0;
    bool first;

    arg = port_text(p, len, text, sizeof(text));
    if (!arg || strncmp(arg, "clear", 5) ||
        (arg[5] && !g_ascii_isspace(arg[5]))) {
        *reply = port_reply(p, "trace: write \"clear\", \"clear CYCLES\" or "
                            "\"clear first\"");
        return -EINVAL;
    }
    arg = g_strchug(arg + 5);
    first = !strcmp(arg, "first");
    if (*arg && !first) {
        if (arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &window) ||
            !window) {
            *reply = port_reply(p, "trace: bad window \"%s\"", arg);
            return -EINVAL;
        }
    }
    p->trace_first = first;
    p->trace_head = 0;
    p->trace_count = 0;
    p->trace_dropped = 0;
    p->trace_until = !window ? 0 :
                     window > UINT64_MAX - p->s->now ? UINT64_MAX :
                     p->s->now + window;
    return 0;
}

/* "0xOFFSET 0xVALUE": set a pad as config-pin does (value at most 0x7f) */
static int port_write_pads(AM335xPrussState *p, uint32_t len, uint32_t *reply)
{
    const char *end;
    char text[64], *arg;
    uint64_t off, val;

    arg = port_text(p, len, text, sizeof(text));
    if (!arg) {
        goto bad;
    }
    if (qemu_strtou64(arg, &end, 0, &off) || !g_ascii_isspace(*end)) {
        goto bad;
    }
    arg = g_strchug(arg + (end - arg));
    if (arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &val) || off < 0x800 ||
        off >= 0x800 + PADS_SIZE || off & 3 || val > PAD_MASK) {
        goto bad;
    }
    p->pad[(off - 0x800) / 4] = val;
    p->pad_writes++;
    pads_changed(p);
    return 0;
bad:
    *reply = port_reply(p,
                        "pads: write \"0xOFFSET 0xVALUE\", "
                        "a pad 0x800..0x%x and a value up to 0x%x",
                        0x800 + PADS_SIZE - 4, PAD_MASK);
    return -EINVAL;
}

/* jitter: a new seed (or off), the same slices and pauses for the same one */
static void jitter_seed(AM335xPrussState *p)
{
    g_rand_set_seed(p->rng, p->jitter);
    /* the DDR's jitter: from the same seed, only while the knob is on */
    prusim_set_ddr_jitter(p->s, p->jitter ? p->ddr_jitter : 0, p->jitter);
}

static int port_write_knob(AM335xPrussState *p, uint32_t *knob, uint32_t max,
                           uint32_t len, uint32_t *reply)
{
    char text[32], *arg;
    uint64_t v;

    arg = port_text(p, len, text, sizeof(text));
    if (!arg || arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &v)) {
        *reply = port_reply(p, "a number from 0 to %u", max);
        return -EINVAL;
    }
    if (v > max) {
        *reply = port_reply(p, "at most %u", max);
        return -ERANGE;
    }
    *knob = v;
    return 0;
}

static int port_write(AM335xPrussState *p, unsigned int file, uint32_t len,
                      uint32_t *reply)
{
    int ret;

    switch (file) {
    case PF_TRACE:
        return port_write_trace(p, len, reply);
    case PF_PADS:
        return port_write_pads(p, len, reply);
    case PF_OCP_WRITE_PAUSE_US:
        return port_write_knob(p, &p->ocp_write_pause_us, KNOB_MAX_US, len,
                               reply);
    case PF_FREEZE:
        return port_write_knob(p, &p->freeze, 1, len, reply);
    case PF_JITTER:
        ret = port_write_knob(p, &p->jitter, UINT32_MAX, len, reply);
        if (!ret) {
            jitter_seed(p);
        }
        return ret;
    case PF_HOLD_MODE:
        return port_write_knob(p, &p->hold_mode, HOLD_NONE, len, reply);
    case PF_OCP_WRITE_DELAY:
        ret = port_write_knob(p, &p->ocp_write_delay, OCP_WRITE_DELAY_MAX,
                              len, reply);
        if (!ret) {
            prusim_set_ocp_write_delay(p->s, p->ocp_write_delay);
        }
        return ret;
    case PF_OCP_WRITE_FLIGHT_US:
        return port_write_knob(p, &p->ocp_write_flight_us, KNOB_MAX_US, len,
                               reply);
    case PF_DDR_JITTER:
        ret = port_write_knob(p, &p->ddr_jitter, DDR_JITTER_MAX, len, reply);
        if (!ret) {
            jitter_seed(p);
        }
        return ret;
    }
    return -EINVAL;
}

/* Check the complete lines a piece of stimulus text finishes */
static int port_append(AM335xPrussState *p, PrussStage *st, uint32_t len,
                       uint32_t *reply)
{
    char err[PRUSIM_REASON_LEN];
    size_t end, staged = 0;
    unsigned int i;
    int ret;

    for (i = 0; i < PORT_HANDLES; i++) {
        staged += p->stage[i].len;
    }
    if (len > STIM_MAX - staged) {
        *reply = port_reply(p, "input %u: more than %u MiB of text staged",
                            st->port, STIM_MAX >> 20);
        return -EFBIG;
    }
    if (st->len + len > st->cap) {
        st->cap = MAX(st->len + len, 2 * st->cap);
        st->text = g_realloc(st->text, st->cap);
    }
    memcpy(st->text + st->len, p->buf, len);
    end = st->len + len;
    while (end > st->checked && st->text[end - 1] != '\n') {
        end--;
    }
    if (end > st->checked &&
        prusim_stim_parse(st->text + st->checked, end - st->checked, NULL,
                          err, sizeof(err)) < 0) {
        /* a piece may be wrong only out of context: check it all */
        ret = prusim_stim_parse(st->text, end, NULL, err, sizeof(err));
        if (ret < 0) {
            *reply = port_reply(p, "input %u: %s", st->port, err);
            return ret;
        }
    }
    st->checked = MAX(st->checked, end);
    st->len += len;
    return 0;
}

static int port_install(AM335xPrussState *p, PrussStage *stg, uint32_t *reply)
{
    PrussInput *in = &p->input[stg->port];
    struct prusim_stim st = { 0 };
    char err[PRUSIM_REASON_LEN];
    int n;

    n = prusim_stim_parse(stg->text, stg->len, NULL, err, sizeof(err));
    if (n > 0) {
        st.cycle = g_new(uint64_t, n);
        st.value = g_new(uint32_t, n);
        st.count = n;
        n = prusim_stim_parse(stg->text, stg->len, &st, err, sizeof(err));
    }
    if (n < 0) {
        stim_free(&st);
        *reply = port_reply(p, "input %u: %s; input unchanged", stg->port, err);
        return n;
    }
    stim_free(&in->stim);
    in->stim = st;
    in->pending_origin = !prusim_active(p->s);
    in->origin = p->s->now;
    in->origin_iep = iep_count(p);
    /* the simulator caches inputs until their announced next change */
    prusim_input_changed(p->s, stg->port);
    p->runnable = true;
    return 0;
}

static void stage_free(PrussStage *st)
{
    g_free(st->text);
    memset(st, 0, sizeof(*st));
}

/* Run a command of the test port.  BQL and lock held. */
static void port_command(AM335xPrussState *p, uint32_t cmd)
{
    unsigned int op = PRUSIM_TEST_PORT_CMD_OP(cmd);
    unsigned int file = PRUSIM_TEST_PORT_CMD_FILE(cmd);
    unsigned int h = PRUSIM_TEST_PORT_CMD_HANDLE(cmd);
    uint32_t len = MIN(p->port_len, (uint32_t)PORT_BUF_SIZE), reply = 0;
    PrussStage *st = h < PORT_HANDLES ? &p->stage[h] : NULL;
    int status = 0;
    unsigned int i;

    switch (op) {
    case PRUSIM_TEST_PORT_OP_LIST:
        for (i = 0; i < PF_NUM; i++) {
            port_add(p, &reply, "%s %s %s\n", port_file_name[i],
                     i == PF_STATS ? "0400" : "0600",
                     i >= PF_INPUT ? "staged" : "snapshot");
        }
        break;
    case PRUSIM_TEST_PORT_OP_READ:
        status = port_read(p, file, &reply);
        break;
    case PRUSIM_TEST_PORT_OP_WRITE:
        status = file >= PF_INPUT ? -EINVAL : port_write(p, file, len, &reply);
        break;
    case PRUSIM_TEST_PORT_OP_OPEN:
        status = -EMFILE;
        if (file < PF_INPUT || file >= PF_NUM) {
            status = -EINVAL;
            break;
        }
        for (i = 0; i < PORT_HANDLES; i++) {
            if (!p->stage[i].used) {
                p->stage[i].used = true;
                p->stage[i].port = file - PF_INPUT;
                p->port_handle = i;
                status = 0;
                break;
            }
        }
        break;
    case PRUSIM_TEST_PORT_OP_APPEND:
        status = st && st->used ? port_append(p, st, len, &reply) : -EBADF;
        break;
    case PRUSIM_TEST_PORT_OP_CLOSE:
    case PRUSIM_TEST_PORT_OP_DROP:
        if (!st || !st->used) {
            status = -EBADF;
            break;
        }
        if (op == PRUSIM_TEST_PORT_OP_CLOSE && st->len) {
            status = port_install(p, st, &reply);
        }
        stage_free(st);
        break;
    default:
        status = -EINVAL;
        break;
    }
    p->port_status = -status;     /* the register: a positive errno */
    p->port_len = reply;
    trace_am335x_pruss_port(op, file, status, reply);
}

static uint64_t port_read_reg(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPrussState *p = opaque;

    switch (off) {
    case PRUSIM_TEST_PORT_REG_ID:
        return PRUSIM_TEST_PORT_ID;
    case PRUSIM_TEST_PORT_REG_VERSION:
        return PRUSIM_TEST_PORT_VERSION;
    case PRUSIM_TEST_PORT_REG_STATUS:
        return p->port_status;
    case PRUSIM_TEST_PORT_REG_LEN:
        return p->port_len;
    case PRUSIM_TEST_PORT_REG_BUFSIZE:
        return PORT_BUF_SIZE;
    case PRUSIM_TEST_PORT_REG_HANDLE:
        return p->port_handle;
    }
    qemu_log_mask(LOG_GUEST_ERROR,
                  "am335x-pruss: test port read at 0x%" HWADDR_PRIx "\n", off);
    return 0;
}

static void port_write_reg(void *opaque, hwaddr off, uint64_t val,
                           unsigned int size)
{
    AM335xPrussState *p = opaque;

    switch (off) {
    case PRUSIM_TEST_PORT_REG_LEN:
        p->port_len = val;
        return;
    case PRUSIM_TEST_PORT_REG_CMD:
        pruss_lock(p);
        port_command(p, val);
        pruss_update_irqs(p);
        pruss_unlock(p, true);
        return;
    }
    qemu_log_mask(LOG_GUEST_ERROR,
                  "am335x-pruss: test port write at 0x%" HWADDR_PRIx "\n",
                  off);
}

static const MemoryRegionOps port_ops = {
    .read = port_read_reg,
    .write = port_write_reg,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 4, .max_access_size = 4 },
};

/* ------------------------------------------------------------------ */
/* The simulation thread                                               */

/* Log why a core stopped, once. */
static void report_stops(AM335xPrussState *p)
{
    unsigned int i;

    for (i = 0; i < PRUSIM_NUM_CORES; i++) {
        struct prusim_status st;

        prusim_get_status(p->s, i, &st);
        if (st.state != PRUSIM_STOPPED) {
            p->stopped_reported[i] = false;
            continue;
        }
        if (!p->stopped_reported[i]) {
            qemu_log_mask(LOG_GUEST_ERROR,
                          "am335x-pruss: PRU%u stopped at pc 0x%x: %s\n",
                          i, st.pc * 4, st.reason);
        }
        p->stopped_reported[i] = true;
    }
}

/*
 * The knobs' waits, without the lock (the ARM runs on): each store
 * ocp_write_flight_us holds back lands after its own wait, one after the
 * other; then ocp_write_pause_us for each store that landed.  The PRUs run
 * no cycle meanwhile, so nothing they do after a store overtakes it.
 */
static void knob_waits(AM335xPrussState *p)
{
    uint64_t pause_us;

    while (p->flight_n) {
        qemu_mutex_unlock(&p->lock);
        g_usleep(p->ocp_write_flight_us);
        qemu_mutex_lock(&p->lock);
        flight_land_one(p);
    }
    pause_us = (uint64_t)p->ocp_pauses * p->ocp_write_pause_us;
    p->ocp_pauses = 0;
    if (pause_us) {
        qemu_mutex_unlock(&p->lock);
        g_usleep(pause_us);
        qemu_mutex_lock(&p->lock);
    }
}

static void *pruss_thread(void *opaque)
{
    AM335xPrussState *p = opaque;

    /* the OCP port's RAM accesses are RCU readers of the memory map */
    rcu_register_thread();
    qemu_mutex_lock(&p->lock);
    while (!p->quit) {
        int wait_ms = 0;
        uint32_t pause_us, jitter_us, slice;
        int64_t t0;

        /*
         * A stopped VM, or the knob: simulated time stands still, the
         * registers still answer
         */
        if (!p->vm_running || p->freeze) {
            qemu_cond_wait(&p->wake, &p->lock);
            continue;
        }
        /* before the PRUs go on: what an ARM access drained into the knobs */
        knob_waits(p);
        if (pruss_held(p, &wait_ms)) {
            qemu_cond_timedwait(&p->wake, &p->lock, wait_ms);
            continue;
        }
        if (!p->runnable || !prusim_active(p->s)) {
            p->runnable = false;
            qemu_cond_wait(&p->wake, &p->lock);
            continue;
        }
        /* MMIO handlers first: a handler waits at most one slice */
        if (qatomic_read(&p->waiters)) {
            qemu_cond_wait(&p->turn, &p->lock);
            continue;
        }
        t0 = now_ns();
        slice = p->slice_cycles;
        if (p->jitter) {
            /* knob: random slices; the ARM's accesses land anywhere */
            slice = g_rand_int_range(p->rng, 1, 2 * p->slice_cycles + 1);
            p->jitter_slices++;
        }
        prusim_run(p->s, slice);
        p->host_ns += now_ns() - t0;
        /*
         * Idle: every core waits for something only the outside brings
         * (an ARM store, which comes through the MMIO handlers, or new
         * input), and no input pattern has a change to come.
         */
        p->runnable = !p->s->waiting || inputs_pending(p);
        report_stops(p);
        knob_waits(p);
        pause_us = 0;
        if (p->jitter &&
            !g_rand_int_range(p->rng, 0, JITTER_PAUSE_ONE_IN)) {
            /* knob: the simulation stops a while, the ARM runs on */
            jitter_us = g_rand_int_range(p->rng, 0, JITTER_PAUSE_MAX_US + 1);
            pause_us += jitter_us;
            p->jitter_pauses++;
            p->jitter_pause_ns += jitter_us * SCALE_US;
        }
        if (pause_us) {
            /* knob: the simulation stops a while, the ARM runs on */
            qemu_mutex_unlock(&p->lock);
            g_usleep(pause_us);
            qemu_mutex_lock(&p->lock);
        }
        if (p->irq_dirty) {
            qemu_mutex_unlock(&p->lock);
            qemu_mutex_lock_iothread();
            qemu_mutex_lock(&p->lock);
            pruss_update_irqs(p);
            qemu_mutex_unlock_iothread();
        }
    }
    qemu_mutex_unlock(&p->lock);
    rcu_unregister_thread();
    return NULL;
}

/* BQL held */
static void pruss_vm_state_change(void *opaque, bool running, RunState state)
{
    AM335xPrussState *p = opaque;

    pruss_lock(p);
    p->vm_running = running;
    if (running && p->hold_since) {
        /* a hold's cap counts host time the VM ran */
        p->hold_since = now_ns();
    }
    pruss_unlock(p, true);
}

/* ------------------------------------------------------------------ */
/* Device                                                              */

static void pruss_reset_state(AM335xPrussState *p)
{
    struct prusim_config cfg;
    unsigned int i;

    prusim_default_config(&cfg);
    /* while every core waits for the ARM, simulated time stands still */
    cfg.stop_when_idle = true;
    /* a PRU's store reaches RAM later than its next event can */
    p->ocp_write_delay = p->ocp_write_delay_reset;
    cfg.ocp_write_delay = p->ocp_write_delay;
    p->event_latency = cfg.event_latency;
    prusim_init(p->s, &cfg, &pruss_sim_ops, p);
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        /* the AM335x's reset value: every line an input */
        prusim_gpio_write(p->s, i, PRUSIM_GPIO_OE, 0xffffffff);
        memset(p->gpio_reg[i], 0, sizeof(p->gpio_reg[i]));
    }
    for (i = 0; i < PADS_NUM; i++) {
        p->pad[i] = PAD_RESET;
    }
    pads_masks(p);
    memset(p->gpio_out, 0, sizeof(p->gpio_out));
    memset(p->gpio_shown, 0, sizeof(p->gpio_shown));
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        p->gpio_oe[i] = 0xffffffff;
    }
    for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
        stim_free(&p->input[i].stim);
        memset(&p->input[i], 0, sizeof(p->input[i]));
    }
    for (i = 0; i < PORT_HANDLES; i++) {
        stage_free(&p->stage[i]);
    }
    p->trace_head = p->trace_count = 0;
    p->trace_dropped = p->trace_origin = p->trace_until = 0;
    p->trace_first = false;
    p->r30 = p->r30_shown = 0;
    p->in_service = 0;
    p->taken = 0;
    p->expired_lines = 0;
    p->expired_events = 0;
    p->hold_since = 0;
    p->ocp_pauses = 0;
    p->ocp_write_pause_us = 0;
    p->ocp_write_flight_us = 0;
    p->flight_n = 0;
    memset(p->strobe, 0, sizeof(p->strobe));
    memset(p->stopped_reported, 0, sizeof(p->stopped_reported));
    p->freeze = 0;
    p->jitter = p->jitter_seed;
    p->ddr_jitter = p->ddr_jitter_reset;
    jitter_seed(p);
    p->hold_mode = p->hold_mode_reset;
    p->runnable = false;
    p->irq_dirty = true;
}

/* Resettable: the state in the enter phase, the interrupt lines in hold */
static void am335x_pruss_reset_enter(Object *obj, ResetType type)
{
    AM335xPrussState *p = AM335X_PRUSS(obj);

    pruss_lock(p);
    pruss_reset_state(p);
    pruss_unlock(p, false);
}

static void am335x_pruss_reset_hold(Object *obj)
{
    AM335xPrussState *p = AM335X_PRUSS(obj);

    pruss_lock(p);
    pruss_update_irqs(p);
    pruss_unlock(p, true);
}

static void am335x_pruss_realize(DeviceState *dev, Error **errp)
{
    AM335xPrussState *p = AM335X_PRUSS(dev);
    SysBusDevice *sbd = SYS_BUS_DEVICE(dev);
    Error *err = NULL;
    unsigned int i;

    if (!p->slice_cycles) {
        error_setg(errp, "slice-cycles must be at least 1");
        return;
    }
    if (p->hold_mode_reset > HOLD_NONE) {
        error_setg(errp, "hold-mode must be 0, 1 or 2");
        return;
    }
    if (p->ddr_jitter_reset > DDR_JITTER_MAX) {
        error_setg(errp, "ddr-jitter must be at most %u cycles",
                   DDR_JITTER_MAX);
        return;
    }
    if (p->ocp_write_delay_reset > OCP_WRITE_DELAY_MAX) {
        error_setg(errp, "ocp-write-delay must be at most %u cycles",
                   OCP_WRITE_DELAY_MAX);
        return;
    }

    memory_region_init_io(&p->pruss_mr, OBJECT(p), &pruss_ops, p,
                          "am335x-pruss.icss", PRUSS_SIZE);
    sysbus_init_mmio(sbd, &p->pruss_mr);
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        g_autofree char *name = g_strdup_printf("am335x-pruss.gpio%u", i);

        memory_region_init_io(&p->gpio_mr[i], OBJECT(p), &gpio_ops[i], p,
                              name, GPIO_SIZE);
        sysbus_init_mmio(sbd, &p->gpio_mr[i]);
    }
    memory_region_init_io(&p->pads_mr, OBJECT(p), &pads_ops, p,
                          "am335x-pruss.pads", PADS_SIZE);
    sysbus_init_mmio(sbd, &p->pads_mr);
    memory_region_init_io(&p->port_mr, OBJECT(p), &port_ops, p,
                          "am335x-pruss.port", PORT_SIZE);
    sysbus_init_mmio(sbd, &p->port_mr);
    memory_region_init_ram(&p->port_buf, OBJECT(p), "am335x-pruss.port-buf",
                           PORT_BUF_SIZE, &err);
    if (err) {
        error_propagate(errp, err);
        return;
    }
    p->buf = memory_region_get_ram_ptr(&p->port_buf);
    sysbus_init_mmio(sbd, &p->port_buf);
    for (i = 0; i < NUM_CATCH; i++) {
        g_autofree char *name = g_strdup_printf("am335x-pruss.%s",
                                                catch_regions[i].name);

        memory_region_init_io(&p->catch_mr[i], OBJECT(p), &catch_ops,
                              &p->catch_mr[i], name, catch_regions[i].size);
        sysbus_init_mmio(sbd, &p->catch_mr[i]);
    }
    for (i = 0; i < AM335X_PRUSS_NUM_HOST_IRQS; i++) {
        sysbus_init_irq(sbd, &p->host_irq[i]);
    }
    for (i = 0; i < AM335X_PRUSS_NUM_GPIO_IRQS; i++) {
        sysbus_init_irq(sbd, &p->gpio_irq[i]);
    }

    p->s = g_malloc0(sizeof(*p->s));
    p->trace = g_new0(struct prusim_trace_rec, TRACE_LEN);
    qemu_mutex_init(&p->lock);
    qemu_cond_init(&p->wake);
    qemu_cond_init(&p->turn);
    p->rng = g_rand_new();
    pruss_reset_state(p);
    p->vm_running = runstate_is_running();
    p->vmstate_entry = qemu_add_vm_change_state_handler(pruss_vm_state_change,
                                                        p);
    qemu_thread_create(&p->thread, "am335x-pruss", pruss_thread, p,
                       QEMU_THREAD_JOINABLE);
}

static void am335x_pruss_unrealize(DeviceState *dev)
{
    AM335xPrussState *p = AM335X_PRUSS(dev);
    unsigned int i;

    qemu_del_vm_change_state_handler(p->vmstate_entry);
    pruss_lock(p);
    p->quit = true;
    pruss_unlock(p, true);
    qemu_thread_join(&p->thread);
    for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
        stim_free(&p->input[i].stim);
    }
    for (i = 0; i < PORT_HANDLES; i++) {
        stage_free(&p->stage[i]);
    }
    g_free(p->trace);
    g_free(p->s);
    g_rand_free(p->rng);
    qemu_cond_destroy(&p->turn);
    qemu_cond_destroy(&p->wake);
    qemu_mutex_destroy(&p->lock);
}

static Property am335x_pruss_props[] = {
    /* PRU cycles per slice of the thread: bounds an MMIO access's wait */
    DEFINE_PROP_UINT32("slice-cycles", AM335xPrussState, slice_cycles, 2000),
    /* longest hold of simulated time for one undelivered interrupt */
    DEFINE_PROP_UINT32("hold-cap-ms", AM335xPrussState, hold_cap_ms, 200),
    /* the jitter knob's seed at reset (0: off) */
    DEFINE_PROP_UINT32("jitter-seed", AM335xPrussState, jitter_seed, 0),
    /* the hold at reset: 0 until serviced, 1 until taken, 2 none */
    DEFINE_PROP_UINT32("hold-mode", AM335xPrussState, hold_mode_reset,
                       HOLD_TAKEN),
    /* PRU cycles from a store over the OCP master port until it lands */
    DEFINE_PROP_UINT32("ocp-write-delay", AM335xPrussState,
                       ocp_write_delay_reset, 100),
    /* while the jitter knob is on: each DDR access up to this much longer */
    DEFINE_PROP_UINT32("ddr-jitter", AM335xPrussState, ddr_jitter_reset, 0),
    DEFINE_PROP_END_OF_LIST(),
};

/* A simulator in the middle of a slice cannot be saved: not migratable. */
static const VMStateDescription vmstate_am335x_pruss = {
    .name = TYPE_AM335X_PRUSS,
    .unmigratable = 1,
};

static void am335x_pruss_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    ResettableClass *rc = RESETTABLE_CLASS(klass);

    dc->realize = am335x_pruss_realize;
    dc->unrealize = am335x_pruss_unrealize;
    rc->phases.enter = am335x_pruss_reset_enter;
    rc->phases.hold = am335x_pruss_reset_hold;
    dc->vmsd = &vmstate_am335x_pruss;
    dc->desc = "AM335x PRU-ICSS (prukit's prusim), GPIO banks and pads";
    dc->user_creatable = false;
    device_class_set_props(dc, am335x_pruss_props);
}

static const TypeInfo am335x_pruss_info = {
    .name = TYPE_AM335X_PRUSS,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(AM335xPrussState),
    .class_init = am335x_pruss_class_init,
};

DeviceState *am335x_pruss_create(qemu_irq *host_irq, qemu_irq *gpio_irq)
{
    DeviceState *dev = qdev_new(TYPE_AM335X_PRUSS);
    SysBusDevice *sbd = SYS_BUS_DEVICE(dev);
    unsigned int i, n = 0;

    sysbus_realize_and_unref(sbd, &error_fatal);
    sysbus_mmio_map(sbd, n++, PRUSS_BASE);
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        sysbus_mmio_map(sbd, n++, gpio_base[i]);
    }
    sysbus_mmio_map(sbd, n++, PADS_BASE);
    sysbus_mmio_map(sbd, n++, PORT_BASE);
    sysbus_mmio_map(sbd, n++, PORT_BUF_BASE);
    for (i = 0; i < NUM_CATCH; i++) {
        sysbus_mmio_map_overlap(sbd, n++, catch_regions[i].base, -1000);
    }
    for (i = 0; i < AM335X_PRUSS_NUM_HOST_IRQS; i++) {
        sysbus_connect_irq(sbd, i, host_irq[i]);
    }
    for (i = 0; i < AM335X_PRUSS_NUM_GPIO_IRQS; i++) {
        sysbus_connect_irq(sbd, AM335X_PRUSS_NUM_HOST_IRQS + i, gpio_irq[i]);
    }
    return dev;
}

static void am335x_pruss_register_types(void)
{
    type_register_static(&am335x_pruss_info);
}
type_init(am335x_pruss_register_types)
