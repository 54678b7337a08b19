// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * consumer-irqmap: the test consumer's firmware, plus a .pru_irq_map that
 * maps the event the consumer's device tree node takes as its interrupt
 * (see fw.mk).
 */
#include <prukit/irq_map.h>

#include "../consumer-test/consumer-test.c"

PRUKIT_IRQ_MAP(PRUKIT_IRQ_EVT(PRU_TEST_EVENT, 4, 4));
