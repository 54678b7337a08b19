/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS and the parts of the SoC a PRU reaches (prukit): see
 * am335x_pruss.c and prukit's Documentation/qemu-pruss.rst.
 */
#ifndef HW_MISC_AM335X_PRUSS_H
#define HW_MISC_AM335X_PRUSS_H

#include "hw/irq.h"

/* One device per block (am335x_pruss_create() makes and wires them) */
#define TYPE_AM335X_PRUSS "am335x-pruss"            /* the PRU-ICSS */
#define TYPE_AM335X_GPIO "am335x-gpio"              /* a GPIO bank */
#define TYPE_AM335X_PADS "am335x-pads"              /* control module pads */
#define TYPE_AM335X_PRCM "am335x-prcm"              /* PRM_PER, CM_* parts */
#define TYPE_AM335X_PRUSS_PORT "am335x-pruss-port"  /* prukit's test port */

/* Interrupts: host_intr0..7 (INTC hosts 2..9); GPIO banks 0..3 (unused) */
#define AM335X_PRUSS_NUM_HOST_IRQS      8
#define AM335X_PRUSS_NUM_GPIO_IRQS      4

/*
 * am335x_pruss_create() - the PRU-ICSS, GPIO banks, pad registers, PRCM's
 * registers and the test port at their addresses in the system memory map,
 * and QEMU's unimplemented devices over the rest of L4_WKUP, L4_PER and
 * L4_FAST; returns the PRU-ICSS
 * @host_irq: AM335X_PRUSS_NUM_HOST_IRQS interrupt inputs (host_intr0..7)
 * @gpio_irq: AM335X_PRUSS_NUM_GPIO_IRQS interrupt inputs (GPIO banks 0..3)
 */
DeviceState *am335x_pruss_create(qemu_irq *host_irq, qemu_irq *gpio_irq);

#endif /* HW_MISC_AM335X_PRUSS_H */
