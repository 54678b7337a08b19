/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * hub75_proto.h - the hub75 driver's control block, shared verbatim by the
 * driver (drivers/hub75/hub75_drv.c) and its PRU firmware
 * (firmware/hub75_main.c, hub75_scan.S).
 *
 * One core refreshes a HUB75 panel (or a chain of them) without end, from
 * one of two frame buffers in DDR that the driver prepares:
 *
 *  - A frame buffer holds @units blocks of @row_bytes bytes, in the order
 *    they are shown: block k is address row k % @rows of bit plane
 *    order[k / @rows] (the driver chooses the plane order, see
 *    Documentation/hub75.rst).  A block holds one entry per clock of the
 *    row, in clock order: with HUB75_DATA_R30 a byte, R30's bits 0..7 as
 *    the data pins must be (the clock bit 0); with HUB75_DATA_GPIO a
 *    16-bit word, the GPIO bank's data bits shifted right by @gpio_shift;
 *    with HUB75_DATA_BANKS four 32-bit words, the data bits to set in the
 *    GPIO banks of @bank_addr[0..3] (the others of @bank_mask cleared).
 *  - Per block the firmware clocks the row in (the clock on R30 bit
 *    @clk_bit), raises the latch, puts the row's address lines
 *    (@row_addr[row], within @addr_mask) on R30, lowers the latch, and
 *    lights the row: output enable (@oe_bit, active low) low for exactly
 *    @oe_cycles[block / @rows] cycles, 0 for none.  Outside those cycles
 *    OE is high: rows are never lit while their data or address changes.
 *  - A refresh shows every block once.  At its start the firmware takes
 *    the buffer @show names (0 or 1), writes it to @shown, counts
 *    @refreshes and writes the length of the previous refresh in cycles to
 *    @refresh_cycles.  So once @shown equals what the driver last wrote to
 *    @show, the other buffer is the driver's to fill: a frame is never
 *    shown half old, half new.
 *
 * Commands (struct prukit_ctrl_hdr):
 *  START: checks and takes the parameters, answers, and refreshes until
 *	the next command.  @show, @oe_cycles may change while it runs (@oe_cycles
 *	is read per plane: brightness).
 *	Before its first refresh START clocks in the panel's control register
 *	words (@init, FM6126A-class driver chips), each on every data line:
 *	a row of @row_bytes / entry clocks, bit 15 - (clock % 16) of the word
 *	on the data lines, the latch high for the last @init's LATCH clocks
 *	(the register number), the address lines at @row_addr[1 % @rows], OE
 *	high (dark) throughout.
 *  STOP: ends the refresh, sets OE (@oe_bit) high: the panel goes dark.
 *	The driver sends it once right after loading the firmware too: R30 is
 *	0 when a core starts, so OE is low (lit) until then.
 */
#ifndef _HUB75_PROTO_H
#define _HUB75_PROTO_H

#ifdef __KERNEL__
#include "prukit/pru_ctrl.h"
#elif !defined(__ASSEMBLER__)
#include <prukit/pru_ctrl.h>
#endif

#define HUB75_MAGIC		0x35374248u	/* "HB75" */
#define HUB75_VERSION		2

#define HUB75_MAX_PLANES	12
#define HUB75_MAX_ROWS		32
#define HUB75_CHUNK_BYTES	32	/* @row_bytes is a multiple of this */
#define HUB75_MAX_ROW_BYTES	4096
#define HUB75_MAX_CLK_DELAY	255
#define HUB75_MAX_INIT		4

/* @init[]: a register word and the clocks the latch is high for it */
#define HUB75_INIT(word, latch)	((__u32)(word) | (__u32)(latch) << 16)
#define HUB75_INIT_WORD(v)	((v) & 0xffffu)
#define HUB75_INIT_LATCH(v)	((v) >> 16 & 0xffu)
#define HUB75_INIT_MIN_LATCH	4	/* fewer clocks are a data latch */
#define HUB75_INIT_MAX_LATCH	16

/* @data_mode */
#define HUB75_DATA_R30		0	/* data pins and clock in R30 bits 0..7 */
#define HUB75_DATA_GPIO		1	/* data pins in one GPIO bank */
#define HUB75_DATA_BANKS	2	/* every line on GPIO banks, see below */

/*
 * HUB75_DATA_BANKS: parallel outputs, every line a GPIO pin (the
 * Octoscroller cape).  The control lines are bits of the bank at
 * @gpio_base: @clk_bit, @lat_bit, @oe_bit, the address lines @addr_mask
 * (@row_addr[] are values of that bank).  The data lines are in up to four
 * banks, slots 0..3 of @bank_addr/@bank_mask, slot 3 always @gpio_base's
 * bank with the clock in its @bank_mask; @bank_used has bit k set for a
 * slot in use.  Per clock the firmware writes each used slot's
 * CLEARDATAOUT and SETDATAOUT at once (the entry's word, and @bank_mask
 * without it: the clock falls with slot 3), then the clock's SETDATAOUT.
 */
#define HUB75_BANK_SLOTS	4
#define HUB75_BANK_CTRL_SLOT	3

/* GPIO bank registers the firmware writes (AM335x TRM, chapter 25) */
#define HUB75_GPIO_CLEARDATAOUT	0x190
#define HUB75_GPIO_SETDATAOUT	0x194

/* Opcodes */
#define HUB75_CMD_START		1
#define HUB75_CMD_STOP		2

/* Results */
#define HUB75_OK		0
#define HUB75_EINVAL		1	/* a START parameter out of range */
#define HUB75_EOPCODE		2	/* unknown opcode */

#ifndef __ASSEMBLER__
/**
 * struct hub75_ctrl - the control block, at PRUKIT_CTRL_DA in the core's RAM
 * @hdr: magic HUB75_MAGIC, version HUB75_VERSION, command and status
 * @buf_addr: START: bus addresses of the two frame buffers
 * @gpio_base: START, HUB75_DATA_GPIO: the GPIO bank's (OCP) address
 * @gpio_mask: START, HUB75_DATA_GPIO: the data pins' bits in the bank
 * @addr_mask: START: R30 bits of the address lines
 * @row_bytes: START: bytes of a block, a multiple of HUB75_CHUNK_BYTES,
 *	at most HUB75_MAX_ROW_BYTES
 * @rows: START: address rows (the panel's scan), 1..HUB75_MAX_ROWS
 * @data_mode: START: HUB75_DATA_R30 or HUB75_DATA_GPIO
 * @planes: START: bit planes, 1..HUB75_MAX_PLANES
 * @clk_bit: START: R30 bit of the clock (0..7 with HUB75_DATA_R30)
 * @lat_bit: START: R30 bit of the latch
 * @oe_bit: START: R30 bit of output enable (active low)
 * @gpio_shift: START, HUB75_DATA_GPIO: a block's word << @gpio_shift is
 *	the bank's data bits
 * @clk_delay: START, HUB75_DATA_R30: the clock is 4 + 2 * @clk_delay
 *	cycles per pixel, half of it high; 1..HUB75_MAX_CLK_DELAY
 * @reserved: zero
 * @row_addr: START: R30 value of the address lines for each row
 * @oe_cycles: cycles the rows of the planes are lit, in the order the
 *	planes are shown; read per plane, so it may change while running
 * @show: the buffer (0 or 1) to show from the next refresh on
 * @shown: PRU: the buffer the current refresh shows
 * @refreshes: PRU: refreshes begun since START
 * @refresh_cycles: PRU: cycles the previous refresh took (0 before one did)
 * @init: START: the register words to clock in before the first refresh,
 *	HUB75_INIT(word, latch clocks), in order; the first 0 ends the list
 * @bank_addr: START, HUB75_DATA_BANKS: the GPIO bank of each slot
 * @bank_mask: START, HUB75_DATA_BANKS: the pins the firmware writes there
 * @bank_used: START, HUB75_DATA_BANKS: bit k: slot k is used (bit 3 set)
 * @reserved2: zero
 */
struct hub75_ctrl {
	struct prukit_ctrl_hdr hdr;
	__u32 buf_addr[2];
	__u32 gpio_base;
	__u32 gpio_mask;
	__u32 addr_mask;
	__u16 row_bytes;
	__u16 rows;
	__u8 data_mode;
	__u8 planes;
	__u8 clk_bit;
	__u8 lat_bit;
	__u8 oe_bit;
	__u8 gpio_shift;
	__u8 clk_delay;
	__u8 reserved;
	__u32 row_addr[HUB75_MAX_ROWS];
	__u32 oe_cycles[HUB75_MAX_PLANES];
	__u32 show;
	__u32 shown;
	__u32 refreshes;
	__u32 refresh_cycles;
	__u32 init[HUB75_MAX_INIT];
	__u32 bank_addr[HUB75_BANK_SLOTS];
	__u32 bank_mask[HUB75_BANK_SLOTS];
	__u8 bank_used;
	__u8 reserved2[3];
} __packed __aligned(4);
#endif

/* Offsets the assembler source uses (hub75_main.c checks them) */
#define HUB75_CTRL_BUF_ADDR	16
#define HUB75_CTRL_GPIO_BASE	24
#define HUB75_CTRL_ROW_BYTES	36
#define HUB75_CTRL_DATA_MODE	40
#define HUB75_CTRL_ROW_ADDR	48
#define HUB75_CTRL_OE_CYCLES	(HUB75_CTRL_ROW_ADDR + 4 * HUB75_MAX_ROWS)	/* 176 */
#define HUB75_CTRL_SHOW		(HUB75_CTRL_OE_CYCLES + 4 * HUB75_MAX_PLANES)	/* 224 */
#define HUB75_CTRL_SHOWN	(HUB75_CTRL_SHOW + 4)
#define HUB75_CTRL_REFRESHES	(HUB75_CTRL_SHOW + 8)
#define HUB75_CTRL_REFRESH_CYCLES (HUB75_CTRL_SHOW + 12)
#define HUB75_CTRL_INIT		(HUB75_CTRL_SHOW + 16)
#define HUB75_CTRL_BANK_ADDR	(HUB75_CTRL_INIT + 4 * HUB75_MAX_INIT)	/* 256 */
#define HUB75_CTRL_BANK_MASK	(HUB75_CTRL_BANK_ADDR + 4 * HUB75_BANK_SLOTS)
#define HUB75_CTRL_BANK_USED	(HUB75_CTRL_BANK_MASK + 4 * HUB75_BANK_SLOTS)
#define HUB75_CTRL_SIZE		(HUB75_CTRL_BANK_USED + 4)

#endif /* _HUB75_PROTO_H */
