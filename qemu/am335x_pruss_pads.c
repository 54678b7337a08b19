/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x control module pads for prukit's test VM (TYPE_AM335X_PADS): the
 * conf_* registers pinctrl-single writes, at 0x44e10800 (see am335x_pruss.c
 * and prukit's Documentation/qemu-pruss.rst).  A pad's mode and receiver
 * decide what reaches its pin (am335x_pruss_pins.c), so every access takes
 * the PRU-ICSS's lock.  The rest of the control module is not modelled.
 */

#include "qemu/osdep.h"
#include "qapi/error.h"
#include "hw/qdev-properties.h"
#include "migration/vmstate.h"
#include "trace.h"

#include "am335x_pruss_internal.h"

void am335x_pads_set(AM335xPadsState *pads, unsigned int i, uint32_t val)
{
    stl_le_p(&pads->regs[4 * i], val & PAD_MASK);
    pads->writes++;
    pruss_pads_changed(pads->pruss);
}

static uint64_t pads_read(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPadsState *pads = opaque;
    uint32_t v = 0;

    pruss_lock(pads->pruss);
    if (size != 4 || off & 3) {
        pruss_unimp(pads->pruss, "pad read of %u bytes at 0x%03" HWADDR_PRIx,
                    size, 0x800 + off);
    } else {
        v = pad_reg(pads, off / 4);
    }
    pruss_unlock(pads->pruss, false);
    return v;
}

static void pads_write(void *opaque, hwaddr off, uint64_t val,
                       unsigned int size)
{
    AM335xPadsState *pads = opaque;

    trace_am335x_pruss_pad_write(0x800 + off, val);
    pruss_lock(pads->pruss);
    if (size != 4 || off & 3) {
        pruss_unimp(pads->pruss, "pad write of %u bytes at 0x%03" HWADDR_PRIx,
                    size, 0x800 + off);
    } else {
        am335x_pads_set(pads, off / 4, val);
    }
    pruss_unlock(pads->pruss, false);
}

static const MemoryRegionOps pads_ops = {
    .read = pads_read,
    .write = pads_write,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 4 },
};

/* Resettable: the registers (enter), then what reaches a pin (hold) */
static void pads_reset_enter(Object *obj, ResetType type)
{
    AM335xPadsState *pads = AM335X_PADS(obj);
    unsigned int i;

    pruss_lock(pads->pruss);
    for (i = 0; i < PADS_NUM; i++) {
        stl_le_p(&pads->regs[4 * i], PAD_RESET);
    }
    pads->writes = 0;
    pruss_unlock(pads->pruss, false);
}

static void pads_reset_hold(Object *obj)
{
    AM335xPadsState *pads = AM335X_PADS(obj);

    pruss_lock(pads->pruss);
    pruss_pads_masks(pads->pruss);
    pruss_unlock(pads->pruss, false);
}

static void pads_realize(DeviceState *dev, Error **errp)
{
    AM335xPadsState *pads = AM335X_PADS(dev);

    if (!pads->pruss) {
        error_setg(errp, "link pruss is not set");
        return;
    }
    memory_region_init_io(&pads->mr, OBJECT(pads), &pads_ops, pads,
                          "am335x-pads", PADS_SIZE);
    sysbus_init_mmio(SYS_BUS_DEVICE(dev), &pads->mr);
}

static Property pads_props[] = {
    DEFINE_PROP_LINK("pruss", AM335xPadsState, pruss, TYPE_AM335X_PRUSS,
                     AM335xPrussState *),
    DEFINE_PROP_END_OF_LIST(),
};

/* What a pad decides is in the PRU-ICSS's state, which cannot be saved. */
static const VMStateDescription vmstate_am335x_pads = {
    .name = TYPE_AM335X_PADS,
    .unmigratable = 1,
};

static void pads_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    ResettableClass *rc = RESETTABLE_CLASS(klass);

    dc->realize = pads_realize;
    rc->phases.enter = pads_reset_enter;
    rc->phases.hold = pads_reset_hold;
    dc->vmsd = &vmstate_am335x_pads;
    dc->desc = "AM335x control module pads (prukit)";
    dc->user_creatable = false;
    device_class_set_props(dc, pads_props);
}

static const TypeInfo pads_info = {
    .name = TYPE_AM335X_PADS,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(AM335xPadsState),
    .class_init = pads_class_init,
};

static void pads_register_types(void)
{
    type_register_static(&pads_info);
}
type_init(pads_register_types)
