#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""The pru_pwm table builder and firmware, to the cycle (run by check.sh).

1. pru_pwm_table.c (the driver's, built for the host as pwm_table) against
   the rounding rules of Documentation/pru_pwm.rst, written again here from
   the text: on hundreds of random channel states, every channel's duty and
   every step's R30 value; and the states the driver must refuse.
2. The real pru_pwm-pru1.elf in the prusim host tool, its control block
   preloaded (--load) with a SET of table 0 and a table 1, and PRU0 running
   pwm-poke, which posts further commands into PRU1's block at given
   cycles, as the driver does: the whole list of pin changes must be
   exactly the one the tables give, period after period, the new table
   starting at the first period start after its SET was seen (no period cut
   short, no runt); @late must be 0 at the gaps the firmware promises, and
   not 0 one cycle below them; refused commands change nothing.

usage: pwm_sim.py PRUSIM FW_DIR PWM_TABLE WORK_DIR"""
import os
import random
import struct
import subprocess
import sys

TOP = os.path.realpath(os.path.join(os.path.dirname(__file__), "../../.."))
PROTO = os.path.join(TOP, "drivers/pru_pwm/pru_pwm_proto.h")
TABLE_H = os.path.join(TOP, "drivers/pru_pwm/pru_pwm_table.h")
sys.path.insert(0, os.path.join(TOP, "tests", "lib"))
from cdefs import defines  # noqa: E402

# prusim's names of PRU1's R30 bits (tools/prusim: the Black's header pins)
PRU1_R30 = ["P8_45", "P8_46", "P8_43", "P8_44", "P8_41", "P8_42", "P8_39", "P8_40",
            "P8_27", "P8_29", "P8_28", "P8_30", "P8_21", "P8_20"]
# The Robotics Control Library's servo channels 1..8 on PRU1's R30
BITS = [8, 10, 9, 11, 6, 7, 4, 5]

passed = failed = 0


def check(name, cond, detail=""):
    global passed, failed
    print(("PASS: " if cond else "FAIL: ") + name + ("" if cond or not detail else ": %s" % (detail,)))
    if cond:
        passed += 1
    else:
        failed += 1
    return cond


D = defines(os.path.join(TOP, "include/prukit/pru_ctrl.h"), PROTO, TABLE_H)
MIN_GAP, END_GAP = D["PRU_PWM_MIN_GAP"], D["PRU_PWM_END_GAP"]
MIN_PERIOD, MAX_PERIOD = D["PRU_PWM_MIN_PERIOD"], D["PRU_PWM_MAX_PERIOD"]
IDLE = D["PRU_PWM_IDLE_PERIOD"]
# What the loop needs from a period's last step to its end when it takes a
# SET there (pru_pwm_run.S's count; PRU_PWM_END_GAP adds a margin)
LOOP_END_GAP = 71
NSTEPS = D["PRU_PWM_MAX_STEPS"]
TABLE_FMT = "<II" + "II" * NSTEPS + "III" * D["PRU_PWM_CHANNELS"]
TABLE_BYTES = struct.calcsize(TABLE_FMT)
CTRL_HEAD = "<IHHIIIIIII"                # hdr, next, active, periods, late, started_at
CTRL_BYTES = struct.calcsize(CTRL_HEAD) + 2 * TABLE_BYTES
PRU1_CTRL_FROM_PRU0 = 0x2000 + D["PRUKIT_CTRL_DA"]


# ---- 1. the rules, from the documentation ----------------------------------

def expected(chans):
    """chans: [(bit, period, duty, enabled, inversed)] -> (period, duties,
    steps [(at, r30)]) as Documentation/pru_pwm.rst says, or None (refused)."""
    en = [c for c in chans if c[3]]
    periods = {c[1] for c in en}
    if len(periods) > 1 or any(c[1] < MIN_PERIOD or c[1] > MAX_PERIOD or c[2] > c[1] for c in en):
        return None
    period = periods.pop() if periods else IDLE
    rounded, last = {}, 0
    for e in sorted({c[2] for c in en if 0 < c[2] < period}):
        r = min(e, period - END_GAP)
        if r != last and r - last < MIN_GAP:
            r = last
        rounded[e] = last = r
    duties = [(rounded.get(c[2], c[2]) if c[3] else 0) for c in chans]
    steps = []
    for at in sorted({0} | {d for d in duties if 0 < d < period}):
        r30 = 0
        for c, d in zip(chans, duties):
            r30 |= (bool(c[3] and at < d) != bool(c[4])) << c[0]
        steps.append((at, r30))
    return period, duties, steps


def build(tool, work, chans, name="t"):
    """pwm_table on chans -> (table bytes, period, duties, steps) or None."""
    path = os.path.join(work, name + ".tbl")
    args = ["%d:%d:%d:%s" % (b, p, d, ("e" if e else "") + ("i" if i else "") or "-")
            for b, p, d, e, i in chans]
    r = subprocess.run([tool, path] + args, capture_output=True, text=True)
    if r.returncode == 1 and r.stdout.strip() == "EINVAL":
        return None
    if r.returncode:
        raise RuntimeError("pwm_table: %s" % r.stderr)
    data = open(path, "rb").read()
    v = struct.unpack(TABLE_FMT, data)
    period, nsteps = v[0], v[1]
    steps = [(v[2 + 2 * k], v[3 + 2 * k]) for k in range(nsteps)]
    ch = v[2 + 2 * NSTEPS:]
    duties = [ch[3 * k] for k in range(len(chans))]
    return data, period, duties, steps


def random_chans(rng):
    n = rng.randint(1, 8)
    period = rng.choice([MIN_PERIOD, MIN_PERIOD + 1, rng.randint(MIN_PERIOD, 3000), 2000,
                         4000000, rng.randint(MIN_PERIOD, 10 ** 7)])
    base = rng.randint(0, period)
    chans = []
    for k in range(n):
        kind = rng.random()
        if kind < 0.3:          # clustered: ends closer than MIN_GAP
            d = min(period, max(0, base + rng.randint(-30, 30)))
        elif kind < 0.4:        # at the ends of the period
            d = rng.choice([0, 1, MIN_GAP - 1, MIN_GAP, period - END_GAP,
                            period - END_GAP + 1, period - 1, period])
        else:
            d = rng.randint(0, period)
        chans.append((BITS[k], period, d, rng.random() < 0.85, rng.random() < 0.25))
    return chans


def table_checks(tool, work):
    rng = random.Random(26)
    bad = []
    rounded = 0
    for i in range(400):
        chans = random_chans(rng)
        want = expected(chans)
        got = build(tool, work, chans)
        if want is None or got is None or got[1:] != want:
            bad.append((chans, want, got and got[1:]))
        elif any(c[3] and c[2] != d for c, d in zip(chans, want[1])):
            rounded += 1
    check("pru_pwm_table.c follows the documented rules on 400 random states "
          "(%d of them rounded a duty down)" % rounded, not bad and rounded > 20,
          bad[:1])
    for name, chans in (
            ("enabled channels with two periods", [(8, 4000, 10, 1, 0), (10, 5000, 10, 1, 0)]),
            ("a period one cycle below PRU_PWM_MIN_PERIOD", [(8, MIN_PERIOD - 1, 10, 1, 0)]),
            ("a period above PRU_PWM_MAX_PERIOD", [(8, MAX_PERIOD + 1, 10, 1, 0)]),
            ("a duty above the period", [(8, 4000, 4001, 1, 0)])):
        check("the table builder refuses %s" % name, build(tool, work, chans) is None)
    ok = build(tool, work, [(8, 4000, 10, 1, 0), (10, 5000, 10, 0, 0)])
    check("a disabled channel's period does not matter", ok is not None and ok[1] == 4000)
    idle = build(tool, work, [(b, 4000, 100, 0, k % 2) for k, b in enumerate(BITS)])
    check("all disabled: one step at the idle period, inversed channels high",
          idle is not None and idle[1] == IDLE and len(idle[3]) == 1 and
          idle[3][0][1] == sum(1 << b for k, b in enumerate(BITS) if k % 2))


# ---- 2. the firmware in prusim ------------------------------------------------

def ctrl_block(t0, t1, command=(1 << 16) | D["PRU_PWM_CMD_SET"], nxt=0):
    head = struct.pack(CTRL_HEAD, D["PRU_PWM_MAGIC"], D["PRU_PWM_VERSION"], CTRL_BYTES,
                       command, 0, nxt, D["PRU_PWM_NONE"], 0, 0, 0)
    return head + t0 + t1


def raw_table(period, steps):
    v = [period, len(steps)]
    for k in range(NSTEPS):
        v += list(steps[k]) if k < len(steps) else [0, 0]
    v += [0] * (3 * D["PRU_PWM_CHANNELS"])
    return struct.pack(TABLE_FMT, *v)


class Sim:
    """One prusim run of pru_pwm on PRU1 (and pwm-poke on PRU0)."""

    def __init__(self, prusim, fw, work, tag, t0, t1, cycles, pokes=()):
        base = os.path.join(work, tag)
        with open(base + ".ctrl", "wb") as f:
            f.write(ctrl_block(t0, t1))
        cmd = [prusim, "--pru1", os.path.join(fw, "pru_pwm-pru1.elf"),
               "--load", "pru1:0x%x:%s" % (D["PRUKIT_CTRL_DA"], base + ".ctrl"),
               "--dump", "pru1:0x%x:%d:%s" % (D["PRUKIT_CTRL_DA"], CTRL_BYTES, base + ".out"),
               "--events", base + ".events", "--max-cycles", str(cycles)]
        if pokes:
            words = [len(pokes)]
            for cycle, off, value in pokes:
                words += [cycle, PRU1_CTRL_FROM_PRU0 + off, value]
            with open(base + ".pokes", "wb") as f:
                f.write(struct.pack("<%dI" % len(words), *words))
            cmd += ["--pru0", os.path.join(fw, "pwm-poke-pru0.elf"),
                    "--load", "pru0:0x%x:%s" % (D["PRUKIT_CTRL_DA"], base + ".pokes")]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode:
            raise RuntimeError("prusim (%s) exited %d: %s" % (tag, r.returncode, r.stderr))
        v = struct.unpack(CTRL_HEAD, open(base + ".out", "rb").read()[:struct.calcsize(CTRL_HEAD)])
        self.status, self.active, self.periods, self.late = v[4], v[6], v[7], v[8]
        self.events = []
        with open(base + ".events") as f:
            for line in f:
                c, pin, level = line.split()
                if pin in PRU1_R30:
                    self.events.append((int(c), PRU1_R30.index(pin), int(level)))
        self.cycles = cycles


def schedule(tables, start, switch_after, end):
    """The pin changes (cycle, bit, level) the tables give from cycle
    start: tables[0] for the first switch_after periods, then tables[1]
    (switch_after None: never), up to cycle end."""
    out, r30, s, k = [], 0, start, 0
    while s < end:
        period, steps = tables[0] if switch_after is None or k < switch_after else tables[1]
        for at, val in steps:
            if s + at >= end:
                break
            for b in range(len(PRU1_R30)):
                if (val ^ r30) >> b & 1:
                    out.append((s + at, b, val >> b & 1))
            r30 = val
        s += period
        k += 1
    return out


def matches(sim, tables, switch_candidates):
    """Does the run's list of changes equal the tables' schedule, for one of
    the candidate switch points?  Returns [the one that matched], or []."""
    if not sim.events:
        return []
    start = sim.events[0][0]
    end = sim.events[-1][0] + 1
    for sw in switch_candidates:
        if sorted(schedule(tables, start, sw, end)) == sorted(sim.events):
            return [sw]
    return []


def status_of(seq, result):
    return (seq << 16) | D["PRUKIT_CTRL_READY"] | result


def sim_checks(prusim, fw, tool, work):
    set_cmd = D["PRU_PWM_CMD_SET"]
    # 8 channels MIN_GAP apart at the shortest period, the last END_GAP before its end
    tight = [(b, MIN_PERIOD, MIN_GAP * (k + 1), 1, 0) for k, b in enumerate(BITS)]
    t = build(tool, work, tight, "tight")
    check("8 ends PRU_PWM_MIN_GAP apart at PRU_PWM_MIN_PERIOD need no rounding",
          t is not None and t[2] == [MIN_GAP * (k + 1) for k in range(8)] and
          MIN_PERIOD - t[3][-1][0] == END_GAP, t and t[3])
    s = Sim(prusim, fw, work, "tight", t[0], t[0], 20 * MIN_PERIOD)
    check("tight table: every pin change in its cycle, period after period (%d changes)"
          % len(s.events), matches(s, [(t[1], t[3])], [None]) == [None] and len(s.events) > 200)
    check("tight table: none late, the SET answered", s.late == 0 and
          s.status == status_of(1, 0) and s.active == 0, (s.late, hex(s.status)))

    # one cycle below the promise: a gap of MIN_GAP - 1 is late
    steps = [(0, 1 << 8), (MIN_GAP - 1, 0), (200, 1 << 10), (230, 0)]
    s = Sim(prusim, fw, work, "short-gap", raw_table(MIN_PERIOD, steps), raw_table(MIN_PERIOD, steps),
            10 * MIN_PERIOD)
    later = [e for e in s.events if e[1] == 10]
    check("a gap of PRU_PWM_MIN_GAP - 1 is late (the gap promised is the loop's own)",
          s.late > 0, s.late)
    check("and the steps after it keep their deadlines",
          len(later) > 4 and all((b[0] - a[0]) in (30, MIN_PERIOD - 30)
                                 for a, b in zip(later, later[1:])))
    # the end of a period: the loop's own need when it takes a SET there
    # (pru_pwm_run.S), below PRU_PWM_END_GAP
    for gap, late in ((END_GAP, False), (LOOP_END_GAP, False), (LOOP_END_GAP - 1, True)):
        steps = [(0, 1 << 8), (50, 0), (MIN_PERIOD - gap, 1 << 10)]
        tbl = raw_table(MIN_PERIOD, steps)
        s = Sim(prusim, fw, work, "end-gap", tbl, tbl, 10 * MIN_PERIOD,
                pokes=[(700, 16, 1), (700, 8, (2 << 16) | set_cmd)])
        check("a last step %d cycles before the period's end, a SET taken there: %s"
              % (gap, "late" if late else "in time"), (s.late > 0) == late and
              s.status == status_of(2, 0), (s.late, hex(s.status)))

    # SET at the end of a period with the last step END_GAP before it: 100 kHz
    a = [(b, 2000, 100 + 237 * k, 1, k == 3) for k, b in enumerate(BITS)]
    a[7] = (BITS[7], 2000, 2000 - END_GAP, 1, 0)
    b = [(bb, 2000, 1900 - 211 * k, 1, k == 5) for k, bb in enumerate(BITS)]
    ta, tb = build(tool, work, a, "a"), build(tool, work, b, "b")
    for at in (5000, 5999, 7000):
        s = Sim(prusim, fw, work, "switch%d" % at, ta[0], tb[0], 20000,
                pokes=[(at, 16, 1), (at, 8, (2 << 16) | set_cmd)])
        sw = matches(s, [(ta[1], ta[3]), (tb[1], tb[3])], range(1, 12))
        check("100 kHz, SET posted at cycle %d: every change exact, the new table from a "
              "period start on (after period %s), no runt" % (at, sw),
              bool(sw) and s.late == 0 and
              s.status == status_of(2, 0) and s.active == 1, (sw, s.late, hex(s.status)))

    # a SET from a long period to a short one, and back: the period played
    # ends whole, the new one starts at its end (the waits' bound is the
    # longer of the two while the new table waits for the old period's end)
    lng = [(b, 20000, 1000 + 1500 * k, 1, 0) for k, b in enumerate(BITS)]
    sht = [(b, 2000, 100 + 200 * k, 1, 0) for k, b in enumerate(BITS)]
    tl, tsh = build(tool, work, lng, "long"), build(tool, work, sht, "short")
    for name, first, second, at in (("20000 to 2000 cycles", tl, tsh, 35000),
                                    ("2000 to 20000 cycles", tsh, tl, 5100)):
        s = Sim(prusim, fw, work, "periods", first[0], second[0], 90000,
                pokes=[(at, 16, 1), (at, 8, (2 << 16) | set_cmd)])
        sw = matches(s, [(first[1], first[3]), (second[1], second[3])], range(1, 40))
        check("a SET from a period of %s: the old period ends whole, the new table from "
              "its end (after period %s), every change exact" % (name, sw),
              bool(sw) and s.late == 0 and s.active == 1, (sw, s.late, s.active))

    # coinciding ends: one write
    c = [(b, 3000, 1000 if k < 4 else 2000, 1, k in (1, 5)) for k, b in enumerate(BITS)]
    tc = build(tool, work, c, "coincide")
    s = Sim(prusim, fw, work, "coincide", tc[0], tc[0], 10000)
    at1000 = {e[0] for e in s.events if e[1] in BITS[:4] and e[0] % 3000 != s.events[0][0] % 3000}
    check("four channels ending in the same cycle change in one cycle",
          matches(s, [(tc[1], tc[3])], [None]) == [None] and len(at1000) == 3 and len(tc[3]) == 3,
          (sorted(at1000), tc[3]))

    # servos: 50 Hz, 500..2500 us
    sv = [(b, 4000000, 100000 + 57143 * k, 1, 0) for k, b in enumerate(BITS)]
    ts = build(tool, work, sv, "servo")
    s = Sim(prusim, fw, work, "servo", ts[0], ts[0], 8200000)
    highs = [e2[0] - e1[0] for e1, e2 in zip(s.events, s.events[1:])]
    widths = sorted({e2[0] - e1[0] for e1 in s.events for e2 in s.events
                     if e1[1] == e2[1] and e1[2] == 1 and e2[2] == 0 and 0 < e2[0] - e1[0] < 4000000})
    check("servos at 50 Hz: 8 pulses of 500..2500 us, exact to the cycle, period 4000000 cycles",
          matches(s, [(ts[1], ts[3])], [None]) == [None] and
          widths == [100000 + 57143 * k for k in range(8)] and s.late == 0, (widths[:3], highs[:3]))

    # refused commands change nothing
    pokes = [(3000, 16, 2), (3000, 8, (2 << 16) | set_cmd),
             (9000, 8, (3 << 16) | 7),
             (15000, 16, 1), (15000, 8, (4 << 16) | set_cmd)]
    bad1 = raw_table(2000, [])                       # steps 0
    s = Sim(prusim, fw, work, "refused", ta[0], bad1, 24000, pokes=pokes)
    check("SET of table 2, an unknown opcode, SET of a table with no steps: refused, "
          "the table played goes on unchanged",
          matches(s, [(ta[1], ta[3])], [None]) == [None] and s.active == 0 and
          s.status == status_of(4, D["PRU_PWM_EINVAL"]) and s.late == 0, hex(s.status))
    s = Sim(prusim, fw, work, "eopcode", ta[0], ta[0], 12000, pokes=[(3000, 8, (2 << 16) | 7)])
    check("an unknown opcode is answered PRU_PWM_EOPCODE",
          s.status == status_of(2, D["PRU_PWM_EOPCODE"]), hex(s.status))
    short = raw_table(MIN_PERIOD - 1, [(0, 1 << 8)])
    s = Sim(prusim, fw, work, "short", ta[0], short, 12000,
            pokes=[(3000, 16, 1), (3000, 8, (2 << 16) | set_cmd)])
    check("a table shorter than PRU_PWM_MIN_PERIOD is refused (PRU_PWM_EINVAL)",
          s.status == status_of(2, D["PRU_PWM_EINVAL"]) and s.active == 0, hex(s.status))
    print("info: PRU_PWM_MIN_GAP %d cycles (%d ns), PRU_PWM_END_GAP %d, shortest period %d "
          "cycles (%.0f kHz with 8 channels)" % (MIN_GAP, 5 * MIN_GAP, END_GAP, MIN_PERIOD,
                                                 200000 / MIN_PERIOD))


def main():
    prusim, fw, tool, work = sys.argv[1:5]
    table_checks(tool, work)
    sim_checks(prusim, fw, tool, work)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
