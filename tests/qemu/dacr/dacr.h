/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * What start.S and dacr.c share: the kinds of abort fault_entry() is
 * given, the SVC number of user mode, and (for C) the symbols of start.S
 * and the C functions it calls.
 */
#ifndef DACR_H
#define DACR_H

#define DATA_ABORT	1
#define PREFETCH_ABORT	2

/*
 * The SVC that ends a user_call() (any other SVC is fatal).  Semihosting
 * uses SVC 0x123456, which QEMU handles before it reaches the vector.
 */
#define USER_SVC	0x42

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

/* An unprivileged (PL0 translation) load at PL1, as probe_ldr. */
u32 probe_ldrt(u32 addr);
extern char probe_ldrt_insn[];

/*
 * Run fn(arg) in USR mode, entered by an exception return (user_call) or
 * by a CPS to USR mode in gate, then a branch (user_call_cps).  fn ends
 * with SVC USER_SVC, which returns its r0 to the caller; fault_entry()
 * may return there too (user_call_ret), if fn itself prefetch-aborts.
 */
u32 user_call(u32 fn, u32 arg);
u32 user_call_cps(u32 fn, u32 arg, u32 gate);
extern char user_call_ret[], svc_read_insn[];

/*
 * The words of the user-mode code, copied where it is to run: "return
 * 42", a load of [r0] (both ending with SVC USER_SVC) and the CPS gate.
 */
extern char ufn42_start[], ufn42_end[];
extern char uldr_start[], uldr_insn[], uldr_end[];
extern char ugate_start[], ugate_end[];
void set_user_sp(u32 sp);

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
