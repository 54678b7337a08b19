/* SPDX-License-Identifier: (GPL-2.0-only OR BSD-2-Clause) */
/*
 * The first cell of an ARM GIC "interrupts" specifier (the arm,gic
 * binding): which kind of interrupt the second cell numbers.  The emulated
 * board's tree (tests/vm/board/am335x-pruss.dtso) uses it; scripts/
 * overlays.sh --check builds that tree with the kernels' own headers as
 * well and requires the same blob.
 */
#ifndef _DT_BINDINGS_INTERRUPT_CONTROLLER_ARM_GIC_H
#define _DT_BINDINGS_INTERRUPT_CONTROLLER_ARM_GIC_H

#include <dt-bindings/interrupt-controller/irq.h>

#define GIC_SPI		0	/* shared peripheral interrupt, number - 32 */
#define GIC_PPI		1	/* private peripheral interrupt */

#endif
