#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""make demo's encoder part, on the host: the simulated encoder's position
after each stretch of turning (tests/vm/demo/encoder: encoder.json) and the
count pru_encoder reported then, drawn against each other (encoder.png);
fails unless they agree at every stretch.

usage: encoder_demo.py OUT_DIR"""
import json
import os
import sys

from PIL import Image, ImageDraw


def main():
    out = sys.argv[1]
    with open(os.path.join(out, "encoder.json")) as f:
        d = json.load(f)
    stim, count = d["stimulus"], d["count"]
    bad = [(i, s, c) for i, (s, c) in enumerate(zip(stim, count)) if s != c]
    ok = len(stim) == len(count) and len(stim) > 10 and not bad
    print("%s: the count follows the encoder at all %d stretches (%d to %d), each edge %d PRU "
          "cycles apart%s" % ("PASS" if ok else "FAIL", len(stim), min(stim), max(stim),
                              d["spacing"], "" if ok else ": %s" % bad[:3]))
    w, h, left, top, bottom = 900, 340, 60, 30, 30
    lo, hi = min(stim + count) - 20, max(stim + count) + 20
    img = Image.new("RGB", (w, h), (255, 255, 255))
    dr = ImageDraw.Draw(img)

    def xy(i, v):
        return (left + i * (w - left - 20) / (len(stim) - 1),
                top + (hi - v) * (h - top - bottom) / (hi - lo))

    for v in range((lo // 100 + 1) * 100, hi, 100):
        _, y = xy(0, v)
        dr.line([(left, y), (w - 20, y)], fill=(225, 225, 225))
        dr.text((8, y - 6), str(v), fill=(0, 0, 0))
    dr.line([xy(i, s) for i, s in enumerate(stim)], fill=(40, 150, 230), width=3)
    for i, c in enumerate(count):
        x, y = xy(i, c)
        dr.ellipse([x - 4, y - 4, x + 4, y + 4], outline=(230, 80, 40), width=2)
    dr.text((left, 8), "encoder position fed to P8_16/P8_15 (line)", fill=(40, 150, 230))
    dr.text((left + 330, 8), "count0/count read after each stretch (circles)", fill=(230, 80, 40))
    img.save(os.path.join(out, "encoder.png"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
