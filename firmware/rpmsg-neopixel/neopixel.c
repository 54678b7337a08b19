// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * rpmsg-neopixel: a string of 24 WS2812 ("NeoPixel") LEDs on PRU0 R30 bit 1
 * (P9_29, pad mcasp0_fsx, mux mode 5), driven over rpmsg as in the PRU
 * Cookbook:
 *
 *	echo "0 0xff 0 127" > /dev/rpmsg_pru30	# pixel 0: red 255, blue 127
 *	echo "-1" > /dev/rpmsg_pru30		# send all 24 pixels
 *
 * A message holds one or more lines separated by '\n' (the last one needs
 * none).  A line is "index red green blue", each a decimal or 0x-prefixed
 * hexadecimal number, index 0..23 and colours 0..255, separated by blanks
 * (space, tab, CR); or "-1" alone, which sends the whole string (GRB, MSB
 * first) and then holds the line low for the 300 us reset.  Blank lines are
 * skipped.  Anything else - too few or too many fields, not a number, index
 * or colour out of range, a line of more than NEOPIXEL_LINE_MAX characters -
 * is ignored and counted in neopixel_stats.lines_bad.  Lines do not continue
 * across messages.  All pixels are off (0) at start.
 */
#include <errno.h>
#include <stdint.h>

#include <prukit/pru.h>
#include <prukit/rpmsg.h>

#include "neopixel.h"

/* Global, not static: tests and debuggers find them by symbol. */
struct prukit_rpmsg rpmsg;
struct neopixel_stats neopixel_stats;
/* GRB, the order the WS2812 wants on the wire */
uint8_t neopixel_grb[NEOPIXEL_COUNT][3];

static char msg[RPMSG_PRU_MAX_PAYLOAD];
static uint32_t r30;

static int is_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r';
}

static const char *skip_blanks(const char *p, const char *end)
{
	while (p < end && is_blank(*p))
		p++;
	return p;
}

static int hex_digit(char c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	if (c >= 'a' && c <= 'f')
		return c - 'a' + 10;
	if (c >= 'A' && c <= 'F')
		return c - 'A' + 10;
	return -1;
}

/*
 * Parse one number at *pp (decimal, or hexadecimal after "0x"/"0X") that
 * ends at a blank or at end.  Large values saturate at 0x10000, which is out
 * of every range.  Returns 0 and advances *pp, or -EINVAL.
 */
static int parse_number(const char **pp, const char *end, uint32_t *val)
{
	const char *p = *pp;
	uint32_t base = 10, v = 0;
	int digits = 0, d;

	if (end - p > 2 && p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
		base = 16;
		p += 2;
	}
	for (; p < end && !is_blank(*p); p++) {
		d = hex_digit(*p);
		if (d < 0 || (uint32_t)d >= base)
			return -EINVAL;
		v = v * base + d;
		if (v > 0x10000)
			v = 0x10000;
		digits++;
	}
	if (!digits)
		return -EINVAL;
	*val = v;
	*pp = p;
	return 0;
}

static void send_frame(void)
{
	ws2812_send(&neopixel_grb[0][0], sizeof(neopixel_grb), r30);
	__delay_cycles(WS2812_RESET);
	neopixel_stats.frames++;
}

/* One line, without its '\n': 0 if applied or blank, -EINVAL if malformed */
static int do_line(const char *p, const char *end)
{
	uint32_t v[4];
	unsigned int i;

	if (end - p > NEOPIXEL_LINE_MAX)
		return -EINVAL;
	p = skip_blanks(p, end);
	if (p == end)
		return 0;
	if (*p == '-') {
		if (end - p < 2 || p[1] != '1' || skip_blanks(p + 2, end) != end)
			return -EINVAL;
		send_frame();
		return 0;
	}
	for (i = 0; i < 4; i++) {
		if (p == end || parse_number(&p, end, &v[i]))
			return -EINVAL;
		p = skip_blanks(p, end);
	}
	if (p != end || v[0] >= NEOPIXEL_COUNT || v[1] > 255 || v[2] > 255 || v[3] > 255)
		return -EINVAL;
	neopixel_grb[v[0]][0] = v[2];
	neopixel_grb[v[0]][1] = v[1];
	neopixel_grb[v[0]][2] = v[3];
	neopixel_stats.lines_ok++;
	return 0;
}

static void do_message(const char *p, uint16_t len)
{
	const char *end = p + len, *eol;

	neopixel_stats.msgs++;
	while (p < end) {
		for (eol = p; eol < end && *eol != '\n'; eol++)
			;
		if (do_line(p, eol))
			neopixel_stats.lines_bad++;
		p = eol + 1;
	}
}

int main(void)
{
	uint32_t src;
	uint16_t len;
	int ret;

	/* Data line low, then a reset's worth of low before anything else */
	r30 = read_r30() & ~(1u << NEOPIXEL_BIT);
	write_r30(r30);
	__delay_cycles(WS2812_RESET);

	if (prukit_rpmsg_init(&rpmsg))
		pru_halt();

	for (;;) {
		ret = prukit_rpmsg_recv(&rpmsg, msg, &len, &src);
		if (ret == -EAGAIN || ret == -EIO)
			prukit_rpmsg_wait(&rpmsg);
		else if (!ret)
			do_message(msg, len);
	}
}
