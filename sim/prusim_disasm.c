// SPDX-License-Identifier: GPL-2.0-only
/*
 * prusim disassembler: prints one PRU v3 instruction word exactly as the GNU
 * pru-objdump does (mnemonic, a tab, then comma separated operands, with the
 * assembler's pseudo-ops nop, mov, ret, call, wbs, wbc, fill and zero).
 * Branch targets are printed as plain addresses ("0x%x"), as objdump does for
 * an image without symbols.
 */

#include "prusim.h"

/* Fields of an instruction word (TI SPRUIJ2 / AM335x TRM formats 1..6) */
#define F(insn, sh, bits)	(((insn) >> (sh)) & ((1u << (bits)) - 1))
#define RD(i)		F(i, 0, 5)
#define RDSEL(i)	F(i, 5, 3)
#define RDB(i)		F(i, 5, 2)
#define RS1(i)		F(i, 8, 5)
#define RS1SEL(i)	F(i, 13, 3)
#define RS2(i)		F(i, 16, 5)
#define RS2SEL(i)	F(i, 21, 3)
#define IO(i)		F(i, 24, 1)
#define IMM8(i)		F(i, 16, 8)
#define IMM16(i)	F(i, 8, 16)
#define SUBOP(i)	F(i, 25, 4)

#define SUBOP_OR	9
#define SUBOP_NOT	11
#define SEL_W2		6	/* .w2 field select, used by call/ret */
#define SEL_FULL	7
#define BURST_R0	124	/* burst length codes 124..127: R0.b0..b3 */

struct prusim_out {
	char *buf;
	size_t size;
	size_t len;
};

static __printf(2, 3) void out(struct prusim_out *o, const char *fmt, ...)
{
	va_list ap;
	int n;

	va_start(ap, fmt);
	n = vsnprintf(o->buf + o->len, o->len < o->size ? o->size - o->len : 0, fmt, ap);
	va_end(ap);
	if (n > 0)
		o->len += n;
}

static void out_reg(struct prusim_out *o, u32 reg, u32 sel)
{
	static const char *const suffix[8] = {
		".b0", ".b1", ".b2", ".b3", ".w0", ".w1", ".w2", ""
	};
	static const char *const alias[5] = { NULL, NULL, "sp", "ra", "fp" };

	if (reg < 5 && alias[reg])
		out(o, "%s%s", alias[reg], suffix[sel]);
	else
		out(o, "r%u%s", reg, suffix[sel]);
}

/* Second ALU operand: an 8-bit immediate (plus @bias) or a register field */
static void out_op2(struct prusim_out *o, u32 insn, u32 bias)
{
	if (IO(insn))
		out(o, "%u", IMM8(insn) + bias);
	else
		out_reg(o, RS2(insn), RS2SEL(insn));
}

/* Burst or XFR length: 1..124 bytes, or the count in R0.b0..b3 */
static void out_len(struct prusim_out *o, u32 code)
{
	if (code < BURST_R0)
		out(o, "%u", code + 1);
	else
		out(o, "r0.b%u", code - BURST_R0);
}

static void out_undefined(struct prusim_out *o, u32 insn)
{
	out(o, "0x%x", insn);
}

static void dis_format1(struct prusim_out *o, u32 insn)
{
	static const char *const names[16] = {
		"add", "adc", "sub", "suc", "lsl", "lsr", "rsb", "rsc",
		"and", "or", "xor", "not", "min", "max", "clr", "set"
	};
	u32 sub = SUBOP(insn);

	if (sub == SUBOP_OR && (insn & 0x01ffffff) == 0x00e0e0e0) {
		out(o, "nop");
		return;
	}
	if (sub == SUBOP_NOT && !IO(insn)) {
		out_undefined(o, insn);
		return;
	}
	if (sub == SUBOP_NOT || (sub == SUBOP_OR && IO(insn) && !IMM8(insn))) {
		out(o, "%s\t", sub == SUBOP_NOT ? "not" : "mov");
		out_reg(o, RD(insn), RDSEL(insn));
		out(o, ", ");
		out_reg(o, RS1(insn), RS1SEL(insn));
		return;
	}
	out(o, "%s\t", names[sub]);
	out_reg(o, RD(insn), RDSEL(insn));
	out(o, ", ");
	out_reg(o, RS1(insn), RS1SEL(insn));
	out(o, ", ");
	out_op2(o, insn, 0);
}

/* JMP/JAL target: an IRAM word address or a register */
static void out_jump(struct prusim_out *o, u32 insn, u32 addr)
{
	if (IO(insn))
		out(o, "0x%x", IMM16(insn) * 4 + (addr & ~0x3fffffu));
	else
		out_reg(o, RS2(insn), RS2SEL(insn));
}

static void dis_xfr(struct prusim_out *o, u32 insn)
{
	static const char *const names[4] = { NULL, "xin", "xout", "xchg" };
	u32 kind = F(insn, 23, 2);
	u32 wba = F(insn, 15, 8);
	bool scan = F(insn, 14, 1);

	if (!kind) {
		out_undefined(o, insn);
		return;
	}
	if (kind == 1 && !scan && wba >= 254)
		out(o, "%s\t", wba == 254 ? "fill" : "zero");
	else
		out(o, "%s%s\t%u, ", scan ? "s" : "", names[kind], wba);
	out_reg(o, RD(insn), RDB(insn));
	out(o, ", ");
	out_len(o, F(insn, 7, 7));
}

static void dis_format2(struct prusim_out *o, u32 insn, u32 addr)
{
	switch (SUBOP(insn)) {
	case 0:
		if (!IO(insn) && RS2SEL(insn) == SEL_W2 && RS2(insn) == 3) {
			out(o, "ret");
			return;
		}
		out(o, "jmp\t");
		break;
	case 1:
		if (RDSEL(insn) == SEL_W2 && RD(insn) == 3) {
			out(o, "call\t");
		} else {
			out(o, "jal\t");
			out_reg(o, RD(insn), RDSEL(insn));
			out(o, ", ");
		}
		break;
	case 2:
		out(o, "ldi\t");
		out_reg(o, RD(insn), RDSEL(insn));
		out(o, ", %u", IMM16(insn));
		return;
	case 3:
		out(o, "lmbd\t");
		out_reg(o, RD(insn), RDSEL(insn));
		out(o, ", ");
		out_reg(o, RS1(insn), RS1SEL(insn));
		out(o, ", ");
		out_op2(o, insn, 0);
		return;
	case 5:
		out(o, "halt");
		return;
	case 7:
		dis_xfr(o, insn);
		return;
	case 8:
		out(o, "%s\t0x%x, ", F(insn, 15, 1) ? "iloop" : "loop", addr + F(insn, 0, 8) * 4);
		out_op2(o, insn, 1);
		return;
	case 15:
		out(o, "slp\t%u", F(insn, 23, 1));
		return;
	default:
		out_undefined(o, insn);
		return;
	}
	out_jump(o, insn, addr);
}

/* Quick branch target: a signed 10-bit word offset in bits 26:25 and 7:0 */
static u32 qb_target(u32 insn, u32 addr)
{
	u32 raw = F(insn, 25, 2) << 8 | F(insn, 0, 8);

	return addr + (raw & 0x200 ? raw - 0x400 : raw) * 4;
}

static void dis_format4(struct prusim_out *o, u32 insn, u32 addr)
{
	static const char *const names[8] = {
		NULL, "qblt", "qbeq", "qble", "qbgt", "qbne", "qbge", "qba"
	};
	u32 cond = F(insn, 27, 3);

	if (!cond) {
		out_undefined(o, insn);
		return;
	}
	out(o, "%s\t0x%x", names[cond], qb_target(insn, addr));
	if (cond == 7)
		return;
	out(o, ", ");
	out_reg(o, RS1(insn), RS1SEL(insn));
	out(o, ", ");
	out_op2(o, insn, 0);
}

static void dis_format5(struct prusim_out *o, u32 insn, u32 addr)
{
	u32 bits = F(insn, 27, 2);
	bool wait = !(insn & 0x060000ff);

	if (bits != 1 && bits != 2) {
		out_undefined(o, insn);
		return;
	}
	/* A bit branch to itself waits: qbbs to self is "wbc", qbbc is "wbs" */
	if (wait)
		out(o, "%s\t", bits == 2 ? "wbc" : "wbs");
	else
		out(o, "%s\t0x%x, ", bits == 2 ? "qbbs" : "qbbc", qb_target(insn, addr));
	out_reg(o, RS1(insn), RS1SEL(insn));
	out(o, ", ");
	out_op2(o, insn, 0);
}

static void dis_format6(struct prusim_out *o, u32 insn, bool cbase)
{
	bool load = F(insn, 28, 1);
	u32 len = F(insn, 25, 3) << 4 | F(insn, 13, 3) << 1 | F(insn, 7, 1);

	out(o, "%s%s\t", load ? "l" : "s", cbase ? "bco" : "bbo");
	out_reg(o, RD(insn), RDB(insn));
	if (cbase) {
		out(o, ", %u, ", RS1(insn));
	} else {
		out(o, ", ");
		out_reg(o, RS1(insn), SEL_FULL);
		out(o, ", ");
	}
	out_op2(o, insn, 0);
	out(o, ", ");
	out_len(o, len);
}

/**
 * prusim_disasm() - disassemble one instruction like pru-objdump
 * @buf: output buffer
 * @size: size of @buf; the text is truncated to fit
 * @insn: instruction word
 * @addr: byte address of the instruction, used for branch targets (the GNU
 *	tools place IRAM at 0x20000000)
 *
 * Return: length of the full text (as snprintf()).
 */
int prusim_disasm(char *buf, size_t size, u32 insn, u32 addr)
{
	struct prusim_out o = { .buf = buf, .size = size };

	if (size)
		buf[0] = '\0';
	switch (insn >> 29) {
	case 0:
		dis_format1(&o, insn);
		break;
	case 1:
		dis_format2(&o, insn, addr);
		break;
	case 2:
	case 3:
		dis_format4(&o, insn, addr);
		break;
	case 4:
		dis_format6(&o, insn, true);
		break;
	case 6:
		dis_format5(&o, insn, addr);
		break;
	case 7:
		dis_format6(&o, insn, false);
		break;
	default:
		out_undefined(&o, insn);
		break;
	}
	return o.len;
}
