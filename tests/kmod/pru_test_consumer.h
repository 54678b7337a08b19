/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * What pru_test_consumer (tests/kmod) and its firmware
 * (firmware/consumer-test) agree on: the control block after the common
 * header of include/prukit/pru_ctrl.h, its commands and results.  Shared
 * verbatim by both.
 */
#ifndef PRU_TEST_CONSUMER_H
#define PRU_TEST_CONSUMER_H

#include "prukit/pru_ctrl.h"

#define PRU_TEST_MAGIC		0x54555250u	/* "PRUT" */
#define PRU_TEST_VERSION	1

/* Commands */
#define PRU_TEST_CMD_PING	1	/* count it in @pings */
#define PRU_TEST_CMD_COPY	2	/* @len bytes @src -> @dst over OCP, XOR @xor */
#define PRU_TEST_CMD_EVENTS	3	/* strobe PRU_TEST_EVENT @count times */

/* Results */
#define PRU_TEST_OK		0
#define PRU_TEST_EINVAL		1	/* unknown command or bad parameter */

/* COPY moves whole 32-bit words, at most this many bytes at once. */
#define PRU_TEST_MAX_COPY	65536u
/* EVENTS: the system event strobed (the consumer's node maps it) ... */
#define PRU_TEST_EVENT		20
/* ... and the PRU cycles between two strobes (10 us). */
#define PRU_TEST_EVENT_GAP	2000

/**
 * struct pru_test_ctrl - the test consumer's control block
 * @hdr: magic PRU_TEST_MAGIC, version PRU_TEST_VERSION, command, status
 * @src: COPY: bus address the PRU reads
 * @dst: COPY: bus address the PRU writes
 * @len: COPY: bytes, a multiple of 4, at most PRU_TEST_MAX_COPY
 * @xor: COPY: each 32-bit word is XORed with this on its way
 * @count: EVENTS: number of strobes, at most 1000
 * @pings: PING commands the firmware answered since it started
 */
struct pru_test_ctrl {
	struct prukit_ctrl_hdr hdr;
	__u32 src;
	__u32 dst;
	__u32 len;
	__u32 xor;
	__u32 count;
	__u32 pings;
} __packed __aligned(4);

#define PRU_TEST_MAX_EVENTS	1000

#endif /* PRU_TEST_CONSUMER_H */
