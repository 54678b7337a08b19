/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * hub75 firmware: the refresh loop of HUB75_DATA_BANKS, parallel outputs
 * with every line a GPIO pin (hub75_proto.h has the protocol).
 *
 *   void hub75_scan_banks(volatile struct hub75_ctrl *c, uint32_t command);
 *
 * As hub75_scan(), but every line goes through the GPIO banks' CLEARDATAOUT
 * and SETDATAOUT over the OCP master port.  A frame buffer entry is four
 * 32-bit words, the bits to set in the banks of slots 0..3; per clock:
 *
 *	for each used slot k:	sbbo {mask_k ^ word_k, word_k}, bank_k + CLEAR, 8
 *	then:			sbbo clk, bank_3 + SET, 4
 *
 * An 8-byte store is two words on the L4 path: it takes them at
 * gpio_write_interval (8) cycles a word, and both land together,
 * gpio_write_latency (17) cycles after it took them (prusim's model,
 * Documentation/prusim.rst).  So a clock of n used slots takes
 * (2n + 1) * 8 cycles: the path's own pace, the core waits for it.  Slot
 * 3's mask holds the clock, so the clock falls with slot 3's data; it rises
 * 16 cycles after the last data landed, and the next clock's first data
 * lands 8 cycles after it rose.
 *
 * After a row: LAT high, the address (CLEAR and SET at once), LAT low, all
 * while OE is high; then OE low for exactly the plane's cycles T: its
 * CLEAR taken at t0, its SET at t0 + T (T >= 8, one write's time on the
 * path: the driver makes sure), both landing 17 cycles later.  Rows are
 * never lit while anything else changes.
 *
 * Registers:
 *   r0, r1	a CLEAR and SET pair; scratch
 *   r3		b3: the used slots (bank_used); w0: the chunks left in the row
 *   r4..r7	the slots' banks + CLEARDATAOUT (SETDATAOUT is + 4)
 *   r8..r11	the slots' masks
 *   r12	the next byte of the frame buffer
 *   r13	the clock's bit
 *   r14..r29	64 bytes: four entries (and scratch between rows)
 * The rest lives in the stack frame (L_*).
 */
#include "hub75_proto.h"

#define CTRL_COMMAND	8
#define CTRL_ADDR_MASK	32
#define IEP_COUNT	0x0c	/* in the IEP's registers, constant table entry 26 */
#define CHUNK		64	/* bytes a load: four entries */

#define SAVED		44	/* r3..r13 */
#define L_CTRL		44	/* &ctrl, and next to it */
#define L_CMD		48	/* the command that started the refresh */
#define L_ROWS4		52
#define L_PLANES4	56
#define L_CHUNKS	60	/* chunks a row */
#define L_ROW		64	/* row * 4 */
#define L_PLANE		68	/* plane * 4 */
#define L_OE		72	/* the plane's lit cycles */
#define L_IEP		76	/* the IEP count as the refresh began */
#define L_LAT		80	/* the latch's bit */
#define L_OEM		84	/* OE's bit */
#define L_ADDRM		88	/* the address lines' bits */
#define FRAME		92

/* One clock: @a..@d are the entry's words of slots 0..3 */
	.macro	BPIX a, b, c, d
	qbbc	1f, r3.b3, 0
	xor	r0, \a, r8
	mov	r1, \a
	sbbo	&r0, r4, 0, 8
1:
	qbbc	2f, r3.b3, 1
	xor	r0, \b, r9
	mov	r1, \b
	sbbo	&r0, r5, 0, 8
2:
	qbbc	3f, r3.b3, 2
	xor	r0, \c, r10
	mov	r1, \c
	sbbo	&r0, r6, 0, 8
3:
	xor	r0, \d, r11
	mov	r1, \d
	sbbo	&r0, r7, 0, 8
	sbbo	&r13, r7, 4, 4
	.endm

	.section .text.hub75_scan_banks, "ax", @progbits
	.global	hub75_scan_banks
hub75_scan_banks:
	sub	r2, r2, FRAME
	sbbo	&r3, r2, 0, SAVED
	sbbo	&r14, r2, L_CTRL, 8			/* &ctrl, command */

	/* the parameters */
	ldi	r0, HUB75_CTRL_BANK_ADDR
	lbbo	&r4, r14, r0, 32			/* r4..r7 banks, r8..r11 masks */
	ldi	r0, HUB75_GPIO_CLEARDATAOUT
	add	r4, r4, r0
	add	r5, r5, r0
	add	r6, r6, r0
	add	r7, r7, r0
	ldi	r0, HUB75_CTRL_BANK_USED
	lbbo	&r3.b3, r14, r0, 1
	lbbo	&r16, r14, HUB75_CTRL_ROW_BYTES, 12	/* r16 bytes, rows; r17, r18 */
	lsr	r0, r16.w0, 6				/* CHUNK */
	sbbo	&r0, r2, L_CHUNKS, 4
	lsl	r0, r16.w2, 2
	sbbo	&r0, r2, L_ROWS4, 4
	lsl	r0, r17.b1, 2				/* planes */
	sbbo	&r0, r2, L_PLANES4, 4
	ldi	r13, 1
	lsl	r13, r13, r17.b2			/* clock */
	ldi	r0, 1
	lsl	r0, r0, r17.b3				/* latch */
	sbbo	&r0, r2, L_LAT, 4
	ldi	r0, 1
	lsl	r0, r0, r18.b0				/* OE */
	sbbo	&r0, r2, L_OEM, 4
	lbbo	&r0, r14, CTRL_ADDR_MASK, 4
	sbbo	&r0, r2, L_ADDRM, 4
	/* dark, the latch low */
	lbbo	&r0, r2, L_OEM, 4
	sbbo	&r0, r7, 4, 4
	lbbo	&r0, r2, L_LAT, 4
	sbbo	&r0, r7, 0, 4
	lbco	&r0, 26, IEP_COUNT, 4
	sbbo	&r0, r2, L_IEP, 4

refresh:
	/* the buffer to show */
	lbbo	&r14, r2, L_CTRL, 4
	lbbo	&r0, r14, HUB75_CTRL_SHOW, 4
	and	r0, r0, 1
	sbbo	&r0, r14, HUB75_CTRL_SHOWN, 4
	lsl	r0, r0, 2
	add	r0, r0, HUB75_CTRL_BUF_ADDR
	lbbo	&r12, r14, r0, 4
	/* count it; the previous one's length */
	lbbo	&r0, r14, HUB75_CTRL_REFRESHES, 4
	lbco	&r1, 26, IEP_COUNT, 4
	qbeq	1f, r0, 0
	lbbo	&r16, r2, L_IEP, 4
	sub	r16, r1, r16
	sbbo	&r16, r14, HUB75_CTRL_REFRESH_CYCLES, 4
1:
	sbbo	&r1, r2, L_IEP, 4
	add	r0, r0, 1
	sbbo	&r0, r14, HUB75_CTRL_REFRESHES, 4
	ldi	r0, 0
	sbbo	&r0, r2, L_PLANE, 4

plane:
	lbbo	&r14, r2, L_CTRL, 8			/* &ctrl, command */
	lbbo	&r0, r14, CTRL_COMMAND, 4
	qbne	done, r0, r15
	lbbo	&r1, r2, L_PLANE, 4
	ldi	r0, HUB75_CTRL_OE_CYCLES
	add	r0, r0, r1
	lbbo	&r0, r14, r0, 4
	sbbo	&r0, r2, L_OE, 4
	ldi	r0, 0
	sbbo	&r0, r2, L_ROW, 4

row:
	lbbo	&r3.b0, r2, L_CHUNKS, 2
chunk:
	lbbo	&r14, r12, 0, CHUNK
	add	r12, r12, CHUNK
	BPIX	r14, r15, r16, r17
	BPIX	r18, r19, r20, r21
	BPIX	r22, r23, r24, r25
	BPIX	r26, r27, r28, r29
	sub	r3.w0, r3.w0, 1
	qbne	chunk, r3.w0, 0

	/* latch the row with its address, dark */
	lbbo	&r0, r2, L_LAT, 4
	sbbo	&r0, r7, 4, 4
	lbbo	&r14, r2, L_CTRL, 4
	lbbo	&r15, r2, L_ROW, 4
	ldi	r0, HUB75_CTRL_ROW_ADDR
	add	r0, r0, r15
	lbbo	&r1, r14, r0, 4
	lbbo	&r0, r2, L_ADDRM, 4
	xor	r0, r0, r1
	sbbo	&r0, r7, 0, 8
	lbbo	&r0, r2, L_LAT, 4
	sbbo	&r0, r7, 0, 4

	/* light the rows for T cycles: OE's CLEAR taken at t0, its SET at t0 + T */
	lbbo	&r26, r2, L_OE, 4
	qbeq	lit, r26, 0
	lbbo	&r0, r2, L_OEM, 4
	sub	r1, r26, 2
	sbbo	&r0, r7, 0, 4
	loop	1f, r1.w0
	nop
1:
	sbbo	&r0, r7, 4, 4
lit:
	lbbo	&r0, r2, L_ROW, 4
	add	r0, r0, 4
	sbbo	&r0, r2, L_ROW, 4
	lbbo	&r1, r2, L_ROWS4, 4
	qbne	row, r0, r1
	lbbo	&r0, r2, L_PLANE, 4
	add	r0, r0, 4
	sbbo	&r0, r2, L_PLANE, 4
	lbbo	&r1, r2, L_PLANES4, 4
	qbne	plane, r0, r1
	jmp	refresh

done:
	lbbo	&r0, r2, L_OEM, 4
	sbbo	&r0, r7, 4, 4				/* dark */
	lbbo	&r3, r2, 0, SAVED
	add	r2, r2, FRAME
	jmp	r3.w2
