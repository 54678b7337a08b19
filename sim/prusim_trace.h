/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Binary pin trace: what the QEMU PRU-ICSS's "trace" holds (debugfs
 * prusim/trace in the guest) and what the prusim tool reads (--trace-in)
 * and writes (--trace-out).  Little endian.
 *
 * A header, then @count records in cycle order.  Cycles are absolute
 * simulator cycles; @origin is the cycle at which the last PRU core was
 * started (a core's start in the QEMU PRU-ICSS, 0 in the prusim tool), so that
 * "cycle - origin" compares runs made in different places.  @end is the
 * cycle up to which the trace is complete (the simulator's clock when the
 * trace was taken): pins keep their last level until then.
 *
 * Version 2 added @end (version 1 had a 40-byte header without it).
 */
#ifndef _PRUSIM_TRACE_H
#define _PRUSIM_TRACE_H

#include "prusim_platform.h"

#define PRUSIM_TRACE_MAGIC	"PRUTRACE"
#define PRUSIM_TRACE_VERSION	2

/**
 * struct prusim_trace_hdr - start of a binary pin trace
 * @magic: PRUSIM_TRACE_MAGIC, not NUL terminated
 * @version: PRUSIM_TRACE_VERSION
 * @rec_size: sizeof(struct prusim_trace_rec)
 * @origin: reference cycle (see above)
 * @count: number of records that follow
 * @dropped: older records lost because the recorder's buffer was full
 * @end: the trace is complete up to this cycle; not below @origin or the
 *	cycle of the last record
 */
struct prusim_trace_hdr {
	char magic[8];
	u32 version;
	u32 rec_size;
	u64 origin;
	u64 count;
	u64 dropped;
	u64 end;
} __packed;

/**
 * struct prusim_trace_rec - one output pin change
 * @cycle: simulator cycle of the change
 * @pin: pin id, PRUSIM_PIN_R30() or PRUSIM_PIN_GPIO()
 * @level: new level, 0 or 1
 * @reserved: zero
 */
struct prusim_trace_rec {
	u64 cycle;
	u16 pin;
	u8 level;
	u8 reserved[5];
} __packed;

#endif /* _PRUSIM_TRACE_H */
