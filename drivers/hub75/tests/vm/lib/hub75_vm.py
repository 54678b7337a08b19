# SPDX-License-Identifier: GPL-2.0-only
"""Guest side of the hub75 VM test (84-hub75) and of make demo's matrix
part: a bound display (its DRM card and /dev/fbN), the framebuffer
console kept off it, and the simulated pins recorded over whole refreshes
for the host to decode (tools/hub75-decode.py)."""
import glob
import json
import os
import struct
import time

from rpmsg import read_attr, sim_dir, write_attr

SIM = sim_dir()
DRV = "/sys/bus/platform/drivers/hub75"
DEVS = "/sys/bus/platform/devices"

# The 24-panel wall of tests/vm/overlays/test-nodes.dtso: the Octoscroller's
# 8 outputs x 3 64x32 panels at 1/16 scan, every line a GPIO written by PRU0,
# the chains snaking and the picture turned 90 degrees.  WALL_GEOMETRY is
# its part of a capture's metadata (the panel's timing is the caller's).
WALL = "hub75-octo"
WALL_GEOMETRY = dict(width=256, height=192, scan=16, chain=3, outputs=8, serpentine=True,
                     rotation=90, map="octoscroller", format="XRGB8888")


class WallPad:
    """P9_29 (gpio3_15, pad 0x994) for the wall.

    The pad is &pru0's in the VM's tree (PRUKIT-WS281X-00A0) and one of
    the wall's data lines: the wall needs it in GPIO mode, set behind
    pinctrl's back through the simulated board's pads file as config-pin
    would.  restore() gives the pad its mode from before, which the next
    user of PRU0's R30 on it (make demo's NeoPixels) needs.
    """

    PAD = "0x994"

    def __init__(self):
        with open(SIM + "/pads") as f:
            old = [ln.split()[1] for ln in f if ln.startswith(self.PAD + " ")]
        self.old = old[0] if old else None

    def gpio(self):
        """The pad to GPIO mode (7, receiver off); True if the write was taken."""
        return write_attr(SIM + "/pads", self.PAD + " 0x0f") == 0

    def restore(self):
        if self.old is not None:
            write_attr(SIM + "/pads", "%s %s" % (self.PAD, self.old))


def wall_release():
    """After the wall is unbound: its node back to no driver."""
    write_attr(DEVS + "/" + WALL + "/driver_override", "\n")


def sim_cycles():
    with open(SIM + "/stats") as f:
        for line in f:
            if line.startswith("cycles "):
                return int(line.split()[1])
    return 0


def wait_cycles(n, timeout=300):
    """Until the simulator has run N more cycles; False on a timeout."""
    start, t0 = sim_cycles(), time.monotonic()
    while sim_cycles() - start < n:
        if time.monotonic() - t0 > timeout:
            return False
        time.sleep(0.02)
    return True


class Display:
    """A bound hub75 device: its platform device, DRM card and fbdev."""

    def __init__(self, name):
        self.name = name
        self.sys = DEVS + "/" + name
        cards = glob.glob(self.sys + "/drm/card*")
        self.card = "/dev/dri/" + os.path.basename(cards[0]) if cards else None
        self.fb = None
        self.fbname = ""
        me = os.path.realpath(self.sys)
        for f in glob.glob("/sys/class/graphics/fb*"):
            dev = os.path.realpath(f + "/device")
            if dev == me or dev.startswith(me + "/"):
                self.fb = "/dev/" + os.path.basename(f)
                self.fbname = read_attr(f + "/name")
        self.refresh = 0

    def settle(self):
        """Wait until the refresh runs; its length in PRU cycles (0: never)."""
        t0 = time.monotonic()
        while time.monotonic() - t0 < 60:
            c = int(read_attr(self.sys + "/refresh_cycles"))
            if c:
                self.refresh = c
                return c
            time.sleep(0.05)
        return 0


def console_off():
    """fbcon takes every framebuffer that registers (Debian's kernels have
    it built in) and draws its cursor there: a matrix wants none (say
    fbcon=map:... on the kernel command line, or unbind it, as here)."""
    ok = True
    for vt in glob.glob("/sys/class/vtconsole/vtcon*"):
        if "frame buffer" in read_attr(vt + "/name") and read_attr(vt + "/bind") == "1":
            ok &= write_attr(vt + "/bind", "0") == 0
    return ok


class Recorder:
    """Pin traces of pictures, saved to OUT as NAME.trace with their
    description in OUT/hub75.json (the host halves read both)."""

    def __init__(self, out, info=print):
        self.out = out
        self.meta = []
        self.info = info

    def capture(self, disp, name, meta):
        """The pins over 2.6 refreshes, once the last frame was taken."""
        time.sleep(0.1)        # fbdev's deferred I/O flushes after 50 ms
        # the frame is taken at the next refresh; brightness (the refresh's
        # length) at the next plane: the refresh after next is all new
        wait_cycles(int(2.2 * disp.refresh))
        disp.refresh = int(read_attr(disp.sys + "/refresh_cycles")) or disp.refresh
        # a window: the guest may be descheduled long enough for the ring
        # to wrap (seen on 6.1: 35178 records dropped for the chain)
        window = int(2.6 * disp.refresh)
        with open(SIM + "/trace", "w") as f:
            f.write("clear %d" % window)
        wait_cycles(window + 1000)
        with open(SIM + "/trace", "rb") as f:
            data = f.read()
        with open(os.path.join(self.out, name + ".trace"), "wb") as f:
            f.write(data)
        self.meta.append(dict(meta, name=name, refresh=disp.refresh))
        with open(os.path.join(self.out, "hub75.json"), "w") as f:
            json.dump(self.meta, f, indent=1)
        self.info("%s: %d trace bytes, refresh %d cycles" % (name, len(data), disp.refresh))


    def capture_start(self, disp, name, meta, enable):
        """The pins from ENABLE() (a callable, True if it worked) on, the
        first 524285 changes: what the firmware does as the display starts.
        Waits for a whole refresh after it.  False if ENABLE failed."""
        with open(SIM + "/trace", "w") as f:
            f.write("clear first")
        if not enable() or not disp.settle():
            return False
        wait_cycles(int(1.2 * disp.refresh))
        with open(SIM + "/trace", "rb") as f:
            data = f.read()
        with open(os.path.join(self.out, name + ".trace"), "wb") as f:
            f.write(data)
        self.meta.append(dict(meta, name=name, refresh=disp.refresh, kind="start"))
        with open(os.path.join(self.out, "hub75.json"), "w") as f:
            json.dump(self.meta, f, indent=1)
        self.info("%s: %d trace bytes from the start" % (name, len(data)))
        return True


def to_rgb565(xrgb):
    """RGB565 bytes of XRGB8888 bytes (the top bits of each component)."""
    out = bytearray()
    for i in range(0, len(xrgb), 4):
        v = struct.unpack_from("<I", xrgb, i)[0]
        r, g, b = v >> 16 & 255, v >> 8 & 255, v & 255
        out += struct.pack("<H", (r >> 3) << 11 | (g >> 2) << 5 | b >> 3)
    return bytes(out)
