# SPDX-License-Identifier: GPL-2.0-only
"""prukit ws281x: a test pattern on the WS281x (NeoPixel) strings of a
prukit ws281x controller, through its whole-frame device /dev/ws281xN.

A frame is string-major, every string padded to the longest one, 3 bytes
per LED (R, G, B) or 4 (R, G, B, W) when any string is RGBW; the driver
puts each string's bytes in its chips' order (Documentation/ws281x.rst,
Documentation/ABI/testing/dev-ws281x).  The geometry comes from sysfs
(/sys/class/ws281x/ws281xN/strings, leds_per_string, bytes_per_led).
"""
import argparse
import colorsys
import errno
import glob
import os
import time

from . import Error, number_arg, parse_ranges, read, sysfs

OVERLAY = "PRUKIT-WS281X-00A0"
GROUP = "gpio"			# drivers/ws281x/udev/60-ws281x.rules
RAINBOW_STEPS = 32		# frames of one turn of the rainbow
SWEEP_STEPS = 16		# frames from dark to full in the brightness sweep


_count = number_arg(lambda t: int(t, 0), lambda n: n >= 1,
                    "%r is not a number", "%r: at least 1")


_loops = number_arg(lambda t: int(t, 0), lambda n: n >= 0,  # 0: until interrupted
                    "%r is not a number", "%r: 0 (for ever) or more")


_level = number_arg(lambda t: int(t, 0), lambda n: 0 <= n <= 255,
                    "%r is not a number", "%r is not in 0..255")


_seconds = number_arg(float, lambda s: 0 <= s < 3600,
                      "%r is not a number of seconds", "%r is not in 0..3600 seconds")


def parse_list(text):
    """argparse type: "0,2-3" -> [0, 2, 3] (sorted, each once)."""
    try:
        return parse_ranges(text)
    except ValueError as e:
        raise argparse.ArgumentTypeError("%r: %s" % (text, e))


def register(sub):
    p = sub.add_parser(
        "ws281x", help="a test pattern on WS281x (NeoPixel) strings",
        description="Light every LED red, green, blue and white (and W alone on RGBW "
        "strings), run a dot along each string, optionally sweep the brightness, then "
        "turn a rainbow; then leave the LEDs dark (all off) unless --keep.  Frames go "
        "to /dev/ws281xN in R, G, B(, W) order: the driver puts them in each string's "
        "colour order.",
        epilog="The device comes from the overlay %s (or PRUKIT-WS281X-48-00A0) and "
        "the module ws281x; users in group %s may use it.  --brightness scales the "
        "pattern's colours; the driver's own brightness and lut "
        "(/sys/class/ws281x/ws281xN) apply on top.  Documentation/ws281x.rst."
        % (OVERLAY, GROUP))
    p.add_argument("--device", metavar="DEV",
                   help="/dev/ws281xN, ws281xN or N (default: the first one)")
    p.add_argument("--leds", type=_count, metavar="N",
                   help="light the first N LEDs of each string (default: all)")
    p.add_argument("--strings", type=parse_list, metavar="LIST",
                   help="the strings to light, e.g. 0,2-3 (default: all; others stay dark)")
    p.add_argument("--brightness", type=_level, default=64, metavar="0-255",
                   help="the pattern's full level (default 64: a quarter, easy on "
                   "eyes and power supplies)")
    p.add_argument("--sweep", action="store_true",
                   help="also sweep white from dark to --brightness and back")
    p.add_argument("--loops", type=_loops, default=1, metavar="N",
                   help="run the pattern N times (default 1; 0: until Ctrl-C)")
    p.add_argument("--delay", type=_seconds, default=0.5, metavar="SECONDS",
                   help="how long each colour is shown (default 0.5); the dot and "
                   "rainbow frames a tenth of it")
    p.add_argument("--keep", action="store_true",
                   help="leave the last frame lit instead of turning every LED off")
    p.add_argument("--dump", metavar="FILE",
                   help="also write every frame sent to FILE, one after another "
                   "(for tests)")
    p.set_defaults(func=run)


def devices():
    """The controllers' names (ws281x0 ...), in order."""
    names = [os.path.basename(d) for d in glob.glob(sysfs("class", "ws281x", "ws281x*"))]
    return sorted(names, key=lambda n: int(n[6:]) if n[6:].isdigit() else 1 << 30)


def missing_hint():
    return ("The strings come from the overlay %s (or PRUKIT-WS281X-48-00A0):\n"
            "  sudo prukit enable %s\n"
            "then reboot.  If the overlay is enabled, the module may not be loaded:\n"
            "  sudo modprobe ws281x\n"
            "and `dmesg | grep ws281x` says why a controller did not bind."
            % (OVERLAY, OVERLAY))


def find_device(arg):
    """The controller's name (ws281xN) for --device, or the first one."""
    if arg is None:
        names = devices()
        if not names:
            raise Error("no ws281x device (/dev/ws281xN)", missing_hint())
        return names[0]
    name = os.path.basename(arg)
    if name.isdigit():
        name = "ws281x" + name
    if not os.path.isdir(sysfs("class", "ws281x", name)):
        have = devices()
        raise Error("no ws281x device %s%s" % (
            arg, " (there is %s)" % ", ".join("/dev/" + n for n in have) if have else ""),
            None if have else missing_hint())
    return name


def geometry(name):
    """(strings, leds_per_string, bytes_per_led) of controller NAME."""
    vals = []
    for attr in ("strings", "leds_per_string", "bytes_per_led"):
        v = read(sysfs("class", "ws281x", name, attr))
        if v is None or not v.isdigit():
            raise Error("cannot read %s" % sysfs("class", "ws281x", name, attr),
                        "Is the ws281x module the one prukit installed (modinfo ws281x)?")
        vals.append(int(v))
    return tuple(vals)


def os_error(e, dev, doing):
    """An Error for an OSError of DEV while DOING (open, write ...)."""
    code = e.errno
    what = "%s: %s: %s" % (dev, doing, os.strerror(code) if code else e)
    if code in (errno.EACCES, errno.EPERM):
        return Error(what, "The udev rule prukit installs gives %s to group %s:\n"
                     "  sudo adduser $USER %s\n"
                     "then log in again (or run prukit with sudo).  If `ls -l %s` shows "
                     "no group %s,\nthe rule is not installed: make udev_install."
                     % (dev, GROUP, GROUP, dev, GROUP))
    if code in (errno.ENOENT, errno.ENXIO):
        return Error(what, missing_hint())
    if code == errno.EPIPE:
        return Error(what, "A PRU of the controller crashed or was started again behind "
                     "the driver's back: the strings are stopped.  Reload the driver:\n"
                     "  sudo modprobe -r ws281x && sudo modprobe ws281x")
    if code == errno.ETIMEDOUT:
        return Error(what, "No PRU took the frame: a core halted or faulted while "
                     "remoteproc still says \"running\" (dmesg: \"halted or faulted?\").  "
                     "Reload the driver:\n  sudo modprobe -r ws281x && sudo modprobe ws281x")
    if code == errno.ENODEV:
        return Error(what, "The driver let go of the device (unbound or being removed).")
    if code in (errno.EBUSY, errno.EAGAIN):
        return Error(what, "Another program is sending frames to the strings.")
    if code == errno.EINVAL:
        return Error(what, "The frame's size is not the controller's any more: did its "
                     "geometry change?  Run the command again.")
    return Error(what)


def scale(rgb, level):
    """Colour components 0..255 scaled to LEVEL (0..255), rounded."""
    return tuple((v * level + 127) // 255 for v in rgb)


def wheel(hue):
    """The fully saturated colour of HUE (0..1) as R, G, B 0..255."""
    return tuple(int(round(c * 255)) for c in colorsys.hsv_to_rgb(hue % 1.0, 1.0, 1.0))


class Frames:
    """Frames of one controller, with the strings and LEDs the user chose."""

    def __init__(self, strings, leds, bpl, chosen, nleds):
        self.strings, self.leds, self.bpl = strings, leds, bpl
        self.chosen, self.nleds = chosen, nleds

    def make(self, colour_of):
        """A frame: LED k of each chosen string gets colour_of(k), a tuple of
        3 or 4 components (W 0 when missing); everything else is off."""
        f = bytearray(self.strings * self.leds * self.bpl)
        for s in self.chosen:
            for k in range(self.nleds):
                c = tuple(colour_of(k)) + (0,)
                at = (s * self.leds + k) * self.bpl
                f[at:at + self.bpl] = bytes(c[:self.bpl])
        return bytes(f)

    def off(self):
        return bytes(self.strings * self.leds * self.bpl)


def pattern(fr, level, sweep, delay):
    """The frames of one pass of the pattern: (what, frame, seconds to show)."""
    colours = [("red", (255, 0, 0)), ("green", (0, 255, 0)), ("blue", (0, 0, 255)),
               ("white", (255, 255, 255))]
    if fr.bpl == 4:
        colours.append(("W (the RGBW chips' white LED)", (0, 0, 0, 255)))
    for what, c in colours:
        yield what, fr.make(lambda k, c=c: scale(c, level)), delay
    step = delay / 10
    for i in range(fr.nleds):
        yield "dot" if i == 0 else None, fr.make(
            lambda k, i=i: scale((255, 255, 255), level) if k == i else (0, 0, 0)), step
    if sweep:
        ramp = [round(level * i / SWEEP_STEPS) for i in range(SWEEP_STEPS + 1)]
        for i, v in enumerate(ramp + ramp[-2::-1]):
            yield "brightness sweep" if i == 0 else None, fr.make(lambda k, v=v: (v, v, v)), step
    for t in range(RAINBOW_STEPS):
        yield "rainbow" if t == 0 else None, fr.make(
            lambda k, t=t: scale(wheel(k / max(fr.nleds, 1) + t / RAINBOW_STEPS), level)), step


def run(args):
    name = find_device(args.device)
    dev = "/dev/" + name
    strings, leds, bpl = geometry(name)
    chosen = args.strings if args.strings is not None else list(range(strings))
    bad = [s for s in chosen if s >= strings]
    if bad:
        raise Error("--strings %s: %s has %d string%s (0-%d)" % (
            ",".join(map(str, bad)), dev, strings, "" if strings == 1 else "s", strings - 1))
    if args.leds is not None and args.leds > leds:
        raise Error("--leds %d: the strings of %s have %d LEDs (the longest)"
                    % (args.leds, dev, leds))
    nleds = args.leds or leds
    fr = Frames(strings, leds, bpl, chosen, nleds)
    print("%s: %d string%s of %d LEDs, %s; lighting string%s %s, %d LEDs each, at %d/255"
          % (dev, strings, "" if strings == 1 else "s", leds,
             "R, G, B, W" if bpl == 4 else "R, G, B", "" if len(chosen) == 1 else "s",
             ",".join(map(str, chosen)), nleds, args.brightness), flush=True)
    try:
        fd = os.open(dev, os.O_WRONLY)
    except OSError as e:
        raise os_error(e, dev, "open")
    dump = None
    try:
        if args.dump:
            try:
                dump = open(args.dump, "wb")
            except OSError as e:
                raise Error("--dump %s: %s" % (args.dump, e.strerror))

        def show(frame):
            try:
                os.write(fd, frame)
            except OSError as e:
                raise os_error(e, dev, "write")
            if dump:
                dump.write(frame)

        n = 0
        try:
            while args.loops == 0 or n < args.loops:
                n += 1
                for what, frame, secs in pattern(fr, args.brightness, args.sweep, args.delay):
                    if what:
                        print(what, flush=True)
                    show(frame)
                    if secs:
                        time.sleep(secs)
        except KeyboardInterrupt:
            if not args.keep:
                show(fr.off())
            raise
        if not args.keep:
            show(fr.off())
            print("all off", flush=True)
    finally:
        os.close(fd)
        if dump:
            dump.close()
    return 0

