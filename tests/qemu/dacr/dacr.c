// SPDX-License-Identifier: GPL-2.0-only
/*
 * Bare-metal ARMv7-A test of the Domain Access Control Register: after
 * every DACR write, each load, store and instruction fetch that the new
 * value forbids must abort and each one it allows must work, however hot
 * the translation (QEMU TLB) or the code (QEMU jump cache) was before.
 *
 * Short-descriptor tables (TTBCR = 0), identity-mapped: RAM in 1 MB
 * sections of domain 0 (always client), and the test megabytes
 *   SECT_DATA  domain 1, PL1 read/write        loads (and stores)
 *   SECT_RO    domain 1, PL1 read-only          manager vs client stores
 *   SECT_CODE  domain 1, PL1 read/write, exec   a copied "return 42"
 *   SECT_OTHER domain 2, PL1 read/write         data only
 *   SECT_XN    domain 1, PL1 read/write, XN     a copied "return 42"
 *   SECT_PAGES domain 1, 4 KB pages, PL1 r/w    data and a "return 42"
 *   SECT_USER  domain 3, PL0+PL1 r/w, exec      user "return 42"s, data
 *   SECT_UPROBE domain 0, PL0+PL1 r/w, exec     the user-mode load probe,
 *                                               the CPS gate, user stack
 *   SECT_UPRIV domain 3, PL1 r/w, exec          a user "return 42", data
 *
 * The user-mode checks run code in USR mode (PL0) as Linux does: entered
 * by an exception return (or CPS), left by an SVC, with DACR changed at
 * PL1 in between; a QEMU that keeps PL0 code in its jump cache, or PL0 and
 * PL1 translations in their TLBs, across such a write must still abort
 * every PL0 fetch and every PL0 or PL1 access that the new value forbids.
 *
 * Sections of this file: CP15, semihosting output, checks (the PL1 ones,
 * 1-8, then the user-mode ones, 9-17, then 18: readback), exceptions,
 * setup and main().
 *
 * Output and exit go through ARM semihosting.  Each check prints
 * "dacr: result NAME pass|fail DETAIL"; the last line is "dacr: end" and
 * the exit status is the number of failed checks.
 */

#include <stdarg.h>
#include "dacr.h"

#define BIT(n)		(1u << (n))
#define ARRAY_SIZE(a)	(sizeof(a) / sizeof((a)[0]))

#define SECT_DATA	0x80400000u
#define SECT_RO		0x80500000u
#define SECT_CODE	0x80600000u
#define SECT_OTHER	0x80700000u
#define SECT_XN		0x80800000u
#define SECT_PAGES	0x80900000u
#define SECT_USER	0x80a00000u
#define SECT_UPROBE	0x80b00000u
#define SECT_UPRIV	0x80c00000u

/* What SECT_UPROBE holds; domain 0 stays client, so they always work. */
#define UPROBE_LDR	(SECT_UPROBE + 0x0)
#define UPROBE_GATE	(SECT_UPROBE + 0x100)
#define USER_STACK_TOP	(SECT_UPROBE + 0x100000)

/* DACR fields: domain 0 is always client, it holds this program. */
#define D_NOACCESS	0u
#define D_CLIENT	1u
#define D_MANAGER	3u
#define DACR(d1, d2)	(D_CLIENT | (d1) << 2 | (d2) << 4)
/* Domain 3 holds the user-mode test megabytes; DACR() leaves it noaccess. */
#define DACR3(d1, d2, d3)	(DACR(d1, d2) | (d3) << 6)
#define U_DACR(d3)	DACR3(D_CLIENT, D_CLIENT, d3)

/* Short-descriptor fault status (FS[4] is FSR bit 10). */
#define FS_DOMAIN_SECT	0x09
#define FS_PERM_SECT	0x0d
#define FS_DOMAIN_PAGE	0x0b

#define POISON		0xdeadbeefu
#define MAX_REPORTS	5

/* Section descriptor bits. */
#define SD_SECTION	0x2u
#define SD_B		BIT(2)
#define SD_C		BIT(3)
#define SD_XN		BIT(4)
#define SD_DOMAIN(d)	((u32)(d) << 5)
#define SD_AP(ap)	((u32)(ap) << 10)
#define SD_TEX(t)	((u32)(t) << 12)
#define SD_APX		BIT(15)
#define SD_NORMAL_WB	(SD_TEX(1) | SD_C | SD_B)
#define SD_PL1_RW	SD_AP(1)
#define SD_PL1_RO	(SD_APX | SD_AP(1))
#define SD_PL0_RW	SD_AP(3)	/* and PL1 read/write */

/* First-level page table descriptor, second-level small page bits. */
#define L1_PAGE_TABLE	0x1u
#define PD_SMALL	0x2u
#define PD_NORMAL_WB	(BIT(6) | BIT(3) | BIT(2))	/* TEX 1, C, B */
#define PD_PL1_RW	BIT(4)				/* AP 0b01 */

/* SCTLR bits. */
#define SCTLR_M		BIT(0)
#define SCTLR_A		BIT(1)
#define SCTLR_C		BIT(2)
#define SCTLR_Z		BIT(11)
#define SCTLR_I		BIT(12)
#define SCTLR_V		BIT(13)
#define SCTLR_WXN	BIT(19)
#define SCTLR_UWXN	BIT(20)
#define SCTLR_TRE	BIT(28)
#define SCTLR_AFE	BIT(29)

#define NO_FAULT	0	/* besides DATA_ABORT and PREFETCH_ABORT */

#define MODE_MASK	0x1fu
#define MODE_USR	0x10u
#define MODE_SVC	0x13u

/*
 * The last recorded abort, and where a prefetch abort is expected.
 * fault_entry() changes them in the middle of a probe: the probes are
 * calls to start.S, which the compiler assumes may change any of them.
 */
static struct {
	u32 kind, fsr, far;
} fault;
static u32 call_target;
static u32 user_target;		/* the same for a USR-mode function */
static u32 faults_taken;
static u32 svc_unread;		/* user SVCs that vec_svc could not read */

/* The running check. */
static const char *check;
static u32 errors, checks_run, checks_failed;
static u32 dacr_writes, dacr_mismatches;

/* --- CP15 ------------------------------------------------------------- */

#define CP15_READ(name, spec)					\
static inline u32 read_##name(void)				\
{								\
	u32 v;							\
	asm volatile("mrc p15, " spec : "=r"(v));		\
	return v;						\
}

#define CP15_WRITE(name, spec)					\
static inline void write_##name(u32 v)				\
{								\
	asm volatile("mcr p15, " spec :: "r"(v) : "memory");	\
}

CP15_READ(sctlr, "0, %0, c1, c0, 0")
CP15_WRITE(sctlr, "0, %0, c1, c0, 0")
CP15_WRITE(ttbr0, "0, %0, c2, c0, 0")
CP15_WRITE(ttbcr, "0, %0, c2, c0, 2")
CP15_READ(dacr, "0, %0, c3, c0, 0")
CP15_WRITE(dacr_raw, "0, %0, c3, c0, 0")
CP15_READ(dfsr, "0, %0, c5, c0, 0")
CP15_READ(ifsr, "0, %0, c5, c0, 1")
CP15_READ(dfar, "0, %0, c6, c0, 0")
CP15_READ(ifar, "0, %0, c6, c0, 2")
CP15_WRITE(iciallu, "0, %0, c7, c5, 0")
CP15_WRITE(bpiall, "0, %0, c7, c5, 6")
CP15_WRITE(dccmvau, "0, %0, c7, c11, 1")
CP15_WRITE(tlbiall, "0, %0, c8, c7, 0")
CP15_WRITE(vbar, "0, %0, c12, c0, 0")

static inline u32 read_spsr(void)
{
	u32 v;

	asm volatile("mrs %0, spsr" : "=r"(v));
	return v;
}

static inline void write_spsr(u32 v)
{
	asm volatile("msr spsr_cxsf, %0" :: "r"(v) : "memory");
}

static inline void dsb(void) { asm volatile("dsb" ::: "memory"); }
static inline void isb(void) { asm volatile("isb" ::: "memory"); }

/* --- Semihosting output ------------------------------------------------ */

#define SYS_WRITE0		0x04
#define SYS_EXIT_EXTENDED	0x20
#define ADP_STOPPED_APP_EXIT	0x20026

static u32 semihost(u32 op, const void *arg)
{
	register u32 r0 asm("r0") = op;
	register const void *r1 asm("r1") = arg;

	/* A real SVC would take LR_svc; QEMU traps it first, but be safe. */
	asm volatile("svc 0x123456" : "+r"(r0) : "r"(r1) : "memory", "lr");
	return r0;
}

static void sys_exit(u32 code)
{
	u32 block[2] = { ADP_STOPPED_APP_EXIT, code };

	semihost(SYS_EXIT_EXTENDED, block);
	for (;;)
		;
}

struct buf {
	char s[256];
	u32 n;
};

static void put_c(struct buf *b, char c)
{
	if (b->n < sizeof(b->s) - 1)
		b->s[b->n++] = c;
}

static void put_s(struct buf *b, const char *s)
{
	while (*s)
		put_c(b, *s++);
}

static void put_u(struct buf *b, u32 v)
{
	static const u32 pow10[] = {
		1000000000, 100000000, 10000000, 1000000, 100000,
		10000, 1000, 100, 10, 1,
	};
	int started = 0;

	/* No divide instruction in plain ARMv7-A: subtract powers of ten. */
	for (u32 i = 0; i < ARRAY_SIZE(pow10); i++) {
		char d = '0';

		while (v >= pow10[i]) {
			v -= pow10[i];
			d++;
		}
		if (d != '0' || started || pow10[i] == 1) {
			put_c(b, d);
			started = 1;
		}
	}
}

static void put_x(struct buf *b, u32 v)
{
	put_s(b, "0x");
	for (int i = 28; i >= 0; i -= 4)
		put_c(b, "0123456789abcdef"[(v >> i) & 0xf]);
}

/* %s, %u and %x (as 0x%08x). */
static void put_fmt(struct buf *b, const char *fmt, va_list ap)
{
	for (; *fmt; fmt++) {
		if (*fmt != '%' || !fmt[1]) {
			put_c(b, *fmt);
			continue;
		}
		switch (*++fmt) {
		case 's':
			put_s(b, va_arg(ap, const char *));
			break;
		case 'u':
			put_u(b, va_arg(ap, u32));
			break;
		case 'x':
			put_x(b, va_arg(ap, u32));
			break;
		default:
			put_c(b, *fmt);
		}
	}
}

static void emit(struct buf *b)
{
	put_c(b, '\n');
	b->s[b->n] = 0;
	semihost(SYS_WRITE0, b->s);
}

/* One output line, "dacr: " and the formatted text. */
static void pr(const char *fmt, ...)
{
	struct buf b;
	va_list ap;

	b.n = 0;
	put_s(&b, "dacr: ");
	va_start(ap, fmt);
	put_fmt(&b, fmt, ap);
	va_end(ap);
	emit(&b);
}

/* --- Checks ------------------------------------------------------------- */

static void begin(const char *name)
{
	check = name;
	errors = 0;
}

/* One wrong outcome in the running check; the first few are printed. */
static void bad(const char *fmt, ...)
{
	struct buf b;
	va_list ap;

	if (++errors > MAX_REPORTS)
		return;
	b.n = 0;
	put_s(&b, "dacr: ");
	put_s(&b, check);
	put_s(&b, ": ");
	va_start(ap, fmt);
	put_fmt(&b, fmt, ap);
	va_end(ap);
	emit(&b);
}

/* The running check's result line. */
static void report(const char *fmt, ...)
{
	struct buf b;
	va_list ap;

	b.n = 0;
	checks_run++;
	if (errors)
		checks_failed++;
	put_s(&b, "dacr: result ");
	put_s(&b, check);
	put_s(&b, errors ? " fail " : " pass ");
	va_start(ap, fmt);
	put_fmt(&b, fmt, ap);
	va_end(ap);
	if (errors) {
		put_s(&b, "; ");
		put_u(&b, errors);
		put_s(&b, " wrong outcome(s)");
	}
	emit(&b);
}

/* Every DACR write goes through here, and is read back (check 18). */
static void set_dacr(u32 v)
{
	u32 got;

	write_dacr_raw(v);
	isb();
	dacr_writes++;
	got = read_dacr();
	if (got != v) {
		dacr_mismatches++;
		if (dacr_mismatches <= MAX_REPORTS)
			pr("DACR write %x read back as %x", v, got);
	}
}

static u32 fs_of(u32 fsr)
{
	return (fsr & 0xf) | ((fsr >> 6) & 0x10);
}

static void clear_fault(void)
{
	fault.kind = NO_FAULT;
	fault.fsr = 0;
	fault.far = 0;
}

/* The access just probed took a data abort with this FS, WnR and DFAR. */
static int data_abort_was(const char *what, u32 addr, u32 fs, u32 wnr)
{
	if (fault.kind != DATA_ABORT) {
		bad("%s %x: no data abort", what, addr);
		return 0;
	}
	if (fs_of(fault.fsr) != fs || ((fault.fsr >> 11) & 1) != wnr ||
	    fault.far != addr) {
		bad("%s %x: DFSR %x DFAR %x, want FS %x WnR %u DFAR %x",
		    what, addr, fault.fsr, fault.far, fs, wnr, addr);
		return 0;
	}
	return 1;
}

/* A read by probe (a load of some kind) that must work and return want. */
static int read_ok(const char *what, u32 (*probe)(u32), u32 addr, u32 want)
{
	u32 v;

	clear_fault();
	v = probe(addr);
	if (fault.kind != NO_FAULT) {
		bad("%s %x: aborted, kind %u FSR %x", what, addr, fault.kind,
		    fault.fsr);
		return 0;
	}
	if (v != want) {
		bad("%s %x: read %x, want %x", what, addr, v, want);
		return 0;
	}
	return 1;
}

/* A read by probe that must take a data abort with status fs. */
static int read_faults(const char *what, u32 (*probe)(u32), u32 addr, u32 fs)
{
	clear_fault();
	probe(addr);
	return data_abort_was(what, addr, fs, 0);
}

/* A load that must work and return want. */
static int load_ok(u32 addr, u32 want)
{
	return read_ok("load", probe_ldr, addr, want);
}

/* A load that must take a data abort with status fs. */
static int load_faults(u32 addr, u32 fs)
{
	return read_faults("load", probe_ldr, addr, fs);
}

/* A store that must work (and be read back). */
static int store_ok(u32 addr, u32 val)
{
	clear_fault();
	probe_str(addr, val);
	if (fault.kind != NO_FAULT) {
		bad("store %x: aborted, FSR %x", addr, fault.fsr);
		return 0;
	}
	return load_ok(addr, val);
}

/* A store that must take a data abort with status fs. */
static int store_faults(u32 addr, u32 val, u32 fs)
{
	clear_fault();
	probe_str(addr, val);
	return data_abort_was("store", addr, fs, 1);
}

/* A call of the copied function that must return 42. */
static int call_ok(u32 fn)
{
	u32 r;

	clear_fault();
	call_target = fn;
	r = probe_call(fn);
	call_target = 0;
	if (fault.kind != NO_FAULT) {
		bad("call %x: aborted, kind %u FSR %x", fn, fault.kind,
		    fault.fsr);
		return 0;
	}
	if (r != 42) {
		bad("call %x: returned %x, want 42", fn, r);
		return 0;
	}
	return 1;
}

/* A call that must take a prefetch abort with status fs on fn itself. */
static int call_faults(u32 fn, u32 fs)
{
	u32 r;

	clear_fault();
	call_target = fn;
	r = probe_call(fn);
	call_target = 0;
	if (fault.kind != PREFETCH_ABORT) {
		bad("call %x: returned %x, no prefetch abort", fn, r);
		return 0;
	}
	if (fs_of(fault.fsr) != fs || fault.far != fn || r == 42) {
		bad("call %x: IFSR %x IFAR %x r0 %x, want FS %x IFAR %x",
		    fn, fault.fsr, fault.far, r, fs, fn);
		return 0;
	}
	return 1;
}

/* Copy the code from start to end to addr and make it fetchable. */
static void put_code(u32 addr, const char *start, const char *end)
{
	const u32 *src = (const u32 *)start;
	u32 *dst = (u32 *)addr;
	u32 n = (u32)(end - start) / 4;

	for (u32 i = 0; i < n; i++)
		dst[i] = src[i];
	for (u32 a = addr & ~31u; a < addr + n * 4; a += 32)
		write_dccmvau(a);
	dsb();
	write_iciallu(0);
	write_bpiall(0);
	dsb();
	isb();
}

/* Copy the "return 42" function to addr. */
static void put_fn42(u32 addr)
{
	put_code(addr, fn42_start, fn42_end);
}

/* The function's words, read as data. */
static int fn42_words_ok(u32 addr)
{
	const u32 *src = (const u32 *)fn42_start;
	u32 n = (u32)(fn42_end - fn42_start) / 4;
	int ok = 1;

	for (u32 i = 0; i < n; i++)
		ok &= load_ok(addr + 4 * i, src[i]);
	return ok;
}

/*
 * 1. Loads from a domain-1 section, in several 4 KB pages (QEMU caches
 * each page's translation): client (or, every other round, manager) works,
 * noaccess takes a section domain fault with DFAR = the address, and the
 * next grant reads the old data again.
 */
#define DATA_PAGES 4
#define ROUNDS 200
#define CALLS 1000

static u32 data_addr(u32 i)
{
	return SECT_DATA + i * 0x41000 + 4 * i;	/* pages 0, 65, 130, 195 */
}

static void check_load_domain(void)
{
	u32 ok = 0, faulted = 0;

	begin("load-domain");
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	for (u32 i = 0; i < DATA_PAGES; i++)
		store_ok(data_addr(i), 0x1000 + i);

	for (u32 r = 0; r < ROUNDS; r++) {
		set_dacr(DACR(r & 1 ? D_MANAGER : D_CLIENT, D_CLIENT));
		for (u32 i = 0; i < DATA_PAGES; i++) {
			/* The value the last round left there. */
			ok += load_ok(data_addr(i), r * 0x10000 + 0x1000 + i);
			store_ok(data_addr(i), (r + 1) * 0x10000 + 0x1000 + i);
		}
		set_dacr(DACR(D_NOACCESS, D_CLIENT));
		for (u32 i = 0; i < DATA_PAGES; i++)
			faulted += load_faults(data_addr(i), FS_DOMAIN_SECT);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	for (u32 i = 0; i < DATA_PAGES; i++)
		ok += load_ok(data_addr(i), ROUNDS * 0x10000 + 0x1000 + i);
	if (ok != ROUNDS * DATA_PAGES + DATA_PAGES ||
	    faulted != ROUNDS * DATA_PAGES)
		bad("counted %u good loads, %u noaccess faults", ok, faulted);
	report("%u rounds: %u client/manager loads worked, %u noaccess ones domain-faulted",
	       ROUNDS, ok, faulted);
}

/*
 * 2. A PL1 read-only section in domain 1: as manager (no permission
 * checks) a store works; as client (a reduction) the store takes a
 * section permission fault and leaves the data, while loads still work.
 */
static void check_store_manager_client(void)
{
	const u32 addr[2] = { SECT_RO + 0x100, SECT_RO + 0x7f100 };
	u32 stored = 0, refused = 0;

	begin("store-manager-client");
	for (u32 r = 0; r < ROUNDS; r++) {
		u32 v = 0x5a000000 + r;

		set_dacr(DACR(D_MANAGER, D_CLIENT));
		for (u32 i = 0; i < 2; i++)
			stored += store_ok(addr[i], v + (i << 16));
		set_dacr(DACR(D_CLIENT, D_CLIENT));
		for (u32 i = 0; i < 2; i++) {
			refused += store_faults(addr[i], ~v, FS_PERM_SECT);
			load_ok(addr[i], v + (i << 16));
		}
	}
	if (stored != 2 * ROUNDS || refused != 2 * ROUNDS)
		bad("counted %u manager stores, %u client permission faults",
		    stored, refused);
	report("%u rounds: %u manager stores worked, %u client ones permission-faulted",
	       ROUNDS, stored, refused);
}

/*
 * 3. The same reduction for instruction fetch: manager ignores XN, so a
 * hot function in an XN section of domain 1 runs as manager and takes a
 * prefetch abort (section permission fault) as client.
 */
static void check_fetch_manager_client(void)
{
	const u32 fn = SECT_XN + 0x20, other = SECT_OTHER + 0x5000;
	const u32 rounds = 100;
	u32 ok = 0, faulted = 0;

	begin("fetch-manager-client");
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	put_fn42(fn);
	store_ok(other, 0x2b2b2b2b);
	for (u32 r = 0; r < rounds; r++) {
		set_dacr(DACR(D_MANAGER, D_CLIENT));
		for (u32 i = 0; i < CALLS; i++)
			ok += call_ok(fn);
		if (r & 1) {
			/* A domain-2 reduction between, with data to flush. */
			load_ok(other, 0x2b2b2b2b);
			set_dacr(DACR(D_MANAGER, D_NOACCESS));
			for (u32 i = 0; i < 10; i++)
				ok += call_ok(fn);
		}
		set_dacr(DACR(D_CLIENT, D_CLIENT));
		for (u32 i = 0; i < 3; i++)
			faulted += call_faults(fn, FS_PERM_SECT);
		fn42_words_ok(fn);	/* XN stops fetches, not loads */
	}
	if (ok != rounds * CALLS + rounds / 2 * 10 || faulted != 3 * rounds)
		bad("counted %u good calls, %u prefetch aborts", ok, faulted);
	report("%u rounds: %u manager calls returned 42, %u client ones prefetch-aborted",
	       rounds, ok, faulted);
}

/*
 * 4. Writing the DACR value it already holds changes nothing: what
 * worked still works and what faulted still faults.
 */
static void check_same_value(u32 fn)
{
	static const u32 d1[] = { D_CLIENT, D_NOACCESS, D_MANAGER };
	u32 steps = 0;

	begin("same-value");
	for (u32 r = 0; r < 50; r++) {
		u32 v = 0x33000000 + r;

		set_dacr(DACR(D_CLIENT, D_CLIENT));
		store_ok(SECT_DATA, v);
		for (u32 k = 0; k < 3; k++) {
			u32 dacr = DACR(d1[k], D_CLIENT);

			set_dacr(dacr);
			for (u32 again = 0; again < 2; again++) {
				if (again)
					set_dacr(dacr);
				switch (d1[k]) {
				case D_CLIENT:
					load_ok(SECT_DATA, v);
					store_faults(SECT_RO, v, FS_PERM_SECT);
					call_ok(fn);
					break;
				case D_NOACCESS:
					load_faults(SECT_DATA, FS_DOMAIN_SECT);
					load_faults(SECT_RO, FS_DOMAIN_SECT);
					call_faults(fn, FS_DOMAIN_SECT);
					break;
				case D_MANAGER:
					load_ok(SECT_DATA, v);
					store_ok(SECT_RO, v);
					call_ok(fn);
					break;
				}
				steps++;
			}
		}
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	report("%u steps, each before and after rewriting the same value",
	       steps);
}

/*
 * 5. Instruction fetch from domain 1, with the function hot in QEMU's
 * jump cache: noaccess must still take a prefetch abort on it.
 */
static void check_fetch_hot(u32 fn)
{
	u32 ok = 0, faulted = 0;
	const u32 rounds = 100;

	begin("fetch-hot");
	for (u32 r = 0; r < rounds; r++) {
		set_dacr(DACR(D_CLIENT, D_CLIENT));
		for (u32 i = 0; i < CALLS; i++)
			ok += call_ok(fn);
		set_dacr(DACR(D_NOACCESS, D_CLIENT));
		for (u32 i = 0; i < 3; i++)
			faulted += call_faults(fn, FS_DOMAIN_SECT);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	ok += call_ok(fn);
	if (ok != rounds * CALLS + 1 || faulted != 3 * rounds)
		bad("counted %u good calls, %u prefetch aborts", ok, faulted);
	report("%u rounds: %u client calls returned 42, %u noaccess ones prefetch-aborted",
	       rounds, ok, faulted);
}

/*
 * 6. The first access to the code after a grant is a data read of its
 * words: the call must still work, and noaccess must stop it.  Each
 * round uses one of 16 copies, in 16 pages.
 */
static void check_data_then_fetch(void)
{
	u32 ok = 0, faulted = 0;
	const u32 rounds = 64;

	begin("data-then-fetch");
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	for (u32 p = 0; p < 16; p++)
		put_fn42(SECT_CODE + 0x80000 + p * 0x1000 + 8 * p);

	for (u32 r = 0; r < rounds; r++) {
		u32 fn = SECT_CODE + 0x80000 + (r % 16) * 0x1000 + 8 * (r % 16);

		set_dacr(DACR(D_NOACCESS, D_CLIENT));
		set_dacr(DACR(D_CLIENT, D_CLIENT));
		if (fn42_words_ok(fn))
			ok += call_ok(fn);
		set_dacr(DACR(D_NOACCESS, D_CLIENT));
		faulted += call_faults(fn, FS_DOMAIN_SECT);
		faulted += load_faults(fn, FS_DOMAIN_SECT);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != rounds || faulted != 2 * rounds)
		bad("counted %u good calls, %u noaccess faults", ok, faulted);
	report("%u rounds: %u calls after a data read worked, %u noaccess ones aborted",
	       rounds, ok, faulted);
}

/*
 * 7. Domain 2 holds data only.  Reducing and granting it while the
 * domain-1 function is hot must leave the function running, and must
 * fault domain-2 loads whose translation was cached.  Then domain 1 is
 * reduced: the function must stop, although (in even rounds) nothing of
 * domain 1 was walked since domain 2 was reduced, the function ran from
 * QEMU's jump cache alone.  In odd rounds a domain-1 load comes between.
 */
static void check_other_domain(u32 fn)
{
	const u32 other = SECT_OTHER + 0x2000, rounds = 100;
	u32 calls = 0, loads = 0, d2_faults = 0, d1_faults = 0;

	begin("other-domain");
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	store_ok(other, 0x22220000);
	store_ok(SECT_DATA, 0x44440000);
	for (u32 r = 0; r < rounds; r++) {
		set_dacr(DACR(D_CLIENT, D_CLIENT));
		for (u32 i = 0; i < 100; i++)
			calls += call_ok(fn);
		loads += load_ok(other, 0x22220000 + r);
		store_ok(other, 0x22220000 + r + 1);

		/* Reduce domain 2, grant it, reduce it again. */
		set_dacr(DACR(D_CLIENT, D_NOACCESS));
		d2_faults += load_faults(other, FS_DOMAIN_SECT);
		for (u32 i = 0; i < 10; i++)
			calls += call_ok(fn);
		set_dacr(DACR(D_CLIENT, D_MANAGER));
		calls += call_ok(fn);
		set_dacr(DACR(D_CLIENT, D_NOACCESS));
		calls += call_ok(fn);
		d2_faults += load_faults(other, FS_DOMAIN_SECT);
		if (r & 1)
			loads += load_ok(SECT_DATA, 0x44440000);

		/* Reduce domain 1: the hot function must stop. */
		set_dacr(DACR(D_NOACCESS, D_NOACCESS));
		for (u32 i = 0; i < 2; i++)
			d1_faults += call_faults(fn, FS_DOMAIN_SECT);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (calls != rounds * 112 || loads != rounds + rounds / 2 ||
	    d2_faults != 2 * rounds || d1_faults != 2 * rounds)
		bad("counted %u calls, %u loads, %u domain-2 faults, %u aborted calls",
		    calls, loads, d2_faults, d1_faults);
	report("%u rounds: %u calls, %u loads worked; %u domain-2 loads, %u calls aborted",
	       rounds, calls, loads, d2_faults, d1_faults);
}

/*
 * 8. A megabyte mapped by a second-level table of 4 KB pages, as Linux
 * maps most memory: a load and a hot function in domain 1 work as
 * client, and as noaccess take a page domain fault.
 */
static void check_page_domain(void)
{
	const u32 data = SECT_PAGES + 0x3000, fn = SECT_PAGES + 0x7040;
	const u32 rounds = 100;
	u32 ok = 0, faulted = 0;

	begin("page-domain");
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	put_fn42(fn);
	store_ok(data, 0x88880000);
	for (u32 r = 0; r < rounds; r++) {
		set_dacr(DACR(D_CLIENT, D_CLIENT));
		for (u32 i = 0; i < 100; i++)
			ok += call_ok(fn);
		ok += load_ok(data, 0x88880000 + r);
		store_ok(data, 0x88880000 + r + 1);
		set_dacr(DACR(D_NOACCESS, D_CLIENT));
		faulted += call_faults(fn, FS_DOMAIN_PAGE);
		faulted += load_faults(data, FS_DOMAIN_PAGE);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != rounds * 101 || faulted != 2 * rounds)
		bad("counted %u good calls and loads, %u faults", ok, faulted);
	report("%u rounds: %u client calls/loads worked, %u noaccess ones page-faulted",
	       rounds, ok, faulted);
}

/* --- User-mode checks ---------------------------------------------------- */

/* What the user-mode checks use in SECT_USER and SECT_UPRIV. */
#define UFN		(SECT_USER + 0x40)
#define UFN2		(SECT_USER + 0x5080)	/* another page */
#define UPRIV_FN	(SECT_UPRIV + 0x40)
#define UPRIV_DATA	(SECT_UPRIV + 0x3000)
#define USER_CALLS	1000
#define USER_ROUNDS	100

enum user_entry { BY_ERET, BY_CPS };

/*
 * Run fn in USR mode, entered by an exception return or by CPS.  vec_svc
 * reads the SVC that ends fn back; if it could not, fn ran from a page
 * that DACR forbids (see start.S), and no check expects that.
 */
static u32 user_run(u32 fn, u32 arg, enum user_entry how)
{
	u32 r, unread = svc_unread;

	clear_fault();
	user_target = fn;
	if (how == BY_CPS)
		r = user_call_cps(fn, arg, UPROBE_GATE);
	else
		r = user_call(fn, arg);
	user_target = 0;
	if (svc_unread != unread)
		bad("user call %x(%x): its SVC at PL0 was not readable at PL0",
		    fn, arg);
	return r;
}

/* A USR-mode call that must return 42. */
static int user_call_ok(u32 fn, enum user_entry how)
{
	u32 r = user_run(fn, 0, how);

	if (fault.kind != NO_FAULT) {
		bad("user call %x (%s): aborted, kind %u FSR %x FAR %x", fn,
		    how == BY_CPS ? "cps" : "eret", fault.kind, fault.fsr,
		    fault.far);
		return 0;
	}
	if (r != 42) {
		bad("user call %x: returned %x, want 42", fn, r);
		return 0;
	}
	return 1;
}

/* A USR-mode call that must take a prefetch abort with status fs on fn. */
static int user_call_faults(u32 fn, enum user_entry how, u32 fs)
{
	u32 r = user_run(fn, 0, how);

	if (fault.kind != PREFETCH_ABORT) {
		bad("user call %x (%s): returned %x, kind %u, no prefetch abort",
		    fn, how == BY_CPS ? "cps" : "eret", r, fault.kind);
		return 0;
	}
	if (fs_of(fault.fsr) != fs || fault.far != fn || r == 42) {
		bad("user call %x: IFSR %x IFAR %x r0 %x, want FS %x IFAR %x",
		    fn, fault.fsr, fault.far, r, fs, fn);
		return 0;
	}
	return 1;
}

/* A load at PL0: the copy of uldr, in domain 0, run in USR mode. */
static u32 user_ldr(u32 addr)
{
	return user_run(UPROBE_LDR, addr, BY_ERET);
}

/* A load at PL0 that must return want. */
static int user_load_ok(u32 addr, u32 want)
{
	return read_ok("user load", user_ldr, addr, want);
}

/* A load at PL0 that must take a data abort with status fs. */
static int user_load_faults(u32 addr, u32 fs)
{
	return read_faults("user load", user_ldr, addr, fs);
}

/* An LDRT at PL1 (PL0 permissions) that must return want. */
static int ldrt_ok(u32 addr, u32 want)
{
	return read_ok("ldrt", probe_ldrt, addr, want);
}

/* An LDRT at PL1 that must take a data abort with status fs. */
static int ldrt_faults(u32 addr, u32 fs)
{
	return read_faults("ldrt", probe_ldrt, addr, fs);
}

/* Revoke the user domain and do some PL1 work, as a kernel entry does. */
static void revoke_and_work(u32 v)
{
	set_dacr(DACR3(D_CLIENT, D_CLIENT, D_NOACCESS));
	store_ok(SECT_DATA + 0x80, v);
	load_ok(SECT_DATA + 0x80, v);
	call_ok(SECT_CODE + 0x40);
}

/*
 * 9. A user function, hot in QEMU's jump cache (a thousand round trips
 * through exception return and SVC), whose domain is revoked at PL1: the
 * return to USR mode at that same code must take a prefetch abort (a
 * section domain fault), for it and for a second hot function in another
 * page; in odd rounds the PL1 code does more work first.
 */
static void check_user_fetch_revoke(void)
{
	u32 ok = 0, faulted = 0;

	begin("user-fetch-revoke");
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		set_dacr(U_DACR(D_CLIENT));
		for (u32 i = 0; i < USER_CALLS; i++)
			ok += user_call_ok(UFN, BY_ERET);
		for (u32 i = 0; i < 10; i++)
			ok += user_call_ok(UFN2, BY_ERET);
		if (r & 1)
			revoke_and_work(r);
		else
			set_dacr(U_DACR(D_NOACCESS));
		for (u32 i = 0; i < 3; i++)
			faulted += user_call_faults(UFN, BY_ERET,
						    FS_DOMAIN_SECT);
		faulted += user_call_faults(UFN2, BY_ERET, FS_DOMAIN_SECT);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != USER_ROUNDS * (USER_CALLS + 10) || faulted != 4 * USER_ROUNDS)
		bad("counted %u good user calls, %u prefetch aborts", ok,
		    faulted);
	report("%u rounds: %u user calls returned 42, %u after a revoke prefetch-aborted",
	       USER_ROUNDS, ok, faulted);
}

/*
 * 10. The same hot user function, its domain revoked and then granted
 * again (client, or manager in odd rounds) before the return to USR
 * mode, as Linux does around every kernel entry: it must run.
 */
static void check_user_fetch_restore(void)
{
	u32 ok = 0, faulted = 0;

	begin("user-fetch-restore");
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		set_dacr(U_DACR(D_CLIENT));
		for (u32 i = 0; i < USER_CALLS; i++)
			ok += user_call_ok(UFN, BY_ERET);
		set_dacr(U_DACR(D_NOACCESS));
		if (r & 2)
			faulted += ldrt_faults(UFN, FS_DOMAIN_SECT);
		set_dacr(U_DACR(r & 1 ? D_MANAGER : D_CLIENT));
		for (u32 i = 0; i < 3; i++)
			ok += user_call_ok(UFN, BY_ERET);
		ok += user_call_ok(UFN2, BY_ERET);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != USER_ROUNDS * (USER_CALLS + 4) || faulted != USER_ROUNDS / 2)
		bad("counted %u good user calls, %u ldrt faults", ok, faulted);
	report("%u rounds: %u user calls returned 42, also after revoke and grant",
	       USER_ROUNDS, ok);
}

/*
 * 11. Revoke, grant, revoke again (several writes at PL1, the last one a
 * reduction again): the hot user function must take a prefetch abort.
 */
static void check_user_fetch_revoke_again(void)
{
	static const u32 seq[][4] = {
		{ D_NOACCESS, D_CLIENT, D_NOACCESS, D_NOACCESS },
		{ D_NOACCESS, D_MANAGER, D_CLIENT, D_NOACCESS },
		{ D_MANAGER, D_NOACCESS, D_CLIENT, D_NOACCESS },
		{ D_NOACCESS, D_CLIENT, D_NOACCESS, D_CLIENT },
	};
	u32 ok = 0, faulted = 0, want_ok = 0, want_faulted = 0;

	begin("user-fetch-revoke-again");
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		const u32 *d3 = seq[r % ARRAY_SIZE(seq)];

		set_dacr(U_DACR(D_CLIENT));
		for (u32 i = 0; i < USER_CALLS; i++)
			ok += user_call_ok(UFN, BY_ERET);
		for (u32 k = 0; k < 4; k++)
			set_dacr(U_DACR(d3[k]));
		/* The last sequence ends granted: a control. */
		if (d3[3] == D_NOACCESS) {
			faulted += user_call_faults(UFN, BY_ERET,
						    FS_DOMAIN_SECT);
			want_faulted++;
		} else {
			ok += user_call_ok(UFN, BY_ERET);
			want_ok++;
		}
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != USER_ROUNDS * USER_CALLS + want_ok || faulted != want_faulted)
		bad("counted %u good user calls, %u prefetch aborts", ok,
		    faulted);
	report("%u rounds: %u user calls returned 42, %u revoked again prefetch-aborted",
	       USER_ROUNDS, ok, faulted);
}

/*
 * 12. The return to USR mode is a CPS at PL1 and a branch (through the
 * gate in domain 0), not an exception return: the hot user function
 * (made hot through the gate or, in odd rounds, by exception returns)
 * must take a prefetch abort after a revoke, and run after a grant.
 */
static void check_user_fetch_cps(void)
{
	u32 ok = 0, faulted = 0;

	begin("user-fetch-cps");
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		enum user_entry hot = r & 1 ? BY_ERET : BY_CPS;

		set_dacr(U_DACR(D_CLIENT));
		for (u32 i = 0; i < USER_CALLS; i++)
			ok += user_call_ok(UFN, hot);
		set_dacr(U_DACR(D_NOACCESS));
		for (u32 i = 0; i < 2; i++)
			faulted += user_call_faults(UFN, BY_CPS,
						    FS_DOMAIN_SECT);
		set_dacr(U_DACR(D_CLIENT));
		ok += user_call_ok(UFN, BY_CPS);
		set_dacr(U_DACR(D_NOACCESS));
		set_dacr(U_DACR(D_CLIENT));
		set_dacr(U_DACR(D_NOACCESS));
		faulted += user_call_faults(UFN, BY_CPS, FS_DOMAIN_SECT);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != USER_ROUNDS * (USER_CALLS + 1) || faulted != 3 * USER_ROUNDS)
		bad("counted %u good user calls, %u prefetch aborts", ok,
		    faulted);
	report("%u rounds: %u user calls returned 42, %u revoked CPS ones prefetch-aborted",
	       USER_ROUNDS, ok, faulted);
}

/*
 * 13. Domain 1 (PL1 data and code, hot) is reduced too, in the same
 * write as the user domain or in another one: the user function must
 * abort exactly when its own domain 3 ends revoked, and domain-1 loads
 * must fault.
 *   round % 4 == 0: domain 1 only              user call runs
 *   round % 4 == 1: domains 1 and 3 at once     user call aborts
 *   round % 4 == 2: domain 3, then domain 1     user call aborts
 *   round % 4 == 3: 3 revoked, granted, then 1  user call runs
 */
static void check_user_fetch_other_domain(void)
{
	const u32 d1data = SECT_DATA + 0x3000;
	u32 ok = 0, faulted = 0, d1_faults = 0, want_ok = 0;

	begin("user-fetch-other-domain");
	set_dacr(U_DACR(D_CLIENT));
	store_ok(d1data, 0x13131313);
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		set_dacr(U_DACR(D_CLIENT));
		for (u32 i = 0; i < USER_CALLS; i++)
			ok += user_call_ok(UFN, BY_ERET);
		load_ok(d1data, 0x13131313);
		call_ok(SECT_CODE + 0x40);
		switch (r % 4) {
		case 0:
			set_dacr(DACR3(D_NOACCESS, D_CLIENT, D_CLIENT));
			break;
		case 1:
			set_dacr(DACR3(D_NOACCESS, D_CLIENT, D_NOACCESS));
			break;
		case 2:
			set_dacr(DACR3(D_CLIENT, D_CLIENT, D_NOACCESS));
			set_dacr(DACR3(D_NOACCESS, D_CLIENT, D_NOACCESS));
			break;
		case 3:
			set_dacr(DACR3(D_CLIENT, D_CLIENT, D_NOACCESS));
			set_dacr(DACR3(D_CLIENT, D_CLIENT, D_CLIENT));
			set_dacr(DACR3(D_NOACCESS, D_CLIENT, D_CLIENT));
			break;
		}
		if (r % 4 == 0 || r % 4 == 3) {
			ok += user_call_ok(UFN, BY_ERET);
			want_ok++;
		} else {
			faulted += user_call_faults(UFN, BY_ERET,
						    FS_DOMAIN_SECT);
		}
		d1_faults += load_faults(d1data, FS_DOMAIN_SECT);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != USER_ROUNDS * USER_CALLS + want_ok ||
	    faulted != USER_ROUNDS - want_ok || d1_faults != USER_ROUNDS)
		bad("counted %u good user calls, %u prefetch aborts, %u domain-1 load faults",
		    ok, faulted, d1_faults);
	report("%u rounds: %u user calls returned 42, %u aborted; %u domain-1 loads faulted",
	       USER_ROUNDS, ok, faulted, d1_faults);
}

/*
 * 14. SECT_UPRIV has no PL0 access by its AP bits: as manager (no
 * permission checks) a user function there runs and a user load works,
 * hot; as client (a reduction, not a revoke) the user call takes a
 * section permission fault, and so do the user load and LDRT, while PL1
 * loads and the user function of SECT_USER (same domain) still work.
 */
static void check_user_manager_client(void)
{
	const u32 rounds = 50;
	u32 ok = 0, faulted = 0;

	begin("user-manager-client");
	for (u32 r = 0; r < rounds; r++) {
		u32 v = 0x77000000 + r;

		set_dacr(U_DACR(D_MANAGER));
		store_ok(UPRIV_DATA, v);
		for (u32 i = 0; i < USER_CALLS; i++)
			ok += user_call_ok(UPRIV_FN, BY_ERET);
		for (u32 i = 0; i < 100; i++)
			ok += user_load_ok(UPRIV_DATA, v);
		set_dacr(U_DACR(D_CLIENT));
		faulted += user_call_faults(UPRIV_FN, r & 1 ? BY_CPS : BY_ERET,
					    FS_PERM_SECT);
		faulted += user_load_faults(UPRIV_DATA, FS_PERM_SECT);
		faulted += ldrt_faults(UPRIV_DATA, FS_PERM_SECT);
		ok += load_ok(UPRIV_DATA, v);
		ok += user_call_ok(UFN, BY_ERET);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != rounds * (USER_CALLS + 102) || faulted != 3 * rounds)
		bad("counted %u good calls and loads, %u permission faults",
		    ok, faulted);
	report("%u rounds: %u manager user calls/loads worked, %u client ones permission-faulted",
	       rounds, ok, faulted);
}

/* Data words of SECT_USER, each in its own page (not UFN's or UFN2's). */
#define USER_PAGES	4

static u32 user_data(u32 i)
{
	return SECT_USER + 0x20000 + i * 0x11000 + 4 * i;
}

static u32 pl0_only_data(u32 i)
{
	return SECT_USER + 0x80000 + i * 0x3000 + 8 * i;
}

static u32 pl1_only_data(u32 i)
{
	return SECT_USER + 0xc0000 + i * 0x5000 + 12 * i;
}

/*
 * 15. A user data page, loaded hot both at PL1 and at PL0 (so both
 * translation regimes hold it): after a revoke at PL1, a PL1 load, an
 * LDRT at PL1 and a PL0 load must each take a section domain fault,
 * whichever comes first; after a grant all three read the data again.
 */
static void check_user_data_revoke(void)
{
	u32 ok = 0, faulted = 0;

	begin("user-data-revoke");
	set_dacr(U_DACR(D_CLIENT));
	for (u32 i = 0; i < USER_PAGES; i++)
		store_ok(user_data(i), 0x55000000 + i);
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		set_dacr(U_DACR(D_CLIENT));
		for (u32 k = 0; k < 25; k++) {
			for (u32 i = 0; i < USER_PAGES; i++) {
				u32 v = 0x55000000 + r * 0x100 + i;

				ok += load_ok(user_data(i), v);
				ok += user_load_ok(user_data(i), v);
			}
		}
		set_dacr(U_DACR(D_NOACCESS));
		for (u32 i = 0; i < USER_PAGES; i++) {
			u32 a = user_data(i);

			/* Each kind of access comes first in some rounds. */
			switch ((r + i) % 3) {
			case 0:
				faulted += load_faults(a, FS_DOMAIN_SECT);
				faulted += ldrt_faults(a, FS_DOMAIN_SECT);
				faulted += user_load_faults(a, FS_DOMAIN_SECT);
				break;
			case 1:
				faulted += ldrt_faults(a, FS_DOMAIN_SECT);
				faulted += user_load_faults(a, FS_DOMAIN_SECT);
				faulted += load_faults(a, FS_DOMAIN_SECT);
				break;
			case 2:
				faulted += user_load_faults(a, FS_DOMAIN_SECT);
				faulted += load_faults(a, FS_DOMAIN_SECT);
				faulted += ldrt_faults(a, FS_DOMAIN_SECT);
				break;
			}
		}
		set_dacr(U_DACR(D_CLIENT));
		for (u32 i = 0; i < USER_PAGES; i++) {
			u32 v = 0x55000000 + r * 0x100 + i;

			ok += ldrt_ok(user_data(i), v);
			ok += user_load_ok(user_data(i), v);
			ok += load_ok(user_data(i), v);
			store_ok(user_data(i), v + 0x100);
		}
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != USER_ROUNDS * USER_PAGES * 53 ||
	    faulted != USER_ROUNDS * USER_PAGES * 3)
		bad("counted %u good loads, %u domain faults", ok, faulted);
	report("%u rounds: %u PL1/LDRT/PL0 loads worked, %u after a revoke domain-faulted",
	       USER_ROUNDS, ok, faulted);
}

/*
 * 16. User data pages that PL1 never loads (written at PL1 once, then
 * TLBIALL): their translations are hot at PL0 only, made by PL0 loads or
 * (odd rounds) by LDRT.  After a revoke, an LDRT at PL1 must take a
 * domain fault, with no PL1 access to them in between, and so must a PL0
 * load; after a grant LDRT reads the data again.
 */
static void check_user_data_pl0_only(void)
{
	u32 ok = 0, faulted = 0;

	begin("user-data-pl0-only");
	set_dacr(U_DACR(D_CLIENT));
	for (u32 i = 0; i < USER_PAGES; i++)
		store_ok(pl0_only_data(i), 0x66000000 + i);
	write_tlbiall(0);
	dsb();
	isb();
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		set_dacr(U_DACR(D_CLIENT));
		for (u32 k = 0; k < 50; k++) {
			for (u32 i = 0; i < USER_PAGES; i++) {
				u32 a = pl0_only_data(i), v = 0x66000000 + i;

				if (r & 1)
					ok += ldrt_ok(a, v);
				else
					ok += user_load_ok(a, v);
			}
		}
		set_dacr(U_DACR(D_NOACCESS));
		for (u32 i = 0; i < USER_PAGES; i++)
			faulted += ldrt_faults(pl0_only_data(i), FS_DOMAIN_SECT);
		for (u32 i = 0; i < USER_PAGES; i++)
			faulted += user_load_faults(pl0_only_data(i),
						    FS_DOMAIN_SECT);
		set_dacr(U_DACR(D_CLIENT));
		for (u32 i = 0; i < USER_PAGES; i++)
			ok += ldrt_ok(pl0_only_data(i), 0x66000000 + i);
	}
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != USER_ROUNDS * USER_PAGES * 51 ||
	    faulted != USER_ROUNDS * USER_PAGES * 2)
		bad("counted %u good loads, %u domain faults", ok, faulted);
	report("%u rounds: %u PL0/LDRT loads worked, %u revoked LDRT/PL0 ones domain-faulted",
	       USER_ROUNDS, ok, faulted);
}

/*
 * 17. The converse: user data pages loaded hot at PL1 only, never at PL0
 * nor by LDRT while accessible.  After a revoke, a PL0 load (or, in odd
 * rounds, an LDRT) comes first, then the other, then a PL1 load: all
 * must take a domain fault; after a grant PL1 loads work again.
 */
static void check_user_data_pl1_only(void)
{
	u32 ok = 0, faulted = 0;

	begin("user-data-pl1-only");
	set_dacr(U_DACR(D_CLIENT));
	for (u32 i = 0; i < USER_PAGES; i++)
		store_ok(pl1_only_data(i), 0x99000000 + i);
	for (u32 r = 0; r < USER_ROUNDS; r++) {
		set_dacr(U_DACR(D_CLIENT));
		for (u32 k = 0; k < 50; k++)
			for (u32 i = 0; i < USER_PAGES; i++)
				ok += load_ok(pl1_only_data(i), 0x99000000 + i);
		set_dacr(U_DACR(D_NOACCESS));
		for (u32 i = 0; i < USER_PAGES; i++) {
			u32 a = pl1_only_data(i);

			if (r & 1) {
				faulted += ldrt_faults(a, FS_DOMAIN_SECT);
				faulted += user_load_faults(a, FS_DOMAIN_SECT);
			} else {
				faulted += user_load_faults(a, FS_DOMAIN_SECT);
				faulted += ldrt_faults(a, FS_DOMAIN_SECT);
			}
			faulted += load_faults(a, FS_DOMAIN_SECT);
		}
	}
	set_dacr(U_DACR(D_CLIENT));
	for (u32 i = 0; i < USER_PAGES; i++)
		ok += load_ok(pl1_only_data(i), 0x99000000 + i);
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (ok != (USER_ROUNDS * 50 + 1) * USER_PAGES ||
	    faulted != USER_ROUNDS * USER_PAGES * 3)
		bad("counted %u good loads, %u domain faults", ok, faulted);
	report("%u rounds: %u PL1 loads worked, %u PL0/LDRT/PL1 ones after a revoke domain-faulted",
	       USER_ROUNDS, ok, faulted);
}

/*
 * 18. DACR reads back as written: every write of the checks above, and a
 * few patterns (domain 0 kept client, no reserved 0b10 field).
 */
static void check_readback(void)
{
	static const u32 patterns[] = {
		0x55555555, 0xfffffffd, 0x00000001, 0xc3c3c3c1, 0x3c3c3c3d,
		0x0000fff5, 0xffff0005,
	};

	begin("readback");
	for (u32 i = 0; i < ARRAY_SIZE(patterns); i++)
		set_dacr(patterns[i]);
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	if (dacr_mismatches)
		bad("%u of %u DACR writes read back wrong", dacr_mismatches,
		    dacr_writes);
	report("%u DACR writes, each read back as written", dacr_writes);
}

/* --- Exceptions ----------------------------------------------------------- */

static const char *mode_name(u32 mode)
{
	switch (mode) {
	case 0x10: return "usr";
	case 0x11: return "fiq";
	case 0x12: return "irq";
	case 0x13: return "svc";
	case 0x16: return "mon";
	case 0x17: return "abt";
	case 0x1a: return "hyp";
	case 0x1b: return "und";
	case 0x1f: return "sys";
	}
	return "?";
}

/*
 * Called by the abort entries with frame = { r0, r1, r2, r3, r12, pc },
 * pc the aborted instruction, and SPSR_abt the mode it ran in.  Only the
 * probes may abort: at PL1, or the copy of uldr and user_target in USR
 * mode.  The read of the SVC number in vec_svc is let pass (see start.S).
 */
void fault_entry(u32 kind, u32 *frame)
{
	const u32 uldr = UPROBE_LDR + (u32)(uldr_insn - uldr_start);
	u32 pc = frame[5], spsr = read_spsr();
	int from_usr = (spsr & MODE_MASK) == MODE_USR;

	if (kind == DATA_ABORT && !from_usr && pc == (u32)svc_read_insn) {
		svc_unread++;
		frame[4] = USER_SVC;	/* r12, the SVC number */
		frame[5] = pc + 4;
	} else if (kind == DATA_ABORT &&
		   (from_usr ? pc == uldr :
			       pc == (u32)probe_ldr_insn ||
			       pc == (u32)probe_str_insn ||
			       pc == (u32)probe_ldrt_insn)) {
		fault.fsr = read_dfsr();
		fault.far = read_dfar();
		fault.kind = kind;
		frame[0] = POISON;	/* a faulted load reads nothing */
		frame[5] = pc + 4;
	} else if (kind == PREFETCH_ABORT && call_target && pc == call_target) {
		fault.fsr = read_ifsr();
		fault.far = read_ifar();
		fault.kind = kind;
		frame[0] = POISON;	/* the callee did not run */
		frame[5] = (u32)probe_call_ret;
	} else if (kind == PREFETCH_ABORT && from_usr && user_target &&
		   pc == user_target) {
		fault.fsr = read_ifsr();
		fault.far = read_ifar();
		fault.kind = kind;
		frame[0] = POISON;
		/* Back to the caller of user_call, in SVC mode. */
		frame[5] = (u32)user_call_ret;
		write_spsr((spsr & ~MODE_MASK) | MODE_SVC);
	} else {
		pr("unexpected %s abort at %x in %s mode: DFSR %x DFAR %x IFSR %x IFAR %x",
		   kind == DATA_ABORT ? "data" : "prefetch", pc,
		   mode_name(spsr & MODE_MASK), read_dfsr(), read_dfar(),
		   read_ifsr(), read_ifar());
		pr("stopped in check %s", check ? check : "(start)");
		sys_exit(100);
	}
	faults_taken++;
}

void unexpected_exception(u32 vec, u32 lr)
{
	pr("unexpected exception, vector %x, LR %x", vec, lr);
	pr("stopped in check %s", check ? check : "(start)");
	sys_exit(101);
}

/* --- Setup ------------------------------------------------------------------- */

static void mmu_on(void)
{
	u32 sctlr;

	/* RAM (0x80000000, 256 MB): domain 0, PL1 read/write, cacheable. */
	for (u32 mb = 0x800; mb < 0x900; mb++)
		ttb[mb] = mb << 20 | SD_SECTION | SD_NORMAL_WB | SD_PL1_RW |
			  SD_DOMAIN(0);
	ttb[SECT_DATA >> 20] = SECT_DATA | SD_SECTION | SD_NORMAL_WB |
			       SD_PL1_RW | SD_DOMAIN(1);
	ttb[SECT_RO >> 20] = SECT_RO | SD_SECTION | SD_NORMAL_WB |
			     SD_PL1_RO | SD_DOMAIN(1);
	ttb[SECT_CODE >> 20] = SECT_CODE | SD_SECTION | SD_NORMAL_WB |
			       SD_PL1_RW | SD_DOMAIN(1);
	ttb[SECT_OTHER >> 20] = SECT_OTHER | SD_SECTION | SD_NORMAL_WB |
				SD_PL1_RW | SD_DOMAIN(2);
	ttb[SECT_XN >> 20] = SECT_XN | SD_SECTION | SD_NORMAL_WB | SD_PL1_RW |
			     SD_XN | SD_DOMAIN(1);
	ttb[SECT_PAGES >> 20] = (u32)l2_pages | L1_PAGE_TABLE | SD_DOMAIN(1);
	/* The user-mode megabytes: PL0 may use them (but for SECT_UPRIV). */
	ttb[SECT_USER >> 20] = SECT_USER | SD_SECTION | SD_NORMAL_WB |
			       SD_PL0_RW | SD_DOMAIN(3);
	ttb[SECT_UPROBE >> 20] = SECT_UPROBE | SD_SECTION | SD_NORMAL_WB |
				 SD_PL0_RW | SD_DOMAIN(0);
	ttb[SECT_UPRIV >> 20] = SECT_UPRIV | SD_SECTION | SD_NORMAL_WB |
				SD_PL1_RW | SD_DOMAIN(3);
	for (u32 i = 0; i < 256; i++)
		l2_pages[i] = (SECT_PAGES + (i << 12)) | PD_SMALL |
			      PD_NORMAL_WB | PD_PL1_RW;
	dsb();

	write_vbar((u32)vectors);
	write_ttbcr(0);
	write_ttbr0((u32)ttb);
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	write_tlbiall(0);
	write_iciallu(0);
	dsb();
	isb();

	sctlr = read_sctlr();
	/* No WXN/UWXN: PL1 runs the CPS gate, which PL0 may write. */
	sctlr &= ~(SCTLR_A | SCTLR_V | SCTLR_WXN | SCTLR_UWXN | SCTLR_TRE |
		   SCTLR_AFE);
	sctlr |= SCTLR_M | SCTLR_C | SCTLR_I | SCTLR_Z;
	write_sctlr(sctlr);
	isb();
}

/*
 * The user-mode code: the load probe and the CPS gate in domain 0, the
 * functions in domain 3 (granted while they are copied); and a stack.
 */
static void user_setup(void)
{
	put_code(UPROBE_LDR, uldr_start, uldr_end);
	put_code(UPROBE_GATE, ugate_start, ugate_end);
	set_dacr(U_DACR(D_CLIENT));
	put_code(UFN, ufn42_start, ufn42_end);
	put_code(UFN2, ufn42_start, ufn42_end);
	put_code(UPRIV_FN, ufn42_start, ufn42_end);
	set_dacr(DACR(D_CLIENT, D_CLIENT));
	set_user_sp(USER_STACK_TOP);
}

void main(void)
{
	u32 cpsr, fn = SECT_CODE + 0x40;

	check = "setup";
	asm volatile("mrs %0, cpsr" : "=r"(cpsr));
	pr("entered in %s mode (CPSR %x), running in %s mode",
	   mode_name(boot_cpsr & 0x1f), boot_cpsr, mode_name(cpsr & 0x1f));
	if ((cpsr & 0x1f) != 0x13) {
		pr("not in SVC mode, cannot run");
		sys_exit(102);
	}
	mmu_on();
	put_fn42(fn);
	user_setup();
	pr("MMU on; domain 1: data %x, read-only %x, code %x, XN %x, pages %x",
	   SECT_DATA, SECT_RO, SECT_CODE, SECT_XN, SECT_PAGES);
	pr("domain 2: data %x; domain 3: user %x, PL1-only %x", SECT_OTHER,
	   SECT_USER, SECT_UPRIV);
	pr("domain 0: this program, user probes %x", SECT_UPROBE);

	check_load_domain();
	check_store_manager_client();
	check_fetch_manager_client();
	check_same_value(fn);
	check_fetch_hot(fn);
	check_data_then_fetch();
	check_other_domain(fn);
	check_page_domain();
	check_user_fetch_revoke();
	check_user_fetch_restore();
	check_user_fetch_revoke_again();
	check_user_fetch_cps();
	check_user_fetch_other_domain();
	check_user_manager_client();
	check_user_data_revoke();
	check_user_data_pl0_only();
	check_user_data_pl1_only();
	check_readback();

	pr("%u checks, %u failed, %u faults taken", checks_run, checks_failed,
	   faults_taken);
	pr("end");
	sys_exit(checks_failed);
}
