/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * What start.S and dacr.c share: the kinds of abort fault_entry() is
 * given, and (for C) the symbols of start.S and the C functions it calls.
 */
#ifndef DACR_H
#define DACR_H

#define DATA_ABORT	1
#define PREFETCH_ABORT	2

#ifndef __ASSEMBLER__

typedef unsigned int u32;

/* One access each; an abort on it resumes after it (see start.S). */
u32 probe_ldr(u32 addr);
void probe_str(u32 addr, u32 val);
/* Calls fn; a prefetch abort on fn itself resumes at probe_call_ret. */
u32 probe_call(u32 fn);
extern char probe_ldr_insn[], probe_str_insn[], probe_call_ret[];

/* The words of a "return 42" function, to copy where it is to run. */
extern char fn42_start[], fn42_end[];

extern char vectors[];
extern u32 ttb[4096];		/* first-level table, 16 KB aligned */
extern u32 l2_pages[256];	/* a second-level table, 1 KB aligned */
extern u32 boot_cpsr;		/* CPSR at entry */

/* Called from start.S. */
void main(void);
void fault_entry(u32 kind, u32 *frame);
void unexpected_exception(u32 vec, u32 lr);

#endif /* __ASSEMBLER__ */
#endif /* DACR_H */
