// SPDX-License-Identifier: GPL-2.0-only
/*
 * KUnit tests of prukit_pru_fw.c: the system events of a PRU firmware's
 * .pru_irq_map, from ELF images built here, well-formed and not; the events
 * rpmsg takes from a map; the map made of the older support package's
 * interrupt resource, and the copy of a file with it added; and whether
 * prukit_pru_kick gives a PRU remote processor its kick.
 */
#include <kunit/test.h>
#include <linux/elf.h>
#include <linux/mm.h>
#include <linux/remoteproc.h>
#include <linux/string.h>

#include "prukit_pru_fw.h"

#define IMG_SIZE	512

/* strtab offsets of the names below */
static const char fw_strtab[] = "\0.pru_irq_map\0.shstrtab\0.text";
#define NAME_MAP	1
#define NAME_SHSTRTAB	14
#define NAME_TEXT	24

static void put32(u8 *p, u32 v)
{
	p[0] = v;
	p[1] = v >> 8;
	p[2] = v >> 16;
	p[3] = v >> 24;
}

static void put16(u8 *p, u16 v)
{
	p[0] = v;
	p[1] = v >> 8;
}

/*
 * An ELF32 image: header, the map bytes at 64, the string table at 128,
 * four section headers at 256 (null, .text, .pru_irq_map named @map_name,
 * .shstrtab).  Returns its size.
 */
static size_t fw_image(u8 *img, const u8 *map, u32 map_len, u32 map_name)
{
	u8 *sh = img + 256;

	memset(img, 0, IMG_SIZE);
	memcpy(img, ELFMAG, SELFMAG);
	img[EI_CLASS] = ELFCLASS32;
	img[EI_DATA] = ELFDATA2LSB;
	img[EI_VERSION] = EV_CURRENT;
	put16(img + 16, ET_EXEC);
	put16(img + 18, 144);		/* EM_TI_PRU */
	put32(img + 32, 256);		/* e_shoff */
	put16(img + 46, 40);		/* e_shentsize */
	put16(img + 48, 4);		/* e_shnum */
	put16(img + 50, 3);		/* e_shstrndx */
	memcpy(img + 64, map, map_len);
	memcpy(img + 128, fw_strtab, sizeof(fw_strtab));
	/* section 1: .text (not the map) */
	put32(sh + 40, NAME_TEXT);
	put32(sh + 40 + 16, 52);
	put32(sh + 40 + 20, 8);
	/* section 2: the map */
	put32(sh + 80, map_name);
	put32(sh + 80 + 16, 64);
	put32(sh + 80 + 20, map_len);
	/* section 3: the section name string table */
	put32(sh + 120, NAME_SHSTRTAB);
	put32(sh + 120 + 16, 128);
	put32(sh + 120 + 20, sizeof(fw_strtab));
	return 256 + 4 * 40;
}

/* An image with @map in a section named @name reads as events @want */
static void expect_events(struct kunit *test, const u8 *map, u32 map_len, u32 name, u64 want)
{
	u8 *img = kunit_kzalloc(test, IMG_SIZE, GFP_KERNEL);
	size_t size;
	u64 ev = ~0ull;

	KUNIT_ASSERT_NOT_NULL(test, img);
	size = fw_image(img, map, map_len, name);
	KUNIT_EXPECT_EQ(test, 0, prukit_pru_fw_irq_events(img, size, &ev));
	KUNIT_EXPECT_EQ(test, ev, want);
}

static void prukit_pru_fw_map(struct kunit *test)
{
	static const u8 map[] = { 0, 3, 16, 2, 2, 17, 0, 0, 63, 9, 9 };

	expect_events(test, map, sizeof(map), NAME_MAP, BIT_ULL(16) | BIT_ULL(17) | BIT_ULL(63));
}

static void prukit_pru_fw_no_map(struct kunit *test)
{
	static const u8 map[] = { 0, 1, 20, 4, 4 };
	u8 *img = kunit_kzalloc(test, IMG_SIZE, GFP_KERNEL);
	u64 ev = ~0ull;

	KUNIT_ASSERT_NOT_NULL(test, img);
	/* the same bytes in a section of another name */
	expect_events(test, map, sizeof(map), NAME_TEXT, 0);
	/* no section table at all */
	fw_image(img, map, sizeof(map), NAME_MAP);
	put16(img + 48, 0);
	KUNIT_EXPECT_EQ(test, 0, prukit_pru_fw_irq_events(img, IMG_SIZE, &ev));
	KUNIT_EXPECT_EQ(test, ev, 0ull);
}

static void prukit_pru_fw_events_above_63(struct kunit *test)
{
	/* the AM335x INTC has 64 events; the map's byte may say more */
	static const u8 map[] = { 0, 2, 64, 0, 0, 5, 1, 1 };

	expect_events(test, map, sizeof(map), NAME_MAP, BIT_ULL(5));
}

static void prukit_pru_fw_malformed(struct kunit *test)
{
	static const u8 map[] = { 0, 1, 20, 4, 4 };
	static const u8 bad_type[] = { 1, 1, 20, 4, 4 };
	static const u8 bad_count[] = { 0, 2, 20, 4, 4 };
	u8 *img = kunit_kzalloc(test, IMG_SIZE, GFP_KERNEL);
	size_t size;
	u64 ev;

	KUNIT_ASSERT_NOT_NULL(test, img);
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	KUNIT_EXPECT_EQ(test, 0, prukit_pru_fw_irq_events(img, size, &ev));
	KUNIT_EXPECT_EQ(test, ev, BIT_ULL(20));

	/* not an ELF file, ELF64, big-endian, too short for a header */
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, 40, &ev));
	img[0] = 'X';
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	img[EI_CLASS] = ELFCLASS64;
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	img[EI_DATA] = ELFDATA2MSB;
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));

	/* a section table beyond the file, a string table index out of range */
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size - 1, &ev));
	put16(img + 50, 4);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	put32(img + 32, 0xfffffff0);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));

	/*
	 * section headers of another size than pru_rproc's steps: it would
	 * read another table than this reader
	 */
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	put16(img + 46, 0);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	put16(img + 46, 39);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	put16(img + 46, 41);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	/* in 80-byte steps, a table of the null section and the string table */
	put16(img + 46, 80);
	put16(img + 48, 2);
	put16(img + 50, 1);
	memcpy(img + 256 + 80, img + 256 + 120, 40);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));

	/* a string table beyond the file */
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	put32(img + 256 + 120 + 16, size);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	put32(img + 256 + 120 + 20, 0xffffff00);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));

	/* a map section past the end of the file */
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	put32(img + 256 + 80 + 16, 0xfffffff0);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));

	/* a map of another type, or whose size disagrees with its count */
	size = fw_image(img, bad_type, sizeof(bad_type), NAME_MAP);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	size = fw_image(img, bad_count, sizeof(bad_count), NAME_MAP);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));

	/* a map shorter than its header */
	size = fw_image(img, map, 1, NAME_MAP);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));

	/*
	 * a section name without its terminating NUL inside the string table,
	 * or beyond it: pru_rproc would compare past the table's end
	 */
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	put32(img + 256 + 120 + 20, NAME_MAP + 5);	/* strtab cut inside ".pru_irq_map" */
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
	size = fw_image(img, map, sizeof(map), NAME_MAP);
	put32(img + 256 + 40, sizeof(fw_strtab));	/* .text's name at the table's end */
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_irq_events(img, size, &ev));
}

/* The map rpmsg reads: the entries as prukit_pru_fw_irq_map() returns them */
static void expect_rpmsg(struct kunit *test, const u8 *map, u32 map_len, int ret,
			 int kick, int vring, u8 vring_host)
{
	struct prukit_pru_fw_irq k = { .event = -2 }, v = { .event = -2 };
	u8 *img = kunit_kzalloc(test, IMG_SIZE, GFP_KERNEL);
	const u8 *entries;
	unsigned int count;
	size_t size;

	KUNIT_ASSERT_NOT_NULL(test, img);
	size = fw_image(img, map, map_len, NAME_MAP);
	KUNIT_ASSERT_EQ(test, 0, prukit_pru_fw_irq_map(img, size, &entries, &count));
	KUNIT_ASSERT_EQ(test, map_len, 2 + 3 * count);
	KUNIT_EXPECT_EQ(test, ret, prukit_pru_fw_rpmsg_events(entries, count, &k, &v));
	if (ret)
		return;
	KUNIT_EXPECT_EQ(test, kick, k.event);
	KUNIT_EXPECT_EQ(test, vring, v.event);
	if (vring >= 0)
		KUNIT_EXPECT_EQ(test, vring_host, v.host);
}

static void prukit_pru_fw_rpmsg(struct kunit *test)
{
	/* prukit's intc_map_0.h: 17 -> host 0 first, then 16 -> host 2 */
	static const u8 prukit0[] = { 0, 2, 17, 0, 0, 16, 2, 2 };
	/* and PRU1's: 19 -> host 1, 18 -> host 3 */
	static const u8 prukit1[] = { 0, 2, 19, 1, 1, 18, 3, 3 };
	/* the support package's examples: only the kick, the vring in the tree */
	static const u8 ti[] = { 0, 1, 17, 0, 0 };
	/* a consumer's event to the ARM first: nothing the ARM raises reaches the PRU */
	static const u8 arm_first[] = { 0, 2, 16, 2, 2, 17, 0, 0 };
	/* an empty map */
	static const u8 empty[] = { 0, 0 };
	/* hosts above 9 reach nobody: no vring */
	static const u8 host10[] = { 0, 2, 17, 0, 0, 16, 9, 10 };

	expect_rpmsg(test, prukit0, sizeof(prukit0), 0, 17, 16, 2);
	expect_rpmsg(test, prukit1, sizeof(prukit1), 0, 19, 18, 3);
	expect_rpmsg(test, ti, sizeof(ti), 0, 17, -1, 0);
	expect_rpmsg(test, arm_first, sizeof(arm_first), -ENOENT, 0, 0, 0);
	expect_rpmsg(test, empty, sizeof(empty), -ENOENT, 0, 0, 0);
	expect_rpmsg(test, host10, sizeof(host10), 0, 17, -1, 0);
}

static void prukit_pru_fw_no_map_no_rpmsg(struct kunit *test)
{
	struct prukit_pru_fw_irq k, v;

	/* a firmware without a map: TI's 5.10 kick dereferences NULL here */
	KUNIT_EXPECT_EQ(test, -ENOENT, prukit_pru_fw_rpmsg_events(NULL, 0, &k, &v));
	KUNIT_EXPECT_EQ(test, -1, v.event);
}

static void fake_kick(struct rproc *rproc, int vqid)
{
}

/*
 * The operations of both PRU remoteproc drivers as they matter here
 * (review-checked against their sources: TI's pru_rproc_ops has .kick =
 * pru_rproc_kick in ti-linux-5.10.y and 6.1.y; mainline's pru_rproc_ops
 * has start, stop, da_to_va and no kick).
 */
static void prukit_pru_kick_choice(struct kunit *test)
{
	const struct rproc_ops mainline = { .kick = NULL };
	const struct rproc_ops ti = { .kick = fake_kick };

	KUNIT_EXPECT_EQ(test, PRUKIT_PRU_KICK_GIVE, prukit_pru_kick_choose(&mainline));
	KUNIT_EXPECT_EQ(test, PRUKIT_PRU_KICK_ASIDE, prukit_pru_kick_choose(&ti));
}

/*
 * An image as the support package's releases for TI's 4.x kernels build
 * one: no .pru_irq_map; a resource table (at 160: a vdev, then the type 5
 * interrupt resource, whose { event, channel } pairs are at data address
 * 0x40); one loadable data segment (file offset 100 = address 0x40, 16
 * bytes); sections null, .resource_table, .shstrtab at 400.
 */
#define SSP_SIZE	520
#define SSP_RSC		160
#define SSP_RSC_LEN	60
#define SSP_INTS	(SSP_RSC + 28)
#define SSP_PAIRS	100
#define SSP_PAIRS_DA	0x40
static const char ssp_strtab[] = "\0.resource_table\0.shstrtab";

static size_t ssp_image(u8 *img, const u8 *pairs, u32 count, const u8 *channel_host)
{
	u8 *sh = img + 400;

	memset(img, 0, SSP_SIZE);
	memcpy(img, ELFMAG, SELFMAG);
	img[EI_CLASS] = ELFCLASS32;
	img[EI_DATA] = ELFDATA2LSB;
	img[EI_VERSION] = EV_CURRENT;
	put16(img + 16, ET_EXEC);
	put16(img + 18, 144);		/* EM_TI_PRU */
	put32(img + 28, 52);		/* e_phoff */
	put32(img + 32, 400);		/* e_shoff */
	put16(img + 42, 32);		/* e_phentsize */
	put16(img + 44, 1);		/* e_phnum */
	put16(img + 46, 40);		/* e_shentsize */
	put16(img + 48, 3);		/* e_shnum */
	put16(img + 50, 2);		/* e_shstrndx */
	/* the data segment */
	put32(img + 52, PT_LOAD);
	put32(img + 52 + 4, SSP_PAIRS);
	put32(img + 52 + 8, SSP_PAIRS_DA);
	put32(img + 52 + 12, SSP_PAIRS_DA);
	put32(img + 52 + 16, 16);
	put32(img + 52 + 20, 16);
	put32(img + 52 + 24, PF_R | PF_W);
	memcpy(img + SSP_PAIRS, pairs, 2 * count);
	/* the resource table: version 1, two resources at 24 and 28 */
	put32(img + SSP_RSC, 1);
	put32(img + SSP_RSC + 4, 2);
	put32(img + SSP_RSC + 16, 24);
	put32(img + SSP_RSC + 20, 28);
	put32(img + SSP_RSC + 24, 3);	/* a vdev: only its type is read */
	put32(img + SSP_INTS, 5);	/* TYPE_CUSTOM */
	put32(img + SSP_INTS + 4, 1);	/* TYPE_PRU_INTS */
	put32(img + SSP_INTS + 8, 20);
	memcpy(img + SSP_INTS + 14, channel_host, 10);
	put32(img + SSP_INTS + 24, count);
	put32(img + SSP_INTS + 28, SSP_PAIRS_DA);
	memcpy(img + 240, ssp_strtab, sizeof(ssp_strtab));
	put32(sh + 40, 1);		/* .resource_table */
	put32(sh + 40 + 16, SSP_RSC);
	put32(sh + 40 + 20, SSP_RSC_LEN);
	put32(sh + 80, 17);		/* .shstrtab */
	put32(sh + 80 + 16, 240);
	put32(sh + 80 + 20, sizeof(ssp_strtab));
	return SSP_SIZE;
}

/* PRU0's routing in the support package's RPMsg echo example */
static const u8 ssp_pairs[] = { 16, 2, 17, 0 };
static const u8 ssp_hosts[10] = { 0, 255, 2, 255, 255, 255, 255, 255, 255, 255 };

static void prukit_pru_fw_ssp_map(struct kunit *test)
{
	/* the event to host 0 (the kick) first, then the one to the ARM */
	static const u8 want[] = { 0, 2, 17, 0, 0, 16, 2, 2 };
	static const u8 pairs3[] = { 20, 5, 16, 2, 19, 1 };
	static const u8 hosts3[10] = { 255, 1, 2, 255, 255, 7, 255, 255, 255, 255 };
	static const u8 want3[] = { 0, 3, 19, 1, 1, 20, 5, 7, 16, 2, 2 };
	u8 *img = kunit_kzalloc(test, SSP_SIZE, GFP_KERNEL);
	u8 map[PRUKIT_PRU_FW_IRQ_MAP_MAX];
	const u8 *entries;
	unsigned int count;
	size_t size, len;

	KUNIT_ASSERT_NOT_NULL(test, img);
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	KUNIT_ASSERT_EQ(test, 0, prukit_pru_fw_irq_map(img, size, &entries, &count));
	KUNIT_EXPECT_NULL(test, entries);
	KUNIT_ASSERT_EQ(test, 0, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	KUNIT_ASSERT_EQ(test, len, sizeof(want));
	KUNIT_EXPECT_EQ(test, 0, memcmp(map, want, sizeof(want)));

	/* three events, the resource's order kept within each group */
	size = ssp_image(img, pairs3, 3, hosts3);
	KUNIT_ASSERT_EQ(test, 0, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	KUNIT_ASSERT_EQ(test, len, sizeof(want3));
	KUNIT_EXPECT_EQ(test, 0, memcmp(map, want3, sizeof(want3)));

	/* no events: an empty map */
	size = ssp_image(img, ssp_pairs, 0, ssp_hosts);
	KUNIT_ASSERT_EQ(test, 0, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	KUNIT_EXPECT_EQ(test, len, 2);
	KUNIT_EXPECT_EQ(test, map[1], 0);
}

static void prukit_pru_fw_ssp_bad(struct kunit *test)
{
	static const u8 no_host[10] = { 255, 255, 2, 255, 255, 255, 255, 255, 255, 255 };
	static const u8 host10[10] = { 10, 255, 2, 255, 255, 255, 255, 255, 255, 255 };
	static const u8 ev64[] = { 64, 2 };
	static const u8 ch10[] = { 16, 10 };
	u8 *img = kunit_kzalloc(test, SSP_SIZE, GFP_KERNEL);
	u8 map[PRUKIT_PRU_FW_IRQ_MAP_MAX];
	size_t size, len;

	KUNIT_ASSERT_NOT_NULL(test, img);
	/* no resource of the kind: a vdev only, another sub type, no table */
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_RSC + 4, 1);
	KUNIT_EXPECT_EQ(test, -ENOENT, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_INTS + 4, 2);
	KUNIT_EXPECT_EQ(test, -ENOENT, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + 400 + 40, 17);	/* .resource_table renamed .shstrtab */
	KUNIT_EXPECT_EQ(test, -ENOENT, prukit_pru_fw_ssp_irq_map(img, size, map, &len));

	/* a channel without a host, a host above 9, an event above 63, channel 10 */
	size = ssp_image(img, ssp_pairs, 2, no_host);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ssp_pairs, 2, host10);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ev64, 1, ssp_hosts);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ch10, 1, ssp_hosts);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));

	/* more than 64 events; pairs past the segment's file bytes or before it */
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_INTS + 24, 65);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	put32(img + SSP_INTS + 24, 9);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_INTS + 28, SSP_PAIRS_DA - 1);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	put32(img + SSP_INTS + 28, 0xfffffffe);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	/* the pairs in code (an executable segment) are not data */
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + 52 + 24, PF_R | PF_X);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));

	/* the table: another version, a resource or an offset beyond it */
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_RSC, 2);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_RSC + 20, SSP_RSC_LEN - 4);
	put32(img + SSP_RSC + SSP_RSC_LEN - 4, 5);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	put32(img + SSP_RSC + 20, SSP_RSC_LEN - 3);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_RSC + 4, 20);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	/* a resource body shorter than the support package's */
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	put32(img + SSP_INTS + 8, 19);
	KUNIT_EXPECT_EQ(test, -EINVAL, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
}

static void prukit_pru_fw_add_map(struct kunit *test)
{
	u8 *img = kunit_kzalloc(test, SSP_SIZE, GFP_KERNEL);
	u8 map[PRUKIT_PRU_FW_IRQ_MAP_MAX], again[PRUKIT_PRU_FW_IRQ_MAP_MAX];
	const u8 *entries;
	unsigned int count;
	size_t size, len, len2, copy_size;
	u64 ev;
	u8 *copy;

	KUNIT_ASSERT_NOT_NULL(test, img);
	size = ssp_image(img, ssp_pairs, 2, ssp_hosts);
	KUNIT_ASSERT_EQ(test, 0, prukit_pru_fw_ssp_irq_map(img, size, map, &len));
	copy = prukit_pru_fw_add_irq_map(img, size, map, len, &copy_size);
	KUNIT_ASSERT_NOT_NULL(test, copy);
	KUNIT_EXPECT_GT(test, copy_size, size);
	/* the file's bytes stay where they were but for e_shoff and e_shnum */
	KUNIT_EXPECT_EQ(test, 0, memcmp(copy, img, 32));
	KUNIT_EXPECT_EQ(test, 0, memcmp(copy + 36, img + 36, 12));
	KUNIT_EXPECT_EQ(test, 0, memcmp(copy + 50, img + 50, size - 50));
	/* the map reads back as a .pru_irq_map, exactly */
	KUNIT_ASSERT_EQ(test, 0, prukit_pru_fw_irq_map(copy, copy_size, &entries, &count));
	KUNIT_ASSERT_NOT_NULL(test, entries);
	KUNIT_EXPECT_EQ(test, count, 2);
	KUNIT_EXPECT_EQ(test, 0, memcmp(entries, map + 2, 6));
	KUNIT_EXPECT_EQ(test, 0, prukit_pru_fw_irq_events(copy, copy_size, &ev));
	KUNIT_EXPECT_EQ(test, ev, BIT_ULL(16) | BIT_ULL(17));
	/* and the resource table is still found, the same */
	KUNIT_EXPECT_EQ(test, 0, prukit_pru_fw_ssp_irq_map(copy, copy_size, again, &len2));
	KUNIT_EXPECT_EQ(test, len, len2);
	KUNIT_EXPECT_EQ(test, 0, memcmp(map, again, len));
	kvfree(copy);

	/* an empty map (a header only) is a map too */
	map[1] = 0;
	copy = prukit_pru_fw_add_irq_map(img, size, map, 2, &copy_size);
	KUNIT_ASSERT_NOT_NULL(test, copy);
	KUNIT_EXPECT_EQ(test, 0, prukit_pru_fw_irq_map(copy, copy_size, &entries, &count));
	KUNIT_EXPECT_NOT_NULL(test, entries);
	KUNIT_EXPECT_EQ(test, count, 0);
	kvfree(copy);

	/* a file without a section table cannot name a section: no copy */
	put16(img + 48, 0);
	KUNIT_EXPECT_NULL(test, prukit_pru_fw_add_irq_map(img, size, map, len, &copy_size));
}

static struct kunit_case prukit_pru_fw_cases[] = {
	KUNIT_CASE(prukit_pru_fw_rpmsg),
	KUNIT_CASE(prukit_pru_fw_no_map_no_rpmsg),
	KUNIT_CASE(prukit_pru_kick_choice),
	KUNIT_CASE(prukit_pru_fw_map),
	KUNIT_CASE(prukit_pru_fw_no_map),
	KUNIT_CASE(prukit_pru_fw_events_above_63),
	KUNIT_CASE(prukit_pru_fw_malformed),
	KUNIT_CASE(prukit_pru_fw_ssp_map),
	KUNIT_CASE(prukit_pru_fw_ssp_bad),
	KUNIT_CASE(prukit_pru_fw_add_map),
	{}
};

static struct kunit_suite prukit_pru_fw_suite = {
	.name = "prukit_pru_fw",
	.test_cases = prukit_pru_fw_cases,
};

kunit_test_suite(prukit_pru_fw_suite);

MODULE_DESCRIPTION("KUnit tests of prukit_pru's firmware reader");
MODULE_LICENSE("GPL");
