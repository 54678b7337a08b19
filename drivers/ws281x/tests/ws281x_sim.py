#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""The ws281x firmware under prusim, to the cycle (run by check.sh).

Runs the real ws281x-pru0.elf / ws281x-pru1.elf in out/tools/prusim with a
control block and a frame preloaded (--load), reads the block back
(--dump), and checks every string's edges in the --events list: the bits
decoded by high time equal the bytes sent, every rise is 250 cycles after
the previous one, every high is exactly 70 or 140 cycles, each pin kind's
edges sit at one constant offset from the slot's start, the reset is held
for at least @reset cycles after the last slot before the frame is counted
and the event strobed.  One R30 capture is also decoded by sigrok's own
rgb_led_ws281x decoder.  Prints PASS:/FAIL: lines and info: lines.

usage: ws281x_sim.py PRUSIM FW_DIR WORK_DIR"""
import json
import os
import random
import re
import struct
import subprocess
import sys

TOP = os.environ.get("PRUKIT_TOP") or \
    os.path.realpath(os.path.join(os.path.dirname(__file__), "../../.."))
sys.path.insert(0, os.path.join(TOP, "tests", "lib"))
from cdefs import defines  # noqa: E402
PROTO = os.path.join(TOP, "drivers/ws281x/ws281x_proto.h")
CTRL_H = os.path.join(TOP, "include/prukit/pru_ctrl.h")
DDR = 0x80000000
FRAME_AT = DDR + 0x100          # where the frame is put (bus address)
# GPIO bank b's edges land 17 + 1 + 8 * b cycles after the R30 edge with
# prusim's default gpio_write_latency 17 and gpio_write_interval 8
# (ws281x_send.S); measured, compared with this.
GPIO_OFFSET = [18 + 8 * b for b in range(4)]

# BeagleBone header names prusim gives R30 pins (tools/prusim/pinlog.c)
R30_PINS = [
    ["P9_31", "P9_29", "P9_30", "P9_28", "P9_42", "P9_27", "P9_41", "P9_25"]
    + [None] * 6 + ["P8_12", "P8_11"],
    ["P8_45", "P8_46", "P8_43", "P8_44", "P8_41", "P8_42", "P8_39", "P8_40",
     "P8_27", "P8_29", "P8_28", "P8_30", "P8_21", "P8_20"],
]

failed = 0
passed = 0


def check(name, cond, detail=""):
    global failed, passed
    tail = "" if cond or detail == "" else ": " + str(detail)
    print(("PASS: " if cond else "FAIL: ") + name + tail)
    if cond:
        passed += 1
    else:
        failed += 1
    return cond


def info(text):
    print("info: " + text)


D = defines(PROTO, CTRL_H)
SLOT = D["WS281X_SLOT_CYCLES"]
T0H = D["WS281X_T0H_CYCLES"]
T1H = D["WS281X_T1H_CYCLES"]


def status(seq, result):
    return (seq << 16) | D["PRUKIT_CTRL_READY"] | result


CTRL_FMT = "<IHHII" + "I" * 16     # struct ws281x_ctrl, 80 bytes
CTRL_SIZE = struct.calcsize(CTRL_FMT)
FIELDS = ["magic", "version", "size", "command", "status", "frame", "slots",
          "r30_mask", "gpio0", "gpio1", "gpio2", "gpio3", "reset", "event",
          "frames", "first_cycle", "sync", "ready", "started", "start_at", "unsynced"]


def pin_name(kind, core, bit):
    if kind == "r30":
        name = R30_PINS[core][bit] if bit < len(R30_PINS[core]) else None
        return name or "pru%d_r30_%d" % (core, bit)
    return "gpio%d_%d" % (kind, bit)


class Frame:
    """Strings (kind "r30" or GPIO bank 0..3, bit, bytes) and their slots."""

    def __init__(self, core, strings):
        self.core = core
        self.strings = strings
        self.slots = max(len(s[2]) for s in strings) * 8
        self.r30_mask = 0
        self.gpio_mask = [0] * 4
        for kind, bit, _ in strings:
            if kind == "r30":
                self.r30_mask |= 1 << bit
            else:
                self.gpio_mask[kind] |= 1 << bit
        words = []
        for i in range(self.slots):
            w = [0] * 5
            for kind, bit, data in strings:
                if self.bit(data, i):
                    w[0 if kind == "r30" else 1 + kind] |= 1 << bit
            words.append(struct.pack("<5I", *w))
        self.data = b"".join(words)

    @staticmethod
    def bit(data, i):
        """Bit i on the wire: MSB first; 0 past the string's end (padding)."""
        return (data[i // 8] >> (7 - i % 8)) & 1 if i // 8 < len(data) else 0


class Run:
    """One prusim run: preloaded block and frame, events, block read back."""

    def __init__(self, work, fw, frame, max_cycles, params=None, tag="run",
                 vcd=False, config=()):
        p = {"frame": FRAME_AT, "slots": frame.slots, "r30_mask": frame.r30_mask,
             "gpio": frame.gpio_mask, "reset": D["WS281X_RESET_MIN"], "event": 17,
             "command": (1 << 16) | D["WS281X_CMD_SHOW"], "sync": 0}
        p.update(params or {})
        core = frame.core
        ctrl = struct.pack(CTRL_FMT, D["WS281X_MAGIC"], D["WS281X_VERSION"], CTRL_SIZE,
                           p["command"], 0, p["frame"], p["slots"], p["r30_mask"],
                           *p["gpio"], p["reset"], p["event"], 0, 0, p["sync"], 0, 0, 0, 0)
        base = os.path.join(work, tag)
        for suffix, data in ((".ctrl", ctrl), (".frame", frame.data)):
            with open(base + suffix, "wb") as f:
                f.write(data)
        pru = "pru%d" % core
        cmd = [PRUSIM, "--" + pru, fw % core, "--ddr", str(0x100 + len(frame.data) + 0x100),
               "--load", "%s:0x%x:%s" % (pru, D["PRUKIT_CTRL_DA"], base + ".ctrl"),
               "--load", "0x%x:%s" % (FRAME_AT, base + ".frame"),
               "--dump", "%s:0x%x:%d:%s" % (pru, D["PRUKIT_CTRL_DA"], CTRL_SIZE, base + ".out"),
               "--events", base + ".events", "--max-cycles", str(max_cycles), "--json"]
        for c in config:
            cmd += ["-C", c]
        if vcd:
            cmd += ["--vcd", base + ".vcd"]
        self.vcd = base + ".vcd"
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode:
            raise RuntimeError("prusim (%s) exited %d: %s" % (tag, r.returncode, r.stderr.strip()))
        self.json = json.loads(r.stdout.splitlines()[-1])
        with open(base + ".out", "rb") as f:
            self.ctrl = dict(zip(FIELDS, struct.unpack(CTRL_FMT, f.read())))
        self.edges = {}
        with open(base + ".events") as f:
            for line in f:
                cycle, pin, level = line.split()
                self.edges.setdefault(pin, []).append((int(cycle), int(level)))
        self.core = core
        self.params = p
        self.overrides = params
        self.config = config

    def event_raised(self, ev):
        return bool((self.json["intc"]["raw"] >> ev) & 1)

    def counter(self):
        return self.json["pru"][self.core]["cycle_counter"]


class PairRun:
    """Both cores at once, each with its frame and control block (params
    per core: sync...), as the driver runs a 48-string map."""

    def __init__(self, work, fw, frames, max_cycles, params, tag="pair", extra=()):
        base = os.path.join(work, tag)
        at = FRAME_AT
        cmd = [PRUSIM, "--max-cycles", str(max_cycles), "--json"]
        self.params, self.ctrl = [], []
        for frame, prm in zip(frames, params):
            pru = "pru%d" % frame.core
            p = {"frame": at, "slots": frame.slots, "r30_mask": frame.r30_mask,
                 "gpio": frame.gpio_mask, "reset": D["WS281X_RESET_MIN"],
                 "event": 17 + frame.core, "command": (1 << 16) | D["WS281X_CMD_SHOW"],
                 "sync": 0}
            p.update(prm)
            ctrl = struct.pack(CTRL_FMT, D["WS281X_MAGIC"], D["WS281X_VERSION"], CTRL_SIZE,
                               p["command"], 0, p["frame"], p["slots"], p["r30_mask"],
                               *p["gpio"], p["reset"], p["event"], 0, 0, p["sync"], 0, 0, 0, 0)
            for suffix, data in ((".ctrl", ctrl), (".frame", frame.data)):
                with open("%s%d%s" % (base, frame.core, suffix), "wb") as f:
                    f.write(data)
            cmd += ["--" + pru, fw % frame.core,
                    "--load", "%s:0x%x:%s%d.ctrl" % (pru, D["PRUKIT_CTRL_DA"], base, frame.core),
                    "--load", "0x%x:%s%d.frame" % (at, base, frame.core),
                    "--dump", "%s:0x%x:%d:%s%d.out" % (pru, D["PRUKIT_CTRL_DA"], CTRL_SIZE,
                                                       base, frame.core)]
            self.params.append(p)
            at += (len(frame.data) + 0xff) & ~0xff
        cmd += ["--ddr", str(at - DDR + 0x100), "--events", base + ".events"] + list(extra)
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode:
            raise RuntimeError("prusim (%s) exited %d: %s" % (tag, r.returncode, r.stderr.strip()))
        self.json = json.loads(r.stdout.splitlines()[-1])
        for frame in frames:
            with open("%s%d.out" % (base, frame.core), "rb") as f:
                self.ctrl.append(dict(zip(FIELDS, struct.unpack(CTRL_FMT, f.read()))))
        self.edges = {}
        with open(base + ".events") as f:
            for line in f:
                cycle, pin, level = line.split()
                self.edges.setdefault(pin, []).append((int(cycle), int(level)))

    def event_raised(self, ev):
        return bool((self.json["intc"]["raw"] >> ev) & 1)


def pair_check(work, fw, rng, worst_all):
    """Both cores with R30 and GPIO strings on all four banks: alone, their
    bank writes collide and edges move; in step (sync), every edge of both
    is exact and PRU1's slots start WS281X_SYNC_PHASE cycles after PRU0's."""
    frames = []
    for core, bits in ((0, (3, 11, 20, 29)), (1, (4, 12, 21, 30))):
        strings = [("r30", 2 + core, random_bytes(rng, 9 + 3 * core))]
        strings += [(b, bits[b], random_bytes(rng, 6 + 3 * ((b + core) % 3))) for b in range(4)]
        frames.append(Frame(core, strings))
    budget = 300000
    alone = PairRun(work, fw, frames, budget, [{}, {}], "pair-alone")
    moved = 0
    for frame in frames:
        for kind, bit, _ in frame.strings:
            e = alone.edges.get(pin_name(kind, frame.core, bit), [])
            highs = {b[0] - a[0] for a, b in zip(e[0::2], e[1::2])}
            moved += len(highs - {T0H, T1H})
    check("both cores alone (no sync), GPIO strings on both: their bank writes collide and "
          "edges move (%d odd high times)" % moved, moved > 0)
    lead, follow = D["WS281X_SYNC_LEADER"], D["WS281X_SYNC_FOLLOWER"]
    run = PairRun(work, fw, frames, budget, [{"sync": lead}, {"sync": follow}], "pair-sync")
    starts = []
    for frame, ctrl in zip(frames, run.ctrl):
        name = "in step, pru%d" % frame.core
        start, worst, offsets = check_frame(name, run, frame)
        starts.append(start)
        for k, v in worst.items():
            worst_all.setdefault("R30" if k == "r30" else "gpio%d" % k, []).append(v)
        check("%s: every edge exact (worst %d), bank offsets %s == %s"
              % (name, max(worst.values()), [offsets.get(b) for b in range(4)], GPIO_OFFSET),
              max(worst.values()) == 0 and [offsets.get(b) for b in range(4)] == GPIO_OFFSET)
        check("%s: the frame sent and counted, none unsynced (frames %d, unsynced %d)"
              % (name, ctrl["frames"], ctrl["unsynced"]),
              ctrl["frames"] == 1 and ctrl["unsynced"] == 0 and
              ctrl["status"] == status(1, D["WS281X_OK"]))
    if None not in starts:
        check("in step: PRU1's slot 0 starts %d cycles after PRU0's (WS281X_SYNC_PHASE %d)"
              % (starts[1] - starts[0], D["WS281X_SYNC_PHASE"]),
              starts[1] - starts[0] == D["WS281X_SYNC_PHASE"])
    check("in step: first_cycle of both on the IEP counter, %d apart"
          % (run.ctrl[1]["first_cycle"] - run.ctrl[0]["first_cycle"]),
          run.ctrl[1]["first_cycle"] - run.ctrl[0]["first_cycle"] == D["WS281X_SYNC_PHASE"] and
          run.ctrl[0]["start_at"] == run.ctrl[0]["first_cycle"])
    # a follower whose leader never starts sends alone, after the wait
    solo = PairRun(work, fw, frames[1:], D["WS281X_SYNC_WAIT"] + budget, [{"sync": follow}],
                   "pair-solo")
    check("a follower without its leader sends the frame alone after about %d cycles "
          "(frames %d, unsynced %d)" % (D["WS281X_SYNC_WAIT"], solo.ctrl[0]["frames"],
                                        solo.ctrl[0]["unsynced"]),
          solo.ctrl[0]["frames"] == 1 and solo.ctrl[0]["unsynced"] == 1)
    # a follower whose leader went ahead alone: its slot 0 deadline is past
    late = os.path.join(work, "pair-late-leader.ctrl")
    with open(late, "wb") as f:
        f.write(struct.pack(CTRL_FMT, D["WS281X_MAGIC"], D["WS281X_VERSION"], CTRL_SIZE,
                            *([0] * 13), 0, 1, 1, 5, 0))
    run = PairRun(work, fw, frames[1:], budget, [{"sync": follow}], "pair-late",
                  ("--load", "pru0:0x%x:%s" % (D["PRUKIT_CTRL_DA"], late)))
    _, worst, _ = check_frame("follower of a leader gone ahead", run, frames[1])
    check("a follower whose leader's slot 0 is already past sends on its own schedule: "
          "every edge exact (worst %d), unsynced %d" % (max(worst.values()),
                                                        run.ctrl[0]["unsynced"]),
          max(worst.values()) == 0 and run.ctrl[0]["unsynced"] == 1 and
          run.ctrl[0]["frames"] == 1)
    bad = PairRun(work, fw, frames[1:], 100000, [{"sync": lead}], "pair-bad")
    check("PRU1 asked to lead: refused (EINVAL)",
          bad.ctrl[0]["status"] == status(1, D["WS281X_EINVAL"]) and not bad.edges)


def decode(edges, slots):
    """Rises, highs and bits of one pin; raises ValueError if malformed."""
    if len(edges) != 2 * slots:
        raise ValueError("%d edges, %d slots" % (len(edges), slots))
    rises, highs = [], []
    for i in range(0, len(edges), 2):
        (tr, lr), (tf, lf) = edges[i], edges[i + 1]
        if (lr, lf) != (1, 0):
            raise ValueError("edges out of order at cycle %d" % tr)
        rises.append(tr)
        highs.append(tf - tr)
    return rises, highs


def check_frame(name, run, frame, start=None, quiet=False):
    """Every string's edges; returns (slot 0 start, worst error by kind, offsets).
    quiet: only look (a run whose edges are meant to move): no PASS/FAIL
    lines, and a string that does not decode counts as an error of 1."""
    kinds = {}
    for kind, bit, data in frame.strings:
        kinds.setdefault(kind, []).append((bit, data))
    # the reference: R30 strings if any (offset 0), else first_cycle's edge
    ref = None
    if "r30" in kinds:
        first = run.edges.get(pin_name("r30", frame.core, kinds["r30"][0][0]), [])
        ref = first[0][0] if first else None
    if ref is None:
        ref = start
    worst, offsets = {}, {}
    ok_bits = ok_period = ok_high = ok_same = True
    detail = []
    for kind, strings in sorted(kinds.items(), key=lambda k: str(k[0])):
        off = None
        err = 0
        for bit, data in strings:
            pin = pin_name(kind, frame.core, bit)
            try:
                rises, highs = decode(run.edges.get(pin, []), frame.slots)
            except ValueError as e:
                ok_bits = False
                detail.append("%s: %s" % (pin, e))
                continue
            want = [Frame.bit(data, i) for i in range(frame.slots)]
            got = [1 if h == T1H else 0 for h in highs]
            if got != want:
                ok_bits = False
                detail.append("%s: bits differ from slot %d" %
                              (pin, next(i for i in range(frame.slots) if got[i] != want[i])))
            if any(h not in (T0H, T1H) for h in highs):
                ok_high = False
            if any(b - a != SLOT for a, b in zip(rises, rises[1:])):
                ok_period = False
            o = rises[0] - ref
            if off is None:
                off = o
            ok_same = ok_same and o == off
            for i, (r, w) in enumerate(zip(rises, want)):
                s = ref + SLOT * i + off
                err = max(err, abs(r - s), abs(r + highs[i] - (s + (T1H if w else T0H))))
        offsets[kind] = off
        worst[kind] = err
    n = len(frame.strings)
    if quiet:
        if not (ok_bits and ok_high and ok_period and ok_same):
            worst["decode"] = max([1] + list(worst.values()))
        return ref, worst, offsets
    check("%s: %d strings x %d slots: every string's bits (by high time) == the bytes sent"
          % (name, n, frame.slots), ok_bits, "; ".join(detail[:4]))
    check("%s: every high is exactly %d or %d cycles" % (name, T0H, T1H), ok_high)
    check("%s: every rise exactly %d cycles after the previous one, on every string"
          % (name, SLOT), ok_period)
    check("%s: all strings of one pin kind move in the same cycle" % name, ok_same)
    return ref, worst, offsets


def check_done(name, work, fw, frame, run, start):
    """Reset held >= reset after the last slot, then frames and the event."""
    p, params, config = run.params, run.overrides, run.config
    end = start + frame.slots * SLOT           # end of the last slot
    check("%s: SHOW answered READY|OK|seq 1, frames == 1, event %d strobed"
          % (name, p["event"]),
          run.ctrl["status"] == status(1, D["WS281X_OK"]) and run.ctrl["frames"] == 1 and
          run.event_raised(p["event"]),
          "status 0x%x frames %d" % (run.ctrl["status"], run.ctrl["frames"]))
    last = max(e[-1][0] for e in run.edges.values())
    early = Run(work, fw, frame, end + p["reset"], params, name + "-early", config=config)
    check("%s: after the last fall nothing moves, and at %d cycles from the end of the last "
          "slot (the reset) the frame is not counted yet nor the event strobed"
          % (name, p["reset"]),
          last < end and early.ctrl["frames"] == 0 and not early.event_raised(p["event"]))
    # the cycle the frame is counted in: a bisection on --max-cycles
    lo, hi = end + p["reset"], end + p["reset"] + 256
    late = Run(work, fw, frame, hi, params, name + "-late", config=config)
    if not check("%s: the frame is counted and the event strobed within 256 cycles after "
                 "the reset" % name, late.ctrl["frames"] == 1 and late.event_raised(p["event"])):
        return None
    while hi - lo > 1:
        mid = (lo + hi) // 2
        r = Run(work, fw, frame, mid, params, name + "-bisect", config=config)
        if r.event_raised(p["event"]):
            hi = mid
        else:
            lo = mid
    return lo        # the strobe's cycle: raised in a run of lo + 1 cycles


def random_bytes(rng, n):
    return bytes(rng.randrange(256) for _ in range(n))


def sigrok_check(name, run, frame, bit, data):
    pin = pin_name("r30", frame.core, bit)
    r = subprocess.run(["sigrok-cli", "-I", "vcd", "-i", run.vcd,
                        "-P", "rgb_led_ws281x:din=" + pin,
                        "-A", "rgb_led_ws281x=rgb"], capture_output=True, text=True)
    got = re.findall(r"rgb_led_ws281x-1: (#[0-9a-f]{6})", r.stdout)
    # the bytes on the wire, padding included; G, R, B each; sigrok prints #rrggbb
    wire = data + bytes(frame.slots // 8 - len(data))
    want = ["#%02x%02x%02x" % (wire[i + 1], wire[i], wire[i + 2])
            for i in range(0, len(wire) - 2, 3)]
    check("%s: sigrok's rgb_led_ws281x decodes %s as the %d colours sent (GRB on the wire)"
          % (name, pin, len(want)), r.returncode == 0 and got == want,
          r.stderr.strip() or "got %s want %s" % (got, want))


def first_cycle_check(name, work, fw, frame, run, start):
    """first_cycle is CYCLE in the cycle slot 0 starts (R30 edge)."""
    r = Run(work, fw, frame, start + 1, None, name + "-first")
    check("%s: first_cycle (%d) == CYCLE when slot 0 starts" % (name, run.ctrl["first_cycle"]),
          r.counter() == run.ctrl["first_cycle"] + 1 and
          r.ctrl["first_cycle"] == run.ctrl["first_cycle"],
          "CYCLE after that cycle %d" % r.counter())


def main():
    global PRUSIM
    PRUSIM, fwdir, work = sys.argv[1:4]
    fw = os.path.join(fwdir, "ws281x-pru%d.elf")
    rng = random.Random(281)
    worst_all = {}
    budget = 4000000

    # 1. R30 only, 8 strings of different lengths on PRU0
    strings = [("r30", b, random_bytes(rng, 3 * (10 - b % 3))) for b in range(8)]
    frame = Frame(0, strings)
    run = Run(work, fw, frame, budget, tag="r30", vcd=True)
    start, worst, _ = check_frame("pru0 R30", run, frame)
    for k, v in worst.items():
        worst_all.setdefault("R30" if k == "r30" else "gpio%d" % k, []).append(v)
    check("pru0 R30: R30 bits outside r30_mask never move",
          all(p in [pin_name("r30", 0, b) for b in range(8)] for p in run.edges))
    first_cycle_check("pru0 R30", work, fw, frame, run, start)
    check("pru0 R30: the first frame's slot 0 starts at cycle %d, at least the reset (%d) "
          "after the core did: its outputs are held low first, whatever R30 held"
          % (start, run.params["reset"]), start is not None and start >= run.params["reset"])
    done = check_done("pru0 R30", work, fw, frame, run, start)
    if done is not None:
        info("pru0 R30: %d slots, reset %d: slot 0 starts at cycle %d of the run (boot, "
             "setup, slot 0's read); the event is strobed %d cycles after slot 0 started "
             "(%d slots x %d + reset %d + %d)"
             % (frame.slots, run.params["reset"], start, done - start, frame.slots, SLOT,
                run.params["reset"], done - start - frame.slots * SLOT - run.params["reset"]))
    sigrok_check("pru0 R30", run, frame, 0, strings[0][2])

    # 2. GPIO: 2 strings on each bank plus 2 R30 strings, PRU0
    strings = [("r30", 3, random_bytes(rng, 12)), ("r30", 14, random_bytes(rng, 9))]
    for b, bits in enumerate([(2, 31), (0, 17), (5, 22), (14, 21)]):
        strings += [(b, bit, random_bytes(rng, 6 + 3 * b)) for bit in bits]
    frame = Frame(0, strings)
    run = Run(work, fw, frame, budget, tag="gpio", params={"reset": D["WS281X_RESET_DEFAULT"],
                                                           "event": 31})
    start, worst, offsets = check_frame("pru0 GPIO+R30", run, frame)
    for k, v in worst.items():
        worst_all.setdefault("R30" if k == "r30" else "gpio%d" % k, []).append(v)
    check("pru0 GPIO+R30: bank b's edges at R30 + 18 + 8 b (%s) cycles" %
          ", ".join("bank %d +%s" % (b, offsets.get(b)) for b in range(4)),
          [offsets.get(b) for b in range(4)] == GPIO_OFFSET)
    done = check_done("pru0 GPIO+R30", work, fw, frame, run, start)
    if done is not None:
        info("pru0 GPIO+R30: %d slots, reset %d: event %d cycles after slot 0 started "
             "(%d slots x %d + reset + %d)" % (frame.slots, run.params["reset"], done - start,
                                               frame.slots, SLOT,
                                               done - start - frame.slots * SLOT -
                                               run.params["reset"]))

    # The same with DDR reads 15 cycles slower and L4 writes 1 cycle slower
    # each: the deadlines keep every edge where it was (slack 22 - 15 - 3)
    slow = ("ddr=58", "gpio_write_interval=9")
    run = Run(work, fw, frame, budget, tag="gpio-slow", config=slow,
              params={"reset": D["WS281X_RESET_DEFAULT"]})
    _, worst, offsets2 = check_frame("pru0 GPIO+R30, -C %s" % " -C ".join(slow), run, frame)
    check("pru0 GPIO+R30, slow: every edge still exact (worst error %d), bank offsets %s"
          % (max(worst.values()), [offsets2.get(b) for b in range(4)]),
          max(worst.values()) == 0)

    # DDR reads that vary from one to the next (prusim's ddr_jitter, as the
    # VM's knob): up to 18 cycles more each stay inside the slack of 22,
    # and no edge moves; up to 60 more (a busy board's DDR) exceed it, and
    # edges move: the margin is real, and the jitter is applied
    for extra, exact in ((18, True), (60, False)):
        cfg = ("ddr_jitter=%d" % extra, "jitter_seed=20261129")
        run = Run(work, fw, frame, budget, tag="gpio-jitter%d" % extra, config=cfg,
                  params={"reset": D["WS281X_RESET_DEFAULT"]})
        _, worst, _ = check_frame("pru0 GPIO+R30, -C %s" % " -C ".join(cfg), run, frame,
                                  quiet=not exact)
        check("pru0 GPIO+R30, DDR reads up to %d cycles slower: %s (worst error %d)"
              % (extra, "every edge still exact" if exact else "edges move", max(worst.values())),
              (max(worst.values()) == 0) == exact)

    # 3. PRU1: R30 and GPIO strings
    strings = [("r30", b, random_bytes(rng, 6 + b)) for b in (0, 5, 13)]
    strings += [(1, 28, random_bytes(rng, 9)), (3, 19, random_bytes(rng, 3))]
    frame = Frame(1, strings)
    run = Run(work, fw, frame, budget, tag="pru1", vcd=True)
    start, worst, offsets = check_frame("pru1 GPIO+R30", run, frame)
    for k, v in worst.items():
        worst_all.setdefault("R30" if k == "r30" else "gpio%d" % k, []).append(v)
    check("pru1 GPIO+R30: bank offsets %s == pru0's" % [offsets.get(b) for b in (1, 3)],
          [offsets.get(b) for b in (1, 3)] == [GPIO_OFFSET[1], GPIO_OFFSET[3]])
    first_cycle_check("pru1 GPIO+R30", work, fw, frame, run, start)
    check_done("pru1 GPIO+R30", work, fw, frame, run, start)
    sigrok_check("pru1 R30", run, frame, 5, strings[1][2])

    # 4. Refused commands: status, and no pin moves
    frame = Frame(0, [("r30", 0, b"\x55\xaa\x0f")])
    bad = [
        ("slots 0", {"slots": 0}, "WS281X_EINVAL"),
        ("slots MAX + 1", {"slots": D["WS281X_MAX_SLOTS"] + 1}, "WS281X_EINVAL"),
        ("reset RESET_MIN - 1", {"reset": D["WS281X_RESET_MIN"] - 1}, "WS281X_EINVAL"),
        ("event 15", {"event": 15}, "WS281X_EINVAL"),
        ("event 32", {"event": 32}, "WS281X_EINVAL"),
        ("frame 0", {"frame": 0}, "WS281X_EINVAL"),
        ("no output", {"r30_mask": 0, "gpio": [0, 0, 0, 0]}, "WS281X_EINVAL"),
        ("opcode 7", {"command": (1 << 16) | 7}, "WS281X_EOPCODE"),
    ]
    for what, params, res in bad:
        for core in (0, 1) if what == "slots 0" else (0,):
            f = Frame(core, frame.strings)
            r = Run(work, fw, f, 100000, params, "bad")
            check("pru%d SHOW with %s: status READY|%s|seq 1, no pin moves, not counted"
                  % (core, what, res),
                  r.ctrl["status"] == status(1, D[res]) and not r.edges and
                  r.ctrl["frames"] == 0 and r.json["intc"]["raw"] == 0,
                  "status 0x%x, %d pins moved" % (r.ctrl["status"], len(r.edges)))

    # 5. Both cores at once, in step
    pair_check(work, fw, rng, worst_all)

    for kind, errs in sorted(worst_all.items()):
        info("worst edge error, %s strings: %d cycles (over %d runs)" % (kind, max(errs), len(errs)))
    return 1 if failed else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (RuntimeError, OSError, ValueError, KeyError, StopIteration) as e:
        print("FAIL: ws281x prusim check: %s: %s" % (type(e).__name__, e))
        sys.exit(1)
