# SPDX-License-Identifier: GPL-2.0-only
"""prukit capture: a short one-shot capture of the BeagleLogic-compatible
logic analyzer (/dev/beaglelogic), drawn in the terminal.

The capture is set up through the device's sysfs attributes
(/sys/devices/virtual/misc/beaglelogic: samplerate, sampleunit,
triggerflags 0 = one-shot, bufunitsize and memalloc sized to the samples
asked for), read to its end from /dev/beaglelogic, and the settings are
put back as they were (Documentation/beaglelogic.rst,
Documentation/ABI/testing/sysfs-devices-virtual-misc-beaglelogic).
"""
import argparse
import errno
import os
import shutil
import sys

from . import Error, number_arg, parse_ranges, read, sysfs

OVERLAY = "PRUKIT-BEAGLELOGIC-00A0"
GROUP = "gpio"			# drivers/beaglelogic/udev/60-beaglelogic.rules
DEV = "/dev/beaglelogic"
MAX_RATE = 100000000
MAX_BUF = 4194304		# bufunitsize's largest (one allocation)
MAX_SAMPLES = 16 * 1024 * 1024
# The settings a capture changes, in the order they are put back
# (bufunitsize frees the buffers: memalloc after it).
SETTINGS = ("samplerate", "sampleunit", "triggerflags", "trigger", "bufunitsize", "memalloc")
LABEL_W = 6			# "ch 13 "


def attr_dir():
    return sysfs("devices", "virtual", "misc", "beaglelogic")


def parse_rate(text):
    """argparse type: samples per second, "1M", "500k", "100000", "2.5MHz"."""
    t = text.strip().lower()
    for suffix in ("hz", "sps", "sa/s"):
        if t.endswith(suffix):
            t = t[:-len(suffix)]
    mult = 1
    if t[-1:] in ("k", "m", "g"):
        mult = {"k": 10**3, "m": 10**6, "g": 10**9}[t[-1]]
        t = t[:-1]
    try:
        rate = float(t) * mult
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a sample rate (e.g. 1M, 500k)" % text)
    if rate != int(rate) or not 1 <= rate <= MAX_RATE:
        raise argparse.ArgumentTypeError(
            "%r: the sample rate is a whole number of samples per second, 1 to 100M" % text)
    return int(rate)


def parse_samples(text):
    """argparse type: a number of samples, "1000", "4k", "1M"."""
    t = text.strip().lower()
    mult = 1
    if t[-1:] in ("k", "m"):
        mult = {"k": 1000, "m": 1000000}[t[-1]]
        t = t[:-1]
    try:
        n = int(t, 10) * mult
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a number of samples" % text)
    if not 1 <= n <= MAX_SAMPLES:
        raise argparse.ArgumentTypeError("%r is not in 1..%d samples" % (text, MAX_SAMPLES))
    return n


def parse_channels(text):
    """argparse type: "0-7", "0,3,5-6" -> [0, 3, 5, 6] (channels 0-15)."""
    try:
        return parse_ranges(text, 15)
    except ValueError as e:
        if "within" in str(e):
            raise argparse.ArgumentTypeError("%r: channels are 0 to 15" % text)
        raise argparse.ArgumentTypeError("%r is not a channel list like 0-7 or 0,2,5" % text)


_width = number_arg(int, lambda n: 20 <= n <= 10000,
                    "%r is not a number of columns", "%r is not in 20..10000 columns")


def register(sub):
    p = sub.add_parser(
        "capture", help="a short logic analyzer capture, drawn in the terminal",
        description="Capture SAMPLES samples from /dev/beaglelogic (one-shot) and draw "
        "one row per channel: '_' low, '‾' high, '|' where the channel changed (when "
        "there are more samples than columns, a column stands for several samples and "
        "'|' marks those in which the channel toggled), with a time axis.  Channels "
        "0-7 are 8-bit samples, any of 8-15 makes them 16-bit.  The settings "
        "(samplerate, sampleunit ...) are put back afterwards.",
        epilog="The device comes from the overlay %s (or PRUKIT-BEAGLELOGIC-POCKET-00A0) "
        "and the module beaglelogic; users in group %s may use it.  Channel N is PRU1's "
        "R31 bit N (Documentation/beaglelogic.rst has the pins).  For long captures use "
        "sigrok-cli -d beaglelogic or PulseView." % (OVERLAY, GROUP))
    p.add_argument("--rate", type=parse_rate, default=1000000, metavar="RATE",
                   help="samples per second, e.g. 100M, 1M (default), 10k; the device "
                   "takes 100M / n")
    p.add_argument("--samples", type=parse_samples, default=1000, metavar="N",
                   help="how many samples (default 1000)")
    p.add_argument("--channels", type=parse_channels, default=list(range(8)),
                   metavar="LIST", help="the channels to draw, e.g. 0-7 (default), 0,3,12-13")
    p.add_argument("--width", type=_width, metavar="COLS",
                   help="columns of the drawing (default: the terminal's)")
    p.add_argument("--raw", metavar="FILE",
                   help="also save the samples to FILE as read (1 byte per sample, or 2, "
                   "little-endian, for channels 8-15)")
    p.add_argument("--ascii", action="store_true",
                   help="draw with '-' for high (the terminal cannot show '‾')")
    p.set_defaults(func=run)


def missing_hint():
    return ("The logic analyzer comes from the overlay %s (PocketBeagle: "
            "PRUKIT-BEAGLELOGIC-POCKET-00A0):\n"
            "  sudo prukit enable %s\n"
            "then reboot.  If the overlay is enabled, the module may not be loaded:\n"
            "  sudo modprobe beaglelogic\n"
            "and `dmesg | grep beaglelogic` says why it did not bind." % (OVERLAY, OVERLAY))


def perm_hint(what):
    return ("The udev rule prukit installs gives %s to group %s:\n"
            "  sudo adduser $USER %s\n"
            "then log in again (or run prukit with sudo).  If `ls -l %s` shows no "
            "group %s,\nthe rule is not installed: make udev_install."
            % (what, GROUP, GROUP, what, GROUP))


def os_error(e, what, doing):
    """An Error for an OSError of WHAT while DOING."""
    code = e.errno
    msg = "%s: %s: %s" % (what, doing, os.strerror(code) if code else e)
    if code in (errno.EACCES, errno.EPERM):
        return Error(msg, perm_hint(what))
    if code in (errno.ENOENT, errno.ENXIO):
        return Error(msg, missing_hint())
    if code == errno.EBUSY:
        return Error(msg, "A capture is running (sigrok, PulseView, beaglelogic-tcpd or "
                     "another prukit capture): settings cannot change until it ends.")
    if code == errno.EPIPE:
        return Error(msg, "A PRU of the logic analyzer crashed or was stopped: the capture "
                     "ended.  Reload the driver:\n"
                     "  sudo modprobe -r beaglelogic && sudo modprobe beaglelogic")
    if code == errno.ETIMEDOUT:
        return Error(msg, "The storing PRU answered nothing for 2 s: it halted or faulted "
                     "while remoteproc still says \"running\" (dmesg: \"halted or "
                     "faulted?\").  Reload the driver:\n"
                     "  sudo modprobe -r beaglelogic && sudo modprobe beaglelogic")
    if code == errno.EIO:
        return Error(msg, "The firmware fell behind and stopped the capture (lasterror "
                     "%s): try a lower --rate." % read(os.path.join(attr_dir(), "lasterror"),
                                                        "?"))
    if code == errno.ENOMEM:
        return Error(msg, "Not enough capture memory: fewer --samples, or raise the module "
                     "parameter max_memalloc_mib (Documentation/beaglelogic.rst).")
    if code == errno.ENODEV:
        return Error(msg, "The driver let go of the device (unbound or being removed).")
    return Error(msg)


def write_attr(name, value):
    path = os.path.join(attr_dir(), name)
    try:
        with open(path, "w") as f:
            f.write(str(value))
    except OSError as e:
        raise os_error(e, path, "write %s" % value)


def settings():
    """The values to write back for SETTINGS (as they read, in a writable form)."""
    d = attr_dir()
    old = {}
    for name in SETTINGS:
        v = read(os.path.join(d, name))
        if v is None:
            continue
        if name in ("sampleunit", "triggerflags"):
            v = v.split(":")[0]	# "1:8bit" -> 1
        old[name] = v
    return old


def capture(rate, nsamples, unit_bytes):
    """Run a one-shot capture; (samples as bytes, the rate the device took)."""
    nbytes = nsamples * unit_bytes
    buf = min(MAX_BUF, (nbytes + 31) // 32 * 32)
    nbufs = (nbytes + buf - 1) // buf
    write_attr("triggerflags", 0)
    if read(os.path.join(attr_dir(), "trigger"), "none") != "none":
        write_attr("trigger", "none")
    write_attr("samplerate", rate)
    write_attr("sampleunit", 1 if unit_bytes == 1 else 0)
    write_attr("bufunitsize", buf)
    write_attr("memalloc", buf * nbufs)
    took = int(read(os.path.join(attr_dir(), "samplerate"), str(rate)))
    try:
        fd = os.open(DEV, os.O_RDONLY)
    except OSError as e:
        raise os_error(e, DEV, "open")
    chunks, total = [], 0
    try:
        while total < nbytes:
            try:
                b = os.read(fd, buf)
            except OSError as e:
                raise os_error(e, DEV, "read")
            if not b:
                break
            chunks.append(b)
            total += len(b)
    finally:
        os.close(fd)
    data = b"".join(chunks)[:nbytes]
    if len(data) < nbytes:
        raise Error("%s: the capture ended after %d of %d samples"
                    % (DEV, len(data) // unit_bytes, nsamples))
    return data, took


def levels(data, unit_bytes, ch):
    """Channel CH's level (0/1) in each sample."""
    if unit_bytes == 1:
        return [(v >> ch) & 1 for v in data]
    return [(data[i + (ch >> 3)] >> (ch & 7)) & 1 for i in range(0, len(data), 2)]


def row(lv, cols, hi="‾", lo="_", edge="|"):
    """One channel's drawing: COLS characters for the levels LV.  Column c
    stands for samples [c * n / cols, (c + 1) * n / cols) (one each when
    there are no more samples than columns); it is '|' when the channel
    changed from the sample before the column to its last sample."""
    n = len(lv)
    cols = min(cols, n)
    out = []
    for c in range(cols):
        a, b = c * n // cols, (c + 1) * n // cols
        seg = lv[max(a - 1, 0):b]
        if min(seg) != max(seg):
            out.append(edge)
        else:
            out.append(hi if seg[-1] else lo)
    return "".join(out)


def fmt_time(s):
    """Seconds as a short text in s, ms, us or ns ("0" for 0)."""
    if s <= 0:
        return "0"
    for unit, f in (("s", 1), ("ms", 1e3), ("us", 1e6), ("ns", 1e9)):
        if s * f >= 1 or unit == "ns":
            v = s * f
            return ("%d" % round(v) if abs(v - round(v)) < 1e-6 else "%.3g" % v) + unit
    return "0s"


def fmt_rate(r):
    for unit, f in (("MHz", 1e6), ("kHz", 1e3)):
        if r >= f:
            return "%g %s" % (r / f, unit)
    return "%d Hz" % r


def axis(n, cols, rate):
    """Two lines under the rows: tick marks and their times, every "nice"
    interval (1, 2, 5 x 10^k) that leaves at least 10 columns between ticks."""
    per_col = n / cols / rate		# seconds per column
    span = n / rate
    step = None
    for exp in range(-9, 4):
        for m in (1, 2, 5):
            s = m * 10.0 ** exp
            if s / per_col >= 10:
                step = s
                break
        if step:
            break
    step = step or span
    ticks = " " * cols
    labels = ""
    k = 0
    while True:
        t = k * step
        col = int(round(t / per_col))
        if col >= cols or t > span:
            break
        ticks = ticks[:col] + "|" + ticks[col + 1:]
        text = fmt_time(t)
        if col >= len(labels) + (1 if labels else 0) and col + len(text) <= cols + 8:
            labels = labels.ljust(col) + text
        k += 1
    return ticks.rstrip(), labels


def draw(data, unit_bytes, channels, rate, width, out, ascii_only=False):
    """Print the capture: a header, a row per channel and the time axis."""
    n = len(data) // unit_bytes
    cols = min(max(width - LABEL_W, 10), n)
    hi = "-" if ascii_only else "‾"
    per = n / cols
    print("beaglelogic: %d samples at %s (%d samples/s), %s, %s per column" % (
        n, fmt_rate(rate), rate, fmt_time(n / rate),
        "1 sample" if per == 1 else "%.3g samples" % per), file=out)
    for ch in channels:
        print(("ch %-2d " % ch) + row(levels(data, unit_bytes, ch), cols, hi), file=out)
    ticks, labels = axis(n, cols, rate)
    print(" " * LABEL_W + ticks, file=out)
    print(" " * LABEL_W + labels, file=out)


def run(args):
    d = attr_dir()
    if not os.path.exists(DEV) or not os.path.isdir(d):
        raise Error("no logic analyzer: %s is missing" % (DEV if not os.path.exists(DEV) else d),
                    missing_hint())
    if not os.access(DEV, os.R_OK):
        raise Error("%s: open: %s" % (DEV, os.strerror(errno.EACCES)), perm_hint(DEV))
    unit_bytes = 2 if max(args.channels) > 7 else 1
    width = args.width or shutil.get_terminal_size((80, 24)).columns
    ascii_only = args.ascii
    if not ascii_only:
        try:
            "‾".encode(sys.stdout.encoding or "ascii")
        except (UnicodeEncodeError, LookupError):
            ascii_only = True
    old = settings()
    try:
        data, took = capture(args.rate, args.samples, unit_bytes)
    finally:
        for name in SETTINGS:
            if name in old:
                try:
                    with open(os.path.join(d, name), "w") as f:
                        f.write(old[name])
                except OSError:
                    pass
    if took != args.rate:
        print("note: the device samples at 100 MHz / n: %d samples/s asked, %d taken"
              % (args.rate, took), file=sys.stderr)
    if args.raw:
        try:
            with open(args.raw, "wb") as f:
                f.write(data)
        except OSError as e:
            raise Error("--raw %s: %s" % (args.raw, e.strerror))
    draw(data, unit_bytes, args.channels, took, width, sys.stdout, ascii_only)
    return 0
