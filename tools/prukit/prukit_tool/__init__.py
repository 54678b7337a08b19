# SPDX-License-Identifier: GPL-2.0-only
"""The prukit command's package: one module per group of subcommands.

Each command module has register(subparsers), which adds its subcommands
with set_defaults(func=...); a func takes the parsed arguments and returns
the exit status.  A user's mistake or a missing piece of the system raises
Error with what to do about it; cli.main() prints it and exits 1.
"""
import argparse
import os


class Error(Exception):
    """A failure the user can act on: the message, then what to do."""

    def __init__(self, msg, hint=None):
        super().__init__(msg)
        self.hint = hint


def number_arg(convert, ok, bad, out_of_range):
    """An argparse type: CONVERT(text) (int, float, ...) whose result OK
    accepts; BAD and OUT_OF_RANGE are the messages, "%r" the text given."""
    def parse(text):
        try:
            n = convert(text)
        except ValueError:
            raise argparse.ArgumentTypeError(bad % text)
        if not ok(n):
            raise argparse.ArgumentTypeError(out_of_range % text)
        return n
    return parse


def parse_ranges(text, top=None):
    """"0,2-3" -> [0, 2, 3]: sorted, each once, each in 0..TOP (no bound
    without TOP).  ValueError for what is not such a list, with the part
    that is wrong."""
    out = set()
    for part in text.split(","):
        a, sep, b = part.strip().partition("-")
        try:
            lo = int(a)
            hi = int(b) if sep else lo
        except ValueError:
            raise ValueError("not a list like 0,2-3")
        if lo < 0 or hi < lo or (top is not None and hi > top):
            raise ValueError("bad range %r" % part if top is None else
                             "%r is not within 0 to %d" % (part, top))
        out.update(range(lo, hi + 1))
    return sorted(out)


def _top():
    """The checkout this package runs from, or None when installed."""
    top = os.path.realpath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
    return top if os.path.isfile(os.path.join(top, "sim", "am335x-pins.tsv")) else None


def data_file(name):
    """A file of /usr/share/prukit (PRUKIT_DATA_DIR), or of the checkout."""
    d = os.environ.get("PRUKIT_DATA_DIR")
    if d:
        return os.path.join(d, name)
    top = _top()
    if top and name == "am335x-pins.tsv":
        return os.path.join(top, "sim", name)
    return os.path.join("/usr/share/prukit", name)


def sysfs(*parts):
    """A path under /sys, or under PRUKIT_SYSFS (the tests' fake trees)."""
    return os.path.join(os.environ.get("PRUKIT_SYSFS", "/sys"), *parts)


def dt(*parts):
    """A path under /proc/device-tree, or under PRUKIT_DT (the tests')."""
    return os.path.join(os.environ.get("PRUKIT_DT", "/proc/device-tree"), *parts)


def firmware_dir():
    """Where the overlays (.dtbo) and prukit/*.elf live."""
    return os.environ.get("PRUKIT_FIRMWARE_DIR", "/lib/firmware")


def read(path, default=None):
    """A sysfs attribute's text, stripped; default when it cannot be read."""
    try:
        with open(path) as f:
            return f.read().strip()
    except OSError:
        return default
