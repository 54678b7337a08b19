/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS and the parts of the SoC a PRU reaches (prukit): see
 * am335x_pruss.c and prukit's Documentation/qemu-pruss.rst.
 */
#ifndef HW_MISC_AM335X_PRUSS_H
#define HW_MISC_AM335X_PRUSS_H

#include "hw/irq.h"

#define TYPE_AM335X_PRUSS "am335x-pruss"

/* Interrupt outputs: host_intr0..7 (INTC hosts 2..9), then GPIO banks 0..3 */
#define AM335X_PRUSS_NUM_HOST_IRQS      8
#define AM335X_PRUSS_NUM_GPIO_IRQS      4

/*
 * am335x_pruss_create() - the PRU-ICSS, GPIO banks, pad registers and test
 * port at their addresses in the system memory map
 * @host_irq: AM335X_PRUSS_NUM_HOST_IRQS interrupt inputs (host_intr0..7)
 * @gpio_irq: AM335X_PRUSS_NUM_GPIO_IRQS interrupt inputs (GPIO banks 0..3)
 */
DeviceState *am335x_pruss_create(qemu_irq *host_irq, qemu_irq *gpio_irq);

#endif /* HW_MISC_AM335X_PRUSS_H */
