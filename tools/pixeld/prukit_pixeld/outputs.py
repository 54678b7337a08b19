# SPDX-License-Identifier: GPL-2.0-only
"""The devices prukit-pixeld writes whole frames to (a ws281x string set, a
framebuffer, a file or FIFO) and the maps that put network pixels into
their frames."""
import errno
import fcntl
import glob
import os
import struct

from .common import log

SYSFS = os.environ.get("PRUKIT_SYSFS", "/sys")
FBIOGET_VSCREENINFO = 0x4600


# ------------------------------------------------------------------------ outputs

class Output:
    """A device taking whole frames.  .buf holds the frame in the device's
    own layout; .bpp is the bytes of one pixel there (3: R, G, B; 4: R, G,
    B, W); .pixels is None while the device is absent."""

    RETRY = 5.0

    def __init__(self, name, where):
        self.name, self.where = name, where
        self.pixels = None
        self.bpp = 3
        self.buf = bytearray()
        self.fd = None
        self.pending = False	# a frame waits for the device (ws281x: EAGAIN)
        self.next_try = 0.0
        self.said = None
        self.on_close = None	# called before the device is closed

    def say_once(self, msg):
        if msg != self.said:
            log("output %s: %s" % (self.name, msg))
            self.said = msg

    def attach(self, now):
        """Open the device when it is there (at most every RETRY s); True
        when open.  The geometry is read anew each time."""
        if self.fd is not None:
            return True
        if now < self.next_try:
            return False
        self.next_try = now + self.RETRY
        try:
            self.open()
        except OSError as e:
            self.close()
            self.say_once("%s: %s (waiting for it)" % (e.filename or self.where, e.strerror))
            return False
        except ValueError as e:
            self.close()
            self.say_once(str(e))
            return False
        self.buf = bytearray(self.pixels * self.bpp)
        self.say_once("%s, %d pixels of %d bytes" % (self.describe(), self.pixels, self.bpp))
        return True

    def describe(self):
        return self.where

    def close(self):
        if self.fd is not None:
            if self.on_close:
                self.on_close(self)
            os.close(self.fd)
        self.fd = None
        self.pixels = None
        self.pending = False

    def lost(self, e):
        self.say_once("%s: %s (closed; reopened when it is back)" % (self.describe(), e.strerror))
        self.close()

    def frame(self):
        """The bytes to write for .buf (a conversion, for the framebuffer)."""
        return self.buf

    def write(self, stats):
        """Write the frame; False if the device did not take it now."""
        if self.fd is None:
            return False
        try:
            self.put(self.frame())
        except BlockingIOError:
            self.pending = True
            stats.add("output.%s.busy" % self.name)
            return False
        except OSError as e:
            stats.add("output.%s.errors" % self.name)
            self.lost(e)
            return False
        self.pending = False
        stats.add("output.%s.frames" % self.name)
        return True

    def put(self, data):
        os.pwrite(self.fd, data, 0)


def read_sysfs(path):
    with open(path) as f:
        return f.read().strip()


class Ws281xOutput(Output):
    """/dev/ws281xN: string-major frames, R, G, B (and W) whatever the
    chips' wire order; written non-blocking, the newest frame kept while
    the cores are busy (POLLOUT says when they take one)."""

    def open(self):
        base = os.path.join(SYSFS, "class", "ws281x", os.path.basename(self.where))
        try:
            strings = int(read_sysfs(os.path.join(base, "strings")))
            leds = int(read_sysfs(os.path.join(base, "leds_per_string")))
            self.bpp = int(read_sysfs(os.path.join(base, "bytes_per_led")))
        except OSError as e:
            raise OSError(e.errno, "not a ws281x device (%s)" % e.strerror, base) from e
        self.pixels = strings * leds
        self.strings, self.leds = strings, leds
        self.fd = os.open(self.where, os.O_RDWR | os.O_NONBLOCK | os.O_CLOEXEC)

    def put(self, data):
        n = os.write(self.fd, data)
        if n != len(data):
            raise OSError(errno.EIO, "short write (%d of %d bytes)" % (n, len(data)))


class FbOutput(Output):
    """A framebuffer (the hub75 driver's /dev/fbN, or any): pixels row by
    row; R, G, B kept here and converted to the framebuffer's format
    (32 bits per pixel with 8-bit fields, or RGB565) when written."""

    def __init__(self, name, where, find_hub75=False):
        super().__init__(name, where)
        self.find_hub75 = find_hub75
        self.dev = where

    def describe(self):
        return self.dev

    def locate(self):
        if not self.find_hub75:
            return self.where
        for d in sorted(glob.glob(os.path.join(SYSFS, "class", "graphics", "fb*"))):
            try:
                if read_sysfs(os.path.join(d, "name")) == "hub75drmfb":
                    return "/dev/" + os.path.basename(d)
            except OSError:
                continue
        raise OSError(errno.ENOENT, "no framebuffer of the hub75 driver (is its overlay "
                      "loaded?)", os.path.join(SYSFS, "class", "graphics"))

    def open(self):
        self.dev = self.locate()
        self.fd = os.open(self.dev, os.O_RDWR | os.O_CLOEXEC)
        var = bytearray(160)
        fcntl.ioctl(self.fd, FBIOGET_VSCREENINFO, var)
        (xres, yres, _, _, _, _, bits, _, ro, rl, _, go, gl, _, bo, bl, _) = \
            struct.unpack_from("<17I", var)
        self.width, self.height, self.bits = xres, yres, bits
        try:
            self.stride = int(read_sysfs(os.path.join(
                SYSFS, "class", "graphics", os.path.basename(self.dev), "stride")))
        except (OSError, ValueError):
            self.stride = xres * bits // 8
        fields = (ro, rl, go, gl, bo, bl)
        if bits == 32 and (rl, gl, bl) == (8, 8, 8):
            self.fmt = "32"
            self.where_rgb = (ro // 8, go // 8, bo // 8)
        elif bits == 16 and fields == (11, 5, 5, 6, 0, 5):
            self.fmt = "565"
        else:
            raise ValueError("%s: %d bits per pixel with fields %s: not a format prukit-pixeld "
                             "writes (32-bit with 8-bit fields, RGB565)" % (self.dev, bits, fields))
        self.pixels = xres * yres
        self.bpp = 3

    def frame(self):
        rgb = self.buf
        if self.fmt == "32":
            out = bytearray(self.pixels * 4)
            for c, at in enumerate(self.where_rgb):
                out[at::4] = rgb[c::3]
        else:
            out = bytearray(self.pixels * 2)
            for i in range(self.pixels):
                r, g, b = rgb[3 * i:3 * i + 3]
                struct.pack_into("<H", out, 2 * i, (r >> 3) << 11 | (g >> 2) << 5 | b >> 3)
        return out

    def put(self, data):
        row = self.width * self.bits // 8
        if self.stride == row:
            os.pwrite(self.fd, data, 0)
        else:
            for y in range(self.height):
                os.pwrite(self.fd, data[y * row:(y + 1) * row], y * self.stride)


class FileOutput(Output):
    """A file (or FIFO) taking frames of PIXELS x 3 or 4 bytes: for trying a
    configuration without the devices.  "append" keeps every frame."""

    def __init__(self, name, where, pixels, bpp, append):
        super().__init__(name, where)
        self.n, self.nbpp, self.append = pixels, bpp, append

    def open(self):
        flags = os.O_WRONLY | os.O_CREAT | os.O_CLOEXEC | (os.O_APPEND if self.append else 0)
        self.fd = os.open(self.where, flags, 0o644)
        self.pixels, self.bpp = self.n, self.nbpp

    def put(self, data):
        if self.append:
            os.write(self.fd, data)
        else:
            os.pwrite(self.fd, data, 0)


# ---------------------------------------------------------------------------- maps

class Map:
    """Network pixels onto output pixels: PIXELS pixels of NBPP bytes from
    the protocol's address (a universe and channel, an OPC channel, a DDP
    byte offset) to the output's pixels AT.. .  Received bytes land in
    .stream; .apply() puts them into the output's frame."""

    def __init__(self, line, output, proto, nbpp, **kw):
        self.line, self.output, self.proto = line, output, proto
        self.fmt_nbpp = self.nbpp = nbpp	# None: the output's
        self.kw = kw
        self.at = kw.get("at", 0)
        self.want = kw.get("pixels")
        self.pixels = 0
        self.stream = bytearray()
        self.dirty = False

    def resolve(self):
        """Fit the map to its output, now that its size is known."""
        out = self.output
        n = out.pixels - self.at if self.want is None else self.want
        if self.at >= out.pixels or n <= 0:
            log("%s: %s starts at pixel %d of its %d: nothing mapped"
                % (self.line, out.name, self.at, out.pixels))
            n = 0
        elif self.at + n > out.pixels:
            log("%s: %d pixels from %d pass the end of %s (%d pixels): %d mapped"
                % (self.line, n, self.at, out.name, out.pixels, out.pixels - self.at))
            n = out.pixels - self.at
        self.pixels = n
        self.stream = bytearray(n * self.nbpp)

    def apply(self):
        out, n, a = self.output, self.pixels, self.at * self.output.bpp
        ob = out.bpp
        if self.nbpp == ob:
            out.buf[a:a + n * ob] = self.stream
        else:
            for c in range(min(self.nbpp, ob)):
                out.buf[a + c:a + n * ob:ob] = self.stream[c::self.nbpp]
            if ob == 4:		# RGB onto RGBW: no W
                out.buf[a + 3:a + n * ob:ob] = bytes(n)
        self.dirty = False
