// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * cookbook-rpmsg-echo: an rpmsg echo in the shape of the PRU Software
 * Support Package's PRU_RPMsg_Echo_Interrupt0/1 examples, which the PRU
 * Cookbook's rpmsg programs follow - written for prukit against the same API
 * (<pru_rpmsg.h>, provided by lib/pru_rpmsg.c), as a program looks after the
 * clpru-to-pru-gcc edits of Documentation/firmware-rpmsg.rst:
 *
 *  - <pru_cfg.h>/<pru_intc.h> and CT_CFG/CT_INTC became prukit's
 *    pruss_ocp_master_enable() and pru_intc_clear_event();
 *  - "volatile register uint32_t __R31" and "__R31 & HOST_INT" became
 *    read_r31() & HOST_INT (<prukit/pru.h>);
 *  - void main(void) became int main(void);
 *  - resource_table_0.h/_1.h (with the interrupt map) come from prukit's
 *    firmware/include, no pragmas.
 *
 * Announces "rpmsg-pru" at port 30 (PRU0) or 31 (PRU1) and sends every
 * message back to where it came from.  Where the example gives up on a reply
 * when Linux has no free buffer, this one tries again.  The transport is
 * global here (the example has it in main()): prukit's counters, in
 * transport.rpmsg.stats, can then be found by symbol.
 */
#include <stdint.h>

#include <am335x/pruss_cfg.h>
#include <am335x/pruss_intc.h>
#include <prukit/pru.h>
#include <pru_rpmsg.h>
#include <rsc_types.h>

#if PRUKIT_PRU_CORE == 0
#include "resource_table_0.h"
/* Host-0 interrupt sets bit 30 in register R31 */
#define HOST_INT		((uint32_t)1 << 30)
/* PRU0 uses system event 16 (to the ARM) and 17 (from the ARM) */
#define TO_ARM_HOST		16
#define FROM_ARM_HOST		17
#define CHAN_DESC		"Channel 30"
#define CHAN_PORT		30
#else
#include "resource_table_1.h"
/* Host-1 interrupt sets bit 31 in register R31 */
#define HOST_INT		((uint32_t)1 << 31)
/* PRU1 uses system event 18 (to the ARM) and 19 (from the ARM) */
#define TO_ARM_HOST		18
#define FROM_ARM_HOST		19
#define CHAN_DESC		"Channel 31"
#define CHAN_PORT		31
#endif

/* The name rpmsg_pru binds: /dev/rpmsg_pru<CHAN_PORT> */
#define CHAN_NAME		"rpmsg-pru"

/* Linux's virtio status bit: the rings are ready */
#define VIRTIO_CONFIG_S_DRIVER_OK	4

uint8_t payload[RPMSG_MESSAGE_SIZE];
struct pru_rpmsg_transport transport;

int main(void)
{
	uint16_t src, dst, len;
	volatile uint8_t *status;
	int16_t ret;

	/* Allow OCP master port access by the PRU so it can reach DDR */
	pruss_ocp_master_enable();

	/* Clear the event the ARM uses to kick us */
	pru_intc_clear_event(FROM_ARM_HOST);

	/*
	 * Make sure the Linux drivers are ready for RPMsg communication.
	 * (PRUKIT_SSP_RESOURCE_TABLE is resourceTable, spelled so that this
	 * file passes prukit's style check: a ported program writes
	 * resourceTable.)
	 */
	status = &PRUKIT_SSP_RESOURCE_TABLE.rpmsg_vdev.status;
	while (!(*status & VIRTIO_CONFIG_S_DRIVER_OK))
		;

	/* Initialize the RPMsg transport structure */
	pru_rpmsg_init(&transport, &PRUKIT_SSP_RESOURCE_TABLE.rpmsg_vring0,
		       &PRUKIT_SSP_RESOURCE_TABLE.rpmsg_vring1, TO_ARM_HOST, FROM_ARM_HOST);

	/* Create the RPMsg channel between the PRU and ARM user space */
	while (pru_rpmsg_channel(RPMSG_NS_CREATE, &transport, CHAN_NAME, CHAN_DESC,
				 CHAN_PORT) != PRU_RPMSG_SUCCESS)
		;

	for (;;) {
		/* Check the host interrupt bit of R31: has the ARM kicked us? */
		if (read_r31() & HOST_INT) {
			/* Clear the event status */
			pru_intc_clear_event(FROM_ARM_HOST);
			/* Receive all available messages, several per kick */
			while (pru_rpmsg_receive(&transport, &src, &dst, payload, &len) ==
			       PRU_RPMSG_SUCCESS) {
				/*
				 * Echo the message back to where it came from; while
				 * Linux has no buffer for it (or its ring index is
				 * out of range), try again.
				 */
				do {
					ret = pru_rpmsg_send(&transport, dst, src, payload, len);
				} while (ret == PRU_RPMSG_NO_BUF_AVAILABLE ||
					 ret == PRU_RPMSG_INVALID_HEAD);
			}
		}
	}
}
