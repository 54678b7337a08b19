# SPDX-License-Identifier: GPL-2.0-only
"""A minimal DRM/KMS client in python (guest side): the legacy KMS ioctls
a simple program uses to show a dumb buffer, as libdrm's would.  Layouts
from include/uapi/drm/drm.h and drm_mode.h."""
import fcntl
import mmap
import os
import struct

DRM_FORMAT_XRGB8888 = 0x34325258  # "XR24"
DRM_FORMAT_RGB565 = 0x36314752    # "RG16"

MODEINFO = struct.Struct("<I5H5HIII32s")  # 68 bytes
CARD_RES = struct.Struct("<4Q4I4I")
GET_CONNECTOR = struct.Struct("<4Q3I4I4I4x")
CREATE_DUMB = struct.Struct("<4I2IQ")
MAP_DUMB = struct.Struct("<2IQ")
FB_CMD2 = struct.Struct("<5I4I4I4I4x4Q")
CRTC = struct.Struct("<Q7I")
DIRTY = struct.Struct("<4IQ")


def _iowr(nr, size):
    return (3 << 30) | (size << 16) | (ord("d") << 8) | nr


GETRESOURCES = _iowr(0xA0, CARD_RES.size)
GETCONNECTOR = _iowr(0xA7, GET_CONNECTOR.size)
SETCRTC = _iowr(0xA2, CRTC.size + MODEINFO.size)
RMFB = _iowr(0xAF, 4)
DIRTYFB = _iowr(0xB1, DIRTY.size)
CREATEDUMB = _iowr(0xB2, CREATE_DUMB.size)
MAPDUMB = _iowr(0xB3, MAP_DUMB.size)
DESTROYDUMB = _iowr(0xB4, 4)
ADDFB2 = _iowr(0xB8, FB_CMD2.size)


def _ioctl(fd, req, buf):
    b = bytearray(buf)
    fcntl.ioctl(fd, req, b, True)
    return bytes(b)


class Card:
    """An open /dev/dri/cardN, its first CRTC and connector."""

    def __init__(self, path):
        self.fd = os.open(path, os.O_RDWR | os.O_CLOEXEC)
        res = CARD_RES.unpack(_ioctl(self.fd, GETRESOURCES, bytes(CARD_RES.size)))
        ncrtc, nconn = res[5], res[6]
        crtcs = bytearray(4 * ncrtc)
        conns = bytearray(4 * nconn)
        arg = CARD_RES.pack(0, _addr(crtcs), _addr(conns), 0, 0, ncrtc, nconn, 0, 0, 0, 0, 0)
        fcntl.ioctl(self.fd, GETRESOURCES, bytearray(arg), True)
        self.crtc = struct.unpack_from("<I", crtcs)[0]
        self.connector = struct.unpack_from("<I", conns)[0]
        self.modes = self.get_modes()

    def get_modes(self):
        c = GET_CONNECTOR.unpack(_ioctl(self.fd, GETCONNECTOR,
                                        GET_CONNECTOR.pack(*([0] * 8), self.connector,
                                                           *([0] * 6))))
        n = c[4]
        buf = bytearray(MODEINFO.size * n)
        arg = GET_CONNECTOR.pack(0, _addr(buf), 0, 0, n, 0, 0, 0, self.connector, 0, 0, 0, 0, 0, 0)
        fcntl.ioctl(self.fd, GETCONNECTOR, bytearray(arg), True)
        self.connection = c[11]
        return [MODEINFO.unpack_from(buf, i * MODEINFO.size) for i in range(n)]

    def dumb(self, width, height, fmt):
        """A dumb buffer with a framebuffer: (fb_id, handle, pitch, mmap)."""
        bpp = 16 if fmt == DRM_FORMAT_RGB565 else 32
        d = CREATE_DUMB.unpack(_ioctl(self.fd, CREATEDUMB,
                                      CREATE_DUMB.pack(height, width, bpp, 0, 0, 0, 0)))
        handle, pitch, size = d[4], d[5], d[6]
        off = MAP_DUMB.unpack(_ioctl(self.fd, MAPDUMB, MAP_DUMB.pack(handle, 0, 0)))[2]
        m = mmap.mmap(self.fd, size, mmap.MAP_SHARED, mmap.PROT_READ | mmap.PROT_WRITE,
                      offset=off)
        f = FB_CMD2.unpack(_ioctl(self.fd, ADDFB2,
                                  FB_CMD2.pack(0, width, height, fmt, 0, handle, 0, 0, 0,
                                               pitch, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)))
        return f[0], handle, pitch, m

    def set_crtc(self, fb_id, mode):
        conn = bytearray(struct.pack("<I", self.connector))
        arg = CRTC.pack(_addr(conn), 1, self.crtc, fb_id, 0, 0, 0, 1) + MODEINFO.pack(*mode)
        fcntl.ioctl(self.fd, SETCRTC, bytearray(arg), True)

    def dirty(self, fb_id, clips):
        buf = bytearray(b"".join(struct.pack("<4H", *c) for c in clips))
        fcntl.ioctl(self.fd, DIRTYFB, bytearray(DIRTY.pack(fb_id, 0, 0, len(clips), _addr(buf))),
                    True)

    def rmfb(self, fb_id):
        fcntl.ioctl(self.fd, RMFB, bytearray(struct.pack("<I", fb_id)), True)

    def close(self):
        os.close(self.fd)


def _addr(buf):
    """The address of a bytearray's storage, for the ioctls' user pointers."""
    import ctypes
    return ctypes.addressof((ctypes.c_char * len(buf)).from_buffer(buf))
