/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The test port's registers: what the QEMU PRU-ICSS (qemu/am335x_pruss.c)
 * offers its guest beyond the board, and what the guest's prusim_port driver
 * (tests/kmod/prusim_port.c) reads and writes.  One register block and one
 * buffer both sides read and write; the files behind the commands, their
 * formats and errors: Documentation/qemu-pruss.rst.
 *
 * A command is one 32-bit write of PRUSIM_TEST_PORT_CMD(op, file, handle) to
 * CMD after the request's length went to LEN; it runs to completion while
 * the write traps, then STATUS holds 0 or a positive errno and LEN the
 * reply's length.  A new version number means a change both sides make.
 */
#ifndef _PRUSIM_PORT_H
#define _PRUSIM_PORT_H

#define PRUSIM_TEST_PORT_ID		0x4d535250	/* "PRSM" */
#define PRUSIM_TEST_PORT_VERSION	1

/* Registers (32-bit) */
#define PRUSIM_TEST_PORT_REG_ID		0x00
#define PRUSIM_TEST_PORT_REG_VERSION	0x04
#define PRUSIM_TEST_PORT_REG_CMD	0x08
#define PRUSIM_TEST_PORT_REG_STATUS	0x0c
#define PRUSIM_TEST_PORT_REG_LEN	0x10	/* request, then reply */
#define PRUSIM_TEST_PORT_REG_BUFSIZE	0x14
#define PRUSIM_TEST_PORT_REG_HANDLE	0x18	/* what OPEN returned */

/* Commands */
#define PRUSIM_TEST_PORT_OP_LIST	1	/* -> "name mode kind" lines */
#define PRUSIM_TEST_PORT_OP_READ	2	/* file -> its content */
#define PRUSIM_TEST_PORT_OP_WRITE	3	/* file, LEN bytes -> (error text) */
#define PRUSIM_TEST_PORT_OP_OPEN	4	/* file (staged) -> HANDLE */
#define PRUSIM_TEST_PORT_OP_APPEND	5	/* handle, LEN bytes -> (error text) */
#define PRUSIM_TEST_PORT_OP_CLOSE	6	/* handle: install what was written */
#define PRUSIM_TEST_PORT_OP_DROP	7	/* handle: forget what was written */

#define PRUSIM_TEST_PORT_CMD(op, file, handle) \
	((op) | (file) << 8 | (handle) << 16)
#define PRUSIM_TEST_PORT_CMD_OP(cmd)		((cmd) & 0xff)
#define PRUSIM_TEST_PORT_CMD_FILE(cmd)		(((cmd) >> 8) & 0xff)
#define PRUSIM_TEST_PORT_CMD_HANDLE(cmd)	((cmd) >> 16)

#endif /* _PRUSIM_PORT_H */
