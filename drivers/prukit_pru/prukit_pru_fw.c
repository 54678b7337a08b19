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
#include <linux/remoteproc.h>
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
 * prukit_pru_fw_irq_map() - a firmware's .pru_irq_map section
 * @elf: the firmware file
 * @size: its size
 * @entries: set to the map's first entry in @elf, NULL if the file has no
 *	such section; each entry is 3 bytes: system event, channel, host
 * @count: set to the number of entries (0 without the section)
 *
 * Return: 0, or -EINVAL for a file that is no little-endian ELF32 image,
 * whose section table is not one this reader and the PRU remoteproc driver
 * read alike (40-byte entries, every name inside the string table), or
 * whose map is malformed (the PRU remoteproc driver's checks: type 0, a
 * size of exactly its entries).
 */
int prukit_pru_fw_irq_map(const u8 *elf, size_t size, const u8 **entries,
			  unsigned int *count)
{
	const u8 *sh, *strtab, *map;
	u32 shoff, str_off, str_size, i;
	u16 shentsize, shnum, shstrndx;

	*entries = NULL;
	*count = 0;
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
		u32 name, off, len;

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
		*entries = map + FW_IRQ_MAP_HDR;
		*count = map[1];
		return 0;
	}
	return 0;
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
 * as prukit_pru_fw_irq_map().
 */
int prukit_pru_fw_irq_events(const u8 *elf, size_t size, u64 *events)
{
	const u8 *map;
	unsigned int n, count;
	int ret;

	*events = 0;
	ret = prukit_pru_fw_irq_map(elf, size, &map, &count);
	if (ret)
		return ret;
	for (n = 0; n < count; n++) {
		u8 ev = map[FW_IRQ_MAP_ENTRY * n];

		if (ev < 64)
			*events |= BIT_ULL(ev);
	}
	return 0;
}

/**
 * prukit_pru_fw_rpmsg_events() - the system events rpmsg uses, by a
 *	firmware's .pru_irq_map
 * @map: the map's entries (prukit_pru_fw_irq_map())
 * @count: their number
 * @kick: set to the map's first entry: the ARM -> PRU event
 * @vring: set to the first entry routed to a host the ARM receives
 *	(2..9): the PRU -> ARM event; its event is -1 if there is none
 *
 * The convention of TI's PRU support package and its kernels: their
 * pru_rproc kicks by raising the event of the map's first entry, and the
 * firmware waits for it on host 0 or 1 (its R31 bits 30 and 31).
 *
 * Return: 0, or -ENOENT if the map has no first entry routed to host 0 or 1
 * (then nothing the ARM raises would reach the PRU).
 */
int prukit_pru_fw_rpmsg_events(const u8 *map, unsigned int count,
			       struct prukit_pru_fw_irq *kick,
			       struct prukit_pru_fw_irq *vring)
{
	unsigned int n;

	vring->event = -1;
	if (!count || map[2] > 1)
		return -ENOENT;
	kick->event = map[0];
	kick->channel = map[1];
	kick->host = map[2];
	for (n = 1; n < count; n++) {
		const u8 *e = map + FW_IRQ_MAP_ENTRY * n;

		if (e[2] >= 2 && e[2] <= 9) {
			vring->event = e[0];
			vring->channel = e[1];
			vring->host = e[2];
			break;
		}
	}
	return 0;
}

/**
 * prukit_pru_kick_choose() - whether a PRU remote processor needs
 *	prukit_pru_kick
 * @ops: the processor's operations (struct rproc's ops)
 *
 * Decided by what the processor has, never by the kernel's version: TI's
 * pru_rproc (5.10-ti, 6.1-ti, 6.6+) has a kick and requests its "vring"
 * interrupt itself; mainline's (6.4+, and what prukit builds for Debian's
 * kernels) has neither, and remoteproc then refuses every firmware with a
 * vdev (".kick method not defined").
 *
 * Return: what to do with it.
 */
enum prukit_pru_kick_choice prukit_pru_kick_choose(const struct rproc_ops *ops)
{
	return ops->kick ? PRUKIT_PRU_KICK_ASIDE : PRUKIT_PRU_KICK_GIVE;
}
