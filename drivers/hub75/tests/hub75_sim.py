#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""The hub75 firmware in the prusim host tool, without a driver.

Each case writes a control block and two frame buffers (hub75_proto.h's
layout, built here from an image of levels), runs the firmware for a bit
more than two refreshes, and decodes the pins with tools/hub75-decode.py,
which models the panel (shift registers, latch, rows lit while OE is low)
and knows nothing of the firmware.  The second refresh must show every
pixel's levels exactly, each plane lit exactly lsb << plane cycles per
row, no data, latch or address change while a row is lit, no data change
on a clock edge; the refresh length in the trace must be the one the
firmware reports (@refresh_cycles).  Also: the buffer @show names is the
one shown, and START refuses bad parameters.

    hub75_sim.py PRUSIM FWDIR WORKDIR [--bench]

--bench prints the figures of make bench (pixel clock, refresh rates) as
"bench:" lines.  Prints PASS:/FAIL: lines; exits 1 on any failure.
"""
import importlib.util
import os
import struct
import subprocess
import sys

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "../../.."))
spec = importlib.util.spec_from_file_location("hub75_decode", TOP + "/tools/hub75-decode.py")
hd = importlib.util.module_from_spec(spec)
spec.loader.exec_module(hd)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hub75_model  # noqa: E402
from hub75_model import plane_order  # noqa: E402

MAGIC = 0x35374248
VERSION = 2
CTRL_SIZE = 256
MAX_PLANES = 12
START, STOP = 1, 2
DDR = 0x80000000
GPIO1 = 0x4804c000
FAILS = []


def check(name, cond, detail=""):
    print("%s: %s%s" % ("PASS" if cond else "FAIL", name, (" (%s)" % detail) if detail else ""))
    if not cond:
        FAILS.append(name)
    return cond


# The two pin maps of the shipped overlays (the decoder has its own copies)
BONE = dict(core=1, mode=0, data=[0, 1, 2, 3, 4, 5], clk=6, lat=7, oe=8, addr=[9, 10, 11, 12, 13])
POCKET = dict(core=0, mode=1, data=[20, 28, 25, 26, 27, 18], clk=1, lat=0, oe=7, addr=[2, 3, 4, 5])


def image(width, height, planes, seed):
    """Levels (r, g, b) per pixel: gradients and a checker, all levels used."""
    m = (1 << planes) - 1
    img = []
    for y in range(height):
        row = []
        for x in range(width):
            r = (x * 7 + y * 3 + seed) % (m + 1)
            g = (x * y + seed * 5) % (m + 1)
            b = m if (x // 4 + y // 4 + seed) % 2 else (x + 2 * y) % (m + 1)
            row.append((r, g, b))
        img.append(row)
    return img


def frame_buffer(pm, img, rows, planes):
    shift = min(pm["data"]) if pm["mode"] else 0
    return hub75_model.frame_buffer([b - shift for b in pm["data"]], 2 if pm["mode"] else 1,
                                    img, rows, planes)


def ctrl(pm, rows, planes, row_bytes, oe, show, clk_delay, bufs, addr_lines, init=(),
         direct=False):
    addr = pm["addr"][:addr_lines]
    if direct:		# a line per row, low for its row
        row_addr = [sum(1 << addr[i] for i in range(addr_lines) if i != r) for r in range(32)]
    else:
        row_addr = [sum(1 << addr[i] for i in range(addr_lines) if r >> i & 1) for r in range(32)]
    gpio_mask = sum(1 << b for b in pm["data"]) if pm["mode"] else 0
    hdr = struct.pack("<IHHII", MAGIC, VERSION, CTRL_SIZE, START | 1 << 16, 0)
    body = struct.pack("<2I3IHH8B", bufs[0], bufs[1], GPIO1 if pm["mode"] else 0, gpio_mask,
                       sum(1 << a for a in addr), row_bytes, rows, pm["mode"], planes, pm["clk"],
                       pm["lat"], pm["oe"], min(pm["data"]) if pm["mode"] else 0, clk_delay, 0)
    oe = list(oe) + [0] * (MAX_PLANES - len(oe))
    init = [w | n << 16 for w, n in init] + [0] * (4 - len(init))
    return hdr + body + struct.pack("<32I", *row_addr) + struct.pack("<12I", *oe) + \
        struct.pack("<4I", show, 0, 0, 0) + struct.pack("<4I", *init)


def run(prusim, fw, work, pm, width, height, scan, planes, lsb, clk_delay=3, show=0,
        refreshes=2.3, cycles=None, raw_ctrl=None, panel=None):
    """Run the firmware; return (ctrl fields, decoder, images) or None.
    PANEL: dict(mux=NAME, panel_w=W, init=[(word, latch clocks)],
    direct=bool): WIDTH x HEIGHT is then the picture as seen, the panels
    driven as their wiring NAME says."""
    panel = dict(dict(mux="direct", panel_w=width, init=(), direct=False), **(panel or {}))
    stretch = 1 if panel["mux"] == "direct" else 2
    rows = scan
    bpe = 2 if pm["mode"] else 1
    row_bytes = width * stretch * bpe
    imgs = [image(width, height, planes, 1), image(width, height, planes, 2)]
    driven = [hub75_model.driven(img, panel["mux"], panel["panel_w"]) for img in imgs]
    fbs = [frame_buffer(pm, driven[i], rows, planes) for i in range(2)]
    size = len(fbs[0])
    order = plane_order(planes)
    oe = [lsb << p for p in order]
    if cycles is None:
        pix = 16 if pm["mode"] else 4 + 2 * clk_delay
        est = rows * (planes * (row_bytes // 32 * 53 + width * stretch * pix + 40) + sum(oe))
        # the register words: about 70 cycles a clock from C
        cycles = int(est * refreshes) + 2000 + len(panel["init"]) * width * stretch * 120
    blob = raw_ctrl or ctrl(pm, rows, planes, row_bytes, oe, show, clk_delay,
                            [DDR, DDR + size], scan if panel["direct"] else scan.bit_length() - 1,
                            panel["init"], panel["direct"])
    core = "pru%d" % pm["core"]
    with open(work + "/ctrl.bin", "wb") as f:
        f.write(blob)
    with open(work + "/ddr.bin", "wb") as f:
        f.write(fbs[0] + fbs[1])
    cmd = [prusim, "--" + core, "%s/hub75-%s.elf" % (fw, core), "--ddr", "0x%x" % max(2 * size, 0x10000),
           "--load", "%s:0x8:%s/ctrl.bin" % (core, work), "--load", "0x%x:%s/ddr.bin" % (DDR, work),
           "--max-cycles", str(cycles), "--dump", "%s:0x8:%d:%s/out.bin" % (core, CTRL_SIZE, work),
           "--trace-out", work + "/trace.bin"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode:
        print(r.stderr)
        return None
    with open(work + "/out.bin", "rb") as f:
        out = f.read()
    status, = struct.unpack_from("<I", out, 12)
    show_, shown, nref, rcyc = struct.unpack_from("<4I", out, 224)
    _, _, events = hd.read_trace(work + "/trace.bin")
    pins = {"pocketscroller": hd.MAPS["pocketscroller"], "bone-r30": hd.MAPS["bone-r30"]}
    pinmap = dict(pins["pocketscroller" if pm is POCKET else "bone-r30"])
    if scan < 32:
        pinmap.pop("e", None)
    dec = hd.Decoder(events, pinmap, width * stretch, 2 * scan, scan, initial={},
                     row_address="direct" if panel["direct"] else "binary",
                     panel="fm6126a" if panel["init"] else "generic")
    return dict(status=status, shown=shown, refreshes=nref, refresh_cycles=rcyc), dec, imgs, oe


def decode_refresh(dec, rows, planes, k):
    """Pulses and integration of refresh k (from 0)."""
    # OE is low (0) from the core's start to the first refresh's: not a row lit
    first = min(dec.latches() or [0])
    pulses = [p for p in dec.oe_pulses() if p[0] > first]
    n = rows * planes
    if len(pulses) < (k + 1) * n + 1:
        return None
    t0, t1 = pulses[k * n][0], pulses[(k + 1) * n][0]
    return t0, t1, pulses[k * n:(k + 1) * n], dec.integrate(t0, t1)


def case(prusim, fw, work, name, pm, width, height, scan, planes, lsb, clk_delay=3, show=0,
         panel=None):
    res = run(prusim, fw, work, pm, width, height, scan, planes, lsb, clk_delay, show,
              panel=panel)
    if not check("%s: prusim ran" % name, res is not None):
        return None
    c, dec, imgs, oe = res
    check("%s: START answered OK" % name, c["status"] == (1 << 16 | 0x8000), "0x%x" % c["status"])
    check("%s: buffer %d shown" % (name, show), c["shown"] == show, str(c["shown"]))
    got = decode_refresh(dec, scan, planes, 1)
    if not check("%s: two refreshes in the trace" % name, got is not None,
                 "%d pulses" % len(dec.oe_pulses())):
        return None
    t0, t1, pulses, integ = got
    levels, dev = hd.to_levels(integ["on"], lsb)
    if panel:
        levels = hub75_model.seen(levels, panel.get("mux", "direct"),
                                  panel.get("panel_w", width), width, height)
    want = imgs[show]
    bad = [(x, y) for y in range(height) for x in range(width)
           if tuple(levels[y][x]) != tuple(want[y][x])]
    check("%s: every pixel's levels exact" % name, not bad and dev == 0,
          "%d pixels differ, first %s: got %s want %s; deviation %s" % (
              len(bad), bad[:1], bad and levels[bad[0][1]][bad[0][0]],
              bad and want[bad[0][1]][bad[0][0]], dev) if bad or dev else "%d pixels" % (width * height))
    hist = {}
    for s, e, a in pulses:
        hist[e - s] = hist.get(e - s, 0) + 1
    check("%s: each plane lit exactly lsb << plane cycles, per row" % name,
          hist == {t: scan for t in oe}, str(sorted(hist.items())))
    rows_seen = [a for s, e, a in pulses[:scan]]
    check("%s: rows in address order per plane" % name, rows_seen == list(range(scan)), str(rows_seen))
    faults = {k: integ[k] for k in ("setup_violations", "clk_while_lat", "ghosting", "clk_while_lit",
                                    "oe_coincident", "bad_address")}
    check("%s: no change while lit, no data change on a clock edge" % name,
          not any(faults.values()), str(faults))
    if panel and panel.get("init"):
        regs = dec.registers()
        # OE is low from the core's start until the firmware first sets it
        lit = [p for p in dec.oe_pulses() if p[0] > 0]
        want_regs = [(n, {line: [w] * (width * 2 // 16 if panel.get("mux", "direct") != "direct"
                                       else width // 16) for line in hd.DATA})
                     for w, n in panel["init"]]
        check("%s: the register words on every line of every chip, before a row is lit" % name,
              [(n, w) for _, n, w in regs] == want_regs and lit and regs[-1][0] < lit[0][0],
              "%s; first lit at %s" % ([(n, {k: ["%04x" % x for x in set(v)] for k, v in w.items()})
                                        for _, n, w in regs], lit[:1]))
    check("%s: refresh length in the trace = @refresh_cycles" % name,
          c["refreshes"] >= 2 and t1 - t0 == c["refresh_cycles"],
          "trace %d, firmware %d, %d refreshes" % (t1 - t0, c["refresh_cycles"], c["refreshes"]))
    clk = dec.clock_stats(t0, t1)
    return dict(refresh=t1 - t0, clk=clk, lit=sum(e - s for s, e, a in pulses), lsb=lsb)


def bad_start(prusim, fw, work):
    pm = BONE
    good = dict(rows=16, planes=8, row_bytes=64, oe=[26] * 8, show=0, clk_delay=3,
                bufs=[DDR, DDR + 8192], addr_lines=4)
    for what, change in (("row bytes not a multiple of 32", dict(row_bytes=40)),
                         ("13 planes", dict(planes=13)),
                         ("a register word latched with 3 clocks (a data latch)",
                          dict(init=[(0x7FFF, 11), (0x0040, 3)])),
                         ("a register word latched with 17 clocks", dict(init=[(0x7FFF, 17)])),
                         ("clock delay 0", dict(clk_delay=0))):
        args = dict(good, **change)
        blob = ctrl(pm, **args)
        res = run(prusim, fw, work, pm, 64, 32, 16, 8, 26, cycles=20000, raw_ctrl=blob)
        check("START refuses %s" % what, res is not None and res[0]["status"] == (1 << 16 | 0x8000 | 1),
              res and "0x%x" % res[0]["status"])
    # clock above bit 7 with data on R30
    bone = dict(BONE, clk=9, addr=[10, 11, 12, 13, 14])
    blob = ctrl(bone, **good)
    res = run(prusim, fw, work, bone, 64, 32, 16, 8, 26, cycles=20000, raw_ctrl=blob)
    check("START refuses an R30 clock above bit 7", res is not None and res[0]["status"] == (1 << 16 | 0x8000 | 1),
          res and "0x%x" % res[0]["status"])


OCTO_DATA, OCTO_CTRL = hub75_model.OCTO_DATA, hub75_model.OCTO_CTRL
GPIO_BASE = [0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000]


def octo_slots(outputs):
    return hub75_model.bank_slots(OCTO_DATA[:outputs], OCTO_CTRL["bank"])


def banks_frame(outputs, imgs, rows, planes, slots):
    return hub75_model.banks_frame(OCTO_DATA[:outputs], slots, imgs, rows, planes)


def banks_ctrl(outputs, rows, planes, row_bytes, oe, bufs, slots, init=()):
    c = OCTO_CTRL
    addr_lines = rows.bit_length() - 1
    addr = c["addr"][:addr_lines]
    row_addr = [sum(1 << addr[i] for i in range(addr_lines) if r >> i & 1) for r in range(32)]
    masks = [0, 0, 0, 0]
    for o in range(outputs):
        for bank, bit in OCTO_DATA[o]:
            masks[slots.index(bank)] |= 1 << bit
    masks[3] |= 1 << c["clk"]
    used = sum(1 << k for k in range(4) if slots[k] is not None)
    hdr = struct.pack("<IHHII", MAGIC, VERSION, CTRL_SIZE, START | 1 << 16, 0)
    body = struct.pack("<2I3IHH8B", bufs[0], bufs[1], GPIO_BASE[c["bank"]], 0,
                       sum(1 << a for a in addr), row_bytes, rows, 2, planes, c["clk"],
                       c["lat"], c["oe"], 0, 0, 0)
    oe = list(oe) + [0] * (MAX_PLANES - len(oe))
    init = [w | n << 16 for w, n in init] + [0] * (4 - len(init))
    return hdr + body + struct.pack("<32I", *row_addr) + struct.pack("<12I", *oe) + \
        struct.pack("<4I", 0, 0, 0, 0) + struct.pack("<4I", *init) + \
        struct.pack("<4I", *[GPIO_BASE[b] if b is not None else 0 for b in slots]) + \
        struct.pack("<4I", *masks) + struct.pack("<B3x", used)


def octo_pinmap(o):
    pm = {sig: hd.gpio(b, bit) for sig, (b, bit) in zip(hd.DATA, OCTO_DATA[o])}
    c = OCTO_CTRL
    pm.update(clk=hd.gpio(c["bank"], c["clk"]), lat=hd.gpio(c["bank"], c["lat"]),
              oe=hd.gpio(c["bank"], c["oe"]))
    pm.update({s: hd.gpio(c["bank"], b) for s, b in zip(hd.ADDR, c["addr"])})
    return pm


def banks_case(prusim, fw, work, name, outputs, width, scan, planes, lsb, init=(),
               decode=None):
    """The firmware on the Octoscroller's pins: OUTPUTS chains WIDTH wide,
    every output's picture (or those of DECODE, a list) decoded from its
    own pins."""
    rows, height = scan, 2 * scan
    slots = octo_slots(outputs)
    imgs = [image(width, height, planes, 3 + o) for o in range(outputs)]
    fb = banks_frame(outputs, imgs, rows, planes, slots)
    row_bytes = width * 16
    order = plane_order(planes)
    oe = [lsb << p for p in order]
    words = 2 * sum(1 for b in slots if b is not None) + 1
    est = rows * (planes * (width * words * 8 + width // 4 * 60 + 120) + sum(oe))
    cycles = int(est * 2.3) + 5000 + len(init) * width * 200 * words
    with open(work + "/ctrl.bin", "wb") as f:
        f.write(banks_ctrl(outputs, rows, planes, row_bytes, oe, [DDR, DDR + len(fb)], slots,
                           init))
    with open(work + "/ddr.bin", "wb") as f:
        f.write(fb + fb)
    r = subprocess.run([prusim, "--pru0", "%s/hub75-pru0.elf" % fw, "--ddr",
                        "0x%x" % max(2 * len(fb), 0x10000),
                        "--load", "pru0:0x8:%s/ctrl.bin" % work,
                        "--load", "0x%x:%s/ddr.bin" % (DDR, work),
                        "--max-cycles", str(cycles),
                        "--dump", "pru0:0x8:%d:%s/out.bin" % (CTRL_SIZE, work),
                        "--trace-out", work + "/trace.bin"], capture_output=True, text=True)
    if not check("%s: prusim ran" % name, r.returncode == 0, r.stderr[-300:]):
        return None
    with open(work + "/out.bin", "rb") as f:
        out = f.read()
    status, = struct.unpack_from("<I", out, 12)
    nref, rcyc = struct.unpack_from("<2I", out, 232)
    check("%s: START answered OK" % name, status == (1 << 16 | 0x8000), "0x%x" % status)
    _, _, events = hd.read_trace(work + "/trace.bin")
    result = None
    for o in range(outputs) if decode is None else decode:
        dec = hd.Decoder(events, octo_pinmap(o), width, height, scan, initial={"oe": 1},
                         panel="fm6126a" if init else "generic")
        got = decode_refresh(dec, rows, planes, 1)
        if not check("%s, output %d: two refreshes in the trace" % (name, o + 1),
                     got is not None, "%d pulses" % len(dec.oe_pulses())):
            return None
        t0, t1, pulses, integ = got
        levels, dev = hd.to_levels(integ["on"], lsb)
        bad = [(x, y) for y in range(height) for x in range(width)
               if tuple(levels[y][x]) != tuple(imgs[o][y][x])]
        check("%s, output %d: every pixel's levels exact" % (name, o + 1), not bad and dev == 0,
              "%d differ, first %s: got %s want %s" % (
                  len(bad), bad[:1], bad and levels[bad[0][1]][bad[0][0]],
                  bad and imgs[o][bad[0][1]][bad[0][0]]) if bad else "%d pixels" % (width * height))
        faults = {k: integ[k] for k in ("setup_violations", "clk_while_lat", "ghosting",
                                        "clk_while_lit", "oe_coincident", "bad_address")}
        check("%s, output %d: no change while lit, no data change on a clock edge"
              % (name, o + 1), not any(faults.values()), str(faults))
        if init:
            regs = dec.registers()
            want = [(n, {line: [w] * (width // 16) for line in hd.DATA}) for w, n in init]
            lit = [p for p in dec.oe_pulses() if p[0] > 0]
            check("%s, output %d: the register words on every line, before a row is lit"
                  % (name, o + 1), [(n, w) for _, n, w in regs] == want and lit and
                  regs[-1][0] < lit[0][0], [(n, sorted(set(w["r1"]))) for _, n, w in regs])
        if o == 0:
            hist = {}
            for s_, e, a in pulses:
                hist[e - s_] = hist.get(e - s_, 0) + 1
            check("%s: each plane lit exactly lsb << plane cycles, per row" % name,
                  hist == {t: scan for t in oe}, str(sorted(hist.items())))
            check("%s: refresh length in the trace = @refresh_cycles" % name,
                  nref >= 2 and t1 - t0 == rcyc, "trace %d, firmware %d" % (t1 - t0, rcyc))
            result = dict(refresh=t1 - t0, clk=dec.clock_stats(t0, t1),
                          lit=sum(e - s_ for s_, e, a in pulses), lsb=lsb, words=words)
    return result


# Falcon Player's published figure for its BeagleBone matrix driver: 24
# 64x32 panels at 12 bits refresh at 40-101 Hz (../shared/reference/
# pixels-and-matrix.md; not measured here)
FPP_WALL_HZ = (40, 101)


def wall(prusim, fw, work, bench):
    """The Octoscroller wall, 8 outputs of 3 chained 64x32 panels (24
    panels) at 12 bit planes and the shortest lit time OE on a GPIO bank
    allows (8 cycles, 40 ns), every output decoded; with BENCH its figure
    against Falcon Player's and the physical limit: every clock's
    (2 * 4 + 1) GPIO writes at the L4 path's 8 cycles each (prusim's
    model), plus every row's lit time."""
    planes, lsb, rows, clocks = 12, 8, 16, 192
    res = banks_case(prusim, fw, work, "wall: Octoscroller 8 outputs x 3 64x32, 12 planes", 8,
                     clocks, rows, planes, lsb)
    if not res or not bench:
        return
    shift = planes * rows * clocks * res["words"] * 8
    lit = rows * lsb * ((1 << planes) - 1)
    limit = 200e6 / (shift + lit)
    hz = 200e6 / res["refresh"]
    print("BENCH: hub75 Octoscroller wall, 24 64x32 panels (8 outputs x 3), 12 bit planes, "
          "LSB 40 ns: refresh %d PRU cycles = %.1f Hz; %.2fx Falcon Player's 40 Hz, %.2fx its "
          "101 Hz (its published range); %.0f %% of the physical limit %.1f Hz (%d GPIO writes "
          "a clock at 8 cycles: %d cycles shifting + %d lit); pixel clock %.2f MHz peak, "
          "%.2f MHz mean (exact, prusim)"
          % (res["refresh"], hz, hz / FPP_WALL_HZ[0], hz / FPP_WALL_HZ[1], 100 * limit and
             100 * hz / limit, limit, res["words"], shift, lit, res["clk"]["inst_hz"] / 1e6,
             res["clk"]["burst_hz"] / 1e6))


def main():
    prusim, fw, work = sys.argv[1:4]
    bench = "--bench" in sys.argv
    os.makedirs(work, exist_ok=True)
    r = {}
    r["bone"] = case(prusim, fw, work, "bone-r30 64x32 8 planes", BONE, 64, 32, 16, 8, 26)
    r["bone-b1"] = case(prusim, fw, work, "bone-r30 64x32, buffer 1", BONE, 64, 32, 16, 8, 26, show=1)
    r["chain"] = case(prusim, fw, work, "bone-r30 chain of 2 (128x32)", BONE, 128, 32, 16, 8, 26)
    r["64x64"] = case(prusim, fw, work, "bone-r30 64x64 1/32 scan (E line), 6 planes", BONE, 64, 64, 32, 6, 26)
    r["32x16"] = case(prusim, fw, work, "bone-r30 32x16 1/8 scan, 25 MHz, lsb 13", BONE, 32, 16, 8, 8, 13,
                      clk_delay=2)
    r["33mhz"] = case(prusim, fw, work, "bone-r30 64x32 8 planes, 33 MHz (clock delay 1)", BONE,
                      64, 32, 16, 8, 26, clk_delay=1)
    r["pocket"] = case(prusim, fw, work, "pocketscroller 64x32 8 planes", POCKET, 64, 32, 16, 8, 26)
    r["pocket-dim"] = case(prusim, fw, work, "pocketscroller 64x32, lsb 3 (dim)", POCKET, 64, 32, 16, 8, 3)
    r["fm6126a"] = case(prusim, fw, work, "FM6126A chain of 2 (128x32), register words at START",
                        BONE, 128, 32, 16, 8, 26,
                        panel=dict(init=[(0x7FFF, 11), (0x0040, 12)]))
    r["fm6127"] = case(prusim, fw, work, "FM6127 64x32, data on GPIO bank 1, three register words",
                       POCKET, 64, 32, 16, 8, 26,
                       panel=dict(init=[(0xFFCE, 11), (0xE062, 12), (0x5F00, 10)]))
    r["outdoor4"] = case(prusim, fw, work, "outdoor 32x16 1/4 scan, zstripe, direct row select",
                         BONE, 32, 16, 4, 8, 26, panel=dict(mux="zstripe", panel_w=32, direct=True))
    r["outdoor8"] = case(prusim, fw, work, "outdoor 64x32 1/8 scan, stripe, chain of 2", BONE,
                         128, 32, 8, 8, 26, panel=dict(mux="stripe", panel_w=64))
    r["12bit"] = case(prusim, fw, work, "64x32 12 planes, LSB 1 cycle (5 ns)", BONE, 64, 32, 16,
                      12, 1)
    r["octo8"] = banks_case(prusim, fw, work, "Octoscroller 8 outputs x 64x32, 8 planes", 8, 64,
                            16, 8, 26)
    r["octo1-fm"] = banks_case(prusim, fw, work, "Octoscroller output 1, FM6126A chain of 2", 1,
                               128, 16, 6, 16, init=[(0x7FFF, 11), (0x0040, 12)])
    bad_start(prusim, fw, work)
    for k, period in (("bone", 10), ("33mhz", 6), ("pocket", 16)):
        if r[k]:
            clk = r[k]["clk"]
            check("%s: pixel clock within a row (%d cycles)" % (k, period),
                  clk["min_period"] == period, str(clk["min_period"]))
    wall(prusim, fw, work, bench)
    if bench:
        # the yardstick: eight chained 64x32 panels at 8 bit planes
        r["chain8"] = case(prusim, fw, work, "bone-r30 chain of 8 (512x32)", BONE, 512, 32, 16, 8,
                           26)
        what = {"bone": "all-R30 map, one 64x32 panel, 8 planes",
                "chain": "all-R30 map, 2 chained 64x32 panels, 8 planes",
                "chain8": "all-R30 map, 8 chained 64x32 panels (512x32), 8 planes",
                "64x64": "all-R30 map, 64x64 1/32 scan, 6 planes",
                "32x16": "all-R30 map, 32x16 1/8 scan, 8 planes, 25 MHz clock",
                "33mhz": "all-R30 map, one 64x32 panel, 8 planes, the fastest clock (delay 1)",
                "pocket": "PocketScroller map (data on GPIO bank 1), 64x32, 8 planes",
                "outdoor4": "all-R30 map, outdoor 32x16 1/4 scan (zstripe, direct rows), 8 planes",
                "outdoor8": "all-R30 map, 2 outdoor 64x32 1/8 scan (stripe), 8 planes",
                "12bit": "all-R30 map, one 64x32 panel, 12 planes"}
        for k, v in r.items():
            if v and k in what:
                c = v["clk"]
                print("BENCH: hub75 %s: refresh %d PRU cycles = %.1f Hz; pixel clock %.2f MHz "
                      "(%d cycles a pixel); rows lit %.1f %% of the time (LSB %d ns; exact, "
                      "prusim)" % (what[k], v["refresh"], 200e6 / v["refresh"],
                                   c["inst_hz"] / 1e6, c["min_period"],
                                   100.0 * v["lit"] / v["refresh"], 5 * v["lsb"]))
    if FAILS:
        print("%d failed" % len(FAILS))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
