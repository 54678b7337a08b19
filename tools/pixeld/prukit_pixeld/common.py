# SPDX-License-Identifier: GPL-2.0-only
"""What every part of prukit-pixeld uses: its log and its counters."""
import sys


def log(msg):
    print("prukit-pixeld: " + msg, file=sys.stderr, flush=True)


class Stats:
    """Counters.  Every datagram and OPC message received is counted once
    more as exactly one of "accepted", "dropped.REASON" or "ignored.REASON"
    (of its protocol): received = accepted + dropped + ignored."""

    def __init__(self):
        self.c = {}
        self.serial = 0

    def add(self, name, n=1):
        self.c[name] = self.c.get(name, 0) + n

    def get(self, name):
        return self.c.get(name, 0)

    def text(self):
        self.serial += 1
        lines = ["serial %d" % self.serial]
        lines += ["%s %d" % kv for kv in sorted(self.c.items())]
        return "\n".join(lines) + "\n"
