/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x GPIO bank for prukit's test VM (TYPE_AM335X_GPIO), as gpio-omap
 * uses it: see am335x_pruss.c and prukit's Documentation/qemu-pruss.rst.
 *
 * A PRU reaches a bank over its OCP master port, through the simulator:
 * OE, DATAIN and the data registers are the simulator's (prusim_gpio_*()),
 * the rest is stored here.  What a line makes of its pin is the pin path's
 * (am335x_pruss_pins.c), under the PRU-ICSS's lock, which every access
 * takes.  Input "clk": PRCM clocks the bank (its CLKCTRL's MODULEMODE).
 * Output: the bank's interrupt (never raised: not modelled).
 */

#include "qemu/osdep.h"
#include "qemu/bitops.h"
#include "qapi/error.h"
#include "hw/irq.h"
#include "hw/qdev-properties.h"
#include "migration/vmstate.h"
#include "trace.h"

#include "am335x_pruss_internal.h"

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

/* IRQSTATUS_CLR(n) reads and clears IRQSTATUS_SET(n)'s enables */
static hwaddr gpio_enable_reg(hwaddr clr)
{
    return clr - GPIO_IRQSTATUS_CLR(0) + GPIO_IRQSTATUS_SET(0);
}

static uint64_t gpio_read(void *opaque, hwaddr off, unsigned int size)
{
    AM335xGpioState *g = opaque;
    AM335xPrussState *p = g->pruss;
    unsigned int shift;
    uint32_t v = 0;

    pruss_lock(p);
    /*
     * a narrower read (gpio-omap reads REVISION as 16 bits) takes part of the
     * word
     */
    if ((off & 3) + size > 4) {
        pruss_unimp(p, "GPIO%u read of %u bytes at 0x%03" HWADDR_PRIx,
                    g->bank, size, off);
        pruss_unlock(p, false);
        return 0;
    }
    shift = 8 * (off & 3);
    off &= ~(hwaddr)3;
    if (!g->clocked) {
        pruss_unimp(p, "GPIO%u read at 0x%03" HWADDR_PRIx
                    " while PRCM gates its clocks", g->bank, off);
    } else if (gpio_sim_reg(off)) {
        v = prusim_gpio_read(p->s, g->bank,
                             off == PRUSIM_GPIO_OE ||
                             off == PRUSIM_GPIO_DATAIN ?
                             off : PRUSIM_GPIO_DATAOUT);
    } else if (off == GPIO_REVISION) {
        v = GPIO_REVISION_VALUE;
    } else if (off == GPIO_SYSSTATUS) {
        v = 1;          /* RESETDONE */
    } else if (off == GPIO_IRQSTATUS_CLR(0) || off == GPIO_IRQSTATUS_CLR(1)) {
        v = gpio_reg(g, gpio_enable_reg(off));
    } else if (gpio_stored_reg(off)) {
        v = gpio_reg(g, off);
    } else {
        pruss_unimp(p, "GPIO%u read at 0x%03" HWADDR_PRIx, g->bank, off);
    }
    pruss_unlock(p, false);
    trace_am335x_pruss_gpio_read(g->bank, off, v);
    return extract32(v, shift, 8 * size);
}

/* Write the simulator's register @off as the ARM (lock held) */
static void gpio_arm_sim_write(AM335xGpioState *g, hwaddr off, uint32_t v)
{
    AM335xPrussState *p = g->pruss;

    p->arm_gpio = true;
    prusim_gpio_write(p->s, g->bank, off, v);
    p->arm_gpio = false;
}

/*
 * SYSCONFIG's SOFTRESET (ti-sysc resets each bank as it probes its target
 * module): the bank's registers to their reset values, every line an input
 * and DATAOUT 0; RESETDONE (SYSSTATUS) at once.
 */
static void gpio_softreset(AM335xGpioState *g)
{
    gpio_arm_sim_write(g, PRUSIM_GPIO_OE, 0xffffffff);
    gpio_arm_sim_write(g, PRUSIM_GPIO_DATAOUT, 0);
    memset(g->regs, 0, sizeof(g->regs));
}

static void gpio_write(void *opaque, hwaddr off, uint64_t val,
                       unsigned int size)
{
    AM335xGpioState *g = opaque;
    AM335xPrussState *p = g->pruss;
    uint32_t v = val;

    trace_am335x_pruss_gpio_write(g->bank, off, v);
    pruss_lock(p);
    if (size != 4 || off & 3) {
        pruss_unimp(p, "GPIO%u write of %u bytes at 0x%03" HWADDR_PRIx,
                    g->bank, size, off);
    } else if (!g->clocked) {
        pruss_unimp(p, "GPIO%u write at 0x%03" HWADDR_PRIx
                    " (0x%x) while PRCM gates its clocks", g->bank, off, v);
    } else if (off == GPIO_SYSCONFIG && (v & GPIO_SYSCONFIG_SOFTRESET)) {
        gpio_softreset(g);
        gpio_reg_set(g, off, v & ~GPIO_SYSCONFIG_SOFTRESET);
    } else if (gpio_sim_reg(off) && off != PRUSIM_GPIO_DATAIN) {
        gpio_arm_sim_write(g, off, v);
    } else if (gpio_stored_reg(off)) {
        switch (off) {
        case GPIO_IRQSTATUS(0):
        case GPIO_IRQSTATUS(1):
            /* write 1 to clear; never set */
            gpio_reg_set(g, off, gpio_reg(g, off) & ~v);
            break;
        case GPIO_IRQSTATUS_SET(0):
        case GPIO_IRQSTATUS_SET(1):
            if (v) {
                pruss_unimp(p, "GPIO%u interrupts (IRQSTATUS_SET 0x%08x)",
                            g->bank, v);
            }
            gpio_reg_set(g, off, gpio_reg(g, off) | v);
            break;
        case GPIO_IRQSTATUS_CLR(0):
        case GPIO_IRQSTATUS_CLR(1):
            gpio_reg_set(g, gpio_enable_reg(off),
                         gpio_reg(g, gpio_enable_reg(off)) & ~v);
            break;
        case GPIO_IRQSTATUS_RAW(0):
        case GPIO_IRQSTATUS_RAW(1):
            if (v) {
                pruss_unimp(p, "GPIO%u IRQSTATUS_RAW set 0x%08x", g->bank, v);
            }
            break;
        case GPIO_CTRL:
            gpio_reg_set(g, off, v);
            pruss_gpio_show(p, g->bank);    /* enabled: the pins catch up */
            break;
        default:
            gpio_reg_set(g, off, v);
            break;
        }
    } else if (off != GPIO_EOI) {
        pruss_unimp(p, "GPIO%u write at 0x%03" HWADDR_PRIx " (0x%x)",
                    g->bank, off, v);
    }
    p->runnable = true;
    pruss_unlock(p, true);
}

static const MemoryRegionOps gpio_ops = {
    .read = gpio_read,
    .write = gpio_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};

/*
 * "clk": PRCM clocks the bank (1) or gates it (0).  Gated, a PRU's store to
 * it is lost (gpio_gated_writes), a PRU's load stops the core (the
 * simulator's, from prusim_gpio_set_gated()), an ARM access is an
 * unmodelled one, and its pins keep what they showed until it is clocked
 * again.
 */
static void gpio_clk(void *opaque, int n, int level)
{
    AM335xGpioState *g = opaque;
    AM335xPrussState *p = g->pruss;

    pruss_lock(p);
    if (g->clocked && !level) {
        g->clock_gatings++;
    }
    g->clocked = level;
    prusim_gpio_set_gated(p->s, g->bank, !level);
    pruss_gpio_show(p, g->bank);            /* clocked: the pins catch up */
    p->runnable = true;
    pruss_unlock(p, true);
}

/* Resettable: the registers (enter), then the simulator's lines (hold) */
static void gpio_reset_enter(Object *obj, ResetType type)
{
    AM335xGpioState *g = AM335X_GPIO(obj);

    pruss_lock(g->pruss);
    memset(g->regs, 0, sizeof(g->regs));
    /* the TRM's reset values: the clocks disabled, every line an input */
    g->clocked = false;
    g->clock_gatings = 0;
    g->out = 0;
    g->oe = 0xffffffff;
    g->shown = 0;
    g->unpinned_seen = 0;
    pruss_unlock(g->pruss, false);
}

static void gpio_reset_hold(Object *obj)
{
    AM335xGpioState *g = AM335X_GPIO(obj);

    pruss_lock(g->pruss);
    gpio_arm_sim_write(g, PRUSIM_GPIO_OE, 0xffffffff);
    prusim_gpio_set_gated(g->pruss->s, g->bank, true);
    pruss_unlock(g->pruss, false);
}

static void gpio_realize(DeviceState *dev, Error **errp)
{
    AM335xGpioState *g = AM335X_GPIO(dev);
    SysBusDevice *sbd = SYS_BUS_DEVICE(dev);
    g_autofree char *name = NULL;

    if (!g->pruss) {
        error_setg(errp, "link pruss is not set");
        return;
    }
    if (g->bank >= PRUSIM_GPIO_BANKS) {
        error_setg(errp, "bank must be below %u", PRUSIM_GPIO_BANKS);
        return;
    }
    name = g_strdup_printf("am335x-gpio%u", g->bank);
    memory_region_init_io(&g->mr, OBJECT(g), &gpio_ops, g, name, GPIO_SIZE);
    sysbus_init_mmio(sbd, &g->mr);
    sysbus_init_irq(sbd, &g->irq);
    qdev_init_gpio_in_named(dev, gpio_clk, "clk", 1);
}

static Property gpio_props[] = {
    DEFINE_PROP_UINT8("bank", AM335xGpioState, bank, 0),
    DEFINE_PROP_LINK("pruss", AM335xGpioState, pruss, TYPE_AM335X_PRUSS,
                     AM335xPrussState *),
    DEFINE_PROP_END_OF_LIST(),
};

/* Its lines are in the PRU-ICSS's simulator, which cannot be saved. */
static const VMStateDescription vmstate_am335x_gpio = {
    .name = TYPE_AM335X_GPIO,
    .unmigratable = 1,
};

static void gpio_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    ResettableClass *rc = RESETTABLE_CLASS(klass);

    dc->realize = gpio_realize;
    rc->phases.enter = gpio_reset_enter;
    rc->phases.hold = gpio_reset_hold;
    dc->vmsd = &vmstate_am335x_gpio;
    dc->desc = "AM335x GPIO bank (prukit: its lines in the PRU-ICSS's sim)";
    dc->user_creatable = false;
    device_class_set_props(dc, gpio_props);
}

static const TypeInfo gpio_info = {
    .name = TYPE_AM335X_GPIO,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(AM335xGpioState),
    .class_init = gpio_class_init,
};

static void gpio_register_types(void)
{
    type_register_static(&gpio_info);
}
type_init(gpio_register_types)
