/* SPDX-License-Identifier: GPL-2.0-only WITH Linux-syscall-note */
/*
 * /dev/ws281xN: whole frames for the strings of one prukit ws281x
 * controller (Documentation/ws281x.rst, Documentation/ABI/testing/dev-ws281x).
 *
 * A frame is string-major: string 0's LEDs, then string 1's, each string
 * padded to the longest one, 3 bytes per LED (R, G, B), or 4 (R, G, B, W)
 * when any string of the controller is RGBW, whatever the chips' wire
 * order.  The sysfs attributes of the device give the geometry.
 *
 * write() of one whole frame at offset 0 shows it.  mmap() of the device
 * maps the same frame (the driver's own copy, which LED class writes also
 * change); WS281X_IOC_COMMIT shows what it holds.
 */
#ifndef _UAPI_PRUKIT_WS281X_H
#define _UAPI_PRUKIT_WS281X_H

#include <linux/ioctl.h>

#define WS281X_IOC_MAGIC	0xb9	/* free in v6.12's ioctl-number.rst */

/* Show the mapped frame (convert it and queue it for the PRUs). */
#define WS281X_IOC_COMMIT	_IO(WS281X_IOC_MAGIC, 0)

#endif /* _UAPI_PRUKIT_WS281X_H */
