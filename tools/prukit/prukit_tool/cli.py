# SPDX-License-Identifier: GPL-2.0-only
"""prukit's command line: the subcommands of the command modules."""
import argparse
import importlib
import sys

from . import Error

# The command modules, in the order of prukit --help.
MODULES = ("status", "overlays", "ws281x", "hub75", "capture", "servo")

VERSION = "@VERSION@"  # make tool_install writes dkms.conf's PACKAGE_VERSION here


def version():
    if not VERSION.startswith("@"):
        return VERSION
    from . import _top
    try:
        with open(_top() + "/dkms.conf") as f:
            for line in f:
                if line.startswith("PACKAGE_VERSION="):
                    return line.split("=", 1)[1].strip().strip('"') + " (checkout)"
    except (OSError, TypeError):
        pass
    return "unknown"


def parser():
    p = argparse.ArgumentParser(
        prog="prukit",
        description="prukit's BeagleBone PRU devices: what runs, which overlays are "
        "enabled, and tests that show a device working.",
        epilog="Each command has --help.  Documentation: /usr/share/doc/prukit-tools "
        "and the prukit(1) man page.")
    p.add_argument("--version", action="version", version="prukit " + version())
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for name in MODULES:
        importlib.import_module("." + name, __package__).register(sub)
    return p


def main(argv=None):
    args = parser().parse_args(argv)
    try:
        return args.func(args)
    except Error as e:
        print("prukit: error: %s" % e, file=sys.stderr)
        if e.hint:
            for line in e.hint.splitlines():
                print("  " + line, file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
