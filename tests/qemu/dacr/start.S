/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Entry, exception vectors and the probes of the DACR test.
 *
 * QEMU 7.2 enters a non-Linux ELF at its entry point straight out of CPU
 * reset: SVC mode (Secure SVC with vexpress-a15's default EL3), IRQ/FIQ
 * masked, MMU off; so it does with secure=off and virtualization=on or
 * off.  Should something leave us in Hyp mode, we return to SVC first
 * (tried by entering Hyp through HVC).  Then each exception mode gets a
 * stack, .bss is cleared and main() runs in SVC mode.
 *
 * The probes are the only instructions that may abort on purpose:
 *  - probe_ldr/probe_str/probe_ldrt, and the copied user-mode load uldr:
 *    a data abort on their one access is recorded by fault_entry(), which
 *    then resumes at the next instruction;
 *  - probe_call: a prefetch abort on the called address is recorded and
 *    resumes at probe_call_ret, as if the callee had returned;
 *  - user_call/user_call_cps: a prefetch abort on the user function is
 *    recorded and resumes at user_call_ret, in SVC mode.
 * The only SVC that may reach the vector is USER_SVC from USR mode, inside
 * a user_call: it returns to the caller of user_call.  Any other exception
 * is fatal (unexpected_exception() reports and exits).
 */
#include "dacr.h"

	.syntax	unified
	.arm

#define MODE_USR	0x10
#define MODE_FIQ	0x11
#define MODE_IRQ	0x12
#define MODE_SVC	0x13
#define MODE_ABT	0x17
#define MODE_HYP	0x1a
#define MODE_UND	0x1b
#define MODE_SYS	0x1f
#define PSR_T		0x20
#define PSR_I		0x80
#define PSR_F		0x40

	.section .text.start, "ax"
	.global	_start
_start:
	mrs	r4, cpsr		@ r4 = CPSR at entry, for main() to print
	and	r5, r4, #0x1f
	cmp	r5, #MODE_HYP
	bne	1f
	/* Hyp mode: return to SVC mode, interrupts masked, at 1. */
	.arch_extension virt
	bic	r5, r4, #0x1f
	orr	r5, r5, #(MODE_SVC | PSR_I | PSR_F)
	msr	spsr_cxsf, r5		@ SPSR_hyp, the current SPSR
	adr	r5, 1f
	msr	elr_hyp, r5
	eret
1:
	/* One stack for each mode we may run in; the fatal ones share. */
	cpsid	if, #MODE_ABT
	ldr	sp, =abt_stack_top
	cpsid	if, #MODE_UND
	ldr	sp, =exc_stack_top
	cpsid	if, #MODE_IRQ
	ldr	sp, =exc_stack_top
	cpsid	if, #MODE_FIQ
	ldr	sp, =exc_stack_top
	cpsid	if, #MODE_SVC
	ldr	sp, =svc_stack_top

	/* Clear .bss (the stacks are in it, but none is in use yet). */
	ldr	r0, =__bss_start
	ldr	r1, =__bss_end
	mov	r2, #0
2:	cmp	r0, r1
	strlo	r2, [r0], #4
	blo	2b

	ldr	r0, =boot_cpsr
	str	r4, [r0]
	bl	main
	b	.			@ main() exits through semihosting

/*
 * Vector table, for VBAR (32-byte aligned).  Only the two aborts and the
 * user SVC are expected; the rest report which vector was taken and stop.
 */
	.text
	.align	5
	.global	vectors
vectors:
	b	vec_reset		@ 0x00
	b	vec_undef		@ 0x04
	b	vec_svc			@ 0x08
	b	pabt_entry		@ 0x0c
	b	dabt_entry		@ 0x10
	b	vec_hyp			@ 0x14
	b	vec_irq			@ 0x18
	b	vec_fiq			@ 0x1c

	.macro	unexpected name, vec
\name:	mov	r0, #\vec
	mov	r1, lr
	b	unexpected
	.endm

	unexpected vec_reset, 0x00
	unexpected vec_undef, 0x04
	unexpected svc_bad, 0x08
	unexpected vec_hyp, 0x14
	unexpected vec_irq, 0x18
	unexpected vec_fiq, 0x1c

unexpected:
	bl	unexpected_exception	@ does not return
	b	.

/*
 * SVC: accepted only from ARM-state USR mode, inside a user_call, and for
 * SVC USER_SVC; then it returns the user's r0 to the caller of user_call.
 * The SVC instruction is read with LDRT, through the PL0 translation that
 * just fetched it, so that this adds no PL1 translation of user memory.
 * Should that read abort (user code ran although DACR forbids its page:
 * the bug under test), fault_entry() lets it pass as USER_SVC, and the
 * check sees a call that returned instead of aborting.
 */
vec_svc:
	mrs	r12, spsr
	and	r12, r12, #(PSR_T | 0x1f)
	cmp	r12, #MODE_USR
	bne	svc_bad
	ldr	r12, =user_call_sp
	ldr	r12, [r12]
	cmp	r12, #0
	beq	svc_bad
	sub	r1, lr, #4
	.global	svc_read_insn
svc_read_insn:
	ldrt	r12, [r1]		@ the SVC instruction
	bic	r12, r12, #0xff000000	@ its number
	cmp	r12, #USER_SVC
	bne	svc_bad
	b	user_call_ret

/*
 * The aborts: save the caller-saved registers and the address of the
 * aborted instruction as a frame { r0, r1, r2, r3, r12, pc } on the abort
 * stack, let fault_entry(kind, frame) record the fault and rewrite frame
 * r0 and pc, then return there with CPSR from SPSR_abt.
 */
	.macro	abort_entry name, lr_ahead, kind
\name:
	sub	lr, lr, #\lr_ahead	@ LR_abt = aborted instruction + lr_ahead
	push	{r0-r3, r12, lr}
	mov	r0, #\kind
	mov	r1, sp
	bl	fault_entry
	pop	{r0-r3, r12, lr}
	movs	pc, lr
	.endm

	abort_entry dabt_entry, 8, DATA_ABORT
	abort_entry pabt_entry, 4, PREFETCH_ABORT

/* u32 probe_ldr(u32 addr): one load from addr. */
	.global	probe_ldr, probe_ldr_insn
probe_ldr:
probe_ldr_insn:
	ldr	r0, [r0]
	bx	lr

/* void probe_str(u32 addr, u32 val): one store to addr. */
	.global	probe_str, probe_str_insn
probe_str:
probe_str_insn:
	str	r1, [r0]
	bx	lr

/*
 * u32 probe_ldrt(u32 addr): one load from addr with PL0 permissions and
 * translation (LDRT post-indexes, so its base may not be its target).
 */
	.global	probe_ldrt, probe_ldrt_insn
probe_ldrt:
	mov	r1, r0
probe_ldrt_insn:
	ldrt	r0, [r1]
	bx	lr

/* u32 probe_call(u32 fn): call fn through a register, return its r0. */
	.global	probe_call, probe_call_ret
probe_call:
	push	{r4, lr}
	blx	r0
probe_call_ret:
	pop	{r4, pc}

/* The function copied into domain 1; its words are copied, not called. */
	.global	fn42_start, fn42_end
fn42_start:
	mov	r0, #42
	bx	lr
fn42_end:

/*
 * u32 user_call(u32 fn, u32 arg): run fn(arg) in USR mode, entered by an
 * exception return as Linux returns to user space, with IRQ/FIQ still
 * masked.  SVC mode's SP is kept in user_call_sp, for vec_svc and for the
 * prefetch abort that resumes at user_call_ret; both return r0.
 */
	.global	user_call, user_call_cps, user_call_ret
user_call:
	push	{r4-r12, lr}
	ldr	r2, =user_call_sp
	str	sp, [r2]
	mrs	r2, cpsr
	bic	r2, r2, #0x1f
	orr	r2, r2, #MODE_USR
	msr	spsr_cxsf, r2
	mov	lr, r0
	mov	r0, r1
	movs	pc, lr

/*
 * u32 user_call_cps(u32 fn, u32 arg, u32 gate): the same, but entered by
 * the gate (a copy of ugate, fetchable at PL0 and PL1), which changes to
 * USR mode with CPS and then branches to fn: no exception return.
 */
user_call_cps:
	push	{r4-r12, lr}
	ldr	r3, =user_call_sp
	str	sp, [r3]
	mov	r12, r0
	mov	r0, r1
	bx	r2

user_call_ret:
	ldr	r1, =user_call_sp
	ldr	sp, [r1]
	mov	r2, #0
	str	r2, [r1]
	pop	{r4-r12, pc}

/* void set_user_sp(u32 sp): USR mode's SP, set from SYS mode. */
	.global	set_user_sp
set_user_sp:
	mrs	r1, cpsr
	cps	#MODE_SYS
	mov	sp, r0
	msr	cpsr_c, r1
	bx	lr

/*
 * The user-mode code, copied where it is to run (not called here): a
 * "return 42", a load of [r0] (a probe: see fault_entry()), and the gate
 * of user_call_cps, entered at PL1 with fn in r12.
 */
	.global	ufn42_start, ufn42_end, uldr_start, uldr_insn, uldr_end
	.global	ugate_start, ugate_end
ufn42_start:
	mov	r0, #42
	svc	#USER_SVC
ufn42_end:
uldr_start:
uldr_insn:
	ldr	r0, [r0]
	svc	#USER_SVC
uldr_end:
ugate_start:
	cps	#MODE_USR
	bx	r12
ugate_end:

	.bss
	.global	ttb, l2_pages, boot_cpsr
	.align	14
ttb:	.space	16384			@ first-level table
	.align	10
l2_pages:
	.space	1024			@ second-level table
boot_cpsr:
	.space	4
user_call_sp:				@ SVC SP in a user_call, else 0
	.space	4
	.align	3
	.space	16384
svc_stack_top:
	.space	4096
abt_stack_top:
	.space	4096
exc_stack_top:
