// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim ELF loader for GNU pru-gcc/pru-ld executables (ELF32, little endian,
 * EM_TI_PRU).  Code segments carry the 0x20000000 IRAM tag; data segments
 * are addresses in the core's local data map (own DRAM at 0, the other
 * core's DRAM at 0x2000, shared RAM at 0x10000).
 */

#include "prusim_priv.h"

#define EM_TI_PRU		144
#define ELF_ET_EXEC		2
#define ELF_PT_LOAD		1
#define ELF_EHDR_SIZE		52
#define ELF_PHDR_SIZE		32
#define ELF_SHDR_SIZE		40
#define IRQ_MAP_ENTRY		3

/**
 * struct prusim_elf - an ELF image being loaded
 * @img: file contents
 * @size: file size
 * @info: results and error text for the caller
 */
struct prusim_elf {
	const u8 *img;
	size_t size;
	struct prusim_elf_info *info;
};

/**
 * struct prusim_seg - one PT_LOAD segment
 * @iram: goes to IRAM
 * @addr: IRAM byte offset, or local data address
 * @data: file contents
 * @filesz: bytes in the file
 * @memsz: bytes in memory (the rest is zeroed)
 */
struct prusim_seg {
	bool iram;
	u32 addr;
	const u8 *data;
	u32 filesz;
	u32 memsz;
};

static __printf(2, 3) int elf_err(struct prusim_elf *e, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(e->info->err, sizeof(e->info->err), fmt, ap);
	va_end(ap);
	return -ENOEXEC;
}

static bool elf_has(const struct prusim_elf *e, u32 off, u32 len)
{
	return off <= e->size && len <= e->size - off;
}

static u32 elf32(const struct prusim_elf *e, u32 off)
{
	return prusim_get_le32(e->img + off);
}

static u16 elf16(const struct prusim_elf *e, u32 off)
{
	return prusim_get_le16(e->img + off);
}

static int elf_check_header(struct prusim_elf *e)
{
	static const u8 magic[4] = { 0x7f, 'E', 'L', 'F' };

	if (e->size < ELF_EHDR_SIZE || memcmp(e->img, magic, sizeof(magic)))
		return elf_err(e, "not an ELF file");
	if (e->img[4] != 1)
		return elf_err(e, "not a 32-bit ELF file (class %u)", e->img[4]);
	if (e->img[5] != 1)
		return elf_err(e, "not a little-endian ELF file");
	if (elf16(e, 18) != EM_TI_PRU)
		return elf_err(e, "ELF machine %u is not TI PRU (144)", elf16(e, 18));
	if (elf16(e, 16) != ELF_ET_EXEC)
		return elf_err(e, "ELF file is not an executable (type %u)", elf16(e, 16));
	if (elf16(e, 44) && (elf16(e, 42) < ELF_PHDR_SIZE ||
			     !elf_has(e, elf32(e, 28), (u32)elf16(e, 44) * elf16(e, 42))))
		return elf_err(e, "truncated ELF file: program headers");
	if (elf32(e, 32) && (elf16(e, 46) < ELF_SHDR_SIZE ||
			     !elf_has(e, elf32(e, 32), (u32)elf16(e, 48) * elf16(e, 46))))
		return elf_err(e, "truncated ELF file: section headers");
	return 0;
}

/* Check program header @i: 1 and @seg filled in if it is loaded, 0 if not */
static int elf_segment(struct prusim_elf *e, unsigned int i, struct prusim_seg *seg)
{
	u32 ph = elf32(e, 28) + i * elf16(e, 42);
	u32 off, paddr, limit;

	memset(seg, 0, sizeof(*seg));
	seg->memsz = elf32(e, ph + 20);
	if (elf32(e, ph) != ELF_PT_LOAD || !seg->memsz)
		return 0;
	off = elf32(e, ph + 4);
	paddr = elf32(e, ph + 12);
	seg->filesz = elf32(e, ph + 16);
	if (seg->filesz > seg->memsz)
		return elf_err(e, "segment %u: file size exceeds memory size", i);
	if (!elf_has(e, off, seg->filesz))
		return elf_err(e, "truncated ELF file: segment %u data", i);
	seg->data = e->img + off;
	seg->iram = paddr >= PRUSIM_ELF_IRAM_TAG;
	if (seg->iram) {
		seg->addr = paddr - PRUSIM_ELF_IRAM_TAG;
		limit = PRUSIM_IRAM_SIZE;
	} else {
		seg->addr = paddr;
		if (paddr < PRUSIM_DRAM1)
			limit = PRUSIM_DRAM1;
		else if (paddr < PRUSIM_DRAM1 + PRUSIM_DRAM_SIZE)
			limit = PRUSIM_DRAM1 + PRUSIM_DRAM_SIZE;
		else if (paddr >= PRUSIM_SHARED)
			limit = PRUSIM_SHARED + PRUSIM_SHARED_SIZE;
		else
			limit = 0;
	}
	if (seg->addr >= limit || seg->memsz > limit - seg->addr)
		return elf_err(e, "segment %u at 0x%08x+0x%x is outside %s", i, paddr, seg->memsz,
			       seg->iram ? "the 8 KiB IRAM" : "DRAM and shared RAM");
	return 1;
}

static int elf_load_segment(struct prusim *s, unsigned int core, const struct prusim_seg *seg)
{
	static const u8 zero[64];
	u8 *ram;
	u32 done;

	if (!seg->iram) {
		ram = prusim_da_to_va(s, core, seg->addr, seg->memsz);
		if (!ram)
			return -EINVAL;
		memcpy(ram, seg->data, seg->filesz);
		memset(ram + seg->filesz, 0, seg->memsz - seg->filesz);
		return 0;
	}
	if (prusim_write_iram(s, core, seg->addr, seg->data, seg->filesz))
		return -EINVAL;
	for (done = seg->filesz; done < seg->memsz; done += sizeof(zero)) {
		u32 n = seg->memsz - done < sizeof(zero) ? seg->memsz - done : sizeof(zero);

		if (prusim_write_iram(s, core, seg->addr + done, zero, n))
			return -EINVAL;
	}
	return 0;
}

static int elf_segments(struct prusim_elf *e, struct prusim *s, unsigned int core, bool load)
{
	unsigned int i, phnum = elf16(e, 44);
	struct prusim_seg seg;
	int ret;

	for (i = 0; i < phnum; i++) {
		ret = elf_segment(e, i, &seg);
		if (ret <= 0) {
			if (ret)
				return ret;
			continue;
		}
		if (load && elf_load_segment(s, core, &seg))
			return elf_err(e, "segment %u could not be written", i);
	}
	return 0;
}

/* Find section @name: its header offset in @sh, 0 if there is none */
static int elf_section(struct prusim_elf *e, const char *name, u32 *sh)
{
	u32 shoff = elf32(e, 32), shentsize = elf16(e, 46), shnum = elf16(e, 48);
	u32 strtab, strsize, len = strlen(name) + 1, i;

	*sh = 0;
	/* the header table itself was checked by elf_check_header() */
	if (!shoff || elf16(e, 50) >= shnum)
		return 0;
	strtab = shoff + elf16(e, 50) * shentsize;
	strsize = elf32(e, strtab + 20);
	strtab = elf32(e, strtab + 16);
	if (!elf_has(e, strtab, strsize))
		return elf_err(e, "truncated ELF file: section names");
	for (i = 0; i < shnum; i++) {
		u32 hdr = shoff + i * shentsize, name_off = elf32(e, hdr);

		if (name_off < strsize && strsize - name_off >= len &&
		    !memcmp(e->img + strtab + name_off, name, len)) {
			*sh = hdr;
			return 0;
		}
	}
	return 0;
}

static int elf_resource_table(struct prusim_elf *e)
{
	u32 sh;
	int ret = elf_section(e, ".resource_table", &sh);

	if (ret || !sh)
		return ret;
	if (!elf_has(e, elf32(e, sh + 16), elf32(e, sh + 20)))
		return elf_err(e, "truncated ELF file: .resource_table");
	e->info->rsc_addr = elf32(e, sh + 12);
	e->info->rsc_offset = elf32(e, sh + 16);
	e->info->rsc_size = elf32(e, sh + 20);
	return 0;
}

/*
 * .pru_irq_map: u8 type (0), u8 count, then count entries of u8 event,
 * u8 channel, u8 host.  Checked when @s is NULL, applied otherwise.
 */
static int elf_irq_map(struct prusim_elf *e, struct prusim *s)
{
	u32 sh, off, size, n, i;
	int ret = elf_section(e, ".pru_irq_map", &sh);
	const u8 *p;

	if (ret || !sh)
		return ret;
	off = elf32(e, sh + 16);
	size = elf32(e, sh + 20);
	if (!elf_has(e, off, size) || size < 2)
		return elf_err(e, "truncated .pru_irq_map section");
	p = e->img + off;
	n = p[1];
	if (p[0])
		return elf_err(e, ".pru_irq_map type %u is not supported", p[0]);
	if (size < 2 + n * IRQ_MAP_ENTRY)
		return elf_err(e, ".pru_irq_map holds %u bytes, too few for %u events", size, n);
	if (n > PRUSIM_NUM_EVENTS)
		return elf_err(e, ".pru_irq_map maps %u events, more than the %u there are",
			       n, PRUSIM_NUM_EVENTS);
	for (i = 0, p += 2; i < n; i++, p += IRQ_MAP_ENTRY) {
		if (p[0] >= PRUSIM_NUM_EVENTS || p[1] >= PRUSIM_NUM_CHANNELS ||
		    p[2] >= PRUSIM_NUM_HOSTS)
			return elf_err(e, ".pru_irq_map entry %u (%u, %u, %u) out of range",
				       i, p[0], p[1], p[2]);
		memcpy(e->info->irq_map[i], p, IRQ_MAP_ENTRY);
		if (s && !s->cfg.irq_map_by_embedder)
			prusim_intc_map(s, p[0], p[1], p[2]);
	}
	e->info->irq_map_events = n;
	return 0;
}

/**
 * prusim_load_elf() - load a firmware image into one core
 * @s: simulator
 * @core: 0 or 1
 * @image: the ELF file
 * @size: its size
 * @info: filled in: entry point, resource table, error text
 *
 * Loads the PT_LOAD segments (IRAM, own/other DRAM, shared RAM), sets the pc
 * and PCOUNTER_RST_VAL to the entry point and applies the .pru_irq_map
 * section to the INTC (or only reports it, see
 * &prusim_config.irq_map_by_embedder).  Nothing is changed if the image is rejected.  The
 * core stays disabled; start it with prusim_core_enable().
 *
 * Return: 0, -EBUSY if the core runs, or -ENOEXEC with @info->err set.
 */
int prusim_load_elf(struct prusim *s, unsigned int core, const void *image, size_t size,
		    struct prusim_elf_info *info)
{
	struct prusim_elf e = { .img = image, .size = size, .info = info };
	struct prusim_core *c = &s->core[core];
	int ret;

	memset(info, 0, sizeof(*info));
	if (core >= PRUSIM_NUM_CORES)
		return elf_err(&e, "no PRU core %u", core);
	if (c->state == PRUSIM_RUNNING || c->state == PRUSIM_SLEEPING) {
		elf_err(&e, "PRU%u is running", core);
		return -EBUSY;
	}
	ret = elf_check_header(&e);
	if (!ret)
		ret = elf_segments(&e, s, core, false);
	if (!ret)
		ret = elf_resource_table(&e);
	if (!ret)
		ret = elf_irq_map(&e, NULL);
	if (ret)
		return ret;
	info->entry = elf32(&e, 24) & ~PRUSIM_ELF_IRAM_TAG;
	if (info->entry >= PRUSIM_IRAM_SIZE || info->entry & 3)
		return elf_err(&e, "entry point 0x%08x is not an IRAM word", elf32(&e, 24));

	ret = elf_segments(&e, s, core, true);
	if (ret)
		return ret;
	elf_irq_map(&e, s);
	prusim_core_reset(s, core, info->entry / 4);
	return 0;
}
