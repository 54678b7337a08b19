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
 *  - probe_ldr/probe_str: a data abort on their one access is recorded by
 *    fault_entry(), which then resumes at the next instruction;
 *  - probe_call: a prefetch abort on the called address is recorded and
 *    resumes at probe_call_ret, as if the callee had returned.
 * Any other exception is fatal (unexpected_exception() reports and exits).
 */
#include "dacr.h"

	.syntax	unified
	.arm

#define MODE_FIQ	0x11
#define MODE_IRQ	0x12
#define MODE_SVC	0x13
#define MODE_ABT	0x17
#define MODE_HYP	0x1a
#define MODE_UND	0x1b
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
 * Vector table, for VBAR (32-byte aligned).  Only the two aborts are
 * expected; the rest report which vector was taken and stop.
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
	unexpected vec_svc, 0x08
	unexpected vec_hyp, 0x14
	unexpected vec_irq, 0x18
	unexpected vec_fiq, 0x1c

unexpected:
	bl	unexpected_exception	@ does not return
	b	.

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

	.bss
	.global	ttb, l2_pages, boot_cpsr
	.align	14
ttb:	.space	16384			@ first-level table
	.align	10
l2_pages:
	.space	1024			@ second-level table
boot_cpsr:
	.space	4
	.align	3
	.space	16384
svc_stack_top:
	.space	4096
abt_stack_top:
	.space	4096
exc_stack_top:
