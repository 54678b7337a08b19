#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""make demo's servo part, on the host: the pin trace of the guest's sweep
(tests/vm/demo/servo: servo.bin, servo.json) turned into pin changes and a
VCD by the prusim tool, every pulse measured on the four servo pins, and a
picture of the pulse widths over time (servo.png): one line per servo, the
widths the pins had, period after period.  Fails unless every period is
20 ms to the cycle and each servo's pulses are the widths the guest wrote,
in order, each for whole periods.

usage: servo_demo.py PRUSIM OUT_DIR"""
import json
import os
import subprocess
import sys

from PIL import Image, ImageDraw

COLOURS = [(230, 80, 40), (40, 150, 230), (60, 180, 60), (200, 160, 20)]


def collapse(seq):
    out = []
    for v in seq:
        if not out or out[-1] != v:
            out.append(v)
    return out


def main():
    prusim, out = sys.argv[1:3]
    with open(os.path.join(out, "servo.json")) as f:
        want = json.load(f)
    trace = os.path.join(out, "servo.bin")
    subprocess.run([prusim, "--trace-in", trace, "--events", os.path.join(out, "servo.events"),
                    "--vcd", os.path.join(out, "servo.vcd")], check=True)
    edges = {p: [] for p in want["pins"]}
    with open(os.path.join(out, "servo.events")) as f:
        for line in f:
            c, pin, level = line.split()
            if pin in edges:
                edges[pin].append((int(c), int(level)))
    period = want["period"]
    ok = True
    pulses = []
    for k, pin in enumerate(want["pins"]):
        e = edges[pin]
        p = [(a[0], b[0] - a[0]) for a, b in zip(e, e[1:]) if a[1] == 1 and b[1] == 0]
        rises = [c for c, lv in e if lv == 1]
        exact = all(b - a == period for a, b in zip(rises, rises[1:]))
        got = collapse([w for _, w in p])
        asked = collapse(want["widths"][k])
        good = exact and len(got) >= 2 and got == asked[len(asked) - len(got):]
        print("%s: servo %d on %s: %d pulses, %d widths %.0f..%.0f us, every period %d cycles"
              % ("PASS" if good else "FAIL", k + 1, pin, len(p), len(got),
                 min(w for _, w in p) / 200, max(w for _, w in p) / 200, period))
        ok = ok and good
        pulses.append(p)

    # the picture: pulse width (500..2500 us) over time, one line per servo,
    # from a little before the sweep (servo 1 leaves prukit servo's width)
    first = pulses[0][0][1]
    sweep = next((c for c, w in pulses[0] if w != first), pulses[0][0][0])
    t0 = max(min(p[0][0] for p in pulses), sweep - 12 * period)
    t1 = max(p[-1][0] for p in pulses) + period
    pulses = [[(c, w) for c, w in p if c >= t0] for p in pulses]
    w, h, left, top, bottom = 900, 360, 70, 30, 40
    img = Image.new("RGB", (w, h), (255, 255, 255))
    d = ImageDraw.Draw(img)

    def xy(cycle, width):
        x = left + (cycle - t0) * (w - left - 20) / (t1 - t0)
        y = top + (2500 - width / 200) * (h - top - bottom) / 2000
        return x, y

    for us in (600, 1000, 1500, 2000, 2400):
        x0, y = xy(t0, us * 200)
        d.line([(left, y), (w - 20, y)], fill=(225, 225, 225))
        d.text((8, y - 6), "%d us" % us, fill=(0, 0, 0))
    span = (t1 - t0) / 200000
    tick = next(t for t in (100, 200, 500, 1000, 2000, 5000, 10000) if span / t <= 10)
    for ms in range(0, int(span) + 1, tick):
        x, _ = xy(t0 + ms * 200000, 500 * 200)
        d.text((x - 10, h - bottom + 8), "%d ms" % ms, fill=(0, 0, 0))
    for k, p in enumerate(pulses):
        pts = []
        for c, width in p:
            pts += [xy(c, width), xy(c + period, width)]
        d.line(pts, fill=COLOURS[k], width=2)
        d.text((left + 10 + 120 * k, 8), "servo %d (%s)" % (k + 1, want["pins"][k]),
               fill=COLOURS[k])
    img.save(os.path.join(out, "servo.png"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
