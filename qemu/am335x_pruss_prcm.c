/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRCM for prukit's test VM (TYPE_AM335X_PRCM): the registers of it
 * the PRU-ICSS's world uses (see am335x_pruss.c and prukit's
 * Documentation/qemu-pruss.rst):
 *   PRM_PER (0x44e00c00): RM_PER_RSTCTRL's PRU_ICSS_LRST, output
 *               "icss-lrst" (asserted at power-on; on a board ti-sysc
 *               releases it through omap_prm, and asserts it whenever the
 *               PRU-ICSS's target module idles);
 *   CM_PER, CM_WKUP (0x44e00000): the GPIO banks' CLKCTRL, outputs
 *               "gpio-clk" 0..3 (disabled at power-on; ti-sysc enables a
 *               bank's while its module is in use).
 * The rest of PRCM is not modelled (logged and counted as the PRU-ICSS's
 * unmodelled accesses).  MMIO runs under the BQL; the lines' receivers
 * take the PRU-ICSS's lock.
 */

#include "qemu/osdep.h"
#include "qapi/error.h"
#include "hw/irq.h"
#include "hw/qdev-properties.h"
#include "migration/vmstate.h"

#include "am335x_pruss_internal.h"

static void G_GNUC_PRINTF(2, 3) prcm_unimp(AM335xPrcmState *c,
                                           const char *fmt, ...)
{
    g_autofree char *text = NULL;
    va_list ap;

    va_start(ap, fmt);
    text = g_strdup_vprintf(fmt, ap);
    va_end(ap);
    pruss_lock(c->pruss);
    pruss_unimp(c->pruss, "%s", text);
    pruss_unlock(c->pruss, false);
}

/* ------------------------------------------------------------------ */
/* PRM_PER: the PRU-ICSS's local reset                                 */

static uint64_t prm_read(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPrcmState *c = opaque;

    if (off == PRM_RSTCTRL && size == 4) {
        return c->rstctrl;
    }
    prcm_unimp(c, "PRM_PER read of %u bytes at 0x%02" HWADDR_PRIx
               " (not modelled)", size, off);
    return 0;
}

static void prm_write(void *opaque, hwaddr off, uint64_t val,
                      unsigned int size)
{
    AM335xPrcmState *c = opaque;
    uint32_t v = val;

    if (off != PRM_RSTCTRL || size != 4 || (v & ~PRM_ICSS_LRST)) {
        prcm_unimp(c, "PRM_PER write of %u bytes at 0x%02" HWADDR_PRIx
                   " (0x%x, not modelled)", size, off, v);
        return;
    }
    c->rstctrl = v;
    qemu_set_irq(c->icss_lrst, !!(v & PRM_ICSS_LRST));
}

static const MemoryRegionOps prm_ops = {
    .read = prm_read,
    .write = prm_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};

/* ------------------------------------------------------------------ */
/* CM_PER, CM_WKUP: the GPIO banks' clocks                             */

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

static bool cm_enabled(uint32_t clkctrl)
{
    return (clkctrl & CM_MODULEMODE) == CM_MODULEMODE_ENABLE;
}

/* IDLEST follows MODULEMODE at once: fully functional, or disabled */
static uint64_t cm_read(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPrcmState *c = opaque;
    int bank = cm_bank(off);
    uint32_t v;

    if (bank < 0 || size != 4) {
        prcm_unimp(c, "PRCM CM read of %u bytes at 0x%03" HWADDR_PRIx
                   " (not modelled)", size, off);
        return 0;
    }
    v = c->gpio_clkctrl[bank];
    if (!cm_enabled(v)) {
        v |= CM_IDLEST_DISABLED << CM_IDLEST_SHIFT;
    }
    return v;
}

/*
 * MODULEMODE "enabled" (2) clocks the bank, "disabled" (0) gates it (the
 * bank's "clk" input says what that does).  IDLEST is read-only; the
 * reserved modes are not modelled.
 */
static void cm_write(void *opaque, hwaddr off, uint64_t val,
                     unsigned int size)
{
    AM335xPrcmState *c = opaque;
    int bank = cm_bank(off);
    uint32_t v = val & ~CM_IDLEST, mode = v & CM_MODULEMODE;

    if (bank < 0 || size != 4 ||
        (v & ~(CM_MODULEMODE | CM_GPIO_OPTFCLKEN)) ||
        (mode != 0 && mode != CM_MODULEMODE_ENABLE)) {
        prcm_unimp(c, "PRCM CM write of %u bytes at 0x%03" HWADDR_PRIx
                   " (0x%x, not modelled)", size, off, v);
        return;
    }
    c->gpio_clkctrl[bank] = v;
    qemu_set_irq(c->gpio_clk[bank], cm_enabled(v));
}

static const MemoryRegionOps cm_ops = {
    .read = cm_read,
    .write = cm_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};

/* ------------------------------------------------------------------ */
/* Device                                                              */

/* Resettable: the registers (enter), then the lines they drive (hold) */
static void prcm_reset_enter(Object *obj, ResetType type)
{
    AM335xPrcmState *c = AM335X_PRCM(obj);

    /* as on a board: the PRU-ICSS held in reset, every bank's clock off */
    c->rstctrl = PRM_ICSS_LRST;
    memset(c->gpio_clkctrl, 0, sizeof(c->gpio_clkctrl));
}

static void prcm_reset_hold(Object *obj)
{
    AM335xPrcmState *c = AM335X_PRCM(obj);
    unsigned int i;

    qemu_set_irq(c->icss_lrst, 1);
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        qemu_set_irq(c->gpio_clk[i], 0);
    }
}

static void prcm_realize(DeviceState *dev, Error **errp)
{
    AM335xPrcmState *c = AM335X_PRCM(dev);
    SysBusDevice *sbd = SYS_BUS_DEVICE(dev);

    if (!c->pruss) {
        error_setg(errp, "link pruss is not set");
        return;
    }
    memory_region_init_io(&c->prm_mr, OBJECT(c), &prm_ops, c,
                          "am335x-prcm.prm-per", PRM_PER_SIZE);
    sysbus_init_mmio(sbd, &c->prm_mr);
    memory_region_init_io(&c->cm_mr, OBJECT(c), &cm_ops, c,
                          "am335x-prcm.cm", CM_SIZE);
    sysbus_init_mmio(sbd, &c->cm_mr);
    qdev_init_gpio_out_named(dev, &c->icss_lrst, "icss-lrst", 1);
    qdev_init_gpio_out_named(dev, c->gpio_clk, "gpio-clk", PRUSIM_GPIO_BANKS);
}

static Property prcm_props[] = {
    DEFINE_PROP_LINK("pruss", AM335xPrcmState, pruss, TYPE_AM335X_PRUSS,
                     AM335xPrussState *),
    DEFINE_PROP_END_OF_LIST(),
};

static const VMStateDescription vmstate_am335x_prcm = {
    .name = TYPE_AM335X_PRCM,
    .version_id = 1,
    .minimum_version_id = 1,
    .fields = (VMStateField[]) {
        VMSTATE_UINT32(rstctrl, AM335xPrcmState),
        VMSTATE_UINT32_ARRAY(gpio_clkctrl, AM335xPrcmState, PRUSIM_GPIO_BANKS),
        VMSTATE_END_OF_LIST()
    },
};

static void prcm_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    ResettableClass *rc = RESETTABLE_CLASS(klass);

    dc->realize = prcm_realize;
    rc->phases.enter = prcm_reset_enter;
    rc->phases.hold = prcm_reset_hold;
    dc->vmsd = &vmstate_am335x_prcm;
    dc->desc = "AM335x PRCM: the PRU-ICSS's reset, the GPIO banks' clocks";
    dc->user_creatable = false;
    device_class_set_props(dc, prcm_props);
}

static const TypeInfo prcm_info = {
    .name = TYPE_AM335X_PRCM,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(AM335xPrcmState),
    .class_init = prcm_class_init,
};

static void prcm_register_types(void)
{
    type_register_static(&prcm_info);
}
type_init(prcm_register_types)
