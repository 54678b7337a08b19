#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""hub75_conv.c (built for the host as conv_test) against hub75_model.py,
the documented arithmetic written again: every level of every depth and
correction, and frame buffers of several layouts, pixel formats and
partial updates, byte for byte.

    conv_check.py CONV_TEST WORKDIR"""
import os
import random
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import hub75_model  # noqa: E402

FAILS = []


def check(name, cond, detail=""):
    print("%s: %s%s" % ("PASS" if cond else "FAIL", name, (" (%s)" % detail) if detail else ""))
    if not cond:
        FAILS.append(name)


def image(width, height, fmt, seed):
    rnd = random.Random(seed)
    if fmt == "rgb565":
        return b"".join(struct.pack("<H", rnd.getrandbits(16)) for _ in range(width * height))
    return b"".join(struct.pack("<I", rnd.getrandbits(32)) for _ in range(width * height))


def main(conv, work):
    for corr in ("cie1931", "linear"):
        bad = []
        for planes in range(1, 13):
            out = subprocess.run([conv, "lut", str(planes), corr], capture_output=True,
                                 text=True).stdout.split()
            want = [hub75_model.level(v, planes, corr) for v in range(256)]
            if [int(x) for x in out] != want:  # a crash prints nothing: differs
                bad.append(planes)
        check("levels of all 256 values, 1..12 planes, %s" % corr, not bad, "planes %s" % bad)
    layouts = [
        ("64x32 R30 8 planes cie1931 xrgb8888", 64, 32, 16, 8, "cie1931", 1, [0, 1, 2, 3, 4, 5],
         "xrgb8888"),
        ("64x32 GPIO (PocketScroller) 8 planes rgb565", 64, 32, 16, 8, "cie1931", 2,
         [2, 10, 7, 8, 9, 0], "rgb565"),
        ("128x32 chain R30 6 planes linear", 128, 32, 16, 6, "linear", 1, [5, 4, 3, 2, 1, 0],
         "xrgb8888"),
        ("32x16 1/8 R30 11 planes", 32, 16, 8, 11, "cie1931", 1, [0, 1, 2, 3, 4, 5], "xrgb8888"),
        ("64x64 1/32 GPIO 4 planes linear", 64, 64, 32, 4, "linear", 2, [15, 14, 13, 0, 1, 2],
         "rgb565"),
    ]
    for n, (name, w, h, rows, planes, corr, eb, bits, fmt) in enumerate(layouts):
        a = image(w, h, fmt, n)
        pa = os.path.join(work, "a.raw")
        with open(pa, "wb") as f:
            f.write(a)
        args = [conv, "frame", str(planes), corr, str(w), str(h), str(rows), str(eb)] + \
            [str(b) for b in bits] + [fmt, pa]
        got = subprocess.run(args, capture_output=True).stdout
        want = hub75_model.frame_buffer(bits, eb, hub75_model.expected(a, fmt.upper(), w, h, planes, corr), rows, planes)
        check("frame buffer: %s" % name, got == want, "%d/%d bytes" % (len(got), len(want)))
        # a rectangle changes, only it is converted again
        bpp = 2 if fmt == "rgb565" else 4
        b = bytearray(a)
        x1, y1, x2, y2 = w // 5, h // 7, w - w // 3, h - 3
        new = image(w, h, fmt, 100 + n)
        for y in range(y1, y2):
            b[(y * w + x1) * bpp:(y * w + x2) * bpp] = new[(y * w + x1) * bpp:(y * w + x2) * bpp]
        pb = os.path.join(work, "b.raw")
        with open(pb, "wb") as f:
            f.write(b)
        got = subprocess.run(args + [str(x1), str(y1), str(x2), str(y2), pb],
                             capture_output=True).stdout
        want = hub75_model.frame_buffer(bits, eb, hub75_model.expected(bytes(b), fmt.upper(), w, h,
                                                                       planes, corr), rows, planes)
        check("frame buffer: %s, then rectangle (%d,%d)-(%d,%d) changed" % (name, x1, y1, x2, y2),
              got == want)
    mux_checks(conv, work)
    banks_checks(conv, work)
    return 1 if FAILS else 0


def banks_checks(conv, work):
    """HUB75_DATA_BANKS: the Octoscroller's outputs, each a band of the
    display's rows, against hub75_model.banks_frame()."""
    data = hub75_model.OCTO_DATA
    for name, outputs, pw, ph, chain, planes, corr, mux in (
            ("8 outputs x 64x32, 8 planes", 8, 64, 32, 1, 8, "cie1931", "direct"),
            ("3 outputs x 2 32x16 outdoor (stripe), 12 planes", 3, 32, 16, 2, 12, "linear",
             "stripe"),
            ("8 outputs x 3 64x32 (the 24-panel wall), 12 planes", 8, 64, 32, 3, 12, "cie1931",
             "direct")):
        slots = hub75_model.bank_slots(data[:outputs], hub75_model.OCTO_CTRL["bank"])
        lines = ",".join("%d:%d" % (slots.index(b), bit) for o in data[:outputs] for b, bit in o)
        w, h = pw * chain, ph * outputs
        a = image(w, h, "xrgb8888", outputs * 10 + chain)
        pa = os.path.join(work, "a.raw")
        with open(pa, "wb") as f:
            f.write(a)
        got = subprocess.run([conv, "banks", str(planes), corr, str(pw), str(ph), str(chain),
                              str(outputs), mux, lines, pa], capture_output=True).stdout
        img = hub75_model.expected(a, "XRGB8888", w, h, planes, corr)
        rows = ph // (1 if mux == "direct" else 2) // 2
        imgs = [hub75_model.driven(img[o * ph:(o + 1) * ph], mux, pw) for o in range(outputs)]
        want = hub75_model.banks_frame(data[:outputs], slots, imgs, rows, planes)
        check("frame buffer, every line on GPIO banks: %s" % name, got == want,
              "%d/%d bytes" % (len(got), len(want)))
    # the wall as built: serpentine, turned
    outputs, pw, ph, chain = 4, 32, 16, 2
    slots = hub75_model.bank_slots(data[:outputs], hub75_model.OCTO_CTRL["bank"])
    lines = ",".join("%d:%d" % (slots.index(b), bit) for o in data[:outputs] for b, bit in o)
    w, h = pw * chain, ph * outputs
    for serp, rot in ((1, 0), (0, 90), (1, 180), (1, 270)):
        dw, dh = (h, w) if rot in (90, 270) else (w, h)
        a = image(dw, dh, "xrgb8888", 50 + rot + serp)
        pa = os.path.join(work, "a.raw")
        with open(pa, "wb") as f:
            f.write(a)
        got = subprocess.run([conv, "banks", "6", "linear", str(pw), str(ph), str(chain),
                              str(outputs), "direct", lines, pa, str(serp), str(rot)],
                             capture_output=True).stdout
        shown = hub75_model.expected(a, "XRGB8888", dw, dh, 6, "linear")
        chains = [[None] * w for _ in range(h)]
        for y in range(h):
            for x in range(w):
                dx, dy = hub75_model.arrange(x, y, w, h, ph, serp, rot)
                chains[y][x] = shown[dy][dx]
        imgs = [chains[o * ph:(o + 1) * ph] for o in range(outputs)]
        want = hub75_model.banks_frame(data[:outputs], slots, imgs, ph // 2, 6)
        check("frame buffer, 4 outputs x 2 32x16, %sturned %d" % (
            "serpentine, " if serp else "", rot), got == want, "%d/%d bytes" % (len(got), len(want)))


def mux_checks(conv, work):
    """hub75_mux_table() against hub75_model.mux_map() for every wiring on
    the panels it fits, and a frame buffer through one."""
    for name in hub75_model.MUXES:
        for w, h, chain in ((32, 16, 1), (64, 32, 2), (64, 64, 1)):
            out = subprocess.run([conv, "mux", name, str(w), str(h), str(chain)],
                                 capture_output=True, text=True).stdout.split("\n")
            s = 2
            want = [None] * (w * chain * h)
            fits = True
            for y in range(h):
                for vx in range(w * chain):
                    c, x = divmod(vx, w)
                    mx, my = hub75_model.mux_map(name, w, h, x, y)
                    i = my * w * chain * s + c * w * s + mx
                    if not (0 <= mx < w * s and 0 <= my < h // s) or want[i] is not None:
                        fits = False
                    else:
                        want[i] = "%d %d" % (vx, y)
            if not fits or None in want:
                check("%s on %dx%d x %d: refused, it does not fit" % (name, w, h, chain),
                      out[0] == "bad", out[0])
                continue
            check("%s on %dx%d x %d: every LED where the model puts it" % (name, w, h, chain),
                  out[:-1] == want, "%d entries" % (len(out) - 1))
    check("a wiring that does not fit is refused: zstripe on 32x12",
          subprocess.run([conv, "mux", "zstripe", "32", "12", "1"], capture_output=True,
                         text=True).stdout == "bad\n")
    for name, w, h, rows, chain in (("zstripe", 32, 16, 4, 1), ("stripe", 64, 32, 8, 2),
                                     ("p10-outdoor-1r1g1-2", 32, 16, 4, 2)):
        a = image(w * chain, h, "xrgb8888", 7)
        pa = os.path.join(work, "a.raw")
        with open(pa, "wb") as f:
            f.write(a)
        bits = [0, 1, 2, 3, 4, 5]
        args = [conv, "frame", "8", "cie1931", str(w * chain), str(h), str(rows), "1"] + \
            [str(b) for b in bits] + ["xrgb8888", pa, "mux=%s:%d" % (name, w)]
        got = subprocess.run(args, capture_output=True).stdout
        img = hub75_model.expected(a, "XRGB8888", w * chain, h, 8, "cie1931")
        want = hub75_model.frame_buffer(bits, 1, hub75_model.driven(img, name, w), rows, 8)
        check("frame buffer: %s, %dx%d 1/%d scan, chain of %d" % (name, w, h, rows, chain),
              got == want, "%d/%d bytes" % (len(got), len(want)))
        # a rectangle redraws the whole panel as driven
        b = bytearray(image(w * chain, h, "xrgb8888", 8))
        pb = os.path.join(work, "b.raw")
        with open(pb, "wb") as f:
            f.write(b)
        got = subprocess.run(args[:-1] + ["1", "1", "3", "3", pb, args[-1]],
                             capture_output=True).stdout
        img = hub75_model.expected(bytes(b), "XRGB8888", w * chain, h, 8, "cie1931")
        want = hub75_model.frame_buffer(bits, 1, hub75_model.driven(img, name, w), rows, 8)
        check("frame buffer: %s, a rectangle of a new image redraws it all" % name, got == want)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
