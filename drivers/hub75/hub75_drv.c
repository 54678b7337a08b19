// SPDX-License-Identifier: GPL-2.0-only
/*
 * hub75 - a HUB75 RGB LED matrix (one panel or a chain) as a DRM display,
 * refreshed by a BeagleBone PRU.
 *
 * The display is a DRM device with one fixed mode, one primary plane
 * (XRGB8888, RGB565, damage clips) and the kernel's fbdev emulation on top,
 * so /dev/dri/cardN and /dev/fbN both draw on the panel.  On every plane
 * update the changed pixels become bit planes (hub75_conv.c) in the frame
 * buffer the PRU does not show; at its next refresh the PRU takes it
 * (hub75_proto.h).  Brightness is a backlight device: it scales the time
 * the rows are lit.  Documentation/hub75.rst has the whole story.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/backlight.h>
#include <linux/delay.h>
#include <linux/dma-mapping.h>
#include <linux/gpio/consumer.h>
#include <linux/io.h>
#include <linux/math64.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/platform_device.h>
#include <linux/property.h>

#include <drm/drm_atomic.h>
#include <drm/drm_atomic_helper.h>
#include <drm/drm_connector.h>
#include <drm/drm_crtc.h>
#include <drm/drm_damage_helper.h>
#include <drm/drm_drv.h>
#include <drm/drm_encoder.h>
#include <drm/drm_fourcc.h>
#include <drm/drm_gem.h>
#include <drm/drm_gem_framebuffer_helper.h>
#include <drm/drm_gem_shmem_helper.h>
#include <drm/drm_managed.h>
#include <drm/drm_modes.h>
#include <drm/drm_modeset_helper_vtables.h>
#include <drm/drm_plane.h>
#include <drm/drm_probe_helper.h>

#define PRUKIT_COMPAT_DRM
#include "compat.h"
#include "prukit_pru.h"
#include "hub75_conv.h"
#include "hub75_proto.h"

#define HUB75_PRU_HZ		200000000u
#define HUB75_MIN_REFRESH_HZ	100	/* prukit,min-refresh-hz's default */
#define HUB75_LOWEST_REFRESH_HZ	30
#define HUB75_MAX_BRIGHTNESS	100
#define HUB75_MAX_CHAIN		16
#define HUB75_DEFAULT_CLOCK_HZ	20000000u
#define HUB75_DEFAULT_LSB_NS	130
#define HUB75_DEFAULT_PLANES	8
/* The longest lit time the firmware's delay loop counts: 0xffff + 2 */
#define HUB75_MAX_OE_CYCLES	0x10001u

/* PRU cycles the firmware spends around a block's pixels (hub75_scan.S) */
#define HUB75_CHUNK_CYCLES	53	/* a 32-byte load from DDR, add, branch */
#define HUB75_BLOCK_CYCLES	16	/* latch, address, lighting's branches */
#define HUB75_GPIO_TAIL_CYCLES	24	/* the last pixel's clock */
#define HUB75_GPIO_WRITE_CYCLES	8	/* a GPIO write's time on the L4 path */
#define HUB75_GPIO_PIXEL_CYCLES	(2 * HUB75_GPIO_WRITE_CYCLES)	/* CLEAR, SET */
/* hub75_banks.S: a 64-byte load from DDR per 4 clocks; latch, address */
#define HUB75_BANKS_CHUNK_CYCLES 60
#define HUB75_BANKS_BLOCK_CYCLES 120

static const u32 hub75_gpio_banks[PRUKIT_PRU_GPIO_BANKS] = {
	0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000,
};

static const u32 hub75_formats[] = {
	DRM_FORMAT_XRGB8888,
	DRM_FORMAT_RGB565,
};

/**
 * struct hub75 - one matrix display
 * @drm: the DRM device
 * @plane: its one plane, primary
 * @crtc: its one CRTC
 * @encoder: its one encoder, a placeholder between the CRTC and the panel
 * @connector: the panel
 * @mode: the panel's only mode
 * @dev: the platform device
 * @pru: the core that refreshes the panel
 * @ctrl: its control block
 * @layout: where the pixels go in a frame buffer
 * @buf: the two frame buffers (coherent DMA memory)
 * @dma: their bus addresses
 * @buf_size: bytes of each
 * @params: START's parameters, written before every START
 * @lsb_cycles: lit cycles of the least significant plane at full brightness
 * @refresh_cycles: a refresh's length in PRU cycles, as the driver computes it
 * @bl: the brightness control
 * @lock: serialises the commands to the PRU and protects what follows
 * @brightness: 0..HUB75_MAX_BRIGHTNESS
 * @running: the PRU refreshes the panel (the CRTC is enabled)
 * @front: the buffer last handed to the PRU
 * @prev: the rectangle the last update converted (into @front only)
 * @full: the next update converts the whole display
 */
struct hub75 {
	struct drm_device drm;
	struct drm_plane plane;
	struct drm_crtc crtc;
	struct drm_encoder encoder;
	struct drm_connector connector;
	struct drm_display_mode mode;
	struct device *dev;
	struct prukit_pru *pru;
	void __iomem *ctrl;
	struct hub75_layout layout;
	u8 *buf[2];
	dma_addr_t dma[2];
	size_t buf_size;
	struct hub75_ctrl params;
	u32 lsb_cycles;
	u32 refresh_cycles;
	struct backlight_device *bl;
	struct mutex lock;	/* the PRU's commands, and what follows */
	unsigned int brightness;
	bool running;
	unsigned int front;
	struct hub75_rect prev;
	bool full;
};

static struct hub75 *drm_to_hub75(struct drm_device *drm)
{
	return container_of(drm, struct hub75, drm);
}

#define HUB75_CTRL(h, field)	((h)->ctrl + offsetof(struct hub75_ctrl, field))

/* ------------------------------------------------------------------ */
/* the PRU                                                              */
/* ------------------------------------------------------------------ */

/* Lit cycles of each plane, in the order shown, at the brightness */
static void hub75_write_oe(struct hub75 *h)
{
	u32 lsb = DIV_ROUND_CLOSEST(h->lsb_cycles * h->brightness, HUB75_MAX_BRIGHTNESS);
	unsigned int k;

	lockdep_assert_held(&h->lock);
	for (k = 0; k < h->layout.planes; k++)
		writel(lsb << h->layout.order[k], HUB75_CTRL(h, oe_cycles[k]));
}

static int hub75_command(struct hub75 *h, u16 opcode)
{
	int ret;

	lockdep_assert_held(&h->lock);
	if (!prukit_pru_running(h->pru))
		return -EPIPE;
	ret = prukit_pru_ctrl_command(h->pru, h->ctrl, opcode, PRUKIT_PRU_TIMEOUT_MS);
	if (ret > 0) {
		dev_err(h->dev, "the firmware refused command %u: %d\n", opcode, ret);
		return -EPROTO;
	}
	return ret;
}

static int hub75_start(struct hub75 *h)
{
	int ret;

	lockdep_assert_held(&h->lock);
	memcpy_toio(HUB75_CTRL(h, buf_addr), &h->params.buf_addr,
		    offsetof(struct hub75_ctrl, oe_cycles) -
		    offsetof(struct hub75_ctrl, buf_addr));
	memcpy_toio(HUB75_CTRL(h, init), h->params.init,
		    sizeof(struct hub75_ctrl) - offsetof(struct hub75_ctrl, init));
	hub75_write_oe(h);
	writel(h->front, HUB75_CTRL(h, show));
	ret = hub75_command(h, HUB75_CMD_START);
	if (ret)
		dev_err(h->dev, "cannot start the refresh: %d\n", ret);
	return ret;
}

/*
 * Until the PRU shows @front: then the other buffer is free.  A refresh
 * takes its time under emulation: the wait is bounded by the control
 * block's timeout, beyond a whole refresh even there.
 */
static int hub75_wait_taken(struct hub75 *h)
{
	lockdep_assert_held(&h->lock);
	return prukit_pru_poll_timeout(h->pru, readl(HUB75_CTRL(h, shown)) == h->front, 1000,
				       PRUKIT_PRU_TIMEOUT_MS);
}

/* ------------------------------------------------------------------ */
/* the display: plane, CRTC, encoder, connector                       */
/* ------------------------------------------------------------------ */

static enum hub75_format hub75_format_of(const struct drm_framebuffer *fb)
{
	return fb->format->format == DRM_FORMAT_RGB565 ? HUB75_RGB565 : HUB75_XRGB8888;
}

/* Convert @rect (display coordinates) of the plane's image into buffer @b */
static void hub75_convert_plane(struct hub75 *h, unsigned int b, struct drm_plane_state *state,
				const void *vaddr, const struct hub75_rect *rect)
{
	struct drm_framebuffer *fb = state->fb;
	unsigned int x = state->src.x1 >> 16, y = state->src.y1 >> 16;
	const u8 *src = (const u8 *)vaddr + fb->offsets[0] + y * fb->pitches[0] +
			x * fb->format->cpp[0];

	hub75_convert(&h->layout, h->buf[b], src, fb->pitches[0], hub75_format_of(fb), rect);
}

static void hub75_show(struct hub75 *h, struct drm_plane_state *state, const void *vaddr,
		       const struct hub75_rect *rect)
{
	struct hub75_rect all = { 0, 0, h->layout.width, h->layout.height };
	unsigned int back = h->front ^ 1;
	int ret;

	lockdep_assert_held(&h->lock);
	ret = hub75_wait_taken(h);
	if (ret == -EPIPE) {
		/* crashed or restarted: dark until the pipe is enabled again */
		dev_warn(h->dev, "the PRU stopped: the panel stays dark\n");
		h->running = false;
		h->full = true;
		return;
	}
	if (ret) {
		dev_err_ratelimited(h->dev, "the PRU did not take the last frame: %d\n", ret);
		h->full = true;
		return;
	}
	if (h->full) {
		rect = &all;
		h->full = false;
	} else {
		/* the back buffer lacks what went into the front one last time */
		hub75_convert_plane(h, back, state, vaddr, &h->prev);
	}
	hub75_convert_plane(h, back, state, vaddr, rect);
	/* the buffer is coherent memory: written before the PRU sees @show */
	wmb();
	writel(back, HUB75_CTRL(h, show));
	h->front = back;
	h->prev = *rect;
}

/*
 * The plane's image for the CPU, between hub75_fb_begin() and hub75_fb_end():
 * the shadow-plane helpers mapped the framebuffer's BOs; an imported BO's
 * exporter is told the CPU reads it.  NULL if there is none to read.
 */
static void *hub75_fb_begin(struct drm_plane_state *state)
{
	void *vaddr;

	if (!state->fb)
		return NULL;
	vaddr = prukit_drm_fb_vmap(state);
	if (IS_ERR_OR_NULL(vaddr))
		return NULL;
	if (prukit_drm_fb_begin_cpu_access(state->fb)) {
		prukit_drm_fb_vunmap(state, vaddr);
		return NULL;
	}
	return vaddr;
}

static void hub75_fb_end(struct drm_plane_state *state, void *vaddr)
{
	prukit_drm_fb_end_cpu_access(state->fb);
	prukit_drm_fb_vunmap(state, vaddr);
}

static void hub75_crtc_atomic_enable(struct drm_crtc *crtc, struct drm_atomic_state *state)
{
	struct hub75 *h = drm_to_hub75(crtc->dev);
	struct drm_plane_state *plane_state = h->plane.state;
	struct hub75_rect all = { 0, 0, h->layout.width, h->layout.height };
	void *vaddr;
	int idx;

	if (!drm_dev_enter(&h->drm, &idx))
		return;
	vaddr = hub75_fb_begin(plane_state);
	mutex_lock(&h->lock);
	if (vaddr) {
		hub75_convert_plane(h, h->front, plane_state, vaddr, &all);
		h->prev = all;
		h->full = false;
	}
	if (!hub75_start(h))
		h->running = true;
	mutex_unlock(&h->lock);
	if (vaddr)
		hub75_fb_end(plane_state, vaddr);
	drm_dev_exit(idx);
}

static void hub75_crtc_atomic_disable(struct drm_crtc *crtc, struct drm_atomic_state *state)
{
	struct hub75 *h = drm_to_hub75(crtc->dev);
	int idx;

	if (!drm_dev_enter(&h->drm, &idx))
		return;
	mutex_lock(&h->lock);
	if (h->running)
		hub75_command(h, HUB75_CMD_STOP);
	h->running = false;
	h->full = true;
	mutex_unlock(&h->lock);
	drm_dev_exit(idx);
}

static void hub75_plane_atomic_update(struct drm_plane *plane, struct drm_atomic_state *state)
{
	struct hub75 *h = drm_to_hub75(plane->dev);
	struct drm_plane_state *old_state = drm_atomic_get_old_plane_state(state, plane);
	struct drm_plane_state *new_state = drm_atomic_get_new_plane_state(state, plane);
	struct drm_rect damage;
	struct hub75_rect rect;
	void *vaddr;
	int idx;

	if (!new_state->fb || !new_state->visible)
		return;
	if (!drm_atomic_helper_damage_merged(old_state, new_state, &damage))
		return;
	if (!drm_dev_enter(&h->drm, &idx))
		return;
	/* damage is in framebuffer coordinates, the display's start at src */
	rect.x1 = max(damage.x1 - (new_state->src.x1 >> 16), 0);
	rect.y1 = max(damage.y1 - (new_state->src.y1 >> 16), 0);
	rect.x2 = max(damage.x2 - (new_state->src.x1 >> 16), 0);
	rect.y2 = max(damage.y2 - (new_state->src.y1 >> 16), 0);
	if (old_state->fb != new_state->fb ||
	    old_state->src.x1 != new_state->src.x1 || old_state->src.y1 != new_state->src.y1)
		rect = (struct hub75_rect){ 0, 0, h->layout.width, h->layout.height };

	vaddr = hub75_fb_begin(new_state);
	if (!vaddr)
		goto exit;
	mutex_lock(&h->lock);
	if (h->running)
		hub75_show(h, new_state, vaddr, &rect);
	else
		h->full = true;
	mutex_unlock(&h->lock);
	hub75_fb_end(new_state, vaddr);
exit:
	drm_dev_exit(idx);
}

/* The plane covers the whole display, unscaled; it is on while the CRTC is. */
static int hub75_plane_atomic_check(struct drm_plane *plane, struct drm_atomic_state *state)
{
	struct drm_plane_state *plane_state = drm_atomic_get_new_plane_state(state, plane);
	struct drm_crtc_state *crtc_state = NULL;

	if (plane_state->crtc)
		crtc_state = drm_atomic_get_new_crtc_state(state, plane_state->crtc);
	return drm_atomic_helper_check_plane_state(plane_state, crtc_state, DRM_PLANE_NO_SCALING,
						   DRM_PLANE_NO_SCALING, false, false);
}

static enum drm_mode_status hub75_crtc_mode_valid(struct drm_crtc *crtc,
						  const struct drm_display_mode *mode)
{
	struct hub75 *h = drm_to_hub75(crtc->dev);

	if (mode->hdisplay != h->mode.hdisplay || mode->vdisplay != h->mode.vdisplay)
		return MODE_BAD;
	return MODE_OK;
}

/* The panel's size, and the plane exactly while the CRTC is enabled. */
static int hub75_crtc_atomic_check(struct drm_crtc *crtc, struct drm_atomic_state *state)
{
	struct drm_crtc_state *crtc_state = drm_atomic_get_new_crtc_state(state, crtc);
	struct hub75 *h = drm_to_hub75(crtc->dev);
	bool has_plane = crtc_state->plane_mask & drm_plane_mask(crtc->primary);

	if (crtc_state->enable &&
	    (crtc_state->mode.hdisplay != h->mode.hdisplay ||
	     crtc_state->mode.vdisplay != h->mode.vdisplay))
		return -EINVAL;
	if (has_plane != crtc_state->enable)
		return -EINVAL;
	return drm_atomic_add_affected_planes(state, crtc);
}

PRUKIT_DRM_PLANE_HELPERS_COMPAT(hub75_plane_atomic_check, hub75_plane_atomic_update)
PRUKIT_DRM_CRTC_HELPERS_COMPAT(hub75_crtc_atomic_check, hub75_crtc_atomic_enable,
			       hub75_crtc_atomic_disable)

static const struct drm_plane_helper_funcs hub75_plane_helper_funcs = {
	PRUKIT_DRM_SHADOW_PLANE_HELPER_FUNCS,
	PRUKIT_DRM_PLANE_HELPERS(hub75_plane_atomic_check, hub75_plane_atomic_update),
};

static const struct drm_plane_funcs hub75_plane_funcs = {
	.update_plane = drm_atomic_helper_update_plane,
	.disable_plane = drm_atomic_helper_disable_plane,
	.destroy = drm_plane_cleanup,
	PRUKIT_DRM_SHADOW_PLANE_FUNCS,
};

static const struct drm_crtc_helper_funcs hub75_crtc_helper_funcs = {
	.mode_valid = hub75_crtc_mode_valid,
	PRUKIT_DRM_CRTC_HELPERS(hub75_crtc_atomic_check, hub75_crtc_atomic_enable,
				hub75_crtc_atomic_disable),
};

static const struct drm_crtc_funcs hub75_crtc_funcs = {
	.reset = drm_atomic_helper_crtc_reset,
	.destroy = drm_crtc_cleanup,
	.set_config = drm_atomic_helper_set_config,
	.page_flip = drm_atomic_helper_page_flip,
	.atomic_duplicate_state = drm_atomic_helper_crtc_duplicate_state,
	.atomic_destroy_state = drm_atomic_helper_crtc_destroy_state,
};

static const struct drm_encoder_funcs hub75_encoder_funcs = {
	.destroy = drm_encoder_cleanup,
};

static int hub75_connector_get_modes(struct drm_connector *connector)
{
	struct hub75 *h = drm_to_hub75(connector->dev);
	struct drm_display_mode *mode;

	mode = drm_mode_duplicate(connector->dev, &h->mode);
	if (!mode)
		return 0;
	drm_mode_probed_add(connector, mode);
	return 1;
}

static const struct drm_connector_helper_funcs hub75_connector_helper_funcs = {
	.get_modes = hub75_connector_get_modes,
};

static const struct drm_connector_funcs hub75_connector_funcs = {
	.reset = drm_atomic_helper_connector_reset,
	.fill_modes = drm_helper_probe_single_connector_modes,
	.destroy = drm_connector_cleanup,
	.atomic_duplicate_state = drm_atomic_helper_connector_duplicate_state,
	.atomic_destroy_state = drm_atomic_helper_connector_destroy_state,
};

static const struct drm_mode_config_funcs hub75_mode_config_funcs = {
	.fb_create = drm_gem_fb_create_with_dirty,
	.atomic_check = drm_atomic_helper_check,
	.atomic_commit = drm_atomic_helper_commit,
};

DEFINE_DRM_GEM_FOPS(hub75_fops);

static PRUKIT_DRM_DRIVER_CONST struct drm_driver hub75_drm_driver = {
	.driver_features = DRIVER_GEM | DRIVER_MODESET | DRIVER_ATOMIC,
	.fops = &hub75_fops,
	DRM_GEM_SHMEM_DRIVER_OPS,
	.name = "hub75",
	.desc = "HUB75 RGB LED matrix on a BeagleBone PRU",
	PRUKIT_DRM_DRIVER_DATE("20261125")
	.major = 1,
	.minor = 0,
};

/* ------------------------------------------------------------------ */
/* brightness                                                           */
/* ------------------------------------------------------------------ */

static int hub75_bl_update(struct backlight_device *bl)
{
	struct hub75 *h = bl_get_data(bl);
	int idx;

	if (!drm_dev_enter(&h->drm, &idx))
		return -ENODEV;
	mutex_lock(&h->lock);
	h->brightness = backlight_get_brightness(bl);
	/* read per plane by the firmware: the next plane has it */
	hub75_write_oe(h);
	mutex_unlock(&h->lock);
	drm_dev_exit(idx);
	return 0;
}

static const struct backlight_ops hub75_bl_ops = {
	.options = BL_CORE_SUSPENDRESUME,
	.update_status = hub75_bl_update,
};

/* ------------------------------------------------------------------ */
/* sysfs: the refresh as the PRU measures it                            */
/* ------------------------------------------------------------------ */

/* PRU cycles of the last whole refresh; 0 while the panel is off */
static u32 hub75_measured(struct hub75 *h)
{
	u32 cycles = 0;

	mutex_lock(&h->lock);
	if (h->running && prukit_pru_running(h->pru))
		cycles = readl(HUB75_CTRL(h, refresh_cycles));
	mutex_unlock(&h->lock);
	return cycles;
}

static ssize_t refresh_cycles_show(struct device *dev, struct device_attribute *attr,
				   char *buf)
{
	return sysfs_emit(buf, "%u\n", hub75_measured(dev_get_drvdata(dev)));
}
static DEVICE_ATTR_RO(refresh_cycles);

static ssize_t refresh_hz_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	u32 cycles = hub75_measured(dev_get_drvdata(dev));

	return sysfs_emit(buf, "%u\n", cycles ? DIV_ROUND_CLOSEST(HUB75_PRU_HZ, cycles) : 0);
}
static DEVICE_ATTR_RO(refresh_hz);

static struct attribute *hub75_attrs[] = {
	&dev_attr_refresh_cycles.attr,
	&dev_attr_refresh_hz.attr,
	NULL
};
ATTRIBUTE_GROUPS(hub75);

/* ------------------------------------------------------------------ */
/* device tree                                                          */
/* ------------------------------------------------------------------ */

static int hub75_r30_bit(struct device *dev, const char *prop, u32 *bit)
{
	int ret = device_property_read_u32(dev, prop, bit);

	if (ret)
		return dev_err_probe(dev, ret, "no \"%s\"\n", prop);
	if (*bit > 31)
		return dev_err_probe(dev, -EINVAL, "\"%s\" = %u: R30 has bits 0..31\n", prop, *bit);
	return 0;
}

/* GPIO @i of the list @prop ("data-gpios" ...): its AM335x bank and bit */
static int hub75_gpio_at(struct device *dev, const char *prop, unsigned int i, u32 *bank,
			 u32 *bit)
{
	struct of_phandle_args args;
	int b, ret;

	ret = of_parse_phandle_with_args(dev->of_node, prop, "#gpio-cells", i, &args);
	if (ret)
		return dev_err_probe(dev, ret, "\"%s\" has no pin %u\n", prop, i);
	b = prukit_pru_gpio_bank(args.np);
	of_node_put(args.np);
	if (b < 0 || args.args_count < 1 || args.args[0] > 31)
		return dev_err_probe(dev, -EINVAL, "\"%s\" %u is no pin of an AM335x GPIO bank\n",
				     prop, i);
	*bank = b;
	*bit = args.args[0];
	return 0;
}

/* Data lines on a GPIO bank: all six in one bank, 16 bits apart at most */
static int hub75_parse_gpio_data(struct hub75 *h, struct hub75_ctrl *p)
{
	struct device *dev = h->dev;
	u32 bits[HUB75_LINES], lo = 31, bank = 0, b;
	struct gpio_descs *descs;
	unsigned int i;
	int ret;

	if (of_count_phandle_with_args(dev->of_node, "data-gpios", "#gpio-cells") != HUB75_LINES)
		return dev_err_probe(dev, -EINVAL,
				     "\"data-gpios\" needs 6 pins (R1 G1 B1 R2 G2 B2)\n");
	for (i = 0; i < HUB75_LINES; i++) {
		ret = hub75_gpio_at(dev, "data-gpios", i, &b, &bits[i]);
		if (ret)
			return ret;
		if (i && b != bank)
			return dev_err_probe(dev, -EINVAL,
					     "\"data-gpios\": the PRU writes one bank; pins are in %u and %u\n",
					     bank, b);
		bank = b;
		lo = min(lo, bits[i]);
	}
	for (i = 0; i < HUB75_LINES; i++) {
		if (bits[i] - lo > 15)
			return dev_err_probe(dev, -EINVAL,
					     "\"data-gpios\": pins %u and %u are more than 16 bits apart\n",
					     lo, bits[i]);
		h->layout.line_bit[i] = bits[i] - lo;
		p->gpio_mask |= BIT(bits[i]);
	}
	/* Owned through gpiolib: nothing else claims them, the bank stays on. */
	descs = devm_gpiod_get_array(dev, "data", GPIOD_OUT_LOW);
	if (IS_ERR(descs))
		return dev_err_probe(dev, PTR_ERR(descs), "cannot take the data GPIOs\n");
	p->data_mode = HUB75_DATA_GPIO;
	p->gpio_base = hub75_gpio_banks[bank];
	p->gpio_shift = lo;
	h->layout.entry_bytes = 2;
	return 0;
}

/* @row_addr of the address lines @addr: binary, or one line low per row */
static void hub75_row_addr(struct hub75 *h, struct hub75_ctrl *p, const u32 *addr,
			   unsigned int lines, bool direct)
{
	unsigned int r, i;

	for (r = 0; r < h->layout.rows; r++) {
		p->row_addr[r] = 0;
		for (i = 0; i < lines; i++)
			if (direct ? r != i : r & BIT(i))
				p->row_addr[r] |= BIT(addr[i]);
	}
}

/* One control line of HUB75_DATA_BANKS ("clk-gpios" ...), in bank @cb */
static int hub75_ctrl_gpio(struct device *dev, const char *prop, unsigned int i, u32 cb,
			   u32 *taken, u32 *bit)
{
	u32 bank;
	int ret;

	ret = hub75_gpio_at(dev, prop, i, &bank, bit);
	if (ret)
		return ret;
	if (bank != cb)
		return dev_err_probe(dev, -EINVAL,
				     "\"%s\": the control lines must share one GPIO bank (%u, not %u)\n",
				     prop, cb, bank);
	if (taken[bank] & BIT(*bit))
		return dev_err_probe(dev, -EINVAL, "\"%s\": gpio%u_%u is used twice\n", prop,
				     bank, *bit);
	taken[bank] |= BIT(*bit);
	return 0;
}

/*
 * HUB75_DATA_BANKS: every line a GPIO.  The control lines in one bank
 * (slot 3, with the clock in its mask), the outputs' data lines anywhere
 * in banks 0-3, the other banks with data in slots 0..2 (hub75_proto.h).
 */
static int hub75_parse_banks(struct hub75 *h, struct hub75_ctrl *p, bool direct)
{
	struct hub75_layout *l = &h->layout;
	unsigned int addr_lines = direct ? l->rows : ilog2(l->rows);
	unsigned int lines = l->outputs * HUB75_LINES, i, k, slot;
	u32 taken[PRUKIT_PRU_GPIO_BANKS] = { }, data_banks = 0;
	u32 cb, clk, lat, oe, addr[5], bank[HUB75_MAX_OUTPUTS * HUB75_LINES];
	u32 bit[HUB75_MAX_OUTPUTS * HUB75_LINES];
	struct device *dev = h->dev;
	struct gpio_descs *descs;
	struct gpio_desc *desc;
	int ret;

	ret = hub75_gpio_at(dev, "clk-gpios", 0, &cb, &clk);
	if (ret)
		return ret;
	ret = hub75_ctrl_gpio(dev, "clk-gpios", 0, cb, taken, &clk);
	if (!ret)
		ret = hub75_ctrl_gpio(dev, "lat-gpios", 0, cb, taken, &lat);
	if (!ret)
		ret = hub75_ctrl_gpio(dev, "oe-gpios", 0, cb, taken, &oe);
	if (ret)
		return ret;
	if (of_count_phandle_with_args(dev->of_node, "addr-gpios", "#gpio-cells") != addr_lines)
		return dev_err_probe(dev, -EINVAL, "\"addr-gpios\" needs %u pins for the scan\n",
				     addr_lines);
	for (i = 0; i < addr_lines; i++) {
		ret = hub75_ctrl_gpio(dev, "addr-gpios", i, cb, taken, &addr[i]);
		if (ret)
			return ret;
		p->addr_mask |= BIT(addr[i]);
	}
	if (of_count_phandle_with_args(dev->of_node, "data-gpios", "#gpio-cells") != lines)
		return dev_err_probe(dev, -EINVAL,
				     "\"data-gpios\" needs %u pins: R1 G1 B1 R2 G2 B2 of each of %u outputs\n",
				     lines, l->outputs);
	for (i = 0; i < lines; i++) {
		ret = hub75_gpio_at(dev, "data-gpios", i, &bank[i], &bit[i]);
		if (ret)
			return ret;
		if (taken[bank[i]] & BIT(bit[i]))
			return dev_err_probe(dev, -EINVAL, "\"data-gpios\": gpio%u_%u twice\n",
					     bank[i], bit[i]);
		taken[bank[i]] |= BIT(bit[i]);
		if (bank[i] != cb)
			data_banks |= BIT(bank[i]);
	}
	/* slots: the other banks up to slot 2, the control bank in slot 3 */
	slot = HUB75_BANK_CTRL_SLOT - hweight32(data_banks);
	for (k = 0; k < PRUKIT_PRU_GPIO_BANKS; k++) {
		unsigned int s = k == cb ? HUB75_BANK_CTRL_SLOT : slot;

		if (k != cb && !(data_banks & BIT(k)))
			continue;
		p->bank_addr[s] = hub75_gpio_banks[k];
		p->bank_used |= BIT(s);
		for (i = 0; i < lines; i++) {
			if (bank[i] != k)
				continue;
			p->bank_mask[s] |= BIT(bit[i]);
			l->bank_slot[i / HUB75_LINES][i % HUB75_LINES] = s;
			l->bank_bit[i / HUB75_LINES][i % HUB75_LINES] = bit[i];
		}
		if (k != cb)
			slot++;
	}
	p->bank_mask[HUB75_BANK_CTRL_SLOT] |= BIT(clk);
	hub75_row_addr(h, p, addr, addr_lines, direct);

	/* Owned through gpiolib: outputs, nothing else claims them; dark */
	descs = devm_gpiod_get_array(dev, "data", GPIOD_OUT_LOW);
	if (IS_ERR(descs))
		return dev_err_probe(dev, PTR_ERR(descs), "cannot take the data GPIOs\n");
	descs = devm_gpiod_get_array(dev, "addr", GPIOD_OUT_LOW);
	if (IS_ERR(descs))
		return dev_err_probe(dev, PTR_ERR(descs), "cannot take the address GPIOs\n");
	desc = devm_gpiod_get(dev, "oe", GPIOD_OUT_HIGH);
	if (!IS_ERR(desc))
		desc = devm_gpiod_get(dev, "lat", GPIOD_OUT_LOW);
	if (!IS_ERR(desc))
		desc = devm_gpiod_get(dev, "clk", GPIOD_OUT_LOW);
	if (IS_ERR(desc))
		return dev_err_probe(dev, PTR_ERR(desc), "cannot take the control GPIOs\n");
	p->data_mode = HUB75_DATA_BANKS;
	p->gpio_base = hub75_gpio_banks[cb];
	p->clk_bit = clk;
	p->lat_bit = lat;
	p->oe_bit = oe;
	l->entry_bytes = 4 * HUB75_BANK_SLOTS;
	return 0;
}

/*
 * @direct: a line per row, the row's line low, the others high (outdoor
 * panels' "direct row select"); else the row's number in binary, A its
 * least significant bit.
 */
static int hub75_parse_pins(struct hub75 *h, struct hub75_ctrl *p, bool direct)
{
	unsigned int addr_lines = direct ? h->layout.rows : ilog2(h->layout.rows);
	struct device *dev = h->dev;
	u32 bits[HUB75_LINES], addr[5], clk, lat, oe;
	unsigned int i;
	int ret, n;

	if (device_property_present(dev, "clk-gpios"))
		return hub75_parse_banks(h, p, direct);
	ret = hub75_r30_bit(dev, "prukit,clk-r30-bit", &clk);
	if (!ret)
		ret = hub75_r30_bit(dev, "prukit,lat-r30-bit", &lat);
	if (!ret)
		ret = hub75_r30_bit(dev, "prukit,oe-r30-bit", &oe);
	if (ret)
		return ret;
	n = device_property_count_u32(dev, "prukit,addr-r30-bits");
	if (n != addr_lines)
		return dev_err_probe(dev, -EINVAL,
				     "\"prukit,addr-r30-bits\" has %d bits; the scan needs %u\n",
				     n, addr_lines);
	ret = device_property_read_u32_array(dev, "prukit,addr-r30-bits", addr, n);
	if (ret)
		return dev_err_probe(dev, ret, "cannot read \"prukit,addr-r30-bits\"\n");
	for (i = 0; i < addr_lines; i++) {
		if (addr[i] > 31 || p->addr_mask & BIT(addr[i]))
			return dev_err_probe(dev, -EINVAL, "\"prukit,addr-r30-bits\": bit %u\n",
					     addr[i]);
		p->addr_mask |= BIT(addr[i]);
	}
	if (clk == lat || clk == oe || lat == oe ||
	    (p->addr_mask & (BIT(clk) | BIT(lat) | BIT(oe))))
		return dev_err_probe(dev, -EINVAL,
				     "clock, latch, OE and address lines need R30 bits of their own\n");
	hub75_row_addr(h, p, addr, addr_lines, direct);
	p->clk_bit = clk;
	p->lat_bit = lat;
	p->oe_bit = oe;

	if (!device_property_present(dev, "prukit,data-r30-bits"))
		return hub75_parse_gpio_data(h, p);
	ret = device_property_read_u32_array(dev, "prukit,data-r30-bits", bits, HUB75_LINES);
	if (ret)
		return dev_err_probe(dev, ret,
				     "\"prukit,data-r30-bits\" needs 6 bits (R1 G1 B1 R2 G2 B2)\n");
	/* the firmware writes R30's low byte whole: data and clock */
	if (clk > 7 || oe < 8 || (p->addr_mask & 0xff))
		return dev_err_probe(dev, -EINVAL,
				     "with data on R30, the clock needs a bit of 0..7, OE and the address lines bits above 7\n");
	for (i = 0; i < HUB75_LINES; i++) {
		if (bits[i] > 7 || bits[i] == clk || bits[i] == lat)
			return dev_err_probe(dev, -EINVAL,
					     "\"prukit,data-r30-bits\": bit %u (bits 0..7 but the clock's and the latch's)\n",
					     bits[i]);
		h->layout.line_bit[i] = bits[i];
	}
	p->data_mode = HUB75_DATA_R30;
	h->layout.entry_bytes = 1;
	return 0;
}

/* PRU cycles of one refresh, as hub75_scan.S spends them */
static u64 hub75_refresh_cycles(struct hub75 *h, u32 pixel_cycles)
{
	const struct hub75_layout *l = &h->layout;
	u64 block = (u64)l->row_bytes / HUB75_CHUNK_BYTES * HUB75_CHUNK_CYCLES +
		    (u64)l->clocks * pixel_cycles + HUB75_BLOCK_CYCLES;
	u64 lit = 0;
	unsigned int k;

	if (h->params.data_mode == HUB75_DATA_BANKS)
		block = (u64)l->clocks / 4 * HUB75_BANKS_CHUNK_CYCLES +
			(u64)l->clocks * pixel_cycles + HUB75_BANKS_BLOCK_CYCLES;
	if (h->params.data_mode == HUB75_DATA_GPIO)
		block += HUB75_GPIO_TAIL_CYCLES;
	for (k = 0; k < l->planes; k++)
		lit += (u64)h->lsb_cycles << k;
	return l->rows * (l->planes * block + lit);
}

static void hub75_kvfree(void *p)
{
	kvfree(p);
}

/* kvcalloc() for the device's lifetime: a wall's table passes 128 KiB */
static void *hub75_devm_kvcalloc(struct device *dev, size_t n, size_t size)
{
	void *p = kvcalloc(n, size, GFP_KERNEL);

	if (!p || devm_add_action_or_reset(dev, hub75_kvfree, p))
		return NULL;
	return p;
}

/* FM6126A-class driver chips: their register words, in the order sent */
struct hub75_panel_type {
	const char *name;
	u32 init[HUB75_MAX_INIT];
};

static const struct hub75_panel_type hub75_panel_types[] = {
	{ "generic" },
	{ "fm6126a", { HUB75_INIT(0x7fff, 11), HUB75_INIT(0x0040, 12) } },
	{ "fm6127", { HUB75_INIT(0xffce, 11), HUB75_INIT(0xe062, 12), HUB75_INIT(0x5f00, 10) } },
};

static int hub75_parse_panel(struct hub75 *h, u32 width, u32 height, u32 chain, bool banks)
{
	struct device *dev = h->dev;
	struct hub75_layout *l = &h->layout;
	const char *mux = "direct", *type = "generic";
	u32 *table, rotation = 0;
	bool serpentine;
	unsigned int i;
	size_t n;
	int m;

	device_property_read_string(dev, "prukit,multiplexing", &mux);
	device_property_read_string(dev, "prukit,panel-type", &type);
	m = match_string(hub75_mux_names, HUB75_MUX_COUNT, mux);
	if (m < 0)
		return dev_err_probe(dev, -EINVAL, "\"prukit,multiplexing\" = \"%s\": unknown\n",
				     mux);
	for (i = 0; i < ARRAY_SIZE(hub75_panel_types); i++)
		if (!strcmp(hub75_panel_types[i].name, type))
			break;
	if (i == ARRAY_SIZE(hub75_panel_types))
		return dev_err_probe(dev, -EINVAL,
				     "\"prukit,panel-type\" = \"%s\": generic, fm6126a or fm6127\n",
				     type);
	memcpy(h->params.init, hub75_panel_types[i].init, sizeof(h->params.init));
	if (height != 2 * l->rows * hub75_mux_stretch(m))
		return dev_err_probe(dev, -EINVAL,
				     "a %u-row panel with scan 1/%u and multiplexing %s: the rows must be %u\n",
				     height, l->rows, mux, 2 * l->rows * hub75_mux_stretch(m));
	l->clocks = l->width * hub75_mux_stretch(m);
	device_property_read_u32(dev, "prukit,rotation", &rotation);
	serpentine = device_property_read_bool(dev, "prukit,serpentine");
	if (rotation % 90 || rotation > 270)
		return dev_err_probe(dev, -EINVAL, "\"prukit,rotation\" = %u: 0, 90, 180 or 270\n",
				     rotation);
	/* the table; with every line on GPIO banks the conversion always uses it */
	if (m == HUB75_MUX_DIRECT && !banks && !rotation && !serpentine)
		return 0;
	n = (size_t)l->width * height * l->outputs;
	table = hub75_devm_kvcalloc(dev, n, sizeof(*table));
	if (!table)
		return -ENOMEM;
	if (!hub75_mux_table(m, width, height, chain, l->outputs, table))
		return dev_err_probe(dev, -EINVAL, "multiplexing %s does not fit a %ux%u panel\n",
				     mux, width, height);
	hub75_arrange(table, n, l->width, l->height, height, serpentine, rotation);
	if (rotation == 90 || rotation == 270)
		swap(l->width, l->height);
	l->mux = table;
	return 0;
}

static int hub75_parse(struct hub75 *h)
{
	struct device *dev = h->dev;
	struct hub75_layout *l = &h->layout;
	struct hub75_ctrl *p = &h->params;
	u32 width, height, scan, chain = 1, outputs = 1, planes = HUB75_DEFAULT_PLANES;
	u32 lsb_ns = HUB75_DEFAULT_LSB_NS, clock = HUB75_DEFAULT_CLOCK_HZ, pixel_cycles;
	u32 min_hz = HUB75_MIN_REFRESH_HZ;
	const char *corr = "cie1931", *row_address = "binary";
	bool direct, banks = device_property_present(dev, "clk-gpios");
	u64 cycles;
	int ret;

	if (device_property_read_u32(dev, "prukit,panel-width", &width) ||
	    device_property_read_u32(dev, "prukit,panel-height", &height) ||
	    device_property_read_u32(dev, "prukit,scan", &scan))
		return dev_err_probe(dev, -EINVAL,
				     "\"prukit,panel-width\", \"prukit,panel-height\" and \"prukit,scan\" are required\n");
	device_property_read_u32(dev, "prukit,chain-length", &chain);
	device_property_read_u32(dev, "prukit,outputs", &outputs);
	device_property_read_u32(dev, "prukit,bit-planes", &planes);
	device_property_read_u32(dev, "prukit,lsb-time-ns", &lsb_ns);
	device_property_read_u32(dev, "clock-frequency", &clock);
	device_property_read_string(dev, "prukit,correction", &corr);
	device_property_read_string(dev, "prukit,row-address", &row_address);
	device_property_read_u32(dev, "prukit,min-refresh-hz", &min_hz);

	if (scan != 4 && scan != 8 && scan != 16 && scan != 32)
		return dev_err_probe(dev, -EINVAL, "scan 1/%u: 1/4, 1/8, 1/16 or 1/32\n", scan);
	if (!strcmp(row_address, "direct") && scan <= 4)
		direct = true;
	else if (!strcmp(row_address, "binary"))
		direct = false;
	else
		return dev_err_probe(dev, -EINVAL,
				     "\"prukit,row-address\" = \"%s\" with scan 1/%u: \"binary\", or \"direct\" up to 1/4\n",
				     row_address, scan);
	if (!width || width > 256 || width % 16)
		return dev_err_probe(dev, -EINVAL, "panel width %u: 16..256, a multiple of 16\n",
				     width);
	if (chain < 1 || chain > HUB75_MAX_CHAIN)
		return dev_err_probe(dev, -EINVAL, "chain of %u panels: 1..%u\n", chain,
				     HUB75_MAX_CHAIN);
	if (outputs < 1 || outputs > HUB75_MAX_OUTPUTS || (outputs > 1 && !banks))
		return dev_err_probe(dev, -EINVAL,
				     "%u parallel outputs: 1..%u, more than one with every line on GPIO (clk-gpios)\n",
				     outputs, HUB75_MAX_OUTPUTS);
	if (min_hz < HUB75_LOWEST_REFRESH_HZ)
		return dev_err_probe(dev, -EINVAL, "\"prukit,min-refresh-hz\" = %u: %u at least\n",
				     min_hz, HUB75_LOWEST_REFRESH_HZ);
	if (planes < 1 || planes > HUB75_MAX_PLANES)
		return dev_err_probe(dev, -EINVAL, "%u bit planes: 1..%u\n", planes,
				     HUB75_MAX_PLANES);
	l->width = width * chain;
	l->height = height * outputs;
	l->outputs = outputs;
	l->rows = scan;
	l->planes = planes;
	ret = hub75_parse_panel(h, width, height, chain, banks);
	if (ret)
		return ret;
	if (!strcmp(corr, "cie1931"))
		hub75_layout_lut(l, HUB75_CIE1931);
	else if (!strcmp(corr, "linear"))
		hub75_layout_lut(l, HUB75_LINEAR);
	else
		return dev_err_probe(dev, -EINVAL,
				     "\"prukit,correction\" = \"%s\": \"cie1931\" or \"linear\"\n",
				     corr);
	/* fills @entry_bytes */
	ret = hub75_parse_pins(h, p, direct);
	if (ret)
		return ret;
	l->row_bytes = l->clocks * l->entry_bytes;
	if (l->row_bytes % HUB75_CHUNK_BYTES || l->row_bytes > HUB75_MAX_ROW_BYTES)
		return dev_err_probe(dev, -EINVAL,
				     "%u clocks a row: the PRU takes them %u at a time, %u at most\n",
				     l->clocks, HUB75_CHUNK_BYTES / l->entry_bytes,
				     HUB75_MAX_ROW_BYTES / l->entry_bytes);
	hub75_layout_finish(l);

	if (p->data_mode == HUB75_DATA_BANKS) {
		pixel_cycles = (2 * hweight8(p->bank_used) + 1) * HUB75_GPIO_WRITE_CYCLES;
	} else if (p->data_mode == HUB75_DATA_R30) {
		/* 4 + 2 * delay cycles a pixel, the nearest clock not above */
		u32 delay = DIV_ROUND_UP(DIV_ROUND_UP(HUB75_PRU_HZ, max(clock, 1u)), 2);

		delay = delay > 2 ? delay - 2 : 1;
		if (delay > HUB75_MAX_CLK_DELAY)
			return dev_err_probe(dev, -EINVAL, "a %u Hz clock is too slow\n", clock);
		p->clk_delay = delay;
		pixel_cycles = 4 + 2 * delay;
	} else {
		pixel_cycles = HUB75_GPIO_PIXEL_CYCLES;
	}
	h->lsb_cycles = DIV_ROUND_CLOSEST(lsb_ns, 5);
	/* OE on a GPIO bank: its two writes are at least one write's time apart */
	if (banks && h->lsb_cycles < HUB75_GPIO_WRITE_CYCLES)
		return dev_err_probe(dev, -EINVAL,
				     "LSB time %u ns: with OE on a GPIO bank, %u ns at least\n",
				     lsb_ns, HUB75_GPIO_WRITE_CYCLES * 5);
	if (!h->lsb_cycles || (u64)h->lsb_cycles << (planes - 1) > HUB75_MAX_OE_CYCLES)
		return dev_err_probe(dev, -EINVAL,
				     "LSB time %u ns with %u planes: the longest plane must be 5 ns..%u us\n",
				     lsb_ns, planes, HUB75_MAX_OE_CYCLES / 200);

	cycles = hub75_refresh_cycles(h, pixel_cycles);
	if (cycles * min_hz > HUB75_PRU_HZ)
		return dev_err_probe(dev, -EINVAL,
				     "%ux%u at %u bit planes: a refresh takes %llu PRU cycles, %llu Hz, below %u Hz; use fewer planes, a shorter chain or LSB time, or a faster clock\n",
				     l->width, l->height, planes, cycles,
				     div64_u64(HUB75_PRU_HZ, cycles), min_hz);
	h->refresh_cycles = cycles;
	p->row_bytes = l->row_bytes;
	p->rows = l->rows;
	p->planes = l->planes;
	dev_dbg(dev, "%ux%u, %u planes, %u cycles a pixel, refresh %llu cycles\n",
		l->width, l->height, planes, pixel_cycles, cycles);
	return 0;
}

/* ------------------------------------------------------------------ */
/* probe                                                                */
/* ------------------------------------------------------------------ */

/* Dark before the core stops: a halted core could leave a row lit. */
static void hub75_pru_shutdown(void *data)
{
	struct hub75 *h = data;

	mutex_lock(&h->lock);
	if (h->running)
		hub75_command(h, HUB75_CMD_STOP);
	h->running = false;
	mutex_unlock(&h->lock);
	prukit_pru_shutdown(h->pru);
}

static int hub75_pru_init(struct hub75 *h)
{
	struct device *dev = h->dev;
	int ret;

	h->pru = devm_prukit_pru_get(dev, 0);
	if (IS_ERR(h->pru))
		return PTR_ERR(h->pru);
	ret = prukit_pru_boot(h->pru, NULL);
	if (ret)
		return ret;
	ret = devm_add_action_or_reset(dev, hub75_pru_shutdown, h);
	if (ret)
		return ret;
	h->ctrl = prukit_pru_map(h->pru, PRUKIT_CTRL_DA, sizeof(struct hub75_ctrl));
	if (!h->ctrl)
		return dev_err_probe(dev, -EPROTO, "no control block in the PRU's memory\n");
	ret = prukit_pru_ctrl_check(h->pru, h->ctrl, HUB75_MAGIC, HUB75_VERSION,
				    sizeof(struct hub75_ctrl));
	if (ret)
		return ret;
	ret = prukit_pru_ctrl_wait_ready(h->pru, h->ctrl, PRUKIT_PRU_TIMEOUT_MS);
	if (ret)
		return ret;
	/* R30 is 0 when a core starts: OE low, a row lit until STOP */
	writeb(h->params.oe_bit, HUB75_CTRL(h, oe_bit));
	mutex_lock(&h->lock);
	ret = hub75_command(h, HUB75_CMD_STOP);
	mutex_unlock(&h->lock);
	return ret;
}

static int hub75_mode_init(struct hub75 *h)
{
	struct drm_device *drm = &h->drm;
	struct drm_display_mode *m = &h->mode;
	u32 hz = div64_u64(HUB75_PRU_HZ, h->refresh_cycles);
	int ret;

	ret = drmm_mode_config_init(drm);
	if (ret)
		return ret;
	drm->mode_config.min_width = h->layout.width;
	drm->mode_config.min_height = h->layout.height;
	drm->mode_config.max_width = 4096;
	drm->mode_config.max_height = 4096;
	drm->mode_config.preferred_depth = 24;
	drm->mode_config.funcs = &hub75_mode_config_funcs;

	/* the mode's refresh rate is the panel's */
	m->hdisplay = h->layout.width;
	m->hsync_start = m->hdisplay;
	m->hsync_end = m->hdisplay;
	m->htotal = m->hdisplay;
	m->vdisplay = h->layout.height;
	m->vsync_start = m->vdisplay;
	m->vsync_end = m->vdisplay;
	m->vtotal = m->vdisplay;
	m->clock = max(DIV_ROUND_CLOSEST(hz * h->layout.width * h->layout.height, 1000), 1u);
	m->type = DRM_MODE_TYPE_DRIVER | DRM_MODE_TYPE_PREFERRED;
	drm_mode_set_name(m);

	ret = drm_universal_plane_init(drm, &h->plane, 0, &hub75_plane_funcs, hub75_formats,
				       ARRAY_SIZE(hub75_formats), NULL, DRM_PLANE_TYPE_PRIMARY,
				       NULL);
	if (ret)
		return ret;
	drm_plane_helper_add(&h->plane, &hub75_plane_helper_funcs);
	drm_plane_enable_fb_damage_clips(&h->plane);

	ret = drm_crtc_init_with_planes(drm, &h->crtc, &h->plane, NULL, &hub75_crtc_funcs, NULL);
	if (ret)
		return ret;
	drm_crtc_helper_add(&h->crtc, &hub75_crtc_helper_funcs);

	ret = drm_encoder_init(drm, &h->encoder, &hub75_encoder_funcs, DRM_MODE_ENCODER_NONE,
			       NULL);
	if (ret)
		return ret;
	h->encoder.possible_crtcs = drm_crtc_mask(&h->crtc);

	drm_connector_helper_add(&h->connector, &hub75_connector_helper_funcs);
	ret = drm_connector_init(drm, &h->connector, &hub75_connector_funcs,
				 DRM_MODE_CONNECTOR_Unknown);
	if (ret)
		return ret;
	ret = drm_connector_attach_encoder(&h->connector, &h->encoder);
	if (ret)
		return ret;
	drm_mode_config_reset(drm);
	return 0;
}

static void hub75_unregister(void *data)
{
	struct hub75 *h = data;

	drm_dev_unplug(&h->drm);
	drm_atomic_helper_shutdown(&h->drm);
}

static int hub75_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct backlight_properties props = {
		.type = BACKLIGHT_RAW,
		.max_brightness = HUB75_MAX_BRIGHTNESS,
		.brightness = HUB75_MAX_BRIGHTNESS,
	};
	struct hub75 *h;
	unsigned int b;
	int ret;

	h = devm_drm_dev_alloc(dev, &hub75_drm_driver, struct hub75, drm);
	if (IS_ERR(h))
		return PTR_ERR(h);
	h->dev = dev;
	h->brightness = HUB75_MAX_BRIGHTNESS;
	h->full = true;
	mutex_init(&h->lock);
	platform_set_drvdata(pdev, h);

	ret = hub75_parse(h);
	if (ret)
		return ret;

	/* Before the PRU: freed after it stopped reading them. */
	h->buf_size = hub75_buffer_size(&h->layout);
	for (b = 0; b < 2; b++) {
		h->buf[b] = dmam_alloc_coherent(dev, h->buf_size, &h->dma[b], GFP_KERNEL);
		if (!h->buf[b])
			return -ENOMEM;
		if (upper_32_bits(h->dma[b]))
			return dev_err_probe(dev, -EINVAL,
					     "frame buffer beyond the PRU's 32 bits\n");
		h->params.buf_addr[b] = h->dma[b];
	}
	ret = hub75_pru_init(h);
	if (ret)
		return ret;

	ret = hub75_mode_init(h);
	if (ret)
		return ret;

	h->bl = devm_backlight_device_register(dev, dev_name(dev), dev, h, &hub75_bl_ops,
					       &props);
	if (IS_ERR(h->bl))
		return dev_err_probe(dev, PTR_ERR(h->bl), "cannot register the brightness\n");

	ret = drm_dev_register(&h->drm, 0);
	if (ret)
		return ret;
	ret = devm_add_action_or_reset(dev, hub75_unregister, h);
	if (ret)
		return ret;
	prukit_drm_fbdev_setup(&h->drm);
	dev_info(dev, "%ux%u, %u bit planes, %u Hz refresh: %s\n", h->layout.width,
		 h->layout.height, h->layout.planes,
		 (u32)div64_u64(HUB75_PRU_HZ, h->refresh_cycles), dev_name(h->drm.primary->kdev));
	return 0;
}

static void hub75_shutdown(struct platform_device *pdev)
{
	struct hub75 *h = platform_get_drvdata(pdev);

	drm_atomic_helper_shutdown(&h->drm);
}

static const struct of_device_id hub75_of_match[] = {
	{ .compatible = "prukit,hub75" },
	{ }
};
MODULE_DEVICE_TABLE(of, hub75_of_match);

static struct platform_driver hub75_driver = {
	.probe = hub75_probe,
	.shutdown = hub75_shutdown,
	.driver = {
		.name = "hub75",
		.of_match_table = hub75_of_match,
		.dev_groups = hub75_groups,
	},
};
module_platform_driver(hub75_driver);

PRUKIT_IMPORT_NS();
MODULE_DESCRIPTION("HUB75 RGB LED matrix display on a BeagleBone PRU");
MODULE_AUTHOR("prukit developers");
MODULE_LICENSE("GPL");
