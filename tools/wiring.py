#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""wiring.py - what to wire where for a prukit overlay, as an SVG picture.

    wiring.py OVERLAY.dtbo... -o DIR

For each overlay and each board it fits (prukit enable's rule:
prukit_tool.overlays.boards_of), the board's expansion headers
(BeagleBone Black P8/P9, PocketBeagle P1/P2), every pin the
overlay muxes marked with its signal (the PRU's r30 bit it drives, the r31
bit it reads, or the GPIO), output or input from the pad's configuration,
and what the wire needs (a level shifter for 5 V parts, 3.3 V-only inputs).
The pads come from the blob itself and the header pins from prukit's pin
table (sim/am335x-pins.tsv), through the prukit command's readers
(tools/prukit/prukit_tool: fdt, pins).  make check regenerates the pictures
in Documentation/wiring/ and fails if they differ."""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "prukit"))
from prukit_tool import fdt, overlays, pins  # noqa: E402

HEADERS = {"black": (("P8", 46, "_"), ("P9", 46, "_")),
           "pocket": (("P1", 36, "."), ("P2", 36, "."))}
# What the far end of the wires needs, by what the overlay drives.
NOTES = {
    "prukit,ws281x": "Outputs are 3.3 V: WS281x/SK6812 strings powered from 5 V need a "
                     "level shifter on each data line (e.g. 74AHCT125). Join the grounds.",
    "prukit,hub75": "Outputs are 3.3 V: HUB75 panels take 5 V logic, most accept 3.3 V; "
                    "a 74HCT245 buffer makes it sure. Join the grounds.",
    "prukit,beaglelogic": "Inputs are 3.3 V only and not 5 V tolerant: divide or shift 5 V "
                          "signals down. Join the grounds.",
    "prukit,pru-pwm": "Outputs are 3.3 V: hobby servos take it as their signal; power them "
                      "from their own 5-6 V supply, never from the board. Join the grounds.",
    "neopixel": "Output is 3.3 V: a 5 V NeoPixel string needs a level shifter on its data "
                "line (e.g. 74AHCT125). Join the grounds.",
}


def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def pin_name(header, n, sep):
    return "%s%s%s" % (header, sep, n if sep == "." else "%d" % n)


def svg(name, ov, cells, table, board):
    """The picture of one overlay."""
    balls = {}
    for off, mode in sorted(ov.pads.items()):
        pad = table.pads.get(off)
        hdr = pad.header.get(board) if pad else None
        if not hdr:
            continue
        sig = pad.signals.get(mode, "mode %d" % mode)
        out = "_r30_" in sig or (sig.startswith("gpio") and not cells.get(off, 0) & 0x20)
        balls.setdefault(hdr.rstrip("AB"), []).append((sig, out, pad.short, hdr))
    # P9_41 and P9_42 are two balls each: the pin shows the one that drives
    # it, a line below the other one
    used, others = {}, []
    for hdr, bs in balls.items():
        bs.sort(key=lambda b: not b[1])
        used[hdr] = bs[0][:3]
        others += ["%s %s %s %s" % (b[3], b[2], b[0], "out" if b[1] else "in") for b in bs[1:]]
    row, colw, top, left = 16, 600, 70, 10
    hdrs = HEADERS[board]
    rows = max(n for _, n, _ in hdrs) // 2
    width = left * 2 + colw * len(hdrs) - 20
    height = top + rows * row + 90
    o = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
         'font-family="DejaVu Sans Mono, monospace" font-size="11">' % (width, height),
         '<rect width="100%" height="100%" fill="white"/>',
         '<text x="%d" y="20" font-size="15" font-weight="bold">%s</text>' % (left, esc(name)),
         '<text x="%d" y="38">%s: %d pins; orange: PRU/GPIO output, blue: input</text>' %
         (left, "BeagleBone Black" if board == "black" else "PocketBeagle", len(used))]
    for i, (h, n, sep) in enumerate(hdrs):
        x0 = left + i * colw + 290
        o.append('<text x="%d" y="%d" text-anchor="middle" font-weight="bold">%s</text>' %
                 (x0, top - 12, h))
        o.append('<rect x="%d" y="%d" width="36" height="%d" fill="#333" rx="3"/>' %
                 (x0 - 18, top - 6, rows * row + 4))
        for k in range(1, n + 1):
            r, c = (k - 1) // 2, (k - 1) % 2
            x, y = x0 - 9 + 18 * c, top + r * row + 4
            p = pin_name(h, k, sep)
            if p in used:
                sig, out, pad = used[p]
                fill = "#f39c12" if out else "#3498db"
                label = "%s %s %s (%s)" % (p, sig, "out" if out else "in", pad)
                tx, anchor = (x - 10, "end") if c == 0 else (x + 10, "start")
                o.append('<text x="%d" y="%d" text-anchor="%s" font-weight="%s">%s</text>' %
                         (tx, y + 4, anchor, "bold", esc(label)))
            else:
                fill = "#777"
            o.append('<circle cx="%d" cy="%d" r="5" fill="%s"/>' % (x, y, fill))
        o.append('<text x="%d" y="%d" text-anchor="middle" fill="#555">pin 1 top left</text>' %
                 (x0, top + rows * row + 18))
    kind = ov.compatibles[0] if ov.compatibles else ("neopixel" if "NEOPIXEL" in name else None)
    note = NOTES.get(kind, "")
    if note:
        o.append('<text x="%d" y="%d">%s</text>' % (left, top + rows * row + 44, esc(note)))
    if not used:
        o.append('<text x="%d" y="%d">No header pins: the PRUs only talk to Linux '
                 '(rpmsg).</text>' % (left, top + rows * row + 62))
    if others:
        o.append('<text x="%d" y="%d">%s</text>' % (
            left, top + rows * row + 62, esc("Two balls on one pin, the other one muxed too: " +
                                             ", ".join(sorted(others)))))
    o.append("</svg>")
    return "\n".join(o) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dtbo", nargs="+")
    ap.add_argument("-o", "--out", required=True, help="directory for NAME.svg")
    ap.add_argument("--pins", help="the pin table (default: the checkout's)")
    a = ap.parse_args()
    table = pins.PinTable(a.pins)
    os.makedirs(a.out, exist_ok=True)
    for path in a.dtbo:
        name = os.path.basename(path)[:-5]
        root = fdt.load(path)
        ov = fdt.OverlayInfo(name, root)
        cells = {}
        for n in root.walk():
            c = n.cells("pinctrl-single,pins")
            for i in range(0, len(c) - 2, 3):
                cells[0x800 + c[i]] = c[i + 1]
        # one picture per board it fits: NAME.svg, and NAME-pocketbeagle.svg
        # for an overlay of the Black that fits the PocketBeagle too
        for i, board in enumerate(overlays.boards_of(ov, table)):
            if i and not ov.pads:
                continue
            suffix = "-pocketbeagle" if i and board == "pocket" else ""
            with open(os.path.join(a.out, name + suffix + ".svg"), "w") as f:
                f.write(svg(name, ov, cells, table, board))
    return 0


if __name__ == "__main__":
    sys.exit(main())
