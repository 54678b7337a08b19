/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * hub75 firmware: the refresh loop (hub75_proto.h has the protocol).
 *
 *   void hub75_scan(volatile struct hub75_ctrl *c, uint32_t command);
 *
 * Shows the blocks of the frame buffer c->show names, one after the other,
 * refresh after refresh, until c->hdr.command is no longer @command (looked
 * at before each plane).  Per block: clock the row in, latch it with the
 * row's address, light it for the plane's c->oe_cycles.  OE is high (dark)
 * from the end of one lit period to the start of the next, so data, latch
 * and address never change while a row is lit.
 *
 * Clocking a row, data on R30 (HUB75_DATA_R30), per pixel:
 *
 *	mov r30.b0, data	clock low, the pixel's data
 *	delay c->clk_delay	loop over a nop: 1 + clk_delay cycles
 *	or r30.b0, data, clk	clock high: the panel takes the data
 *	delay c->clk_delay
 *
 * 4 + 2 * clk_delay cycles, half high, the data steady 2 + clk_delay
 * cycles either side of the rising edge.  Every 32 pixels the next 32
 * bytes come from DDR (lbbo, about 51 cycles, the clock held high).
 *
 * Data on a GPIO bank (HUB75_DATA_GPIO), per pixel: the bank's CLEARDATAOUT
 * gets the data pins that must be 0, SETDATAOUT those that must be 1.  The
 * bank takes a write every 8 cycles and each lands 17 cycles after it was
 * taken (prusim's model of the L4 path, Documentation/prusim.rst), so a
 * pixel takes 16 cycles and its data is steady from 9 to 17 cycles after
 * the next pixel's CLEARDATAOUT was taken: the clock rises for pixel n in
 * pixel n + 1's time, 12 cycles after that write was taken (3 after the
 * data landed, 5 before it goes), and falls at the next pixel's clear.
 * The row's first pixel raises no clock (r29 = 0), and after its last
 * one the clock rises once more when that pixel's data has landed.
 *
 * Lighting a row for T cycles (T = c->oe_cycles of the plane): OE low for
 * exactly T cycles: "clr r30, oe" ... "set r30, oe" T cycles apart (a
 * loop of T - 2 nops for T >= 4, straight code for 1..3, nothing for 0).
 *
 * GCC's PRU ABI: the arguments in r14, r15; r0, r1 and r14..r29 are the
 * caller's; r4..r13 are saved on the stack here; r3.w2 is the return
 * address.
 *
 * Registers:
 *   r0, r1	scratch (GPIO: the set and clear words)
 *   r4		GPIO: the bank's address + CLEARDATAOUT (SETDATAOUT is + 4)
 *   r5		GPIO: the data pins' mask
 *   r6		~ address lines' mask
 *   r7		rows * 4 (end of the row offsets)
 *   r8		planes * 4 (end of the plane offsets)
 *   r9		bytes per block
 *   r10	b0 clock bit, b1 latch bit, b2 OE bit, b3 GPIO shift
 *   r11	w0 clock delay, b2 the clock's mask in R30.b0, b3 data mode
 *   r12	IEP count at the start of the refresh
 *   r13	1 << clock bit
 *   r14	&ctrl
 *   r15	the command that started the refresh
 *   r16..r23	32 bytes of a block
 *   r24	the next byte of the frame buffer
 *   r25	end of the block
 *   r26	the plane's OE cycles
 *   r27	plane offset * 4
 *   r28	row offset * 4
 *   r29	GPIO: the clock mask to raise (0 for a row's first pixel)
 */
#include "hub75_proto.h"

#define CTRL_COMMAND	8
#define IEP_COUNT	0x0c	/* in the IEP's registers, constant table entry 26 */
#define SAVED		40	/* r4..r13 on the stack */

/* One pixel, data on R30: @reg is its byte */
	.macro	RPIX reg
	mov	r30.b0, \reg
	loop	1f, r11.w0
	nop
1:
	or	r30.b0, \reg, r11.b2
	loop	2f, r11.w0
	nop
2:
	.endm

/* One pixel, data on a GPIO bank: @reg is its half word */
	.macro	GPIX reg
	lsl	r0, \reg, r10.b3
	xor	r1, r0, r5
	sbbo	&r1, r4, 0, 4
	clr	r30, r30, r10.b0
	sbbo	&r0, r4, 4, 4
	nop
	nop
	nop
	or	r30, r30, r29
	mov	r29, r13
	.endm

	.section .text.hub75_scan, "ax", @progbits
	.global	hub75_scan
hub75_scan:
	sub	r2, r2, SAVED
	sbbo	&r4, r2, 0, SAVED

	/* the parameters */
	lbbo	&r4, r14, HUB75_CTRL_GPIO_BASE, 12	/* r4 bank, r5 mask, r6 addr */
	ldi	r0, HUB75_GPIO_CLEARDATAOUT
	add	r4, r4, r0
	not	r6, r6
	lbbo	&r16, r14, HUB75_CTRL_ROW_BYTES, 12	/* r16 bytes, rows; r17, r18 */
	mov	r9, r16.w0
	lsl	r7, r16.w2, 2
	lsl	r8, r17.b1, 2				/* planes */
	mov	r10.b0, r17.b2				/* clock */
	mov	r10.b1, r17.b3				/* latch */
	mov	r10.b2, r18.b0				/* OE */
	mov	r10.b3, r18.b1				/* GPIO shift */
	mov	r11.w0, r18.b2				/* clock delay */
	mov	r11.b3, r17.b0				/* data mode */
	ldi	r13, 1
	lsl	r13, r13, r10.b0
	mov	r11.b2, r13.b0
	set	r30, r30, r10.b2			/* dark */
	clr	r30, r30, r10.b1
	lbco	&r12, 26, IEP_COUNT, 4

refresh:
	/* the buffer to show */
	lbbo	&r0, r14, HUB75_CTRL_SHOW, 4
	and	r0, r0, 1
	sbbo	&r0, r14, HUB75_CTRL_SHOWN, 4
	lsl	r0, r0, 2
	add	r0, r0, HUB75_CTRL_BUF_ADDR
	lbbo	&r24, r14, r0, 4
	/* count it; the previous one's length */
	lbbo	&r0, r14, HUB75_CTRL_REFRESHES, 4
	lbco	&r1, 26, IEP_COUNT, 4
	qbeq	1f, r0, 0
	sub	r16, r1, r12
	sbbo	&r16, r14, HUB75_CTRL_REFRESH_CYCLES, 4
1:
	mov	r12, r1
	add	r0, r0, 1
	sbbo	&r0, r14, HUB75_CTRL_REFRESHES, 4
	ldi	r27, 0

plane:
	lbbo	&r0, r14, CTRL_COMMAND, 4
	qbne	done, r0, r15
	ldi	r0, HUB75_CTRL_OE_CYCLES
	add	r0, r0, r27
	lbbo	&r26, r14, r0, 4
	ldi	r28, 0

row:
	add	r25, r24, r9
	qbbs	gpio_row, r11.b3, 0

r30_chunk:
	lbbo	&r16, r24, 0, HUB75_CHUNK_BYTES
	add	r24, r24, HUB75_CHUNK_BYTES
	RPIX	r16.b0
	RPIX	r16.b1
	RPIX	r16.b2
	RPIX	r16.b3
	RPIX	r17.b0
	RPIX	r17.b1
	RPIX	r17.b2
	RPIX	r17.b3
	RPIX	r18.b0
	RPIX	r18.b1
	RPIX	r18.b2
	RPIX	r18.b3
	RPIX	r19.b0
	RPIX	r19.b1
	RPIX	r19.b2
	RPIX	r19.b3
	RPIX	r20.b0
	RPIX	r20.b1
	RPIX	r20.b2
	RPIX	r20.b3
	RPIX	r21.b0
	RPIX	r21.b1
	RPIX	r21.b2
	RPIX	r21.b3
	RPIX	r22.b0
	RPIX	r22.b1
	RPIX	r22.b2
	RPIX	r22.b3
	RPIX	r23.b0
	RPIX	r23.b1
	RPIX	r23.b2
	RPIX	r23.b3
	qbne	r30_chunk, r24, r25
	jmp	latch

gpio_row:
	ldi	r29, 0
gpio_chunk:
	lbbo	&r16, r24, 0, HUB75_CHUNK_BYTES
	add	r24, r24, HUB75_CHUNK_BYTES
	GPIX	r16.w0
	GPIX	r16.w2
	GPIX	r17.w0
	GPIX	r17.w2
	GPIX	r18.w0
	GPIX	r18.w2
	GPIX	r19.w0
	GPIX	r19.w2
	GPIX	r20.w0
	GPIX	r20.w2
	GPIX	r21.w0
	GPIX	r21.w2
	GPIX	r22.w0
	GPIX	r22.w2
	GPIX	r23.w0
	GPIX	r23.w2
	qbne	gpio_chunk, r24, r25
	/*
	 * The last pixel's clock.  Its CLEARDATAOUT was taken at cycle a, its
	 * SETDATAOUT lands at a + 25; the loop above branched back at a + 14.
	 * Clock low at a + 17 (high from a + 12), high at a + 28.
	 */
	nop
	nop
	clr	r30, r30, r10.b0
	ldi	r0, 8
	loop	1f, r0.w0
	nop
1:
	or	r30, r30, r13
	nop
	nop
	nop
	nop
	clr	r30, r30, r10.b0

latch:
	set	r30, r30, r10.b1
	ldi	r0, HUB75_CTRL_ROW_ADDR
	add	r0, r0, r28
	lbbo	&r0, r14, r0, 4
	and	r30, r30, r6
	or	r30, r30, r0
	clr	r30, r30, r10.b1

	/* light the rows for r26 cycles */
	qbeq	lit, r26, 0
	qbgt	short, r26, 4			/* 4 > r26 */
	sub	r0, r26, 2
	clr	r30, r30, r10.b2
	loop	1f, r0.w0
	nop
1:
	set	r30, r30, r10.b2
	jmp	lit
short:
	qbeq	short1, r26, 1
	qbeq	short2, r26, 2
	clr	r30, r30, r10.b2
	nop
	nop
	set	r30, r30, r10.b2
	jmp	lit
short2:
	clr	r30, r30, r10.b2
	nop
	set	r30, r30, r10.b2
	jmp	lit
short1:
	clr	r30, r30, r10.b2
	set	r30, r30, r10.b2
lit:
	add	r28, r28, 4
	qbne	row, r28, r7
	add	r27, r27, 4
	qbne	plane, r27, r8
	jmp	refresh

done:
	set	r30, r30, r10.b2			/* dark */
	lbbo	&r4, r2, 0, SAVED
	add	r2, r2, SAVED
	jmp	r3.w2
