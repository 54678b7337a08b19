#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""Self-test of tools/hub75-decode.py on hand-made HUB75 pin sequences.

The sequences come from the naive generator below, written for this test and
independent of any firmware: one frame is row after row, each row its 4 bit
planes (binary code modulation, LSB first, plane p lit 10 << p cycles), each
plane shifted column by column (data, then clk high, then clk low), latched
(lat high then low), addressed, and lit (oe low).  Only changes are
recorded, like the simulator's trace.  The decoder must give every pixel's level
back exactly, from the event list and from a binary trace file (nonzero
origin), and must see the faults the generator can put in.

    python3 drivers/hub75/tests/hub75_decode_selftest.py

Prints PASS:/FAIL: lines; exit status 0 when everything passes, 1 otherwise.
"""
import importlib.util
import json
import os
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.normpath(os.path.join(HERE, "..", "..", "..", "tools", "hub75-decode.py"))
LSB, PLANES = 10, 4
DATA = ("r1", "g1", "b1", "r2", "g2", "b2")
ADDR = ("a", "b", "c", "d", "e")

spec = importlib.util.spec_from_file_location("hub75_decode", TOOL)
hd = importlib.util.module_from_spec(spec)
spec.loader.exec_module(hd)

# The two built-in maps, spelled out here independently (pin ids).
BONE = dict(r1=32, g1=33, b1=34, r2=35, g2=36, b2=37, clk=38, lat=39, oe=40,
            a=41, b=42, c=43, d=44, e=45)
POCKET = dict(lat=0, clk=1, a=2, b=3, c=4, d=5, oe=7, r1=116, g1=124, b1=121,
              r2=122, g2=123, b2=114)


class Failure(Exception):
    pass


def check(cond, what):
    if not cond:
        raise Failure(what)


def image(h, n, kind):
    """A deterministic H x N picture of 4-bit (r, g, b) levels."""
    if kind == "mix":
        return [[((x + 3 * y) % 16, (x * y + 5) % 16, (7 * x + 2 * y + 1) % 16)
                 for x in range(n)] for y in range(h)]
    if kind == "gradient":
        return [[(x * 16 // n, y * 16 // h, (x ^ y) & 15) for x in range(n)] for y in range(h)]
    if kind == "inverse":
        return [[tuple(15 - v for v in px) for px in row] for row in image(h, n, "mix")]
    if kind == "no-blue":
        return [[(px[0], px[1], 0) for px in row] for row in image(h, n, "mix")]
    raise ValueError(kind)


def generate(frames, pinmap, scan, n, fault=None, lat_idle_high=False):
    """Events [(cycle, pin, level)] showing FRAMES (images H x N) once each.
    FAULT is (kind, frame, row, plane[, column]) with kind "noclk" (that
    column's clk pulse left out), "setup" (its data changes at the clk
    rising edge's cycle), "ghost" (the next row's address set half way
    through the pulse), "nolat" (no latch pulse) or "badaddr" (address
    row + scan, on the spare line the map has beyond log2(scan))."""
    lines = tuple(s for s in ADDR[:scan.bit_length()] if s in pinmap)	# + 1 spare
    level = {s: 0 for s in DATA + lines + ("clk", "lat", "oe")}
    level["oe"] = 1				# dark: first oe record is a fall
    level["lat"] = 1 if lat_idle_high else 0
    events = []
    t = 7

    def put(sig, v):
        if level[sig] != v:
            events.append((t, pinmap[sig], v))
            level[sig] = v

    def address(row):
        for i, s in enumerate(lines):
            put(s, row >> i & 1)

    for f, img in enumerate(frames):
        for row in range(scan):
            for p in range(PLANES):
                here = fault and fault[1:4] == (f, row, p)
                kind = fault[0] if here else None
                for x in range(n):
                    col = here and len(fault) > 4 and fault[4] == x
                    if col and kind == "setup":
                        t += 1			# data at the clk edge's cycle
                    for ch in range(3):
                        put(DATA[ch], img[row][x][ch] >> p & 1)
                        put(DATA[ch + 3], img[row + scan][x][ch] >> p & 1)
                    if not (col and kind == "setup"):
                        t += 1
                    if not (col and kind == "noclk"):
                        put("clk", 1)
                    t += 1
                    put("clk", 0)
                    t += 1
                if kind != "nolat":
                    put("lat", 0 if lat_idle_high else 1)
                    t += 1
                    put("lat", 1 if lat_idle_high else 0)
                    t += 1
                address(row + scan if kind == "badaddr" else row)
                t += 1
                put("oe", 0)
                on = LSB << p
                if kind == "ghost":
                    t += on // 2
                    address((row + 1) % scan)
                    t += on - on // 2
                else:
                    t += on
                put("oe", 1)
                t += 3
    return events


def write_trace(path, events, origin, end):
    """The prusim binary trace format, written here on its own."""
    with open(path, "wb") as f:
        f.write(struct.pack("<8sIIQQQQ", b"PRUTRACE", 2, 16, origin, len(events), 0,
                            origin + end))
        for c, p, lv in events:
            f.write(struct.pack("<QHB5x", origin + c, p, lv))


def levels(dec, t0=None, t1=None):
    res = dec.integrate(t0, t1)
    lv, dev = hd.to_levels(res["on"], LSB)
    return lv, dev, res


def diff(a, b):
    return sum(1 for ra, rb in zip(a, b) for pa, pb in zip(ra, rb) if pa != pb)


def frame_windows(dec, scan, nframes):
    """(t0, t1) of each frame, from the oe pulses (4 per row)."""
    starts = [p[0] for p in dec.oe_pulses()][::scan * PLANES]
    check(len(starts) == nframes, "expected %d frames, pulses say %d" % (nframes, len(starts)))
    return [(s, starts[i + 1] if i + 1 < nframes else None) for i, s in enumerate(starts)]


def test_good(name, pinmap, w, h, scan, chain, kinds, tmp):
    n = w * chain
    imgs = [image(h, n, k) for k in kinds]
    events = generate(imgs, pinmap, scan, n)
    end = events[-1][0] + 20
    path = os.path.join(tmp, name + ".bin")
    origin = 1000000007
    write_trace(path, events, origin, end)
    o, dropped, read, rend = hd.read_trace(path, with_end=True)
    check((o, dropped, rend) == (origin, 0, end) and read == events,
          "%s: read_trace does not give back the events written" % name)
    for src, evs in (("events", events), ("trace", read)):
        dec = hd.Decoder(evs, pinmap, w, h, scan, chain, end=end if src == "trace" else None)
        check(dec.initial_levels["oe"] == 1, "%s: oe's first record is a fall, initial "
              "level should be 1" % name)
        wins = frame_windows(dec, scan, len(imgs))
        for (t0, t1), img, kind in zip(wins, imgs, kinds):
            got, dev, res = levels(dec, t0, t1)
            check(dev == 0, "%s/%s: on-times not whole LSBs (dev %g)" % (name, src, dev))
            check(got == img, "%s/%s: frame %s: %d pixels differ" % (name, src, kind,
                                                                     diff(got, img)))
            faults = {k: res[k] for k in hd.FAULTS + ("bad_address",) if res[k]}
            check(not faults, "%s/%s: unexpected faults %s" % (name, src, faults))
            hist = dec.planes_timing(t0, t1)
            check(hist == {LSB << p: scan for p in range(PLANES)},
                  "%s: plane timing %s" % (name, hist))
        if len(imgs) == 1:
            got, _, _ = levels(dec)		# whole trace, default window
            check(got == imgs[0], "%s/%s: whole-trace window differs" % (name, src))
        check(len(dec.latches()) == scan * PLANES * len(imgs), "%s: %d latches"
              % (name, len(dec.latches())))
        clk = dec.clock_stats()
        want = dict(edges=n * PLANES * scan * len(imgs), min_period=3, min_high=1, min_low=2)
        check(all(clk[k] == v for k, v in want.items()), "%s: clock stats %s" % (name, clk))
        check(clk["inst_hz"] == 200e6 / 3 and abs(clk["burst_hz"] - 200e6 / 3) < 1,
              "%s: clock rates %s %s" % (name, clk["inst_hz"], clk["burst_hz"]))
        check(len(clk["bursts"]) == scan * PLANES * len(imgs),
              "%s: %d bursts" % (name, len(clk["bursts"])))
        pulses = dec.oe_pulses()
        check([p[2] for p in pulses[:scan * PLANES]] ==
              [r for r in range(scan) for _ in range(PLANES)] and pulses[-1][1] is not None,
              "%s: pulse addresses/ends wrong" % name)
    print("PASS: decoder: %s: %dx%d scan %d chain %d, %d frame(s), %d events, exact from "
          "list and trace" % (name, w, h, scan, chain, len(imgs), len(events)))
    return path, imgs


def test_faults(name, pinmap, w, h, scan, chain):
    n = w * chain
    img = image(h, n, "mix")
    # a column whose data differs from the one before it, row 1 plane 2
    row, plane = 1, 2
    bits = lambda x: [img[row][x][c] >> plane & 1 for c in range(3)] + \
                     [img[row + scan][x][c] >> plane & 1 for c in range(3)]
    col = next(x for x in range(1, n) if bits(x) != bits(x - 1))
    # a row whose planes 0 and 1 differ somewhere, for the missing latch
    lrow = next(r for r in range(scan) if any(
        (img[r][x][c] ^ (img[r][x][c] >> 1)) & 1 for x in range(n) for c in range(3)))
    cases = [
        (("noclk", 0, row, plane, n - 1), "clk_edges", None),
        (("setup", 0, row, plane, col), "setup_violations", 1),
        (("ghost", 0, 1, 3), "ghosting", 1),
        (("nolat", 0, lrow, 1), "latches", None),
    ]
    if len([s for s in ADDR if s in pinmap]) > scan.bit_length() - 1:
        cases.append((("badaddr", 0, 2, 3), "bad_address", 1))
    for fault, field, want in cases:
        dec = hd.Decoder(generate([img], pinmap, scan, n, fault), pinmap, w, h, scan, chain)
        got, _, res = levels(dec)
        bad = diff(got, img)
        check(bad > 0, "%s %s: decoded image still matches" % (name, fault[0]))
        if want is not None:
            check(res[field] == want, "%s %s: %s = %d, want %d"
                  % (name, fault[0], field, res[field], want))
        elif fault[0] == "noclk":
            check(res[field] == n * PLANES * scan - 1, "%s noclk: clk edges %d"
                  % (name, res[field]))
            check(any(got[r][x] != img[r][x] for r in (row, row + scan) for x in range(n)),
                  "%s noclk: rows %d/%d not disturbed" % (name, row, row + scan))
        else:
            check(res[field] == scan * PLANES - 1, "%s nolat: latches %d" % (name, res[field]))
        print("PASS: decoder: %s fault %s: %d pixels differ, %s = %d"
              % (name, fault[0], bad, field, res[field]))


def test_initial(tmp):
    # lat idles high: its first record is a FALL, which must latch
    w, h, scan, chain = 16, 8, 4, 2
    img = image(h, w * chain, "mix")
    events = generate([img], BONE, scan, w * chain, lat_idle_high=True)
    first = next(lv for c, p, lv in events if p == BONE["lat"])
    check(first == 0, "lat idle-high sequence should start with a fall")
    dec = hd.Decoder(events, BONE, w, h, scan, chain)
    got, _, res = levels(dec)
    check(dec.initial_levels["lat"] == 1, "lat initial level not inferred as 1")
    check(got == img, "lat idle high: %d pixels differ" % diff(got, img))
    check(res["clk_while_lat"] == w * chain * PLANES * scan, "clk_while_lat %d"
          % res["clk_while_lat"])
    check(dec.oe_pulses()[0][0] == next(c for c, p, _ in events if p == BONE["oe"]),
          "first oe pulse should start at oe's first record")
    # no blue at all: b1 and b2 have no record, default level 0
    img = image(h, w * chain, "no-blue")
    dec = hd.Decoder(generate([img], BONE, scan, w * chain), BONE, w, h, scan, chain)
    got, _, res = levels(dec)
    spare = [(s, BONE[s]) for s in ADDR[scan.bit_length() - 1:]]	# c d e: never driven
    check(got == img and sorted(res["pins_without_records"]) == [("b1", 34), ("b2", 37)] + spare,
          "no-blue: %d pixels differ, without records %s" % (diff(got, img),
                                                              res["pins_without_records"]))
    # ... while initial={"b1": 1} lights every top pixel's blue on every pulse
    dec = hd.Decoder(generate([img], BONE, scan, w * chain), BONE, w, h, scan, chain,
                     initial={"b1": 1})
    got, _, _ = levels(dec)
    check(all(got[y][x][2] == 15 for y in range(scan) for x in range(w * chain)),
          "initial b1=1 should light top blue fully")
    print("PASS: decoder: initial levels: lat idling high latches on its first record, "
          "pins without records reported and set from initial")


def test_fm6126a():
    """Register words clocked in with lat high: an FM6126A-class panel
    takes them as register writes, a generic one as a data latch."""
    n, t, ev = 32, 10, []
    lv = {}

    def put(sig, v):
        nonlocal t
        if lv.get(sig) != v:
            ev.append((t, BONE[sig], v))
            lv[sig] = v

    for sig in DATA + ("clk", "lat", "a", "b", "c", "d"):
        put(sig, 0)
    put("oe", 1)
    for word, latch in ((0x7FFF, 11), (0x0040, 12), (0x1234, 3)):
        for i in range(n):
            t += 5
            put("lat", 1 if i >= n - latch else 0)
            for sig in DATA:
                put(sig, word >> (15 - i % 16) & 1)
            t += 5
            put("clk", 1)
            t += 5
            put("clk", 0)
        t += 5
        put("lat", 0)
    dec = hd.Decoder(ev, BONE, n, 8, 4, panel="fm6126a")
    regs = dec.registers()
    check([(c, w["r1"], w["b2"]) for _, c, w in regs] ==
          [(11, [0x7FFF] * 2, [0x7FFF] * 2), (12, [0x0040] * 2, [0x0040] * 2)],
          "fm6126a: registers %s" % [(c, [hex(x) for x in w["r1"]]) for _, c, w in regs])
    check(len(dec.latches()) == 3, "fm6126a: 3 lat falls, %d" % len(dec.latches()))
    check(hd.Decoder(ev, BONE, n, 8, 4).registers() == [],
          "generic panel: lat high for 11 clocks is no register write")
    print("PASS: decoder: fm6126a register writes 0x7fff (11 clocks), 0x0040 (12), a data latch (3)")


def test_direct_rows():
    """Direct row select: the row's line low, the others high."""
    ev, t = [], 0
    for sig in ("a", "b", "c", "d"):
        ev.append((t, BONE[sig], 1))
    for row, lines in ((0, "bcd"), (1, "acd"), (2, "abd"), (3, "abc"), (9, "abcd")):
        t += 10
        for k, sig in enumerate("abcd"):
            ev.append((t, BONE[sig], 1 if sig in lines else 0))
        t += 1
        ev.append((t, BONE["oe"], 0))
        t += 10
        ev.append((t, BONE["oe"], 1))
    dec = hd.Decoder(ev, BONE, 16, 8, 4, initial={"oe": 1}, row_address="direct")
    got = [a for _, _, a in dec.oe_pulses()]
    check(got == [0, 1, 2, 3, 4], "direct row select: rows %s" % got)
    check(dec.integrate()["bad_address"] == 1, "direct row select: no line low is a bad address")
    print("PASS: decoder: direct row select (one line low per row, none low: bad address)")


def run_tool(*args):
    flags = ["-W" + w for w in sys.warnoptions]
    return subprocess.run([sys.executable] + flags + [TOOL] + list(args),
                          capture_output=True, text=True, check=False)


def test_cli(path, imgs, tmp):
    geo = ["--map", "bone-r30", "--width", "16", "--height", "8", "--scan", "4",
           "--chain", "2"]
    out = os.path.join(tmp, "out.json")
    r = run_tool(path, *geo, "--pulses", "16", "--lsb", "10", "--json", out, "--print")
    check(r.returncode == 0, "tool failed: %s" % r.stderr)
    with open(out) as f:
        js = json.load(f)
    check([[tuple(px) for px in row] for row in js["levels"]] == imgs[0],
          "CLI --pulses 16: levels differ from frame 1")
    check(js["max_deviation"] == 0 and "refresh:" in r.stdout and "faults:" in r.stdout,
          "CLI summary incomplete:\n" + r.stdout)
    dec = hd.Decoder(hd.read_trace(path)[2], BONE, 16, 8, 4, 2)
    t0 = dec.oe_pulses()[16][0]
    r = run_tool(path, *geo, "--window", "%d:" % t0, "--lsb", "10", "--json", out)
    with open(out) as f:
        js = json.load(f)
    check(r.returncode == 0 and [[tuple(px) for px in row] for row in js["levels"]] == imgs[1],
          "CLI --window T0: levels differ from frame 2")
    r = run_tool(path, "--map", '{"r1": 32, "g1": 33, "b1": 34, "r2": 35, "g2": 36, '
                 '"b2": 37, "clk": 38, "lat": 39, "oe": 40, "a": "pru1.9", "b": 42}',
                 "--width", "16", "--height", "8", "--scan", "4", "--chain", "2",
                 "--pulses", "16", "--lsb", "10", "--json", out)
    with open(out) as f:
        js = json.load(f)
    check(r.returncode == 0 and [[tuple(px) for px in row] for row in js["levels"]] == imgs[0],
          "CLI JSON map: levels differ")
    print("PASS: decoder: CLI: --pulses, --window, JSON map give the frames exactly")
    try:
        import PIL  # noqa: F401
        have_pil = True
    except ImportError:
        have_pil = False
    png = os.path.join(tmp, "out.png")
    r = run_tool(path, *geo, "--pulses", "16", "--lsb", "10", "--png", png, "--scale", "4",
                 "--max-level", "15")
    if have_pil:
        from PIL import Image
        check(r.returncode == 0, "--png failed: " + r.stderr)
        with Image.open(png) as pic:
            check(pic.size == (32 * 5 + 1, 8 * 5 + 1), "png size %s" % (pic.size,))
            want = tuple(v * 255 // 15 for v in imgs[0][2][3])
            check(pic.getpixel((3 * 5 + 2, 2 * 5 + 2)) == want, "png pixel colour")
        print("PASS: decoder: CLI --png: size and a pixel's colour")
    else:
        check(r.returncode == 2 and "python3-pil" in r.stderr, "--png without PIL: " + r.stderr)
        print("PASS: decoder: CLI --png without PIL: clear error "
              "(run with /usr/bin/python3 to draw)")
    junk = os.path.join(tmp, "junk.bin")
    with open(junk, "wb") as f:
        f.write(b"not a trace at all, really")
    for args, why in (([os.path.join(tmp, "missing.bin")] + geo, "missing file"),
                      ([junk] + geo, "not a trace"),
                      ([path, "--map", "nosuchmap"], "unknown map"),
                      ([path, "--map", "bone-r30", "--height", "16", "--scan", "4"], "H != 2S"),
                      ([path, "--map", "r1=1"], "incomplete map")):
        r = run_tool(*args)
        check(r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
              and "Traceback" not in r.stderr, "%s: rc %d, stderr %r" % (why, r.returncode,
                                                                          r.stderr))
    print("PASS: decoder: CLI errors: missing file, not a trace, unknown map, H != 2*S, "
          "incomplete map -> one line, exit 2")


def main():
    try:
        with tempfile.TemporaryDirectory() as tmp:
            path, imgs = test_good("bone-r30-chain", BONE, 16, 8, 4, 2, ["mix", "inverse"], tmp)
            test_good("bone-r30-64x32", BONE, 64, 32, 16, 1, ["gradient"], tmp)
            test_good("pocketscroller-64x32", POCKET, 64, 32, 16, 1, ["gradient", "mix"], tmp)
            check(hd.MAPS["bone-r30"] == BONE and hd.MAPS["pocketscroller"] == POCKET,
                  "built-in maps differ from the spec")
            test_faults("bone-r30-chain", BONE, 16, 8, 4, 2)
            test_faults("pocketscroller-64x32", POCKET, 64, 32, 16, 1)
            test_initial(tmp)
            test_fm6126a()
            test_direct_rows()
            test_cli(path, imgs, tmp)
    except Failure as e:
        print("FAIL: decoder: %s" % e)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
