// SPDX-License-Identifier: GPL-2.0-only
/*
 * prukit_pru - what the layer reads from a PRU firmware file itself
 *
 * The PRU remoteproc driver maps every system event of a firmware's
 * ".pru_irq_map" section when the core starts and disposes of the mappings
 * when it stops.  An event that a consumer's own node maps as its
 * interrupt has the same Linux interrupt, which that disposal would tear
 * down under the consumer's handler; the layer reads the section first to
 * refuse such firmware (prukit_pru_boot()).  No kernel interface exposes
 * it, so this parses the ELF file: GNU pru-gcc's and TI's PRU images are
 * ELF32, little-endian.
 */
#include <linux/bits.h>
#include <linux/elf.h>
#include <linux/errno.h>
#include <linux/string.h>

#include "prukit_pru_fw.h"

/* ELF32 header and section header fields (offsets in bytes) */
#define FW_E_SHOFF		32
#define FW_E_SHENTSIZE		46
#define FW_E_SHNUM		48
#define FW_E_SHSTRNDX		50
#define FW_EHDR_SIZE		52
#define FW_SH_NAME		0
#define FW_SH_OFFSET		16
#define FW_SH_SIZE		20
#define FW_SHDR_SIZE		40

/* .pru_irq_map: u8 type (0), u8 count, then count x { u8 event, channel, host } */
#define FW_IRQ_MAP_HDR		2
#define FW_IRQ_MAP_ENTRY	3

static u32 fw_le32(const u8 *p)
{
	return p[0] | p[1] << 8 | p[2] << 16 | (u32)p[3] << 24;
}

static u16 fw_le16(const u8 *p)
{
	return p[0] | p[1] << 8;
}

/**
 * prukit_pru_fw_irq_events() - the system events a firmware's
 *	.pru_irq_map section maps
 * @elf: the firmware file
 * @size: its size
 * @events: set to the events (bit N: system event N, 0..63)
 *
 * Only system events 0..63 exist on the AM335x's INTC; a map's entry above
 * that is no event of it (and the PRU remoteproc driver fails to map it).
 *
 * Return: 0 (with *@events 0 if the file has no such section), or -EINVAL
 * for a file that is no little-endian ELF32 image, whose section table is
 * not one this reader and the PRU remoteproc driver read alike (40-byte
 * entries, every name inside the string table), or whose map is malformed.
 */
int prukit_pru_fw_irq_events(const u8 *elf, size_t size, u64 *events)
{
	const u8 *sh, *strtab, *map;
	u32 shoff, str_off, str_size, i;
	u16 shentsize, shnum, shstrndx;

	*events = 0;
	if (size < FW_EHDR_SIZE || memcmp(elf, ELFMAG, SELFMAG) ||
	    elf[EI_CLASS] != ELFCLASS32 || elf[EI_DATA] != ELFDATA2LSB)
		return -EINVAL;
	shoff = fw_le32(elf + FW_E_SHOFF);
	shentsize = fw_le16(elf + FW_E_SHENTSIZE);
	shnum = fw_le16(elf + FW_E_SHNUM);
	shstrndx = fw_le16(elf + FW_E_SHSTRNDX);
	if (!shnum)
		return 0;
	/* pru_rproc walks the table in steps of sizeof(struct elf32_shdr) */
	if (shentsize != FW_SHDR_SIZE || shstrndx >= shnum || shoff > size ||
	    (u64)shnum * shentsize > size - shoff)
		return -EINVAL;

	sh = elf + shoff + (size_t)shstrndx * shentsize;
	str_off = fw_le32(sh + FW_SH_OFFSET);
	str_size = fw_le32(sh + FW_SH_SIZE);
	if (str_off > size || str_size > size - str_off)
		return -EINVAL;
	strtab = elf + str_off;

	for (i = 0; i < shnum; i++) {
		u32 name, off, len, n;

		sh = elf + shoff + (size_t)i * shentsize;
		name = fw_le32(sh + FW_SH_NAME);
		/* pru_rproc would compare a name out of bounds: refuse */
		if (name >= str_size || !memchr(strtab + name, 0, str_size - name))
			return -EINVAL;
		if (strcmp(strtab + name, ".pru_irq_map"))
			continue;
		off = fw_le32(sh + FW_SH_OFFSET);
		len = fw_le32(sh + FW_SH_SIZE);
		if (off > size || len > size - off || len < FW_IRQ_MAP_HDR)
			return -EINVAL;
		map = elf + off;
		/* as pru_rproc checks it: type 0, exactly its entries */
		if (map[0] || len != FW_IRQ_MAP_HDR + FW_IRQ_MAP_ENTRY * map[1])
			return -EINVAL;
		for (n = 0; n < map[1]; n++) {
			u8 ev = map[FW_IRQ_MAP_HDR + FW_IRQ_MAP_ENTRY * n];

			if (ev < 64)
				*events |= BIT_ULL(ev);
		}
		return 0;
	}
	return 0;
}
