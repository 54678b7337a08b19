#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""pru_encoder firmware in the prusim host tool (make check, tests/check.sh).

enc_sim.py PRUSIM FW.elf WORKDIR

Runs pru_encoder-pru0.elf with a control block loaded before the start (a
command already posted, as the driver would have written it) and a
quadrature stimulus on PRU0's R31 bits 14..16, and checks what the firmware
left in its control block against a model of the decoder: count, direction,
overflows, underflows, index pulses, reversals, skipped states, the command
results, and the cycles between two samples on every path of the loop
(pru_encoder_loop.S's table: the edge-rate limit).  Prints PASS:/FAIL:
lines; exits 1 on any failure.
"""
import json
import random
import struct
import subprocess
import sys

MAGIC, VERSION, SIZE = 0x434E4550, 1, 0x54
CMD_CONFIG, CMD_ENABLE, CMD_DISABLE, CMD_SET_COUNT, CMD_SET_LIMITS = 1, 2, 3, 4, 5
OK, EINVAL, EOPCODE = 0, 1, 2
FIELDS = ("pins event value set_ceiling set_floor state count direction inputs "
          "overflows underflows indexes reversals skips irq_armed ceiling floor").split()
BLACK = (14, 15, 16)     # A P8_16, B P8_15, index P9_24
POCKET = (16, 15, 14)    # A P2.09, B P2.18, index P2.22
NONE = 0xFF
EVENT = 17
T0 = 20000               # the firmware is in its loop well before
WORST = 39               # pru_encoder_loop.S: the longest gap between samples
PHASES = ((0, 0), (1, 0), (1, 1), (0, 1))   # (A, B), forward

prusim, fw, work = sys.argv[1:4]
failed = 0
runs = 0


def check(ok, what):
    global failed
    print(("PASS: " if ok else "FAIL: ") + what)
    if not ok:
        failed = 1


def block(cmd, pins=BLACK, **kw):
    f = dict(pins=pins[0] | pins[1] << 8 | pins[2] << 16, event=EVENT, value=0,
             set_ceiling=0, set_floor=0, state=0, count=0, direction=0, inputs=0,
             overflows=0, underflows=0, indexes=0, reversals=0, skips=0,
             irq_armed=1, ceiling=0xFFFFFFFF, floor=0)
    f.update(kw)
    return struct.pack("<IHHII", MAGIC, VERSION, SIZE, cmd, 0) + \
        struct.pack("<17I", *(f[k] for k in FIELDS))


def run(blk, stim, cycles, trace=False):
    """Run; return (control block fields, status result, json, sample cycles)."""
    global runs
    runs += 1
    base = "%s/run%d" % (work, runs)
    with open(base + ".blk", "wb") as f:
        f.write(blk)
    with open(base + ".stim", "w") as f:
        f.write("0 0\n" + "".join("%d 0x%x\n" % e for e in stim))
    cmd = [prusim, "--pru0", fw, "--load", "8:" + base + ".blk", "--r31-0", base + ".stim",
           "--max-cycles", str(cycles), "--dump", "8:%d:%s.out" % (SIZE, base), "--json"]
    if trace:
        cmd.append("--trace")
    p = subprocess.run(cmd, stdout=subprocess.PIPE, universal_newlines=True, check=False)
    lines = p.stdout.splitlines()
    js = json.loads(lines[-1]) if lines else {}
    samples = [int(l.split()[0]) for l in lines[:-1] if "lsr\tr23, r31" in l]
    with open(base + ".out", "rb") as f:
        raw = f.read()
    hdr = struct.unpack("<IHHII", raw[:16])
    vals = dict(zip(FIELDS, struct.unpack("<17I", raw[16:SIZE])))
    vals["status"] = hdr[4]
    return vals, hdr[4] & 0x7FFF, js, samples


def quad(steps, spacing, pins, index_at=(), start_phase=0, t0=T0):
    """Stimulus of steps (+1/-1) every @spacing cycles; the index input is
    high from each step number in @index_at for one step."""
    a, b, i = pins
    ph = start_phase
    out = []
    t = t0
    for n, s in enumerate(steps):
        ph = (ph + s) % 4
        va, vb = PHASES[ph]
        v = va << a | vb << b
        if n in index_at and i != NONE:
            v |= 1 << i
        out.append((t, v))
        t += spacing
    return out, t


def model(steps, count, ceiling, floor, index_at=(), direction=0):
    m = dict(count=count, overflows=0, underflows=0, reversals=0, indexes=0,
             direction=direction)
    prev_index = False
    for n, s in enumerate(steps):
        if s > 0:
            if m["count"] == ceiling:
                m["count"] = floor
                m["overflows"] += 1
            else:
                m["count"] += 1
            if m["direction"] != 0:
                m["reversals"] += 1
            m["direction"] = 0
        else:
            if m["count"] == floor:
                m["count"] = ceiling
                m["underflows"] += 1
            else:
                m["count"] -= 1
            if m["direction"] != 1:
                m["reversals"] += 1
            m["direction"] = 1
        idx = n in index_at
        if idx and not prev_index:
            m["indexes"] += 1
        prev_index = idx
    return m


def compare(got, want, what):
    bad = {k: (got[k], v) for k, v in want.items() if got[k] != v}
    check(not bad, what + ("" if not bad else " (got, want: %s)" % bad))


enable = 1 << 16 | CMD_ENABLE

# 1. steady forward and backward, both boards' pin orders, at the 19-cycle gap
for name, pins in (("Black", BLACK), ("PocketBeagle", POCKET)):
    steps = [1] * 400
    stim, end = quad(steps, 19, pins)
    v, res, _, _ = run(block(enable, pins), stim, end + 200)
    compare(v, dict(count=400, direction=0, skips=0, reversals=0, overflows=0, state=1),
            "%s pins: 400 steps forward, 19 cycles apart: count 400, no skip" % name)
    steps = [-1] * 400
    stim, end = quad(steps, 20, pins)
    v, res, _, _ = run(block(enable, pins, count=1000), stim, end + 200)
    compare(v, dict(count=600, direction=1, skips=0, reversals=1, underflows=0),
            "%s pins: 400 steps backward from 1000, 20 cycles apart: count 600, direction 1, one reversal" % name)

# 2. the limit: random walk with reversals, wraps and index pulses every
# WORST cycles (the longest path each time), exact; then beyond it
rng = random.Random(4)
for name, pins in (("Black", BLACK), ("PocketBeagle", POCKET)):
    steps = [rng.choice((1, -1)) for _ in range(600)]
    index_at = set(rng.sample(range(600), 60))
    ceiling, floor = 5, 2
    stim, end = quad(steps, WORST, pins, index_at)
    v, res, _, _ = run(block(enable, pins, count=3, ceiling=ceiling, floor=floor), stim, end + 200)
    want = model(steps, 3, ceiling, floor, index_at)
    want["skips"] = 0
    compare(v, want, "%s pins: 600 random steps %d cycles apart with wraps (floor %d, ceiling %d) "
            "and 60 index pulses: every counter exact (%s)" % (name, WORST, floor, ceiling,
                                                             ", ".join("%s %d" % kv for kv in sorted(want.items()))))

# steady forward: exact at the 19-cycle gap, skipped states at 18
steps = [1] * 1000
stim, end = quad(steps, 18, BLACK)
v, res, _, _ = run(block(enable), stim, end + 200)
check(v["skips"] > 0 and v["count"] == 1000 - 2 * v["skips"],
      "1000 steps 18 cycles apart (beyond the 19-cycle steady limit): %d skipped states "
      "counted, count %d = 1000 - 2 x skips" % (v["skips"], v["count"]))
stim, end = quad([1] * 1000, 12, BLACK)
v, res, _, _ = run(block(enable), stim, end + 200)
check(v["skips"] > 100 and v["count"] == 1000 - 2 * v["skips"],
      "1000 steps 12 cycles apart: %d skipped states, count %d = 1000 - 2 x skips"
      % (v["skips"], v["count"]))
stim, end = quad([-1] * 1000, 19, BLACK)
v, res, _, _ = run(block(enable, count=5000, direction=1), stim, end + 200)
check(v["skips"] > 0 and v["count"] == 4000 + 2 * v["skips"],
      "1000 steps backward 19 cycles apart (beyond the 20-cycle steady limit): %d skipped "
      "states, count %d = 4000 + 2 x skips" % (v["skips"], v["count"]))
stim, end = quad([1, 1, 1, -1, -1, -1] * 100, 20, BLACK)
v, res, _, _ = run(block(enable), stim, end + 200)
check(v["skips"] > 0, "600 steps, a reversal every third one, 20 cycles apart (beyond the "
      "28-cycle reversal path): %d skipped states counted" % v["skips"])

# 3. every path's gap, measured on the trace: a steady step, a reversal,
# an overflow, an underflow with a reversal and an index pulse and the strobe
GAP = 300
steps = [1, 1, -1, 1, 1, 1, -1, -1, -1, -1, -1]
index_at = {10}
stim, end = quad(steps, GAP, BLACK, index_at)
v, res, js, samples = run(block(enable, count=0, floor=0, ceiling=3, irq_armed=0), stim,
                          end + 100, trace=True)
gaps = [y - x for x, y in zip(samples, samples[1:])]
changes = [g for g in gaps if g != 7]
# steps: +1 (1), +1 (2), -1 rev (1), +1 rev (2), +1 (3), +1 ovf (0),
# -1 rev+unf (3), -1 (2), -1 (1), -1 (0), -1 unf+index
want = [19, 19, 28, 28, 19, 27, 32, 20, 20, 20, 31]
check(changes == want, "sample gaps per path (irq not armed): %s, want %s" % (changes, want))
check(set(gaps) - set(changes) == {7}, "sample gap without a change: 7 cycles (%s)"
      % sorted(set(gaps) - set(changes)))
check(js.get("intc", {}).get("raw", 0) & (1 << EVENT) == 0,
      "no event strobed while irq_armed is 0")
# the worst path: a reversal with an underflow, an index pulse and the strobe
stim, end = quad([-1], GAP, BLACK, {0})
v, res, js, samples = run(block(enable, count=0, floor=0, ceiling=3, irq_armed=1), stim,
                          end + 100, trace=True)
gaps = [y - x for x, y in zip(samples, samples[1:]) if y - x != 7]
check(gaps == [WORST], "worst path (reversal, underflow, index, strobe): gap %s, want [%d]"
      % (gaps, WORST))
check(js.get("intc", {}).get("raw", 0) & (1 << EVENT) and v["irq_armed"] == 0,
      "event %d strobed and irq_armed cleared (intc raw 0x%x)" % (EVENT, js.get("intc", {}).get("raw", 0)))
compare(v, dict(count=3, underflows=1, indexes=1, reversals=1, direction=1),
        "worst path: count 3, one underflow, index, reversal")
# a skipped state's gap
stim = [(T0, 3 << 14)]
v, res, js, samples = run(block(enable, irq_armed=0), stim, T0 + 200, trace=True)
gaps = [y - x for x, y in zip(samples, samples[1:]) if y - x != 7]
check(gaps == [23] and v["skips"] == 1 and v["count"] == 0,
      "skipped state (A and B at once): counted as a skip, not a step, gap %s (want [23])" % gaps)
check(v["irq_armed"] == 0, "skipped state without irq_armed: no strobe")
v, res, js, _ = run(block(enable, irq_armed=1), stim, T0 + 200)
check(js["intc"]["raw"] & (1 << EVENT) and v["skips"] == 1,
      "skipped state with irq_armed: event %d strobed" % EVENT)
stim, end = quad([1] * 50, 30, BLACK)
v, res, js, _ = run(block(enable, irq_armed=1), stim, end + 100)
check(js["intc"]["raw"] & (1 << EVENT) == 0 and v["irq_armed"] == 1 and v["count"] == 50,
      "steady counting raises no event")

# 4. commands: results, and nothing changes on a refused one
def cmd(op, **kw):
    return block(1 << 16 | op, **kw)


def status_ok(v, res, want):
    return v["status"] >> 16 == 1 and v["status"] & 0x8000 and res == want


v, res, _, _ = run(cmd(CMD_SET_LIMITS, count=100, set_ceiling=50, set_floor=0), [], 5000)
check(status_ok(v, res, EINVAL) and v["ceiling"] == 0xFFFFFFFF and v["count"] == 100,
      "SET_LIMITS with the ceiling below the count: EINVAL, nothing changed")
v, res, _, _ = run(cmd(CMD_SET_LIMITS, count=100, set_ceiling=10, set_floor=20), [], 5000)
check(status_ok(v, res, EINVAL) and v["floor"] == 0, "SET_LIMITS with floor > ceiling: EINVAL")
v, res, _, _ = run(cmd(CMD_SET_LIMITS, count=100, set_ceiling=1000, set_floor=50), [], 5000)
check(status_ok(v, res, OK) and v["ceiling"] == 1000 and v["floor"] == 50,
      "SET_LIMITS 50..1000 around count 100: done")
v, res, _, _ = run(cmd(CMD_SET_COUNT, value=2000, ceiling=1000), [], 5000)
check(status_ok(v, res, EINVAL) and v["count"] == 0, "SET_COUNT above the ceiling: EINVAL")
v, res, _, _ = run(cmd(CMD_SET_COUNT, value=700, ceiling=1000), [], 5000)
check(status_ok(v, res, OK) and v["count"] == 700, "SET_COUNT 700: done")
v, res, _, _ = run(cmd(99), [], 5000)
check(status_ok(v, res, EOPCODE), "unknown opcode: EOPCODE")
for bad, what in (((14, 14, NONE), "A = B"), ((13, 15, NONE), "A outside bits 14..16"),
                  ((14, 15, 15), "index = B"), ((14, 15, 17), "index outside 14..16")):
    v, res, _, _ = run(cmd(CMD_CONFIG, pins=bad), [], 5000)
    check(status_ok(v, res, EINVAL), "CONFIG with %s: EINVAL" % what)
v, res, _, _ = run(cmd(CMD_CONFIG, event=40), [], 5000)
check(status_ok(v, res, EINVAL), "CONFIG with event 40: EINVAL")
v, res, _, _ = run(cmd(CMD_CONFIG, pins=POCKET, state=1), [], 5000)
check(status_ok(v, res, OK) and v["state"] == 0, "CONFIG (PocketBeagle pins): done, counting stops")
# disabled: inputs move, the count does not
stim, end = quad([1] * 20, 30, BLACK)
v, res, _, _ = run(cmd(CMD_DISABLE), stim, end + 100)
check(status_ok(v, res, OK) and v["count"] == 0 and v["state"] == 0,
      "DISABLE: 20 steps not counted")
# the index input ignored where there is none
stim, end = quad([1] * 20, 30, (14, 15, NONE))
stim = [(t, x | (1 << 16 if n % 2 else 0)) for n, (t, x) in enumerate(stim)]
v, res, _, _ = run(block(enable, (14, 15, NONE)), stim, end + 100)
compare(v, dict(count=20, indexes=0, skips=0), "no index input: bit 16 ignored, 20 steps counted")

sys.exit(failed)
