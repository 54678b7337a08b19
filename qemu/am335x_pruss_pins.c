/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS for prukit's test VM: the pin path - what an R30 bit or
 * a GPIO line makes of a pin through its pad, and the trace of it (see
 * am335x_pruss.c and prukit's Documentation/qemu-pruss.rst).  Not a device:
 * it reads the pads (TYPE_AM335X_PADS) and the GPIO banks
 * (TYPE_AM335X_GPIO), and runs under the PRU-ICSS's lock.
 */

#include "qemu/osdep.h"

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
    return pad_reg(p->pads, (row->offset - 0x800) / 4);
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
    AM335xGpioState *g = p->gpio[bank];
    uint32_t shown = g->out & ~g->oe & p->gpio_pad_mask[bank];
    uint32_t diff = shown ^ g->shown;
    unsigned int bit;

    if (pruss_gpio_gated(p, bank)) {
        return;
    }
    g->shown = shown;
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

void pruss_gpio_show(AM335xPrussState *p, unsigned int bank)
{
    gpio_show(p, p->s->now, bank);
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
    AM335xGpioState *g = p->gpio[bank];
    uint32_t bit = 1u << (pin % 32);
    bool output = !(g->oe & bit);

    if (level) {
        g->out |= bit;
    } else {
        g->out &= ~bit;
    }
    if (pruss_gpio_gated(p, bank) && !p->arm_gpio) {
        p->gpio_gated++;
        p->gpio_unpinned++;
        g->unpinned_seen |= bit;
    } else if (!(output && (p->gpio_pad_mask[bank] & bit)) &&
               (output || !p->arm_gpio)) {
        p->gpio_unpinned++;
        g->unpinned_seen |= bit;
    }
    gpio_show(p, cycle, bank);
}

void pruss_gpio_oe_cb(void *ctx, u64 cycle, unsigned int bank, u32 oe)
{
    AM335xPrussState *p = ctx;

    p->gpio[bank]->oe = oe;
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
