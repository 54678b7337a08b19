/* SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause */
/*
 * The control block: how a prukit driver and its PRU firmware talk without
 * any interrupt towards the PRU.
 *
 * Shared verbatim by kernel drivers (through prukit_pru.h) and PRU firmware.
 * The block lives in the core's own data RAM at PRUKIT_CTRL_DA (the linker
 * script puts the section .prukit_ctrl there).  It starts with this header;
 * a driver's protocol header appends its own fields.  Every field is
 * fixed-width and little-endian (both the ARM and the PRU are); the block
 * is packed, yet 4-byte aligned (__packed __aligned(4), also on a driver's
 * own block): the firmware then reads and writes each 32-bit field with one
 * access, so the ARM's writel() of @command is never seen half-written.
 * The firmware image initialises magic, version and size, so that the
 * driver can check them as soon as the image is loaded.
 *
 * Commands (ARM -> PRU): the driver writes the parameters, then @command =
 * opcode | sequence << 16, the sequence one more than the previous one
 * (never 0).  The firmware polls @command; when the sequence changes it
 * does the work and writes @status = PRUKIT_CTRL_READY | result |
 * sequence << 16.  Result 0 means success; other values are the driver's
 * protocol's.  The firmware sets PRUKIT_CTRL_READY (sequence 0) once it
 * polls.  Bulk data moves through DMA buffers whose bus addresses are
 * parameters; PRU -> ARM events are system events that the driver's device
 * tree node maps (never the firmware's .pru_irq_map).
 */
#ifndef _PRUKIT_PRU_CTRL_H
#define _PRUKIT_PRU_CTRL_H

#ifdef __KERNEL__
#include <linux/compiler.h>
#include <linux/types.h>
#else
#include <prukit/kernel_types.h>	/* firmware/include: __u32, __packed ... */
#endif

/* Device address of the control block in the core's own data RAM. */
#define PRUKIT_CTRL_DA			0x0008

#define PRUKIT_CTRL_OPCODE(cmd)		((cmd) & 0xffffu)
#define PRUKIT_CTRL_SEQ(word)		((word) >> 16)
#define PRUKIT_CTRL_CMD(op, seq)	(((__u32)(seq) << 16) | ((op) & 0xffffu))

/* @status: the firmware polls; result (bits 0..14) of command SEQ(status). */
#define PRUKIT_CTRL_READY		0x8000u
#define PRUKIT_CTRL_RESULT(status)	((status) & 0x7fffu)
#define PRUKIT_CTRL_STATUS(seq, result) \
	(((__u32)(seq) << 16) | PRUKIT_CTRL_READY | ((result) & 0x7fffu))

/**
 * struct prukit_ctrl_hdr - first 16 bytes of every control block
 * @magic: identifies the driver's protocol (its protocol header defines it)
 * @version: protocol version; the driver refuses any other
 * @size: bytes of the whole control block (header included)
 * @command: ARM -> PRU, written last: opcode | sequence << 16
 * @status: PRU -> ARM: READY, and the result of the last command
 */
struct prukit_ctrl_hdr {
	__u32 magic;
	__u16 version;
	__u16 size;
	__u32 command;
	__u32 status;
} __packed __aligned(4);

#define PRUKIT_CTRL_HDR_SIZE		16

#endif /* _PRUKIT_PRU_CTRL_H */
