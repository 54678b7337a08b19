// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * rpmsg-echo: announce "rpmsg-pru" at port 30 (PRU0) or 31 (PRU1) and send
 * every message that arrives back, unchanged, to the address it came from.
 *
 * Messages are handled one at a time and in order: while Linux has no free
 * buffer for the reply (or its ring index is out of range), the firmware
 * waits for a kick, tries again and takes nothing new, so a sender that
 * outruns its reader blocks in Linux instead of losing messages here.
 * Malformed buffers are given back unread and counted in rpmsg.stats (see
 * Documentation/firmware-rpmsg.rst).
 */
#include <errno.h>
#include <stdint.h>

#include <prukit/pru.h>
#include <prukit/rpmsg.h>

/* Global, not static: tests and debuggers find the counters by symbol. */
struct prukit_rpmsg rpmsg;
static uint8_t msg[RPMSG_PRU_MAX_PAYLOAD];

int main(void)
{
	uint32_t src;
	uint16_t len;
	int ret;

	if (prukit_rpmsg_init(&rpmsg))
		pru_halt();

	for (;;) {
		ret = prukit_rpmsg_recv(&rpmsg, msg, &len, &src);
		if (ret == -EAGAIN || ret == -EIO) {
			prukit_rpmsg_wait(&rpmsg);
			continue;
		}
		if (ret)
			continue;	/* -EBADMSG: counted, try the next one */
		/* no buffer (-EAGAIN) or a ring index out of range (-EIO): retry */
		do {
			ret = prukit_rpmsg_send(&rpmsg, src, msg, len);
			if (ret == -EAGAIN || ret == -EIO)
				prukit_rpmsg_wait(&rpmsg);
		} while (ret == -EAGAIN || ret == -EIO);
	}
}
