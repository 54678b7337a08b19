/* SPDX-License-Identifier: GPL-2.0-only WITH Linux-syscall-note */
/*
 * beaglelogic.h - ioctls of /dev/beaglelogic, the logic analyzer on the
 * BeagleBone's PRUs (Documentation/beaglelogic.rst).
 *
 * The numbers, argument types and quirks are the original BeagleLogic's, so
 * that its clients (libsigrok's beaglelogic driver, its TCP server) work
 * unchanged: the SET_* ioctls take the value itself as the argument, not a
 * pointer to it (despite _IOW); the GET_* ioctls take a pointer to a __u32.
 */
#ifndef _UAPI_PRUKIT_BEAGLELOGIC_H
#define _UAPI_PRUKIT_BEAGLELOGIC_H

#include <linux/ioctl.h>
#include <linux/types.h>

#define IOCTL_BL_GET_VERSION		_IOR('k', 0x20, __u32)
#define IOCTL_BL_GET_SAMPLE_RATE	_IOR('k', 0x21, __u32)
#define IOCTL_BL_SET_SAMPLE_RATE	_IOW('k', 0x21, __u32)
#define IOCTL_BL_GET_SAMPLE_UNIT	_IOR('k', 0x22, __u32)
#define IOCTL_BL_SET_SAMPLE_UNIT	_IOW('k', 0x22, __u32)
#define IOCTL_BL_GET_TRIGGER_FLAGS	_IOR('k', 0x23, __u32)
#define IOCTL_BL_SET_TRIGGER_FLAGS	_IOW('k', 0x23, __u32)
#define IOCTL_BL_GET_CUR_INDEX		_IOR('k', 0x24, __u32)
#define IOCTL_BL_CACHE_INVALIDATE	_IO('k', 0x25)
#define IOCTL_BL_GET_BUFFER_SIZE	_IOR('k', 0x26, __u32)
#define IOCTL_BL_SET_BUFFER_SIZE	_IOW('k', 0x26, __u32)
#define IOCTL_BL_GET_BUFUNIT_SIZE	_IOR('k', 0x27, __u32)
#define IOCTL_BL_SET_BUFUNIT_SIZE	_IOW('k', 0x27, __u32)
#define IOCTL_BL_FILL_TEST_PATTERN	_IO('k', 0x28)
#define IOCTL_BL_START			_IO('k', 0x29)
#define IOCTL_BL_STOP			_IO('k', 0x2A)

/* Sample units (IOCTL_BL_*_SAMPLE_UNIT, sysfs sampleunit) */
#define BL_SAMPLEUNIT_16_BITS		0
#define BL_SAMPLEUNIT_8_BITS		1

/* Trigger flags (IOCTL_BL_*_TRIGGER_FLAGS, sysfs triggerflags) */
#define BL_TRIGGERFLAGS_ONESHOT		0
#define BL_TRIGGERFLAGS_CONTINUOUS	1

/* States (sysfs state, when no capture runs) */
#define BL_STATE_DISABLED		0
#define BL_STATE_INITIALIZED		1
#define BL_STATE_MEMALLOCD		2
#define BL_STATE_ARMED			3
#define BL_STATE_RUNNING		4
#define BL_STATE_REQUEST_STOP		5
#define BL_STATE_ERROR			6

/* sysfs filltestpattern: the magic that fills every buffer */
#define BL_FILL_TEST_PATTERN_MAGIC	12345678

#endif /* _UAPI_PRUKIT_BEAGLELOGIC_H */
