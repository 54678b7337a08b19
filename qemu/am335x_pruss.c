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
 *               (this file, TYPE_AM335X_PRUSS)
 *   0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000
 *               GPIO banks 0..3 (gpio-omap; TYPE_AM335X_GPIO): OE and the
 *               data registers are the simulator's, the rest is the bank's
 *   0x44e00c00  PRCM's PRM_PER (TYPE_AM335X_PRCM): RM_PER_RSTCTRL's
 *               PRU_ICSS_LRST holds the PRU-ICSS in reset (asserted at
 *               power-on; ti-sysc releases it, and asserts it whenever the
 *               PRU-ICSS's module idles)
 *   0x44e00000  PRCM's CM_PER and CM_WKUP (TYPE_AM335X_PRCM): the GPIO
 *               banks' CLKCTRL registers (disabled at power-on; ti-sysc
 *               enables a bank's while its module is in use, and a gated
 *               bank takes no access)
 *   0x44e10800  control module pad registers (pinctrl-single;
 *               TYPE_AM335X_PADS): a PRU output or a GPIO output reaches
 *               the pin trace only through a pad in its mode, an input R31
 *               or DATAIN only through one that also has its receiver on
 *   0x5f000000  prukit's test port (TYPE_AM335X_PRUSS_PORT): pin trace,
 *               input stimulus, statistics and timing knobs, for tests
 *               inside the guest (registers: sim/prusim_port.h; a guest
 *               driver, prukit's tests/kmod/prusim_port.c, shows them in
 *               debugfs)
 *
 * Each block is a device of its own (am335x_pruss_internal.h lists them and
 * their files); this file has the PRU-ICSS (TYPE_AM335X_PRUSS): its reset,
 * its interrupts and the simulation, and am335x_pruss_create(), which makes
 * the blocks, links them and maps them.
 *
 * Accesses to registers of the blocks above that are not modelled are
 * logged (-d unimp, "am335x-pruss: ...") and counted in the test port's
 * "stats": a test that makes one fails.  The rest of L4_WKUP, L4_PER and
 * L4_FAST are QEMU's unimplemented devices ("am335x.l4_per: unimplemented
 * device ..." in the same log): prukit's VM harness fails the boot that
 * logs one.
 *
 * Outputs: interrupts host_intr0..7 (INTC host interrupts 2..9).  Input:
 * "lrst", PRCM's PRU_ICSS_LRST (asserted: the PRU-ICSS is held in reset).
 *
 * The simulation runs in a thread of its own, or, with QEMU's -icount, in
 * lockstep with the guest's virtual clock on the vCPUs' thread (see
 * "Lockstep" below).  Lock order: the BQL before the device lock,
 * everywhere.  MMIO handlers run under the BQL and take
 * the device lock; the thread runs a slice under the device lock only,
 * drops it between slices (and waits there while an MMIO handler wants it),
 * and takes the BQL, then the device lock, to change interrupt lines.
 * The thread parks while the VM is stopped.
 *
 * Register values cross the bus as little-endian bytes (ldl_le_p() and
 * stl_le_p()); the simulator keeps its memories and registers in host
 * order, and assumes a little-endian host.
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
#include "qemu/bswap.h"
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
#include "hw/misc/unimp.h"
#include "hw/qdev-properties.h"
#include "hw/sysbus.h"
#include "migration/vmstate.h"
#include "qom/object.h"
#include "sysemu/cpu-timers.h"
#include "sysemu/runstate.h"
#include "trace.h"

#include "hw/misc/am335x_pruss.h"
#include "prusim/prusim.h"
#include "prusim/prusim_port.h"
#include "prusim/prusim_stim.h"
#include "prusim/prusim_trace.h"
#include "am335x_pruss_internal.h"

QEMU_BUILD_BUG_MSG(HOST_BIG_ENDIAN,
                   "prukit's simulator supports little-endian hosts only");

static const hwaddr gpio_base[PRUSIM_GPIO_BANKS] = {
    0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000,
};

/* The unmodelled rest of the L4 interconnects: unimplemented devices */
static const struct {
    hwaddr base;
    hwaddr size;
    const char *name;
} catch_regions[] = {
    { 0x44c00000, 0x00400000, "am335x.l4_wkup" },
    { 0x48000000, 0x01000000, "am335x.l4_per" },
    { 0x4a000000, 0x01000000, "am335x.l4_fast" },
};

/* ------------------------------------------------------------------ */
/* Unmodelled accesses                                                 */

void G_GNUC_PRINTF(2, 3) pruss_unimp(AM335xPrussState *p, const char *fmt,
                                     ...)
{
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(p->unimp_last, sizeof(p->unimp_last), fmt, ap);
    va_end(ap);
    p->unimp++;
    qemu_log_mask(LOG_UNIMP, "am335x-pruss: %s\n", p->unimp_last);
}

/* ------------------------------------------------------------------ */
/* Input stimulus                                                      */

uint32_t pruss_iep_count(AM335xPrussState *p)
{
    return pruss_icss_read32(p, ICSS_IEP_COUNT);
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
            in->origin_iep = pruss_iep_count(p);
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

void pruss_stim_free(struct prusim_stim *st)
{
    g_free(st->cycle);
    g_free(st->value);
    memset(st, 0, sizeof(*st));
}

/* ------------------------------------------------------------------ */
/* prusim callbacks (under the device lock)                            */

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
    .pin = pruss_pin_cb,
    .input = cb_input,
    .gpio_oe = pruss_gpio_oe_cb,
    .host_irq = cb_host_irq,
    .ocp_read = cb_ocp_read,
    .ocp_write = cb_ocp_write,
};

/* ------------------------------------------------------------------ */
/* Interrupt lines and the hold                                        */

uint32_t pruss_icss_read32(AM335xPrussState *p, uint32_t off)
{
    uint8_t b[4] = { 0 };

    prusim_host_read(p->s, off, b, sizeof(b));
    return ldl_le_p(b);
}

/* Events routed to a host interrupt towards the ARM that is enabled */
static uint64_t arm_routed(AM335xPrussState *p)
{
    uint32_t hier = pruss_icss_read32(p, ICSS_INTC_HIER);
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
    int64_t now = pruss_now_ns(p), held;

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
void pruss_update_irqs(AM335xPrussState *p)
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
        if (!extract32(pruss_icss_read32(p, ICSS_INTC_ESR(ev / 32)),
                       ev % 32, 1)) {
            p->in_service |= bit;
        }
        if (!extract32(pruss_icss_read32(p, ICSS_INTC_SRSR(ev / 32)),
                       ev % 32, 1)) {
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

static void lockstep_advance(AM335xPrussState *p);

/* In lockstep the PRUs first run up to the access's virtual time */
void pruss_lock(AM335xPrussState *p)
{
    qatomic_inc(&p->waiters);
    qemu_mutex_lock(&p->lock);
    qatomic_dec(&p->waiters);
    if (p->lockstep) {
        lockstep_advance(p);
    }
}

/* @kick: the access may have given the PRUs something to do */
void pruss_unlock(AM335xPrussState *p, bool kick)
{
    if (kick) {
        if (p->lockstep) {
            lockstep_advance(p);
        }
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
    uint8_t b[4] = { 0 };
    uint32_t v = 0;

    pruss_lock(p);
    if (pruss_icss_in_reset(p)) {
        pruss_unimp(p, "PRU-ICSS read of %u bytes at 0x%05" HWADDR_PRIx
                    " while PRCM holds it in reset", size, addr);
        pruss_unlock(p, false);
        return 0;
    }
    p->ocp_drained += prusim_ocp_drain(p->s);
    if (!prusim_host_modelled(addr, size, false)) {
        pruss_unimp(p, "PRU-ICSS read of %u bytes at 0x%05" HWADDR_PRIx,
                    size, addr);
    }
    /* the bus's bytes, low first: a narrower read leaves the rest 0 */
    prusim_host_read(p->s, addr, b, size);
    v = ldl_le_p(b);
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
    uint8_t b[4];
    bool was_running[PRUSIM_NUM_CORES];
    unsigned int i;

    stl_le_p(b, val);               /* the first @size bytes are the bus's */

    trace_am335x_pruss_write(addr, size, v);
    pruss_lock(p);
    if (pruss_icss_in_reset(p)) {
        pruss_unimp(p, "PRU-ICSS write of %u bytes at 0x%05" HWADDR_PRIx
                    " (0x%x) while PRCM holds it in reset", size, addr, v);
        pruss_unlock(p, false);
        return;
    }
    p->ocp_drained += prusim_ocp_drain(p->s);
    if (!prusim_host_modelled(addr, size, true)) {
        pruss_unimp(p,
                    "PRU-ICSS write of %u bytes at 0x%05" HWADDR_PRIx " (0x%x)",
                    size, addr, v);
    } else if (!prusim_store_modelled(addr, b, size)) {
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
    prusim_host_write(p->s, addr, b, size);
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
/* The local reset (PRCM's PRU_ICSS_LRST)                              */

/*
 * PRU_ICSS_LRST asserted: the PRU-ICSS goes to its reset state, its R30
 * outputs low; the GPIO banks, outside it, keep theirs.  The PRUs' stores
 * on their way to RAM land first.  On a board ti-sysc asserts it through
 * omap_prm whenever the PRU-ICSS's target module idles (pruss unbound).
 */
static void icss_reset(AM335xPrussState *p)
{
    unsigned int i;

    for (i = 0; i < PRUSIM_NUM_CORES; i++) {
        struct prusim_status st;

        prusim_get_status(p->s, i, &st);
        p->reset_states[i] = st.state;
    }
    flight_land(p);
    p->ocp_drained += prusim_ocp_drain(p->s);
    prusim_icss_reset(p->s);
    p->r30 = 0;
    pruss_pads_changed(p);
    p->in_service = 0;
    p->taken = 0;
    memset(p->strobe, 0, sizeof(p->strobe));
    memset(p->stopped_reported, 0, sizeof(p->stopped_reported));
    p->icss_resets++;
    pruss_update_irqs(p);
}

/* "lrst": PRCM's PRU_ICSS_LRST; asserting it resets the PRU-ICSS */
static void pruss_lrst(void *opaque, int n, int level)
{
    AM335xPrussState *p = opaque;

    pruss_lock(p);
    if (level && !p->in_lrst) {
        icss_reset(p);
    }
    p->in_lrst = level;
    pruss_unlock(p, true);
}

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
        t0 = qemu_clock_get_ns(QEMU_CLOCK_REALTIME);
        slice = p->slice_cycles;
        if (p->jitter) {
            /* knob: random slices; the ARM's accesses land anywhere */
            slice = g_rand_int_range(p->rng, 1, 2 * p->slice_cycles + 1);
            p->jitter_slices++;
        }
        prusim_run(p->s, slice);
        p->host_ns += qemu_clock_get_ns(QEMU_CLOCK_REALTIME) - t0;
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

/* ------------------------------------------------------------------ */
/* Lockstep: the PRUs' time is the guest's virtual clock                */

/*
 * With QEMU's -icount, the guest's virtual clock counts the instructions
 * the emulated ARM ran (2^shift ns each: shift 0 is a 1 GHz ARM beside the
 * PRUs' 200 MHz), and one thread runs every vCPU and the virtual clock's
 * timers.  The simulation then has no thread of its own: under the BQL,
 * the PRUs run up to the virtual time of each ARM access to the device
 * (pruss_lock()) and of a timer one slice ahead while they run.  The ARM
 * and the PRUs take turns, so a loaded host slows both alike, and how far
 * a PRU gets while Linux does something depends on what Linux did, not on
 * the host.  An ARM access sees the PRUs exactly as they were at its time;
 * a PRU sees the ARM's stores to DDR up to one slice early (the ARM ran
 * that slice first), and its own reach DDR for the ARM at the latest at the
 * slice's end.  The hold, the knobs' waits and the jitter knob's pauses
 * stop simulated time for virtual time, not host time.
 */

/* Simulated time stands still until @until (virtual ns) */
static void lockstep_rebase(AM335xPrussState *p, int64_t until)
{
    p->vbase = until;
    p->cbase = p->s->now;
}

/* The virtual time the PRUs have reached */
static int64_t lockstep_vsim(AM335xPrussState *p)
{
    return p->vbase + (int64_t)(p->s->now - p->cbase) * PRU_CYCLE_NS;
}

/*
 * The knobs' waits (knob_waits()) in virtual time: each store held back
 * lands once its flight has passed, then the pauses.  True while one
 * lasts (simulated time rebased past its end).
 */
static bool lockstep_knobs(AM335xPrussState *p, int64_t vsim)
{
    uint64_t pause_us;

    if (p->landing) {
        flight_land_one(p);
        p->landing = false;
    }
    if (p->flight_n) {
        p->landing = true;
        lockstep_rebase(p, vsim + (int64_t)p->ocp_write_flight_us * SCALE_US);
        return true;
    }
    pause_us = (uint64_t)p->ocp_pauses * p->ocp_write_pause_us;
    p->ocp_pauses = 0;
    if (pause_us) {
        lockstep_rebase(p, vsim + pause_us * SCALE_US);
        return true;
    }
    return false;
}

/*
 * Run the PRUs up to the guest's virtual time now, and set the timer for
 * when they next have something to do before the ARM comes.  BQL and the
 * device lock held.
 */
static void lockstep_advance(AM335xPrussState *p)
{
    int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    int64_t next = -1;

    while (!p->quit) {
        int64_t vsim = lockstep_vsim(p), t0;
        int wait_ms = 0;
        uint64_t n;

        if (vsim > now) {
            next = vsim;                /* a knob's wait ends then */
            break;
        }
        if (lockstep_knobs(p, vsim)) {
            continue;
        }
        if (pruss_held(p, &wait_ms)) {
            lockstep_rebase(p, now);
            next = now + (int64_t)wait_ms * SCALE_MS;
            break;
        }
        if (p->freeze || !p->runnable || !prusim_active(p->s)) {
            /* until the ARM brings something: its access re-arms */
            p->runnable = p->runnable && prusim_active(p->s);
            lockstep_rebase(p, now);
            break;
        }
        n = (now - vsim) / PRU_CYCLE_NS;
        if (!n) {
            next = vsim + (int64_t)p->slice_cycles * PRU_CYCLE_NS;
            break;
        }
        if (p->jitter) {
            /* knob: random slices */
            n = MIN(n, (uint64_t)g_rand_int_range(p->rng, 1,
                                                  2 * p->slice_cycles + 1));
            p->jitter_slices++;
        } else {
            n = MIN(n, (uint64_t)p->slice_cycles);
        }
        t0 = qemu_clock_get_ns(QEMU_CLOCK_REALTIME);
        n = prusim_run(p->s, n);
        p->host_ns += qemu_clock_get_ns(QEMU_CLOCK_REALTIME) - t0;
        p->lockstep_runs++;
        p->runnable = !p->s->waiting || inputs_pending(p);
        report_stops(p);
        if (!n && p->runnable && !p->irq_dirty && !p->flight_n &&
            !p->ocp_pauses) {
            /* no cycle and nothing to see to: the timer tries again */
            next = now + (int64_t)p->slice_cycles * PRU_CYCLE_NS;
            break;
        }
        if (p->jitter &&
            !g_rand_int_range(p->rng, 0, JITTER_PAUSE_ONE_IN)) {
            /* knob: the simulation stops a while, the ARM runs on */
            uint32_t us = g_rand_int_range(p->rng, 0, JITTER_PAUSE_MAX_US + 1);

            p->jitter_pauses++;
            p->jitter_pause_ns += us * SCALE_US;
            lockstep_rebase(p, lockstep_vsim(p) + (int64_t)us * SCALE_US);
        }
        if (p->irq_dirty) {
            pruss_update_irqs(p);
        }
    }
    if (next < 0 || p->quit) {
        timer_del(p->vtimer);
    } else {
        timer_mod(p->vtimer, next);
    }
}

static void lockstep_timer(void *opaque)
{
    AM335xPrussState *p = opaque;

    qemu_mutex_lock(&p->lock);
    lockstep_advance(p);
    qemu_mutex_unlock(&p->lock);
}

/* BQL held */
static void pruss_vm_state_change(void *opaque, bool running, RunState state)
{
    AM335xPrussState *p = opaque;

    pruss_lock(p);
    p->vm_running = running;
    if (running && p->hold_since && !p->lockstep) {
        /* a hold's cap counts host time the VM ran */
        p->hold_since = pruss_now_ns(p);
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
    p->landing = false;
    if (p->lockstep) {
        /* simulated time starts again from the guest's now */
        lockstep_rebase(p, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL));
    }
    for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
        pruss_stim_free(&p->input[i].stim);
        memset(&p->input[i], 0, sizeof(p->input[i]));
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
    pruss_jitter_seed(p);
    p->hold_mode = p->hold_mode_reset;
    /* as on a board: held in reset until Linux releases it (ti-sysc) */
    p->in_lrst = true;
    p->icss_resets = 0;
    memset(p->reset_states, PRUSIM_DISABLED, sizeof(p->reset_states));
    p->runnable = false;
    p->irq_dirty = true;
}

/*
 * Resettable: the simulator and this device's state in the enter phase,
 * the interrupt lines in the hold phase.  The other blocks reset their
 * registers in their enter phases, and in their hold phases (after the
 * simulator's reset) what they put into it: a GPIO bank its OE and its
 * clock, the pads what reaches a pin; PRCM drives "lrst" and the banks'
 * clocks.
 */
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
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        if (!p->gpio[i]) {
            error_setg(errp, "link gpio%u is not set", i);
            return;
        }
    }
    if (!p->pads) {
        error_setg(errp, "link pads is not set");
        return;
    }

    memory_region_init_io(&p->pruss_mr, OBJECT(p), &pruss_ops, p,
                          "am335x-pruss.icss", PRUSS_SIZE);
    sysbus_init_mmio(sbd, &p->pruss_mr);
    for (i = 0; i < AM335X_PRUSS_NUM_HOST_IRQS; i++) {
        sysbus_init_irq(sbd, &p->host_irq[i]);
    }
    qdev_init_gpio_in_named(dev, pruss_lrst, "lrst", 1);

    p->s = g_malloc0(sizeof(*p->s));
    p->trace = g_new0(struct prusim_trace_rec, TRACE_LEN);
    qemu_mutex_init(&p->lock);
    qemu_cond_init(&p->wake);
    qemu_cond_init(&p->turn);
    p->rng = g_rand_new();
    /* with -icount the PRUs follow the guest's virtual clock, thread-less */
    p->lockstep = icount_enabled();
    if (p->lockstep) {
        p->vtimer = timer_new_ns(QEMU_CLOCK_VIRTUAL, lockstep_timer, p);
    }
    /* the rest comes with the system reset, before the guest runs */
    pruss_reset_state(p);
    p->vm_running = runstate_is_running();
    p->vmstate_entry = qemu_add_vm_change_state_handler(pruss_vm_state_change,
                                                        p);
    if (!p->lockstep) {
        qemu_thread_create(&p->thread, "am335x-pruss", pruss_thread, p,
                           QEMU_THREAD_JOINABLE);
    }
}

static void am335x_pruss_unrealize(DeviceState *dev)
{
    AM335xPrussState *p = AM335X_PRUSS(dev);
    unsigned int i;

    qemu_del_vm_change_state_handler(p->vmstate_entry);
    pruss_lock(p);
    p->quit = true;
    pruss_unlock(p, true);
    if (p->lockstep) {
        timer_free(p->vtimer);
    } else {
        qemu_thread_join(&p->thread);
    }
    for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
        pruss_stim_free(&p->input[i].stim);
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
    /* the blocks the pin path reads */
    DEFINE_PROP_LINK("gpio0", AM335xPrussState, gpio[0], TYPE_AM335X_GPIO,
                     AM335xGpioState *),
    DEFINE_PROP_LINK("gpio1", AM335xPrussState, gpio[1], TYPE_AM335X_GPIO,
                     AM335xGpioState *),
    DEFINE_PROP_LINK("gpio2", AM335xPrussState, gpio[2], TYPE_AM335X_GPIO,
                     AM335xGpioState *),
    DEFINE_PROP_LINK("gpio3", AM335xPrussState, gpio[3], TYPE_AM335X_GPIO,
                     AM335xGpioState *),
    DEFINE_PROP_LINK("pads", AM335xPrussState, pads, TYPE_AM335X_PADS,
                     AM335xPadsState *),
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
    dc->desc = "AM335x PRU-ICSS (prukit's prusim)";
    dc->user_creatable = false;
    device_class_set_props(dc, am335x_pruss_props);
}

static const TypeInfo am335x_pruss_info = {
    .name = TYPE_AM335X_PRUSS,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(AM335xPrussState),
    .class_init = am335x_pruss_class_init,
};

/*
 * A new device, a child of the machine as @name: the links between the
 * blocks name their targets by QOM path, which a device has only once it
 * has a parent.
 */
static DeviceState *block_new(const char *type, const char *name)
{
    DeviceState *dev = qdev_new(type);

    object_property_add_child(qdev_get_machine(), name, OBJECT(dev));
    return dev;
}

static void link_set(DeviceState *dev, const char *name, DeviceState *target)
{
    object_property_set_link(OBJECT(dev), name, OBJECT(target), &error_abort);
}

DeviceState *am335x_pruss_create(qemu_irq *host_irq, qemu_irq *gpio_irq)
{
    DeviceState *icss = block_new(TYPE_AM335X_PRUSS, "am335x-pruss");
    DeviceState *gpio[PRUSIM_GPIO_BANKS], *pads, *prcm, *port;
    unsigned int i;

    /* the links first: the PRU-ICSS's reset reaches the banks and pads */
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        g_autofree char *name = g_strdup_printf("am335x-gpio%u", i);

        gpio[i] = block_new(TYPE_AM335X_GPIO, name);
        qdev_prop_set_uint8(gpio[i], "bank", i);
        link_set(gpio[i], "pruss", icss);
        link_set(icss, name + strlen("am335x-"), gpio[i]);
    }
    pads = block_new(TYPE_AM335X_PADS, "am335x-pads");
    link_set(pads, "pruss", icss);
    link_set(icss, "pads", pads);
    prcm = block_new(TYPE_AM335X_PRCM, "am335x-prcm");
    link_set(prcm, "pruss", icss);
    port = block_new(TYPE_AM335X_PRUSS_PORT, "am335x-pruss-port");
    link_set(port, "pruss", icss);

    sysbus_realize_and_unref(SYS_BUS_DEVICE(icss), &error_fatal);
    sysbus_mmio_map(SYS_BUS_DEVICE(icss), 0, PRUSS_BASE);
    for (i = 0; i < AM335X_PRUSS_NUM_HOST_IRQS; i++) {
        sysbus_connect_irq(SYS_BUS_DEVICE(icss), i, host_irq[i]);
    }
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        sysbus_realize_and_unref(SYS_BUS_DEVICE(gpio[i]), &error_fatal);
        sysbus_mmio_map(SYS_BUS_DEVICE(gpio[i]), 0, gpio_base[i]);
        sysbus_connect_irq(SYS_BUS_DEVICE(gpio[i]), 0, gpio_irq[i]);
    }
    sysbus_realize_and_unref(SYS_BUS_DEVICE(pads), &error_fatal);
    sysbus_mmio_map(SYS_BUS_DEVICE(pads), 0, PADS_BASE);
    sysbus_realize_and_unref(SYS_BUS_DEVICE(prcm), &error_fatal);
    sysbus_mmio_map(SYS_BUS_DEVICE(prcm), 0, PRM_PER_BASE);
    sysbus_mmio_map(SYS_BUS_DEVICE(prcm), 1, CM_BASE);
    qdev_connect_gpio_out_named(prcm, "icss-lrst", 0,
                                qdev_get_gpio_in_named(icss, "lrst", 0));
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        qdev_connect_gpio_out_named(prcm, "gpio-clk", i,
                                    qdev_get_gpio_in_named(gpio[i], "clk", 0));
    }
    sysbus_realize_and_unref(SYS_BUS_DEVICE(port), &error_fatal);
    sysbus_mmio_map(SYS_BUS_DEVICE(port), 0, PORT_BASE);
    sysbus_mmio_map(SYS_BUS_DEVICE(port), 1, PORT_BUF_BASE);
    for (i = 0; i < ARRAY_SIZE(catch_regions); i++) {
        create_unimplemented_device(catch_regions[i].name,
                                    catch_regions[i].base,
                                    catch_regions[i].size);
    }
    return icss;
}

static void am335x_pruss_register_types(void)
{
    type_register_static(&am335x_pruss_info);
}
type_init(am335x_pruss_register_types)
