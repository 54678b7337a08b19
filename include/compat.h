/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * Kernel API differences between Linux 5.10 and 6.12 that prukit meets.
 *
 * This is the only file in prukit that tests the kernel version.  Each entry
 * names the upstream release that changed the interface; drivers use the
 * prukit_* names below and never test versions themselves.
 */
#ifndef PRUKIT_COMPAT_H
#define PRUKIT_COMPAT_H

#include <linux/version.h>

#if LINUX_VERSION_CODE < KERNEL_VERSION(5, 10, 0)
#error "prukit needs Linux 5.10 or later"
#endif

/*
 * v6.2: struct class.devnode() takes a const struct device *
 * ("driver core: make struct class.devnode() take a const *").
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 2, 0)
#define PRUKIT_CLASS_DEVNODE_CONST	const
#else
#define PRUKIT_CLASS_DEVNODE_CONST
#endif

/*
 * v5.11: kmap_local_page()/kunmap_local() ("mm/highmem: Provide
 * kmap_local*"); before, kmap_atomic() is the short-lived mapping.
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 11, 0)
#define prukit_kmap_local_page(page)	kmap_local_page(page)
#define prukit_kunmap_local(addr)	kunmap_local(addr)
#else
#define prukit_kmap_local_page(page)	kmap_atomic(page)
#define prukit_kunmap_local(addr)	kunmap_atomic(addr)
#endif

/*
 * v5.11: the rpmsg name service became an rpmsg device of its own, bound to
 * the rpmsg_ns driver ("rpmsg: Turn name service into a stand alone
 * driver"); it takes only the 40-byte announcement.  TI's kernels (5.10-ti
 * on: "TI-HACK: rpmsg: introduce rpmsg_ns_msg_ext") give channels a
 * description and take the support package's 72-byte form too.  Decided
 * by the kernel's <linux/rpmsg.h> (the top-level Kbuild:
 * PRUKIT_HAVE_RPMSG_DESC): prukit_pru converts the 72-byte form
 * (prukit_pru_ns.c) where the name service is such a device and refuses it.
 */
#if IS_ENABLED(CONFIG_RPMSG) && !defined(PRUKIT_HAVE_RPMSG_DESC) && \
	LINUX_VERSION_CODE >= KERNEL_VERSION(5, 11, 0)
#define PRUKIT_PRU_NS_HOOK
#endif

/*
 * v6.3: vma->vm_flags became const, changed through vm_flags_set() and
 * vm_flags_clear() ("mm: introduce vma->vm_flags wrapper functions").
 * Decided by the kernel's <linux/mm.h> (the top-level Kbuild:
 * PRUKIT_HAVE_VM_FLAGS_CLEAR): Debian's 6.1 lacks it, 6.12 has it.
 */
#ifdef PRUKIT_HAVE_VM_FLAGS_CLEAR
#define prukit_vm_flags_clear(vma, flags)	vm_flags_clear(vma, flags)
#else
#define prukit_vm_flags_clear(vma, flags)	((vma)->vm_flags &= ~(flags))
#endif

/*
 * v5.11: rproc_set_firmware() ("remoteproc: Add a rproc_set_firmware()
 * API"); TI's 5.10 has it too (backported).  Decided by the kernel's
 * <linux/remoteproc.h> (the top-level Kbuild: PRUKIT_HAVE_RPROC_SET_FIRMWARE).
 * Without it, do what remoteproc's sysfs "firmware" store does.
 */
#ifdef PRUKIT_HAVE_RPROC_SET_FIRMWARE
#define prukit_rproc_set_firmware(rproc, name)	rproc_set_firmware(rproc, name)
#else
#include <linux/remoteproc.h>
#include <linux/slab.h>
static inline int prukit_rproc_set_firmware(struct rproc *rproc, const char *name)
{
	char *p;
	int ret;

	if (!name || !*name)
		return -EINVAL;
	ret = mutex_lock_interruptible(&rproc->lock);
	if (ret)
		return ret;
	if (rproc->state != RPROC_OFFLINE) {
		ret = -EBUSY;
		goto out;
	}
	p = kstrdup(name, GFP_KERNEL);
	if (!p) {
		ret = -ENOMEM;
		goto out;
	}
	kfree(rproc->firmware);
	rproc->firmware = p;
out:
	mutex_unlock(&rproc->lock);
	return ret;
}
#endif

/*
 * rproc_vq_interrupt(): exported by the remoteproc core (remoteproc_virtio.c)
 * but declared only in drivers/remoteproc/remoteproc_internal.h, which a
 * module built outside the kernel tree cannot include; unchanged from v3.4
 * to v6.12.  The same on every kernel, here beside its kin.  Checked at
 * build time against each kernel prukit builds the PRU drivers for
 * (scripts/pru-kit.sh compiles this line after the kernel's own: 5.10, 6.1,
 * 6.12 and 6.12-ti's remoteproc core); keep it on one line.
 */
#include <linux/irqreturn.h>
struct rproc;
irqreturn_t rproc_vq_interrupt(struct rproc *rproc, int vq_id);

/*
 * rproc_da_to_va(): exported since v3.4 but declared only in
 * drivers/remoteproc/remoteproc_internal.h until v5.18 ("remoteproc: move
 * rproc_da_to_va declaration to remoteproc.h"); v5.13 added "bool
 * *is_iomem" to it and to rproc_ops.da_to_va ("remoteproc: add is_iomem to
 * da_to_va").  TI backported both into some of its 5.10 trees and not into
 * others (5.10.100-ti has the declaration without is_iomem), so both are
 * decided by the kernel's <linux/remoteproc.h> (the top-level Kbuild:
 * PRUKIT_HAVE_RPROC_DA_TO_VA_DECL, PRUKIT_HAVE_RPROC_DA_TO_VA_IOMEM).
 */
#include <linux/types.h>
#ifndef PRUKIT_HAVE_RPROC_DA_TO_VA_DECL
#ifdef PRUKIT_HAVE_RPROC_DA_TO_VA_IOMEM
void *rproc_da_to_va(struct rproc *rproc, u64 da, size_t len, bool *is_iomem);
#else
void *rproc_da_to_va(struct rproc *rproc, u64 da, size_t len);
#endif
#endif
#ifdef PRUKIT_HAVE_RPROC_DA_TO_VA_IOMEM
#define prukit_rproc_da_to_va(rproc, da, len, is_iomem) \
	rproc_da_to_va(rproc, da, len, is_iomem)
#else
#define prukit_rproc_da_to_va(rproc, da, len, is_iomem) \
	({ *(is_iomem) = false; rproc_da_to_va(rproc, da, len); })
#endif

/*
 * pru_rproc_get()/pru_rproc_put(): the kernel's PRU remoteproc driver hands
 * out its cores.  Decided by what the kernel has, not by its version (TI's
 * 6.1 and Debian's 6.1 are both "6.1"): the driver must be configured, and
 * its header is <linux/remoteproc/pruss.h> (mainline since v6.4, TI's 6.1)
 * or <linux/pruss.h> (TI's 5.10).  Without them, every core is reached
 * with rproc_get_by_phandle().
 */
/* (The top-level Kbuild looks for the headers: PRUKIT_HAVE_*_PRUSS_H.) */
#if IS_ENABLED(CONFIG_PRU_REMOTEPROC) && defined(PRUKIT_HAVE_REMOTEPROC_PRUSS_H)
#include <linux/remoteproc/pruss.h>
#define PRUKIT_HAVE_PRU_RPROC_GET	1
#elif IS_ENABLED(CONFIG_PRU_REMOTEPROC) && defined(PRUKIT_HAVE_LINUX_PRUSS_H)
#include <linux/pruss.h>
#define PRUKIT_HAVE_PRU_RPROC_GET	1
#endif
#ifdef PRUKIT_HAVE_PRU_RPROC_GET
#define prukit_pru_rproc_get(np, index)	pru_rproc_get(np, index, NULL)
#define prukit_pru_rproc_put(rproc)	pru_rproc_put(rproc)
#else
#define prukit_pru_rproc_get(np, index)	ERR_PTR(-ENODEV)
#define prukit_pru_rproc_put(rproc)	do { } while (0)
#endif

/*
 * v6.13: symbol namespaces are string literals ("module: Convert symbol
 * namespace to string literal").
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 13, 0)
#define EXPORT_SYMBOL_PRUKIT(sym)	EXPORT_SYMBOL_NS_GPL(sym, "PRUKIT")
#define PRUKIT_IMPORT_NS()		MODULE_IMPORT_NS("PRUKIT")
#define PRUKIT_IMPORT_NS_COUNTER()	MODULE_IMPORT_NS("COUNTER")
#else
#define EXPORT_SYMBOL_PRUKIT(sym)	EXPORT_SYMBOL_NS_GPL(sym, PRUKIT)
#define PRUKIT_IMPORT_NS()		MODULE_IMPORT_NS(PRUKIT)
#define PRUKIT_IMPORT_NS_COUNTER()	MODULE_IMPORT_NS(COUNTER)
#endif

/*
 * The counter subsystem (pru_encoder).  v5.16 replaced the callbacks
 * (struct counter_comp; "counter: Internalize sysfs interface code") and
 * added events and /dev/counterN ("counter: Add character device
 * interface"); v5.17 added counter_alloc()/counter_add() and their devm_
 * forms ("counter: Provide alternative counter registration functions"),
 * which v6.1 and v6.12 have unchanged.  5.10 has the first interface only:
 * struct counter_device filled by the driver, counter_register(), no
 * events, callbacks with other signatures (read in Debian's 5.10
 * linux-source).  pru_encoder is written for the v5.17 interface; its
 * Kbuild builds it only where <linux/counter.h> declares
 * devm_counter_alloc(), so nothing here maps one interface onto the other.
 * The symbols are in the COUNTER namespace (PRUKIT_IMPORT_NS_COUNTER()).
 *
 * COUNTER_EVENT_DIRECTION_CHANGE: v6.15 ("counter: Introduce the
 * COUNTER_EVENT_DIRECTION_CHANGE event"; ti-eqep pushes it on channel 0).
 * Where the kernel's <uapi/linux/counter.h> has it (Kbuild:
 * PRUKIT_HAVE_COUNTER_DIRECTION_CHANGE), pru_encoder pushes it for a
 * reversal besides its change of state; elsewhere the value below is never
 * pushed nor accepted.
 */
#ifdef PRUKIT_HAVE_COUNTER_DIRECTION_CHANGE
#define PRUKIT_COUNTER_DIRECTION_CHANGE		true
#define PRUKIT_COUNTER_EVENT_DIRECTION_CHANGE	COUNTER_EVENT_DIRECTION_CHANGE
#else
#define PRUKIT_COUNTER_DIRECTION_CHANGE		false
#define PRUKIT_COUNTER_EVENT_DIRECTION_CHANGE	0xff
#endif

/*
 * struct gpio_chip's .set callback returns void in 5.10 to 6.12 and int in
 * the kernels after gpiolib's 2025 setter conversion (v6.16 added .set_rv
 * for it; later releases made .set itself return int).  Pick the variant
 * by the member's type, not by a version number: @set_void and @set_int
 * are the two forms of the same function.
 */
#define prukit_gpio_chip_set(chip, set_void, set_int)				\
	do {									\
		struct gpio_chip *__gc = (chip);				\
										\
		__gc->set = __builtin_choose_expr(				\
			__builtin_types_compatible_p(typeof(__gc->set),		\
				void (*)(struct gpio_chip *, unsigned int, int)), \
			(set_void), (set_int));					\
	} while (0)

/*
 * v5.19: 32-bit ARM uses dma-direct ("ARM/dma-mapping: use dma-direct
 * unconditionally"), whose dma_alloc_noncoherent() allocates cached memory
 * for streaming-style hand-overs.  Before, ARM's own dma_map_ops had neither
 * .alloc_noncoherent nor .alloc_pages, and dma_alloc_noncoherent() returned
 * NULL (Debian's 5.10 armmp).  There the same buffer - cached, handed over
 * with dma_sync_single_for_cpu()/_for_device() - is the driver's own pages
 * mapped once with dma_map_single().  Both free what they allocated.
 */
#include <linux/dma-mapping.h>
#include <linux/gfp.h>

#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 19, 0)
static inline void *prukit_dma_alloc_noncoherent(struct device *dev, size_t size,
						 dma_addr_t *dma, enum dma_data_direction dir)
{
	return dma_alloc_noncoherent(dev, size, dma, dir, GFP_KERNEL);
}

static inline void prukit_dma_free_noncoherent(struct device *dev, size_t size, void *va,
					       dma_addr_t dma, enum dma_data_direction dir)
{
	dma_free_noncoherent(dev, size, va, dma, dir);
}
#else
static inline void *prukit_dma_alloc_noncoherent(struct device *dev, size_t size,
						 dma_addr_t *dma, enum dma_data_direction dir)
{
	void *va = alloc_pages_exact(size, GFP_KERNEL);

	if (!va)
		return NULL;
	*dma = dma_map_single(dev, va, size, dir);
	if (dma_mapping_error(dev, *dma)) {
		free_pages_exact(va, size);
		return NULL;
	}
	return va;
}

static inline void prukit_dma_free_noncoherent(struct device *dev, size_t size, void *va,
					       dma_addr_t dma, enum dma_data_direction dir)
{
	dma_unmap_single(dev, dma, size, dir);
	free_pages_exact(va, size);
}
#endif

/*
 * DRM, for the display drivers (hub75), which define PRUKIT_COMPAT_DRM
 * before including this file: the others do not pull in DRM headers.
 */
#ifdef PRUKIT_COMPAT_DRM
#include <drm/drm_drv.h>
#include <drm/drm_framebuffer.h>
#include <drm/drm_gem_framebuffer_helper.h>
#include <drm/drm_plane.h>

/*
 * v5.11: devm_drm_dev_alloc() takes a const struct drm_driver ("drm:
 * Constify struct drm_driver"; 5.10 writes nothing to it either).
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 11, 0)
#define PRUKIT_DRM_DRIVER_CONST		const
#else
#define PRUKIT_DRM_DRIVER_CONST
#endif

/* v6.14: struct drm_driver lost .date ("drm: remove driver date from struct drm_driver") */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 14, 0)
#define PRUKIT_DRM_DRIVER_DATE(d)
#else
#define PRUKIT_DRM_DRIVER_DATE(d)	.date = (d),
#endif

/*
 * The plane's framebuffer memory for the CPU.  v5.12 added shadow-plane
 * helpers ("drm/gem: Export helpers for shadow-buffered planes"): they map
 * the BOs before the update (map[], the BO's start; data[] of v5.17 adds
 * the framebuffer's offsets, map[] stays).  5.10 has none: the update maps
 * the shmem BO itself with drm_gem_shmem_vmap(), which v5.11 changed to
 * fill a struct dma_buf_map - so prukit's display drivers build for v5.10
 * and for v5.12 on, not for v5.11.  Either way the address is the BO's
 * start; the driver adds fb->offsets[].
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 12, 0)
#include <drm/drm_gem_atomic_helper.h>
#define PRUKIT_DRM_SHADOW_PLANE_FUNCS		DRM_GEM_SHADOW_PLANE_FUNCS
#define PRUKIT_DRM_SHADOW_PLANE_HELPER_FUNCS	DRM_GEM_SHADOW_PLANE_HELPER_FUNCS
static inline void *prukit_drm_fb_vmap(struct drm_plane_state *state)
{
	return to_drm_shadow_plane_state(state)->map[0].vaddr;
}

static inline void prukit_drm_fb_vunmap(struct drm_plane_state *state, void *vaddr)
{
}
#elif LINUX_VERSION_CODE < KERNEL_VERSION(5, 11, 0)
#include <drm/drm_atomic_state_helper.h>
#include <drm/drm_gem_shmem_helper.h>
#define PRUKIT_DRM_SHADOW_PLANE_FUNCS \
	.reset = drm_atomic_helper_plane_reset, \
	.atomic_duplicate_state = drm_atomic_helper_plane_duplicate_state, \
	.atomic_destroy_state = drm_atomic_helper_plane_destroy_state
#define PRUKIT_DRM_SHADOW_PLANE_HELPER_FUNCS	.prepare_fb = drm_gem_fb_prepare_fb
static inline void *prukit_drm_fb_vmap(struct drm_plane_state *state)
{
	return drm_gem_shmem_vmap(state->fb->obj[0]);
}

static inline void prukit_drm_fb_vunmap(struct drm_plane_state *state, void *vaddr)
{
	drm_gem_shmem_vunmap(state->fb->obj[0], vaddr);
}
#else
#error "prukit's DRM drivers build for v5.10 and v5.12 or later"
#endif

/*
 * Telling an imported framebuffer's exporter that the CPU reads it:
 * drm_gem_fb_begin_cpu_access()/end_cpu_access(), which 6.1 has and 5.10
 * has not.  Decided by the kernel's <drm/drm_gem_framebuffer_helper.h> (the
 * top-level Kbuild: PRUKIT_HAVE_DRM_GEM_FB_CPU_ACCESS); without them, shmem
 * BOs of the driver's own are all the CPU reads.
 */
#ifdef PRUKIT_HAVE_DRM_GEM_FB_CPU_ACCESS
#define prukit_drm_fb_begin_cpu_access(fb) drm_gem_fb_begin_cpu_access(fb, DMA_FROM_DEVICE)
#define prukit_drm_fb_end_cpu_access(fb)   drm_gem_fb_end_cpu_access(fb, DMA_FROM_DEVICE)
#else
#define prukit_drm_fb_begin_cpu_access(fb) ((void)(fb), 0)
#define prukit_drm_fb_end_cpu_access(fb)   ((void)(fb))
#endif

/*
 * No scaling of a plane: DRM_PLANE_NO_SCALING in <drm/drm_atomic_helper.h>
 * on 6.1, DRM_PLANE_HELPER_NO_SCALING in <drm/drm_plane_helper.h> on 5.10
 * (the same value).
 */
#include <drm/drm_atomic_helper.h>
#ifndef DRM_PLANE_NO_SCALING
#include <drm/drm_plane_helper.h>
#define DRM_PLANE_NO_SCALING	DRM_PLANE_HELPER_NO_SCALING
#endif

/*
 * The atomic helpers' callbacks take the whole atomic state: CRTCs'
 * atomic_check, atomic_enable and atomic_disable from v5.11, planes'
 * atomic_check and atomic_update from v5.13 ("drm/atomic: Pass the full
 * state to ...").  Drivers write them that way and name them in
 * PRUKIT_DRM_CRTC_HELPERS()/PRUKIT_DRM_PLANE_HELPERS(), after
 * PRUKIT_DRM_*_HELPERS_COMPAT(), which defines, where the kernel passes a
 * CRTC's or a plane's own state, functions taking that state and passing
 * on the atomic state it belongs to (->state: the new state's during a
 * check, the old state's during a commit, where the helpers set it).
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 11, 0)
#define PRUKIT_DRM_CRTC_HELPERS_COMPAT(check, enable, disable)
#define PRUKIT_DRM_CRTC_HELPERS(check, enable, disable) \
	.atomic_check = check, .atomic_enable = enable, .atomic_disable = disable
#else
#define PRUKIT_DRM_CRTC_HELPERS_COMPAT(check, enable, disable)			\
static int check##_compat(struct drm_crtc *crtc, struct drm_crtc_state *s)	\
{										\
	return check(crtc, s->state);						\
}										\
static void enable##_compat(struct drm_crtc *crtc, struct drm_crtc_state *old)	\
{										\
	enable(crtc, old->state);						\
}										\
static void disable##_compat(struct drm_crtc *crtc, struct drm_crtc_state *old)	\
{										\
	disable(crtc, old->state);						\
}

#define PRUKIT_DRM_CRTC_HELPERS(check, enable, disable) \
	.atomic_check = check##_compat, .atomic_enable = enable##_compat, \
	.atomic_disable = disable##_compat
#endif
#if LINUX_VERSION_CODE >= KERNEL_VERSION(5, 13, 0)
#define PRUKIT_DRM_PLANE_HELPERS_COMPAT(check, update)
#define PRUKIT_DRM_PLANE_HELPERS(check, update) \
	.atomic_check = check, .atomic_update = update
#else
#define PRUKIT_DRM_PLANE_HELPERS_COMPAT(check, update)				\
static int check##_compat(struct drm_plane *plane, struct drm_plane_state *s)	\
{										\
	return check(plane, s->state);						\
}										\
static void update##_compat(struct drm_plane *plane, struct drm_plane_state *old) \
{										\
	update(plane, old->state);						\
}

#define PRUKIT_DRM_PLANE_HELPERS(check, update) \
	.atomic_check = check##_compat, .atomic_update = update##_compat
#endif

/*
 * fbdev emulation (/dev/fbN) drawn into a shadow buffer and copied to the
 * plane's framebuffer on damage: drm_fbdev_generic_setup() in
 * <drm/drm_fb_helper.h>, in <drm/drm_fbdev_generic.h> from v6.2 ("drm/
 * fb-helper: Move generic fbdev emulation into separate source file"),
 * renamed drm_fbdev_ttm_setup() in v6.11 ("drm/fbdev-generic: Convert to
 * fbdev-ttm"; its code stays generic, in drm_ttm_helper.ko).  v6.11's
 * drm_fbdev_shmem_setup() maps the GEM object's shmem pages to fbdev
 * clients with deferred I/O instead, and freeing the object at unbind then
 * loops for ever in shmem_undo_range() once a client has faulted a page
 * through an mmap of /dev/fbN (seen on 6.12 in 84-hub75).  The cause, read
 * in 6.12's sources: fb_deferred_io_fault() sets the shmem page's
 * page->mapping to /dev/fbN's address space and nothing sets it back (the
 * last close clears it, to NULL, only on written pages); at the object's
 * last fput(), shmem_undo_range()'s first pass skips a folio of another
 * mapping and its second pass takes it for one swapped out meanwhile and
 * retries it, for ever.  Mainline fixed fb_defio in "fb_defio: do not use
 * deprecated page->mapping, index fields" (6cdef2ddce2b, from v6.15 as far
 * as the merge mails say), not backported to 6.12.  So fbdev-shmem only
 * where the kernel lacks drm_ttm_helper, whose generic fbdev draws into a
 * vmalloc'ed shadow buffer.  v6.13's drm_client_setup() would need
 * .fbdev_probe in the driver.
 */
#if LINUX_VERSION_CODE >= KERNEL_VERSION(6, 11, 0) && IS_ENABLED(CONFIG_DRM_TTM_HELPER)
#include <drm/drm_fbdev_ttm.h>
#define prukit_drm_fbdev_setup(drm)	drm_fbdev_ttm_setup(drm, 32)
#elif LINUX_VERSION_CODE >= KERNEL_VERSION(6, 11, 0)
#include <drm/drm_fbdev_shmem.h>
#define prukit_drm_fbdev_setup(drm)	drm_fbdev_shmem_setup(drm, 32)
#elif LINUX_VERSION_CODE >= KERNEL_VERSION(6, 2, 0)
#include <drm/drm_fbdev_generic.h>
#define prukit_drm_fbdev_setup(drm)	drm_fbdev_generic_setup(drm, 32)
#else
#include <drm/drm_fb_helper.h>
#define prukit_drm_fbdev_setup(drm)	drm_fbdev_generic_setup(drm, 32)
#endif
#endif /* PRUKIT_COMPAT_DRM */

/*
 * The PWM subsystem, for the PWM drivers (pru_pwm), which define
 * PRUKIT_COMPAT_PWM before including this file.  Each difference is
 * probed in <linux/pwm.h> (Kbuild), not taken from a version number: TI's
 * and Debian's kernels of one version backport different changes (Debian's
 * 6.1 has the int get_state() of v6.2).
 */
#ifdef PRUKIT_COMPAT_PWM
#include <linux/device.h>
#include <linux/err.h>
#include <linux/pwm.h>

/*
 * v6.9: the core allocates the chip (devm_pwmchip_alloc()), with the
 * driver's data behind it (pwmchip_get_drvdata()) and its own struct
 * device inside.  Before, a driver embedded the chip in
 * its data and set chip->dev, and chip->base = -1 where the chip still has
 * a base (5.10 and 6.1: the core then picks a free range of PWM numbers).
 */
#ifdef PRUKIT_HAVE_PWMCHIP_ALLOC
#define prukit_devm_pwmchip_alloc(parent, npwm, size)	devm_pwmchip_alloc(parent, npwm, size)
#define prukit_pwmchip_priv(chip)			pwmchip_get_drvdata(chip)
#else
struct prukit_pwmchip {
	struct pwm_chip chip;
	u64 priv[];
};

static inline struct pwm_chip *prukit_devm_pwmchip_alloc(struct device *parent,
							 unsigned int npwm, size_t size)
{
	struct prukit_pwmchip *p = devm_kzalloc(parent, sizeof(*p) + size, GFP_KERNEL);

	if (!p)
		return ERR_PTR(-ENOMEM);
	p->chip.dev = parent;
	p->chip.npwm = npwm;
#ifdef PRUKIT_HAVE_PWM_CHIP_BASE
	p->chip.base = -1;
#endif
	return &p->chip;
}

static inline void *prukit_pwmchip_priv(struct pwm_chip *chip)
{
	return container_of(chip, struct prukit_pwmchip, chip)->priv;
}
#endif

/*
 * devm_pwmchip_add() came after 5.10 (6.1 has it).  5.10's
 * pwmchip_remove() returns int: it unexports the sysfs channels, then
 * refuses (-EBUSY) a chip whose PWMs a kernel consumer still holds; 5.10's
 * of_pwm_get() links such a consumer to the chip's device
 * (DL_FLAG_AUTOREMOVE_CONSUMER), so the driver core unbinds it first.
 */
#ifdef PRUKIT_HAVE_DEVM_PWMCHIP_ADD
#define prukit_devm_pwmchip_add(dev, chip)	devm_pwmchip_add(dev, chip)
#else
static inline void prukit_pwmchip_remove(void *chip)
{
	pwmchip_remove(chip);
}

static inline int prukit_devm_pwmchip_add(struct device *dev, struct pwm_chip *chip)
{
	int ret = pwmchip_add(chip);

	return ret ? ret : devm_add_action_or_reset(dev, prukit_pwmchip_remove, chip);
}
#endif

/*
 * The chip's module: from pwmchip_add() where the core has
 * __pwmchip_add() (6.12; struct pwm_ops lost .owner with it), else
 * struct pwm_ops' .owner (5.10, 6.1).
 */
#ifdef PRUKIT_HAVE_PWMCHIP_ADD_OWNER
#define PRUKIT_PWM_OPS_OWNER
#else
#define PRUKIT_PWM_OPS_OWNER	.owner = THIS_MODULE,
#endif

/*
 * Three cells in "pwms" (channel, period, flags): 6.1's core takes the
 * count from "#pwm-cells" with of_pwm_xlate_with_flags(), and 6.12's has
 * no of_pwm_n_cells; 5.10's defaults to of_pwm_simple_xlate() and two
 * cells, so where the member is there the driver sets both.
 */
#ifdef PRUKIT_HAVE_PWM_OF_N_CELLS
static inline void prukit_pwmchip_of_cells(struct pwm_chip *chip)
{
	chip->of_xlate = of_pwm_xlate_with_flags;
	chip->of_pwm_n_cells = 3;
}
#else
static inline void prukit_pwmchip_of_cells(struct pwm_chip *chip) { }
#endif

/*
 * v6.2: .get_state() returns int (backported: Debian's 6.1 has it too).
 * A driver writes the int form, @fn, and names it with
 * PRUKIT_PWM_GET_STATE(fn) in its ops, which picks it or the void
 * wrapper PRUKIT_PWM_DEFINE_GET_STATE(fn) defines, by the
 * member's type.
 */
#define PRUKIT_PWM_DEFINE_GET_STATE(fn)					\
	static void __maybe_unused fn##_void(struct pwm_chip *chip,	\
					     struct pwm_device *pwm,	\
					     struct pwm_state *state)	\
	{								\
		fn(chip, pwm, state);					\
	}
#define PRUKIT_PWM_GET_STATE(fn)					\
	.get_state = __builtin_choose_expr(				\
		__builtin_types_compatible_p(				\
			typeof(((const struct pwm_ops *)0)->get_state), \
			int (*)(struct pwm_chip *, struct pwm_device *,	\
				struct pwm_state *)),			\
		(fn), (fn##_void))
#endif /* PRUKIT_COMPAT_PWM */

#endif /* PRUKIT_COMPAT_H */
