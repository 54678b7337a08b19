# SPDX-License-Identifier: GPL-2.0-only
"""The integer #defines of C headers, for the host tests that build control
blocks by hand from the protocol headers drivers and firmware share
(drivers/*/tests/*_sim.py)."""
import re


def defines(*paths):
    """{NAME: value} of every object-like #define of the headers whose value
    is an integer expression (of literals and names defined before it, in
    these headers); the others are left out."""
    out = {}
    for path in paths:
        with open(path) as f:
            for line in f:
                m = re.match(r"#define\s+(\w+)\s+([^/]+?)\s*(/\*.*)?$", line)
                if not m or "(" in m.group(1):
                    continue
                expr = re.sub(r"\b(0x[0-9a-fA-F]+|\d+)u\b", r"\1", m.group(2))
                try:
                    out[m.group(1)] = int(eval(expr, {}, dict(out)))
                except Exception:
                    pass
    return out
