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
#include <linux/kernel.h>
#include <linux/remoteproc.h>
#include <linux/sizes.h>
#include <linux/slab.h>
#include <linux/string.h>

#include "prukit_pru_fw.h"

/* ELF32 header, program header and section header fields (offsets in bytes) */
#define FW_E_PHOFF		28
#define FW_E_PHENTSIZE		42
#define FW_E_PHNUM		44
#define FW_E_SHOFF		32
#define FW_E_SHENTSIZE		46
#define FW_E_SHNUM		48
#define FW_E_SHSTRNDX		50
#define FW_EHDR_SIZE		52
#define FW_SH_NAME		0
#define FW_SH_OFFSET		16
#define FW_SH_SIZE		20
#define FW_SH_TYPE		4
#define FW_SH_ADDRALIGN		32
#define FW_SHDR_SIZE		40
#define FW_P_TYPE		0
#define FW_P_OFFSET		4
#define FW_P_PADDR		12
#define FW_P_FILESZ		16
#define FW_P_FLAGS		24
#define FW_PHDR_SIZE		32

/* .pru_irq_map: u8 type (0), u8 count, then count x { u8 event, channel, host } */
#define FW_IRQ_MAP_HDR		2
#define FW_IRQ_MAP_ENTRY	3

/*
 * The resource table (remoteproc's struct resource_table): u32 version (1),
 * u32 count, 8 reserved bytes, then count u32 offsets of the resources,
 * each starting with its u32 type.
 */
#define FW_RSC_HDR		16
#define FW_RSC_VERSION		1

/*
 * The interrupt resource of the PRU Software Support Package's releases for
 * TI's 4.x kernels (its rsc_types.h and pru_types.h): type 5 (TYPE_CUSTOM),
 * u32 sub_type 1 (TYPE_PRU_INTS), u32 size of what follows (20), u16
 * version, u8 channel_host[10] (the host of each INTC channel, 255 for
 * none), u32 num_evts, and u32 event_channel: the firmware's own data
 * address of num_evts { u8 event, u8 channel } pairs.
 */
#define FW_SSP_TYPE		5
#define FW_SSP_PRU_INTS		1
#define FW_SSP_SUB_TYPE		4
#define FW_SSP_BODY_SIZE	8
#define FW_SSP_CHANNEL_HOST	14
#define FW_SSP_NUM_EVTS		24
#define FW_SSP_EVENT_CHANNEL	28
#define FW_SSP_SIZE		32
#define FW_SSP_BODY		20
#define FW_SSP_NO_HOST		255

static u32 fw_le32(const u8 *p)
{
	return p[0] | p[1] << 8 | p[2] << 16 | (u32)p[3] << 24;
}

static u16 fw_le16(const u8 *p)
{
	return p[0] | p[1] << 8;
}

static void fw_put32(u8 *p, u32 v)
{
	p[0] = v;
	p[1] = v >> 8;
	p[2] = v >> 16;
	p[3] = v >> 24;
}

static void fw_put16(u8 *p, u16 v)
{
	p[0] = v;
	p[1] = v >> 8;
}

/*
 * Find the section named @want: its offset and size in the file, both
 * inside it.  Returns 0, -ENOENT if there is none, or -EINVAL for a file
 * that is no little-endian ELF32 image, or whose section table is not one
 * this reader and the PRU remoteproc driver read alike (40-byte entries,
 * every name inside the string table).
 */
static int fw_section(const u8 *elf, size_t size, const char *want, u32 *offset, u32 *length)
{
	const u8 *sh, *strtab;
	u32 shoff, str_off, str_size, i;
	u16 shentsize, shnum, shstrndx;

	if (size < FW_EHDR_SIZE || memcmp(elf, ELFMAG, SELFMAG) ||
	    elf[EI_CLASS] != ELFCLASS32 || elf[EI_DATA] != ELFDATA2LSB)
		return -EINVAL;
	shoff = fw_le32(elf + FW_E_SHOFF);
	shentsize = fw_le16(elf + FW_E_SHENTSIZE);
	shnum = fw_le16(elf + FW_E_SHNUM);
	shstrndx = fw_le16(elf + FW_E_SHSTRNDX);
	if (!shnum)
		return -ENOENT;
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
		if (strcmp(strtab + name, want))
			continue;
		off = fw_le32(sh + FW_SH_OFFSET);
		len = fw_le32(sh + FW_SH_SIZE);
		if (off > size || len > size - off)
			return -EINVAL;
		*offset = off;
		*length = len;
		return 0;
	}
	return -ENOENT;
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
	const u8 *map;
	u32 off, len;
	int ret;

	*entries = NULL;
	*count = 0;
	ret = fw_section(elf, size, ".pru_irq_map", &off, &len);
	if (ret)
		return ret == -ENOENT ? 0 : ret;
	if (len < FW_IRQ_MAP_HDR)
		return -EINVAL;
	map = elf + off;
	/* as pru_rproc checks it: type 0, exactly its entries */
	if (map[0] || len != FW_IRQ_MAP_HDR + FW_IRQ_MAP_ENTRY * map[1])
		return -EINVAL;
	*entries = map + FW_IRQ_MAP_HDR;
	*count = map[1];
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

		if (ev < PRUKIT_INTC_EVENTS)
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

		if (e[2] >= PRUKIT_INTC_HOST_ARM_FIRST && e[2] <= PRUKIT_INTC_HOST_LAST) {
			vring->event = e[0];
			vring->channel = e[1];
			vring->host = e[2];
			break;
		}
	}
	return 0;
}

/*
 * The @len bytes at the firmware's own data address @da, from a loadable
 * segment that holds them in the file (as pru_rproc loads it: at p_paddr),
 * or NULL.
 */
static const u8 *fw_data_at(const u8 *elf, size_t size, u32 da, u32 len)
{
	u32 phoff = fw_le32(elf + FW_E_PHOFF), i;
	u16 phentsize = fw_le16(elf + FW_E_PHENTSIZE);
	u16 phnum = fw_le16(elf + FW_E_PHNUM);

	if (phentsize != FW_PHDR_SIZE || phoff > size ||
	    (u64)phnum * phentsize > size - phoff)
		return NULL;
	for (i = 0; i < phnum; i++) {
		const u8 *ph = elf + phoff + (size_t)i * phentsize;
		u32 off = fw_le32(ph + FW_P_OFFSET);
		u32 paddr = fw_le32(ph + FW_P_PADDR);
		u32 filesz = fw_le32(ph + FW_P_FILESZ);

		if (fw_le32(ph + FW_P_TYPE) != PT_LOAD || fw_le32(ph + FW_P_FLAGS) & PF_X)
			continue;
		if (off > size || filesz > size - off)
			continue;
		if (da >= paddr && da - paddr <= filesz && len <= filesz - (da - paddr))
			return elf + off + (da - paddr);
	}
	return NULL;
}

/**
 * prukit_pru_fw_ssp_irq_map() - a .pru_irq_map made of a firmware's older
 *	interrupt resource
 * @elf: the firmware file
 * @size: its size
 * @map: filled with the map, as a .pru_irq_map section holds it (at most
 *	PRUKIT_PRU_FW_IRQ_MAP_MAX bytes)
 * @len: set to its length
 *
 * The PRU Software Support Package's releases for TI's 4.x kernels (those
 * the PRU Cookbook's rpmsg examples were built with) describe the INTC
 * routing in the resource table, as a type 5 resource, where later
 * kernels read a .pru_irq_map section; no kernel since reads it.  This
 * reads it into the newer form: each event with its channel and that
 * channel's host.  The events routed to host 0 or 1 (the PRUs') come first,
 * in the resource's order, then the others: TI's pru_rproc kicks the core
 * by raising the event of the map's first entry, and the older resource
 * had no order.
 *
 * Return: 0; -ENOENT if the firmware has no resource table or no such
 * resource in it; -EINVAL for a malformed one (a resource beyond the table,
 * more than 64 events, an event above 63 or a channel above 9, a channel
 * without a host, pairs not in the firmware's loaded data) or an ELF file
 * prukit_pru_fw_irq_map() refuses.
 */
int prukit_pru_fw_ssp_irq_map(const u8 *elf, size_t size, u8 *map, size_t *len)
{
	const u8 *rsc, *r, *pairs;
	u32 off, rsc_len, num, i, n, count;
	unsigned int pass;
	int ret;

	ret = fw_section(elf, size, ".resource_table", &off, &rsc_len);
	if (ret)
		return ret;
	rsc = elf + off;
	if (rsc_len < FW_RSC_HDR || fw_le32(rsc) != FW_RSC_VERSION)
		return -EINVAL;
	num = fw_le32(rsc + 4);
	if (num > (rsc_len - FW_RSC_HDR) / 4)
		return -EINVAL;
	for (i = 0, r = NULL; i < num && !r; i++) {
		u32 at = fw_le32(rsc + FW_RSC_HDR + 4 * i);

		if (at > rsc_len || rsc_len - at < 4)
			return -EINVAL;
		if (fw_le32(rsc + at) != FW_SSP_TYPE)
			continue;
		if (rsc_len - at < FW_SSP_SIZE)
			return -EINVAL;
		if (fw_le32(rsc + at + FW_SSP_SUB_TYPE) == FW_SSP_PRU_INTS)
			r = rsc + at;
	}
	if (!r)
		return -ENOENT;
	if (fw_le32(r + FW_SSP_BODY_SIZE) < FW_SSP_BODY)
		return -EINVAL;
	count = fw_le32(r + FW_SSP_NUM_EVTS);
	if (count > PRUKIT_INTC_EVENTS)
		return -EINVAL;
	pairs = fw_data_at(elf, size, fw_le32(r + FW_SSP_EVENT_CHANNEL), 2 * count);
	if (!pairs && count)
		return -EINVAL;

	map[0] = 0;
	map[1] = count;
	n = 0;
	for (pass = 0; pass < 2; pass++) {
		for (i = 0; i < count; i++) {
			u8 ev = pairs[2 * i], ch = pairs[2 * i + 1], host;
			u8 *e = map + FW_IRQ_MAP_HDR + FW_IRQ_MAP_ENTRY * n;
			bool to_pru;

			if (ev >= PRUKIT_INTC_EVENTS || ch >= PRUKIT_INTC_CHANNELS)
				return -EINVAL;
			host = r[FW_SSP_CHANNEL_HOST + ch];
			if (host == FW_SSP_NO_HOST || host > PRUKIT_INTC_HOST_LAST)
				return -EINVAL;
			/* first pass: to the PRUs; second: the rest */
			to_pru = host < PRUKIT_INTC_HOST_ARM_FIRST;
			if (to_pru == !!pass)
				continue;
			e[0] = ev;
			e[1] = ch;
			e[2] = host;
			n++;
		}
	}
	*len = FW_IRQ_MAP_HDR + FW_IRQ_MAP_ENTRY * count;
	return 0;
}

/**
 * prukit_pru_fw_add_irq_map() - a copy of a firmware file with a
 *	.pru_irq_map section
 * @elf: the firmware file, which prukit_pru_fw_irq_map() reads without error
 * @size: its size
 * @map: the section's contents
 * @map_len: their length
 * @copy_size: set to the copy's size
 *
 * The copy is the file, then the map, a section name string table with
 * ".pru_irq_map" added, and the section table with an entry for the map;
 * the ELF header points to the new table.  Nothing the file had moves:
 * its segments and sections read as before.
 *
 * Return: the copy, to be freed with kvfree(), or NULL if there is no
 * memory for it or the file is too large (16 MiB) or has too many sections.
 */
u8 *prukit_pru_fw_add_irq_map(const u8 *elf, size_t size, const u8 *map, size_t map_len,
			      size_t *copy_size)
{
	static const char name[] = ".pru_irq_map";
	u32 shoff = fw_le32(elf + FW_E_SHOFF), str_off, str_size;
	u16 shnum = fw_le16(elf + FW_E_SHNUM), shstrndx = fw_le16(elf + FW_E_SHSTRNDX);
	size_t map_at, str_at, sh_at, total;
	const u8 *strtab_sh;
	u8 *copy, *sh;

	/* what prukit_pru_fw_irq_map() checked; a table is needed for the name */
	if (size > SZ_16M || map_len > SZ_4K || !shnum || shnum >= SHN_LORESERVE - 1)
		return NULL;
	strtab_sh = elf + shoff + (size_t)shstrndx * FW_SHDR_SIZE;
	str_off = fw_le32(strtab_sh + FW_SH_OFFSET);
	str_size = fw_le32(strtab_sh + FW_SH_SIZE);

	map_at = ALIGN(size, 4);
	str_at = map_at + map_len;
	sh_at = ALIGN(str_at + str_size + sizeof(name), 4);
	total = sh_at + ((size_t)shnum + 1) * FW_SHDR_SIZE;
	copy = kvzalloc(total, GFP_KERNEL);
	if (!copy)
		return NULL;
	memcpy(copy, elf, size);
	memcpy(copy + map_at, map, map_len);
	memcpy(copy + str_at, elf + str_off, str_size);
	memcpy(copy + str_at + str_size, name, sizeof(name));
	memcpy(copy + sh_at, elf + shoff, (size_t)shnum * FW_SHDR_SIZE);

	/* the string table's entry: the new table */
	sh = copy + sh_at + (size_t)shstrndx * FW_SHDR_SIZE;
	fw_put32(sh + FW_SH_OFFSET, str_at);
	fw_put32(sh + FW_SH_SIZE, str_size + sizeof(name));
	/* the map's entry, PROGBITS not loaded, as pru-ld and TI's linker write it */
	sh = copy + sh_at + (size_t)shnum * FW_SHDR_SIZE;
	fw_put32(sh + FW_SH_NAME, str_size);
	fw_put32(sh + FW_SH_TYPE, SHT_PROGBITS);
	fw_put32(sh + FW_SH_OFFSET, map_at);
	fw_put32(sh + FW_SH_SIZE, map_len);
	fw_put32(sh + FW_SH_ADDRALIGN, 1);

	fw_put32(copy + FW_E_SHOFF, sh_at);
	fw_put16(copy + FW_E_SHNUM, shnum + 1);
	*copy_size = total;
	return copy;
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
