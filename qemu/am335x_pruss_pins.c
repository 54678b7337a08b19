/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS for prukit's test VM: the pins - the trace of what
 * reaches them, the control module's pad registers, the GPIO banks and
 * their clocks in PRCM (see am335x_pruss.c and prukit's
 * Documentation/qemu-pruss.rst).
 */

#include "qemu/osdep.h"
#include "qemu/log.h"
#include "trace.h"

#include "am335x_pruss_internal.h"
#include "prusim/am335x_pins.h"

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

    if (pruss_gpio_gated(p, bank)) {
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
void pruss_pads_masks(AM335xPrussState *p)
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

void pruss_pads_changed(AM335xPrussState *p)
{
    unsigned int pin, i;

    pruss_pads_masks(p);
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
/* prusim callbacks for the pins (under the device lock)               */

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
    if (pruss_gpio_gated(p, bank) && !p->arm_gpio) {
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

void pruss_gpio_oe_cb(void *ctx, u64 cycle, unsigned int bank, u32 oe)
{
    AM335xPrussState *p = ctx;

    p->gpio_oe[bank] = oe;
    gpio_show(p, cycle, bank);
}

void pruss_pin_cb(void *ctx, u64 cycle, unsigned int pin, bool level)
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

/*
 * The test port's "pads": every pad not at its reset value and every pad
 * of a PRU output
 */
uint32_t pruss_pads_text(AM335xPrussState *p)
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
    if (!pruss_gpio_clocked(p, bank)) {
        pruss_unimp(p, "GPIO%u read at 0x%03" HWADDR_PRIx
                    " while PRCM gates its clocks", bank, off);
    } else if (gpio_sim_reg(off)) {
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

/*
 * SYSCONFIG's SOFTRESET (ti-sysc resets each bank as it probes its target
 * module): the bank's registers to their reset values, every line an input
 * and DATAOUT 0; RESETDONE (SYSSTATUS) at once.
 */
static void gpio_softreset(AM335xPrussState *p, unsigned int bank)
{
    p->arm_gpio = true;
    prusim_gpio_write(p->s, bank, PRUSIM_GPIO_OE, 0xffffffff);
    prusim_gpio_write(p->s, bank, PRUSIM_GPIO_DATAOUT, 0);
    p->arm_gpio = false;
    memset(p->gpio_reg[bank], 0, sizeof(p->gpio_reg[bank]));
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
    } else if (!pruss_gpio_clocked(p, bank)) {
        pruss_unimp(p, "GPIO%u write at 0x%03" HWADDR_PRIx
                    " (0x%x) while PRCM gates its clocks", bank, off, v);
    } else if (off == GPIO_SYSCONFIG && (v & GPIO_SYSCONFIG_SOFTRESET)) {
        gpio_softreset(p, bank);
        p->gpio_reg[bank][off / 4] = v & ~GPIO_SYSCONFIG_SOFTRESET;
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

const MemoryRegionOps pruss_gpio_ops[PRUSIM_GPIO_BANKS] = {
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
        pruss_pads_changed(p);
    }
    pruss_unlock(p, false);
}

const MemoryRegionOps pruss_pads_ops = {
    .read = pads_read,
    .write = pads_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};

/* ------------------------------------------------------------------ */
/* PRCM: the GPIO banks' clocks (CM_WKUP's and CM_PER's CLKCTRL)      */

/* each bank's CLKCTRL, from CM_PER's base (CM_WKUP is at 0x400) */
static const hwaddr cm_gpio_clkctrl[PRUSIM_GPIO_BANKS] = {
    0x408, 0x0ac, 0x0b0, 0x0b4,
};

static int cm_bank(hwaddr off)
{
    unsigned int i;

    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        if (cm_gpio_clkctrl[i] == off) {
            return i;
        }
    }
    return -1;
}

/* IDLEST follows MODULEMODE at once: fully functional, or disabled */
static uint64_t cm_read(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPrussState *p = opaque;
    int bank = cm_bank(off);
    uint32_t v = 0;

    pruss_lock(p);
    if (bank < 0 || size != 4) {
        pruss_unimp(p, "PRCM CM read of %u bytes at 0x%03" HWADDR_PRIx
                    " (not modelled)", size, off);
    } else {
        v = p->gpio_clkctrl[bank];
        if (!pruss_gpio_clocked(p, bank)) {
            v |= CM_IDLEST_DISABLED << CM_IDLEST_SHIFT;
        }
    }
    pruss_unlock(p, false);
    return v;
}

/*
 * MODULEMODE "enabled" (2) clocks the bank, "disabled" (0) gates it: a
 * PRU's store to it is then lost (gpio_gated_writes), a PRU's load stops
 * the core (the simulator's, from prusim_gpio_set_gated()), an ARM access
 * is an unmodelled one, and its pins keep what they showed until it is
 * clocked again.  IDLEST is read-only; the reserved modes are not modelled.
 */
static void cm_write(void *opaque, hwaddr off, uint64_t val,
                     unsigned int size)
{
    AM335xPrussState *p = opaque;
    int bank = cm_bank(off);
    uint32_t v = val & ~CM_IDLEST, mode = v & CM_MODULEMODE;

    pruss_lock(p);
    if (bank < 0 || size != 4 ||
        (v & ~(CM_MODULEMODE | CM_GPIO_OPTFCLKEN)) ||
        (mode != 0 && mode != CM_MODULEMODE_ENABLE)) {
        pruss_unimp(p, "PRCM CM write of %u bytes at 0x%03" HWADDR_PRIx
                    " (0x%x, not modelled)", size, off, v);
    } else {
        if (pruss_gpio_clocked(p, bank) && mode != CM_MODULEMODE_ENABLE) {
            p->gpio_clock_gatings++;
        }
        p->gpio_clkctrl[bank] = v;
        prusim_gpio_set_gated(p->s, bank, !pruss_gpio_clocked(p, bank));
        gpio_show(p, p->s->now, bank);      /* clocked: the pins catch up */
    }
    p->runnable = true;
    pruss_unlock(p, true);
}

const MemoryRegionOps pruss_cm_ops = {
    .read = cm_read,
    .write = cm_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};
