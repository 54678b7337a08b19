# SPDX-License-Identifier: GPL-2.0-only
"""The beaglelogic tests' R31 stimulus, for the guest (which writes it to
pru_sim's input/r31-1) and the host (which computes every sample expected).

A new 16-bit value in every PRU cycle: the states of a maximal 16-bit
Galois LFSR (taps 0xb400), PERIOD cycles long and repeated.  PERIOD is a
prime, so samples taken every 2 * divisor cycles visit every phase, and the
values never repeat within a period: a sample taken one cycle early or late,
or a sample lost or doubled, differs from what is expected."""

PERIOD = 65521
SEED = 0xace1


def values(period=PERIOD, seed=SEED):
    """The stimulus' value in each cycle of one period."""
    out = []
    s = seed
    for _ in range(period):
        out.append(s)
        s = (s >> 1) ^ (0xb400 if s & 1 else 0)
    return out


def text(vals):
    """The stimulus in pru_sim's input format."""
    lines = ["%d %d" % (i, v) for i, v in enumerate(vals)]
    lines.append("repeat %d" % len(vals))
    return "\n".join(lines) + "\n"


def expected(vals, t0, step, count, mask):
    """The COUNT samples taken STEP cycles apart from stimulus cycle T0."""
    n = len(vals)
    return [vals[(t0 + k * step) % n] & mask for k in range(count)]
