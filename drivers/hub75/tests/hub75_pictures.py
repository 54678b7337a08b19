# SPDX-License-Identifier: GPL-2.0-only
"""Host side of the hub75 VM test and of make demo's matrix: one picture
the guest recorded (hub75_vm.Recorder: NAME.trace and its entry in
hub75.json) decoded by tools/hub75-decode.py, a model of the panel that
knows nothing of the firmware, and compared exactly with what the driver
should show (hub75_model.py)."""
import importlib.util
import os

from hub75_model import OCTO_CTRL, OCTO_DATA, arrange, expected, plane_order, seen

TOP = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../.."))
spec = importlib.util.spec_from_file_location("hub75_decode", TOP + "/tools/hub75-decode.py")
hd = importlib.util.module_from_spec(spec)
spec.loader.exec_module(hd)


def stretch(m):
    """How much wider and less high the panels are driven than seen."""
    return 1 if m.get("mux", "direct") == "direct" else 2


def octo_pinmap(o, scan):
    """The pins of output O of the Octoscroller (hub75_model.OCTO_*)."""
    c = OCTO_CTRL
    pm = {sig: hd.gpio(b, bit) for sig, (b, bit) in zip(hd.DATA, OCTO_DATA[o])}
    pm.update(clk=hd.gpio(c["bank"], c["clk"]), lat=hd.gpio(c["bank"], c["lat"]),
              oe=hd.gpio(c["bank"], c["oe"]))
    lines = scan.bit_length() - 1
    pm.update({s: hd.gpio(c["bank"], b) for s, b in zip(hd.ADDR, c["addr"][:lines])})
    return pm


def decoder(art, m, output=0):
    """(dropped records, the decoder of the panels as driven on OUTPUT)"""
    _, dropped, events, end = hd.read_trace(os.path.join(art, m["name"] + ".trace"),
                                            with_end=True)
    if m["map"] == "octoscroller":
        pinmap = octo_pinmap(output, m["scan"])
    else:
        pinmap = dict(hd.MAPS[m["map"]])
    if m["scan"] < 32:
        pinmap.pop("e", None)
    return dropped, hd.Decoder(events, pinmap, m["width"] * stretch(m), 2 * m["scan"], m["scan"],
                               initial={"oe": 1}, end=end,
                               panel="fm6126a" if m.get("panel") == "fm6126a" else "generic")


# the register words of each panel type, in order: (latch clocks, word)
PANEL_WORDS = {"fm6126a": [(11, 0x7FFF), (12, 0x0040)]}


def check_start(art, m, check):
    """A trace from the display's enable on ("clear first"): the panel's
    register words on every data line of every chip, before any row is
    lit, and then rows lit."""
    name = m["name"]
    _, dec = decoder(art, m)
    regs = dec.registers()
    chips = m["width"] * stretch(m) // 16
    want = [(n, {line: [w] * chips for line in hd.DATA}) for n, w in PANEL_WORDS[m["panel"]]]
    got = [(n, w) for _, n, w in regs]
    check("%s: the %s register words on every data line of all %d chips" % (
        name, m["panel"], chips), got == want,
        [(n, {k: sorted("%04x" % x for x in set(v)) for k, v in w.items()}) for n, w in got])
    pulses = dec.oe_pulses()
    check("%s: no row lit before the last register word, rows lit after it" % name,
          regs and pulses and pulses[0][0] > regs[-1][0],
          "words at %s, first lit %s" % ([c for c, _, _ in regs], pulses[:1]))


def check_picture(art, m, check):
    """Decode picture M (an entry of hub75.json) from ART/M["name"].trace
    and check it with CHECK(name, condition, detail); the decoded levels of
    its first whole refresh, or None.  With M["outputs"], each output's
    band of the chains from its own pins, the levels one under the other
    (M["serpentine"], M["rotation"]: where the chains' pixels are on the
    display, M["width"] x M["height"])."""
    outputs = m.get("outputs", 1)
    if outputs == 1:
        return check_output(art, m, check, 0)
    turned = m.get("rotation", 0) in (90, 270)
    width, height = (m["height"], m["width"]) if turned else (m["width"], m["height"])
    band = height // outputs
    levels = []
    for o in range(outputs):
        got = check_output(art, dict(m, width=width, height=band, band=o,
                                     display=(m["width"], m["height"])), check, o)
        if got is None:
            return None
        levels += got
    return levels


def check_output(art, m, check, output):
    """check_picture() of one output (M["band"]: its band of the picture)."""
    name = m["name"] + (" output %d" % (output + 1) if "band" in m else "")
    dropped, dec = decoder(art, m, output)
    check("%s: the trace is whole (no records dropped)" % name, not dropped, dropped)
    pulses = dec.oe_pulses()
    if m["image"] is None:
        check("%s: no row lit at brightness 0" % name,
              not pulses and dec.integrate()["lit_cycles"] == 0, "%d pulses" % len(pulses))
        return None
    rows, planes, lsb = m["scan"], m["planes"], m["lsb"]
    order = plane_order(planes)
    n = rows * planes
    # a refresh starts with row 0 of the longest plane; not the trace's
    # first pulse: the trace may have begun while that row was clocked in
    # (seen on 6.12: 35 pixels of row 0 wrong, the next refresh exact).
    # Rows are clocked in while OE is high, after the pulse before.
    first = [i for i, (s, e, a) in enumerate(pulses)
             if i > 0 and a == 0 and e is not None and e - s == lsb << order[0]]
    if not check("%s: a whole refresh in the trace" % name,
                 first and first[0] + n < len(pulses),
                 "%d pulses, refresh starts at %s" % (len(pulses), first[:3])):
        return None
    i = first[0]
    ref = pulses[i:i + n]
    t0, t1 = ref[0][0], pulses[i + n][0]
    want_t = [lsb << order[k // rows] for k in range(n)]
    got_t = [e - s for s, e, a in ref]
    check("%s: each row lit exactly lsb << plane cycles (lsb %d), planes in the driver's order"
          % (name, lsb), got_t == want_t,
          "first difference at pulse %s" % next((k for k in range(n) if got_t[k] != want_t[k]), None))
    check("%s: rows 0..%d in each plane" % (name, rows - 1),
          [a for s, e, a in ref] == list(range(rows)) * planes)
    res = dec.integrate(t0, t1)
    faults = {k: res[k] for k in ("setup_violations", "clk_while_lat", "ghosting",
                                  "clk_while_lit", "oe_coincident", "bad_address")}
    check("%s: no data, latch or address change while lit, no data change on a clock edge"
          % name, not any(faults.values()), faults)
    check("%s: the refresh in the trace is refresh_cycles long (%d cycles, %.0f Hz)"
          % (name, t1 - t0, 200e6 / (t1 - t0)), t1 - t0 == m["refresh"],
          "trace %d, driver %d" % (t1 - t0, m["refresh"]))
    clk = dec.clock_stats(t0, t1)
    want_clk = {"pocketscroller": 16, "octoscroller": 72}.get(m["map"], 10)
    check("%s: pixel clock %.1f MHz" % (name, 200 / want_clk), clk["min_period"] == want_clk,
          clk["min_period"])
    levels, dev = hd.to_levels(res["on"], lsb)
    levels = seen(levels, m.get("mux", "direct"), m["width"] // m.get("chain", 1), m["width"],
                  m["height"])
    with open(os.path.join(art, m["image"]), "rb") as f:
        data = f.read()
    if "band" in m:		# the output's band of the chains, from the display
        dw, dh = m["display"]
        shown = expected(data, m["format"], dw, dh, planes, m["correction"])
        full = m["height"] * m["outputs"]
        want = []
        for y in range(m["band"] * m["height"], (m["band"] + 1) * m["height"]):
            row = []
            for x in range(m["width"]):
                dx, dy = arrange(x, y, m["width"], full, m["height"], m.get("serpentine", False),
                                 m.get("rotation", 0))
                row.append(shown[dy][dx])
            want.append(row)
    else:
        want = expected(data, m["format"], m["width"], m["height"], planes, m["correction"])
    bad = [(x, y) for y in range(m["height"]) for x in range(m["width"])
           if tuple(levels[y][x]) != want[y][x]]
    check("%s: every pixel shows the picture's levels exactly (%dx%d, %d planes, %s%s)"
          % (name, m["width"], m["height"], planes, m["correction"],
             ", wired %s" % m["mux"] if stretch(m) > 1 else ""), not bad and dev == 0,
          "%d pixels differ, first %s: got %s, want %s" % (
              len(bad), bad[:1], bad and levels[bad[0][1]][bad[0][0]],
              bad and want[bad[0][1]][bad[0][0]]) if bad else "deviation %s" % dev)
    return levels
