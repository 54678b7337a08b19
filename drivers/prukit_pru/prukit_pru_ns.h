/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prukit_pru - inside the layer's module: the name service wrapper
 * (prukit_pru_ns.c) and what it asks of the kick (prukit_pru_kick.c)
 */
#ifndef _PRUKIT_PRU_NS_H
#define _PRUKIT_PRU_NS_H

#include <linux/types.h>

#include "compat.h"

struct device;

bool prukit_pru_kick_owns(struct device *dev);

#ifdef PRUKIT_PRU_NS_HOOK
int prukit_pru_ns_init(void);
void prukit_pru_ns_exit(void);
#else
static inline int prukit_pru_ns_init(void)
{
	return 0;
}

static inline void prukit_pru_ns_exit(void)
{
}
#endif

#endif /* _PRUKIT_PRU_NS_H */
