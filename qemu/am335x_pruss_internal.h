/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS for prukit's test VM: the device's state and what its
 * parts share (am335x_pruss.c: the PRU-ICSS, its interrupts and the
 * simulation thread; am335x_pruss_pins.c: the pins, GPIO banks (and their
 * clocks) and pads; am335x_pruss_port.c: the test port).  Private to
 * hw/misc/am335x_pruss*.c.
 */
#ifndef HW_MISC_AM335X_PRUSS_INTERNAL_H
#define HW_MISC_AM335X_PRUSS_INTERNAL_H

#include "exec/memory.h"
#include "hw/sysbus.h"
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

#define NUM_CATCH               3       /* catch_regions[] */

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

struct AM335xPrussState {
    SysBusDevice parent_obj;

    MemoryRegion pruss_mr;
    MemoryRegion gpio_mr[PRUSIM_GPIO_BANKS];
    MemoryRegion pads_mr;
    MemoryRegion port_mr;
    MemoryRegion port_buf;
    MemoryRegion prm_mr;
    MemoryRegion cm_mr;
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

    /* pads */
    uint32_t pad[PADS_NUM];
    uint64_t r30;                   /* every PRU output's level */
    uint64_t r30_shown;             /* what its pads show */
    uint64_t unmuxed_writes;
    uint64_t unmuxed_seen;          /* outputs written while unmuxed */
    uint64_t pad_writes;
    /* what reaches a pin, from the pads (pruss_pads_changed()) */
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

    /* PRCM: RM_PER_RSTCTRL, and how often it reset the PRU-ICSS */
    uint32_t prm_rstctrl;
    uint64_t icss_resets;
    uint8_t reset_states[PRUSIM_NUM_CORES]; /* the cores' as it came */
    /* PRCM: the GPIO banks' CLKCTRL (MODULEMODE, OPTFCLKEN), clock gatings */
    uint32_t gpio_clkctrl[PRUSIM_GPIO_BANKS];
    uint64_t gpio_clock_gatings;

    /* GPIO registers the simulator does not keep */
    uint32_t gpio_reg[PRUSIM_GPIO_BANKS][GPIO_NUM_STORED];

    PrussInput input[PRUSIM_NUM_PORTS];
    PrussStage stage[PORT_HANDLES];

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
    return p->prm_rstctrl & PRM_ICSS_LRST;
}

/*
 * PRCM clocks a GPIO bank while its CLKCTRL's MODULEMODE is "enabled": on a
 * board ti-sysc enables it as the bank's target module resumes (a line of
 * the bank is requested, or gpio-omap probes) and disables it as the module
 * idles.
 */
static inline bool pruss_gpio_clocked(AM335xPrussState *p, unsigned int bank)
{
    return (p->gpio_clkctrl[bank] & CM_MODULEMODE) == CM_MODULEMODE_ENABLE;
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
           (p->gpio_reg[bank][GPIO_CTRL / 4] & GPIO_CTRL_DISABLEMODULE);
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

/* am335x_pruss_pins.c: the pins, GPIO banks (and their clocks) and pads */

/* Recompute what reaches a pin from the pad registers (reset) */
void pruss_pads_masks(AM335xPrussState *p);
/* ... and show the pins' levels that changed with them */
void pruss_pads_changed(AM335xPrussState *p);
/* prusim_ops: a PRU output or GPIO line changed; a bank's OE changed */
void pruss_pin_cb(void *ctx, u64 cycle, unsigned int pin, bool level);
void pruss_gpio_oe_cb(void *ctx, u64 cycle, unsigned int bank, u32 oe);
/* The test port's "pads" file, in the reply buffer; its length */
uint32_t pruss_pads_text(AM335xPrussState *p);
extern const MemoryRegionOps pruss_gpio_ops[PRUSIM_GPIO_BANKS];
extern const MemoryRegionOps pruss_cm_ops;
extern const MemoryRegionOps pruss_pads_ops;

/* am335x_pruss_port.c: the test port */

/* Append to the reply being built at *@len (in the port's buffer) */
void G_GNUC_PRINTF(3, 4) port_add(AM335xPrussState *p, uint32_t *len,
                                  const char *fmt, ...);
/* The jitter knob's generator, from its seed (p->jitter) */
void pruss_jitter_seed(AM335xPrussState *p);
void pruss_stage_free(PrussStage *st);
extern const MemoryRegionOps pruss_port_ops;

#endif /* HW_MISC_AM335X_PRUSS_INTERNAL_H */
