/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS for prukit's test VM: the devices' state and what they
 * share.  One QOM device per block (am335x_pruss_create() makes and wires
 * them):
 *   am335x_pruss.c       TYPE_AM335X_PRUSS: the PRU-ICSS, its interrupts
 *                        and the simulation (thread or lockstep)
 *   am335x_pruss_pins.c  the pin path: what R30, a GPIO line or a pad
 *                        makes of a pin (a model, not a device)
 *   am335x_pruss_gpio.c  TYPE_AM335X_GPIO: a GPIO bank
 *   am335x_pruss_pads.c  TYPE_AM335X_PADS: the control module's pads
 *   am335x_pruss_prcm.c  TYPE_AM335X_PRCM: PRM_PER's PRU-ICSS reset and
 *                        the GPIO banks' CLKCTRL in CM_PER/CM_WKUP
 *   am335x_pruss_port.c  TYPE_AM335X_PRUSS_PORT: prukit's test port
 * The PRU reaches the GPIO banks through the simulator, whose data path
 * for them (OE, DATAOUT, DATAIN) is the simulator's own: so the GPIO
 * banks, the pads and the test port hold a link to the PRU-ICSS and take
 * its lock, the one lock of the whole pin path.  PRCM drives the PRU-ICSS's
 * local reset and the banks' clocks through GPIO lines, as PRCM's outputs
 * on the SoC.  Private to hw/misc/am335x_pruss*.c.
 */
#ifndef HW_MISC_AM335X_PRUSS_INTERNAL_H
#define HW_MISC_AM335X_PRUSS_INTERNAL_H

#include "exec/memory.h"
#include "hw/sysbus.h"
#include "qemu/bswap.h"
#include "qemu/thread.h"
#include "qemu/timer.h"
#include "qom/object.h"
#include "sysemu/runstate.h"

#include "hw/misc/am335x_pruss.h"
#include "prusim/prusim.h"
#include "prusim/prusim_port.h"
#include "prusim/prusim_stim.h"
#include "prusim/prusim_trace.h"

OBJECT_DECLARE_SIMPLE_TYPE(AM335xPrussState, AM335X_PRUSS)
OBJECT_DECLARE_SIMPLE_TYPE(AM335xGpioState, AM335X_GPIO)
OBJECT_DECLARE_SIMPLE_TYPE(AM335xPadsState, AM335X_PADS)
OBJECT_DECLARE_SIMPLE_TYPE(AM335xPrcmState, AM335X_PRCM)
OBJECT_DECLARE_SIMPLE_TYPE(AM335xPrussPortState, AM335X_PRUSS_PORT)

/* The AM335x memory map (SPRUH73 chapter 2) */
#define PRUSS_BASE              0x4a300000
#define PRUSS_SIZE              0x80000
#define PADS_BASE               0x44e10800
#define PADS_NUM                142             /* conf_* at 0x800..0xa34 */
#define PADS_SIZE               (4 * PADS_NUM)
#define GPIO_SIZE               0x1000
#define PRM_PER_BASE            0x44e00c00      /* PRCM's PRM_PER */
#define PRM_PER_SIZE            0x100
#define PRM_RSTCTRL             0x00            /* RM_PER_RSTCTRL */
#define PRM_ICSS_LRST           0x2             /* PRU_ICSS_LRST */
#define CM_BASE                 0x44e00000      /* PRCM's CM_PER, CM_WKUP */
#define CM_SIZE                 0x500
#define CM_MODULEMODE           0x3             /* a CLKCTRL's bits 1:0 */
#define CM_MODULEMODE_ENABLE    0x2
#define CM_IDLEST_SHIFT         16              /* bits 17:16, read-only */
#define CM_IDLEST               (0x3u << CM_IDLEST_SHIFT)
#define CM_IDLEST_DISABLED      0x3
#define CM_GPIO_OPTFCLKEN       (1u << 18)      /* the debounce clock */

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
#define GPIO_SYSCONFIG_SOFTRESET 0x2    /* self-clearing */
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
#define GPIO_REGS_SIZE          0x160   /* registers stored: 0x000..0x15c */

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
#define PRU_CYCLE_NS            5       /* 200 MHz */
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

/**
 * struct AM335xGpioState - a GPIO bank (gpio-omap's view of it)
 * @bank: which (0..3): the simulator's bank the PRU reaches over OCP
 * @pruss: the PRU-ICSS whose simulator holds OE, DATAOUT and DATAIN
 * @regs: the other registers, as the bus sees them (ldl_le_p/stl_le_p)
 * @clocked: PRCM clocks it (its "clk" input, from its CLKCTRL)
 * @clock_gatings: how often PRCM stopped its clock
 * @out: DATAOUT as it lands (from the simulator's pin callbacks)
 * @oe: OE as it lands
 * @shown: what its pads show
 * @unpinned_seen: lines a store reached no pin with
 *
 * Everything but @mr, @irq, @bank and @pruss is under the PRU-ICSS's lock.
 */
struct AM335xGpioState {
    SysBusDevice parent_obj;

    MemoryRegion mr;
    qemu_irq irq;                   /* never raised: not modelled */
    uint8_t bank;
    AM335xPrussState *pruss;

    uint8_t regs[GPIO_REGS_SIZE];
    bool clocked;
    uint64_t clock_gatings;
    uint32_t out;
    uint32_t oe;
    uint32_t shown;
    uint32_t unpinned_seen;
};

/**
 * struct AM335xPadsState - the control module's pad registers (conf_*)
 * @regs: each pad's register, as the bus sees them (ldl_le_p/stl_le_p)
 * @writes: how many were written
 *
 * Under the PRU-ICSS's lock: a pad decides what reaches a pin.
 */
struct AM335xPadsState {
    SysBusDevice parent_obj;

    MemoryRegion mr;
    AM335xPrussState *pruss;

    uint8_t regs[PADS_SIZE];
    uint64_t writes;
};

/**
 * struct AM335xPrcmState - the parts of PRCM the PRU-ICSS's world uses
 * @rstctrl: RM_PER_RSTCTRL: PRU_ICSS_LRST drives @icss_lrst
 * @gpio_clkctrl: each GPIO bank's CLKCTRL: MODULEMODE drives @gpio_clk
 *
 * MMIO under the BQL only; the lines' receivers take their own locks.
 */
struct AM335xPrcmState {
    SysBusDevice parent_obj;

    MemoryRegion prm_mr;
    MemoryRegion cm_mr;
    qemu_irq icss_lrst;
    qemu_irq gpio_clk[PRUSIM_GPIO_BANKS];
    AM335xPrussState *pruss;        /* where an unmodelled access is logged */

    uint32_t rstctrl;
    uint32_t gpio_clkctrl[PRUSIM_GPIO_BANKS];
};

/**
 * struct AM335xPrussPortState - prukit's test port
 * @buf: @buf_mr's memory: the text or trace both sides read and write
 * @status: the last command's status (a positive errno)
 * @len: the length of what was written, then of the reply
 * @handle: the handle OPEN gave
 * @stage: input stimulus being written, per handle
 */
struct AM335xPrussPortState {
    SysBusDevice parent_obj;

    MemoryRegion mr;
    MemoryRegion buf_mr;
    AM335xPrussState *pruss;

    uint8_t *buf;
    uint32_t status;                /* under the BQL */
    uint32_t len;
    uint32_t handle;
    PrussStage stage[PORT_HANDLES]; /* under the PRU-ICSS's lock */
};

/**
 * struct AM335xPrussState - the PRU-ICSS, and the pin path it drives
 *
 * @gpio, @pads: the blocks the pin path reads (links set by
 * am335x_pruss_create()).
 */
struct AM335xPrussState {
    SysBusDevice parent_obj;

    MemoryRegion pruss_mr;
    qemu_irq host_irq[AM335X_PRUSS_NUM_HOST_IRQS];
    AM335xGpioState *gpio[PRUSIM_GPIO_BANKS];
    AM335xPadsState *pads;

    /* properties */
    uint32_t slice_cycles;
    uint32_t hold_cap_ms;
    uint32_t jitter_seed;
    uint32_t hold_mode_reset;
    uint32_t ocp_write_delay_reset;
    uint32_t ddr_jitter_reset;

    /* Under the BQL */
    bool host_level[AM335X_PRUSS_NUM_HOST_IRQS];

    QemuThread thread;              /* the simulation's, unless lockstep */
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
    /*
     * lockstep (QEMU's -icount): no thread; the PRUs' cycle @cbase was the
     * guest's virtual time @vbase, and they run up to the virtual time of
     * each ARM access to the device and of @vtimer (am335x_pruss.c)
     */
    bool lockstep;
    QEMUTimer *vtimer;
    int64_t vbase;
    uint64_t cbase;
    bool landing;                   /* a held-back store lands at @vbase */
    uint64_t lockstep_runs;

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

    /* the pin path (am335x_pruss_pins.c) */
    uint64_t r30;                   /* every PRU output's level */
    uint64_t r30_shown;             /* what its pads show */
    uint64_t unmuxed_writes;
    uint64_t unmuxed_seen;          /* outputs written while unmuxed */
    /* what reaches a pin, from the pads (pruss_pads_changed()) */
    uint64_t r30_pad_mask;          /* R30 bits on a pad in their mode */
    uint32_t r31_pad_mask[PRUSIM_NUM_CORES]; /* R31 bits a pad feeds */
    uint32_t gpio_pad_mask[PRUSIM_GPIO_BANKS]; /* lines on a pad in mode 7 */
    uint32_t gpio_in_mask[PRUSIM_GPIO_BANKS];  /* ... with its receiver on */
    uint64_t gpio_unpinned;         /* GPIO output stores that reached no pin */
    uint64_t gpio_gated;            /* ... of them, to a bank gpio-omap gated */
    bool arm_gpio;                  /* in an ARM store to a GPIO bank */

    /* PRCM's PRU_ICSS_LRST (the "lrst" input), how often it reset us */
    bool in_lrst;
    uint64_t icss_resets;
    uint8_t reset_states[PRUSIM_NUM_CORES]; /* the cores' as it came */

    PrussInput input[PRUSIM_NUM_PORTS];

    /* interrupt hold (emulation policy, see am335x_pruss.c) */
    uint64_t taken;         /* events the ARM read from HIPIR */
    uint64_t in_service;    /* ... and masked (EICR) or acked masked (SICR) */
    uint32_t expired_lines; /* held past the cap: ignored until they clear */
    uint64_t expired_events;
    int64_t hold_since;     /* pruss_now_ns(), 0 while not holding */
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

/* The clock of holds and their cap: the guest's in lockstep, else the host's */
static inline int64_t pruss_now_ns(AM335xPrussState *p)
{
    return qemu_clock_get_ns(p->lockstep ? QEMU_CLOCK_VIRTUAL :
                             QEMU_CLOCK_REALTIME);
}

/* PRCM holds the PRU-ICSS in its local reset */
static inline bool pruss_icss_in_reset(AM335xPrussState *p)
{
    return p->in_lrst;
}

/* A GPIO bank's register, as stored (@off 4-aligned, below GPIO_REGS_SIZE) */
static inline uint32_t gpio_reg(AM335xGpioState *g, hwaddr off)
{
    return ldl_le_p(&g->regs[off]);
}

static inline void gpio_reg_set(AM335xGpioState *g, hwaddr off, uint32_t v)
{
    stl_le_p(&g->regs[off], v);
}

/*
 * PRCM clocks a GPIO bank while its CLKCTRL's MODULEMODE is "enabled": on a
 * board ti-sysc enables it as the bank's target module resumes (a line of
 * the bank is requested, or gpio-omap probes) and disables it as the module
 * idles.
 */
static inline bool pruss_gpio_clocked(AM335xPrussState *p, unsigned int bank)
{
    return p->gpio[bank]->clocked;
}

/*
 * A bank is gated while PRCM does not clock it, or while gpio-omap
 * disables its module (GPIO_CTRL.DISABLEMODULE: the bank's own clocks
 * gated), as it does when the bank's last requested line is freed (and it
 * enables it when one is requested again).
 */
static inline bool pruss_gpio_gated(AM335xPrussState *p, unsigned int bank)
{
    return !pruss_gpio_clocked(p, bank) ||
           (gpio_reg(p->gpio[bank], GPIO_CTRL) & GPIO_CTRL_DISABLEMODULE);
}

/* A pad's register (@i: its index from conf_* 0x800) */
static inline uint32_t pad_reg(AM335xPadsState *pads, unsigned int i)
{
    return ldl_le_p(&pads->regs[4 * i]);
}

/* am335x_pruss.c */

/* Log an access the device does not model, and count it (stats) */
void G_GNUC_PRINTF(2, 3) pruss_unimp(AM335xPrussState *p, const char *fmt,
                                     ...);
/* The device lock, from an MMIO handler (BQL held); kick wakes the thread */
void pruss_lock(AM335xPrussState *p);
void pruss_unlock(AM335xPrussState *p, bool kick);
/* Drive the host interrupt lines as the INTC says (BQL and lock held) */
void pruss_update_irqs(AM335xPrussState *p);
uint32_t pruss_icss_read32(AM335xPrussState *p, uint32_t off);
uint32_t pruss_iep_count(AM335xPrussState *p);
void pruss_stim_free(struct prusim_stim *st);

/* am335x_pruss_pins.c: the pin path (under the PRU-ICSS's lock) */

/* Recompute what reaches a pin from the pad registers (reset) */
void pruss_pads_masks(AM335xPrussState *p);
/* ... and show the pins' levels that changed with them */
void pruss_pads_changed(AM335xPrussState *p);
/* Show a GPIO bank's lines on their pins as they are now */
void pruss_gpio_show(AM335xPrussState *p, unsigned int bank);
/* prusim_ops: a PRU output or GPIO line changed; a bank's OE changed */
void pruss_pin_cb(void *ctx, u64 cycle, unsigned int pin, bool level);
void pruss_gpio_oe_cb(void *ctx, u64 cycle, unsigned int bank, u32 oe);

/* am335x_pruss_pads.c */

/* Set pad @i as a pad register write does (lock held) */
void am335x_pads_set(AM335xPadsState *pads, unsigned int i, uint32_t val);

/* am335x_pruss_port.c */

/* The jitter knob's generator, from its seed (p->jitter) */
void pruss_jitter_seed(AM335xPrussState *p);

#endif /* HW_MISC_AM335X_PRUSS_INTERNAL_H */
