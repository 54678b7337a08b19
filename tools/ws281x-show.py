#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""Show the frames of WS281x ("NeoPixel") strings from recorded pins.

The pins come from a VCD file, e.g. one made from the QEMU PRU-ICSS's trace with
"prusim --trace-in trace.bin --vcd trace.vcd".  Each frame is printed as a
row of coloured blocks (24-bit colour terminals) and can be written as PNG
pictures and a GIF.

    ws281x-show.py VCD [--pin PIN[:ORDER[:LEDS]]]... [--png-dir DIR]
                   [--strip FILE] [--gif FILE] [--delay MS] [--every N]
                   [--expect FILE]

One --pin NAME (default P9_29): the pin is decoded by sigrok's own
rgb_led_ws281x decoder (sigrok-cli, Debian package sigrok-cli), GRB chips.

Several strings, or one with ORDER or LEDS: --pin P9_30:grb:6 --pin
gpio1_12:grbw:4 ...  ORDER is the chip's colour order on the wire (grb,
rgb, brg ..., grbw for SK6812 RGBW; default grb), LEDS how many LEDs the
string has (default: all the frame carries; a string shorter than the
longest of its PRU is sent zeros after its LEDs).  Each pin is decoded by
this tool's own decoder (a bit is 1 when high longer than 525 ns, a frame
ends at a low of 50 us; a high of neither 350 +- 150 ns nor 700 +- 150 ns
is malformed and fails); GRB pins also by sigrok's rgb_led_ws281x (with
idle times over 100 us shortened to 100 us, sigrok-cli's vcd:compress, as
its decoder steps through every sample), which must agree frame by frame,
LED by LED, and is what is shown.  A frame is
then a row per string, frame N of every string together (every string of a
controller shows every frame).  RGBW LEDs are drawn with W added to R, G, B.

--png-dir writes DIR/frame-NNN.png, one picture per frame; --strip one PNG
of all frames, stacked; --gif an animation (--delay MS per frame, default
40).  Pictures need Debian's python3-pil (run with /usr/bin/python3).
--expect compares the frames with FILE and exits 1 unless they match:

  - a line per frame, the strings separated by "|", each LED "#rrggbb"
    ("#rrggbbww" for RGBW), colours in R, G, B(, W) order whatever the
    wire's (what firmware/rpmsg-neopixel/rainbow.py --print writes);
  - or "state NAME FRAME" lines, a "pattern REGEX" line and optionally a
    "frames N" line: the frames, each named by the state it equals ("?" if
    none) and followed by a space, must match REGEX (Python re.fullmatch),
    and be N.  Lines starting with "#" followed by a space are comments.
"""
import argparse
import os
import re
import subprocess
import sys

LED = 24		# pixels per LED in the pictures
LABEL = 120		# pixels of the frame numbers and strings' names in pictures
GAP = 6			# pixels between frames in a strip
T0H, T1H, TOL = 350, 700, 150	# ns high of a 0 and a 1, and the tolerance
RESET = 50000		# ns low that end a frame (as sigrok's decoder)


def decode(vcd, pin):
    """[[(r, g, b), ...], ...]: the frames, split where the decoder saw RESET."""
    try:
        r = subprocess.run(["sigrok-cli", "-I", "vcd", "-i", vcd,
                            "-P", "rgb_led_ws281x:din=" + pin,
                            "-A", "rgb_led_ws281x=rgb:reset"],
                           capture_output=True, text=True, check=False)
    except FileNotFoundError:
        sys.exit("ws281x-show.py: sigrok-cli not found (apt-get install sigrok-cli)")
    if r.returncode:
        sys.exit("ws281x-show.py: sigrok-cli failed: " + r.stderr.strip())
    frames, cur = [], []
    for line in r.stdout.splitlines():
        ann = line.split(": ", 1)[-1].strip()
        if ann == "RESET":
            if cur:
                frames.append(cur)
            cur = []
        elif re.fullmatch(r"#[0-9a-f]{6}", ann):
            cur.append(tuple(int(ann[i:i + 2], 16) for i in (1, 3, 5)))
    if cur:
        frames.append(cur)
    return frames


def sigrok_strings(vcd, pins, compress=0, downsample=1):
    """{pin: frames} of sigrok's rgb_led_ws281x, one decoder per pin in one
    sigrok-cli run; a frame is a list of (r, g, b), GRB on the wire.  With
    COMPRESS, sigrok-cli's VCD input shortens every time without a change on
    any pin to that many VCD time units (the decoder steps through every
    sample of the idle time otherwise); with DOWNSAMPLE it keeps every Nth
    sample (10 on a 5 ns trace: 20 MHz, 7/14/25 samples per 350/700/1250 ns,
    plenty for the decoder)."""
    cmd = ["sigrok-cli", "-I", "vcd:compress=%d:downsample=%d" % (compress, downsample),
           "-i", vcd]
    for pin in pins:
        cmd += ["-P", "rgb_led_ws281x:din=" + pin]
    try:
        r = subprocess.run(cmd + ["-A", "rgb_led_ws281x=rgb:reset"],
                           capture_output=True, text=True, check=False)
    except FileNotFoundError:
        sys.exit("ws281x-show.py: sigrok-cli not found (apt-get install sigrok-cli)")
    if r.returncode:
        sys.exit("ws281x-show.py: sigrok-cli failed: " + r.stderr.strip())
    frames = {pin: [] for pin in pins}
    cur = {pin: [] for pin in pins}
    for line in r.stdout.splitlines():
        m = re.match(r"rgb_led_ws281x-(\d+): (#[0-9a-f]{6}|RESET)$", line.strip())
        if not m:
            continue
        pin = pins[int(m.group(1)) - 1] if len(pins) > 1 else pins[0]
        if m.group(2) == "RESET":
            if cur[pin]:
                frames[pin].append(cur[pin])
            cur[pin] = []
        else:
            cur[pin].append(tuple(int(m.group(2)[i:i + 2], 16) for i in (1, 3, 5)))
    for pin in pins:
        if cur[pin]:
            frames[pin].append(cur[pin])
    return frames


def read_vcd(path, pins):
    """{pin: [(ns, level), ...]} of the 1-bit signals named PINS, the VCD's
    last time (ns) and its time unit (ns)."""
    units = {"s": 1e9, "ms": 1e6, "us": 1e3, "ns": 1, "ps": 1e-3, "fs": 1e-6}
    with open(path) as f:
        text = f.read()
    head, _, body = text.partition("$enddefinitions")
    m = re.search(r"\$timescale\s+(\d+)\s*(\w+)\s+\$end", head)
    scale = int(m.group(1)) * units[m.group(2)] if m else 1
    ids = {}
    for var in re.finditer(r"\$var\s+\S+\s+1\s+(\S+)\s+(\S+)(?:\s+\S+)?\s+\$end", head):
        if var.group(2) in pins:
            ids[var.group(1)] = var.group(2)
    missing = set(pins) - set(ids.values())
    if missing:
        sys.exit("ws281x-show.py: %s: no signal %s" % (path, ", ".join(sorted(missing))))
    out = {pin: [] for pin in pins}
    now = 0
    for tok in body.split():
        if tok[0] == "#":
            now = int(tok[1:]) * scale
        elif tok[0] in "01" and tok[1:] in ids:
            ev = out[ids[tok[1:]]]
            level = int(tok[0])
            if not ev or ev[-1][1] != level:
                ev.append((now, level))
    return out, now, scale


def own_frames(edges, end):
    """The frames of one pin's edges as wire bytes, and the number of
    malformed bits: this tool's own decoder (see the usage)."""
    frames, bits, bad = [], [], 0
    if edges and edges[0][1] == 0:
        edges = edges[1:]			# the initial level
    for i in range(0, len(edges) - 1, 2):
        (t0, l0), (t1, l1) = edges[i], edges[i + 1]
        if (l0, l1) != (1, 0):
            bad += 1
            continue
        high = t1 - t0
        if not (abs(high - T0H) <= TOL or abs(high - T1H) <= TOL):
            bad += 1
        bits.append(1 if high > (T0H + T1H) / 2 else 0)
        nxt = edges[i + 2][0] if i + 2 < len(edges) else end
        if nxt - t1 >= RESET:
            if len(bits) % 8:
                bad += 1
            frames.append(bytes(int("".join(map(str, bits[k:k + 8])), 2)
                                for k in range(0, len(bits) - 7, 8)))
            bits = []
    return frames, bad


def parse_pin(spec):
    """(name, order, leds or None) of a --pin argument."""
    parts = spec.split(":")
    name = parts[0]
    order = parts[1].lower() if len(parts) > 1 and parts[1] else "grb"
    leds = int(parts[2]) if len(parts) > 2 and parts[2] else None
    if sorted(order) not in (sorted("rgb"), sorted("rgbw")) or len(parts) > 3:
        sys.exit("ws281x-show.py: --pin %s: want NAME[:ORDER[:LEDS]], ORDER a permutation "
                 "of rgb or rgbw" % spec)
    return name, order, leds


def to_leds(wire, order, leds):
    """User-order colour tuples of a string's wire bytes."""
    n = len(order)
    idx = ["rgbw".index(c) for c in order]
    out = []
    for k in range(0, len(wire) - n + 1, n):
        px = [0] * n
        for i, c in enumerate(idx):
            px[c] = wire[k + i]
        out.append(tuple(px))
    return out[:leds] if leds is not None else out


def decode_strings(vcd, strings):
    """[[string's LEDs, ...] per frame]: every string of every frame, its
    LEDs as (r, g, b) or (r, g, b, w); exits when the decoders disagree,
    a bit is malformed or the strings show different numbers of frames."""
    pins = [name for name, _, _ in strings]
    edges, end, unit = read_vcd(vcd, pins)
    own = {}
    for name, order, leds in strings:
        frames, bad = own_frames(edges[name], end)
        if bad:
            sys.exit("ws281x-show.py: %s: %d malformed bits" % (name, bad))
        own[name] = [to_leds(f, order, None) for f in frames]
    grb = [name for name, order, _ in strings if order == "grb"]
    # idle times shortened to 100 us: still a reset to the decoder (50 us)
    sig = sigrok_strings(vcd, grb, int(2 * RESET / unit)) if grb else {}
    for name in grb:
        if sig[name] != own[name]:
            n = next((k for k, (a, b) in enumerate(zip(sig[name], own[name])) if a != b),
                     min(len(sig[name]), len(own[name])))
            sys.exit("ws281x-show.py: %s: sigrok's rgb_led_ws281x and this tool's decoder "
                     "disagree from frame %d (sigrok %d frames, ours %d)"
                     % (name, n, len(sig[name]), len(own[name])))
        own[name] = sig[name]
    counts = {name: len(own[name]) for name in pins}
    if len(set(counts.values())) != 1:
        sys.exit("ws281x-show.py: the strings show different numbers of frames: %s" % counts)
    return [[own[name][n][:leds] if leds is not None else own[name][n]
             for name, _, leds in strings] for n in range(counts[pins[0]])]


def shade(px):
    """The colour a pixel shows: R, G, B with an RGBW LED's W added."""
    if len(px) == 4:
        return tuple(min(255, c + px[3]) for c in px[:3])
    return tuple(px)


def words(leds):
    return " ".join("#" + "".join("%02x" % c for c in px) for px in leds)


def frame_text(frame):
    """A frame as an --expect line."""
    return " | ".join(words(s) for s in frame)


def check_expect(path, frames):
    """Compare the frames with an --expect file (see the usage); True if
    they match."""
    with open(path) as f:
        lines = [ln.strip() for ln in f if ln.strip() and not ln.startswith("# ")]
    states = {}
    pattern, count = None, None
    for ln in lines:
        key, _, rest = ln.partition(" ")
        if key == "state":
            name, _, fr = rest.strip().partition(" ")
            states[" ".join(fr.split())] = name
        elif key == "pattern":
            pattern = rest.strip()
        elif key == "frames":
            count = int(rest)
    got = [" ".join(frame_text(f).split()) for f in frames]
    if pattern is None:
        want = [" ".join(ln.split()) for ln in lines]
        same = sum(1 for w, g in zip(want, got) if w == g)
        print("decoded frames identical to the %d sent: %d" % (len(want), same))
        if same != len(want) or len(got) != len(want):
            for n, (w, g) in enumerate(zip(want, got)):
                if w != g:
                    print("frame %d: sent    %s\n%*s decoded %s" % (n, w, len(str(n)) + 6, "", g))
                    break
            return False
        return True
    seq = "".join(states.get(g, "?") + " " for g in got)
    ok = re.fullmatch(pattern, seq) is not None and (count is None or count == len(got))
    print("decoded frames, by state: %s" % seq.strip())
    print("%s the pattern %s%s" % ("match" if ok else "do NOT match", pattern,
                                   "" if count is None else
                                   " and the %d frames the driver counted" % count))
    return ok


def terminal_row(frame):
    """Coloured blocks, two columns per LED; dark grey shade for an LED off."""
    return "".join("\033[38;2;%d;%d;%dm██" % rgb if any(rgb) else "\033[38;2;64;64;64m░░"
                   for rgb in frame) + "\033[0m"


def draw_frames(frames, png_dir, strip, gif, delay=40):
    try:
        from PIL import Image, ImageDraw
    except ImportError:
        sys.exit("ws281x-show.py: pictures need python3-pil (run with /usr/bin/python3)")

    def leds(frame, width):
        img = Image.new("RGB", (width * LED, LED), (24, 24, 24))
        d = ImageDraw.Draw(img)
        for i, rgb in enumerate(frame):
            d.ellipse((i * LED + 2, 2, i * LED + LED - 3, LED - 3), fill=rgb,
                      outline=(80, 80, 80))
        return img

    width = max(len(f) for f in frames)
    rows = [leds(f, width) for f in frames]
    if png_dir:
        os.makedirs(png_dir, exist_ok=True)
        for n, img in enumerate(rows):
            img.save(os.path.join(png_dir, "frame-%03d.png" % n))
    if strip:
        img = Image.new("RGB", (width * LED, len(rows) * LED))
        for n, row in enumerate(rows):
            img.paste(row, (0, n * LED))
        img.save(strip)
    if gif:
        rows[0].save(gif, save_all=True, append_images=rows[1:], duration=delay, loop=0)


def terminal_strings(frames, strings, every):
    """A line per frame: the strings side by side."""
    cols = [max(2 * max((len(f[s]) for f in frames), default=0), len(name) + len(order) + 1)
            for s, (name, order, _) in enumerate(strings)]
    print(("           " + "  ".join("%-*s" % (w, "%s %s" % (name, order.upper()))
                                    for w, (name, order, _) in zip(cols, strings))).rstrip())
    for n, frame in enumerate(frames):
        if n % every:
            continue
        row = []
        for w, leds in zip(cols, frame):
            row.append(terminal_row([shade(px) for px in leds]) + " " * (w - 2 * len(leds)))
        print("frame %3d  %s" % (n, "  ".join(row)))


def draw_strings(frames, strings, png_dir, strip, gif, delay):
    """A picture per frame: a row per string, its name on the left."""
    try:
        from PIL import Image, ImageDraw
    except ImportError:
        sys.exit("ws281x-show.py: pictures need python3-pil (run with /usr/bin/python3)")
    width = max(len(s) for f in frames for s in f)

    def block(n, frame):
        img = Image.new("RGB", (LABEL + width * LED, len(frame) * LED), (24, 24, 24))
        d = ImageDraw.Draw(img)
        d.text((4, 6), "%d" % n, fill=(255, 255, 160))
        for s, leds in enumerate(frame):
            name, order, _ = strings[s]
            d.text((28, s * LED + 6), "%s %s" % (name, order.upper()), fill=(200, 200, 200))
            for i, px in enumerate(leds):
                x, y = LABEL + i * LED, s * LED
                d.ellipse((x + 2, y + 2, x + LED - 3, y + LED - 3), fill=shade(px),
                          outline=(80, 80, 80))
        return img

    blocks = [block(n, f) for n, f in enumerate(frames)]
    if png_dir:
        os.makedirs(png_dir, exist_ok=True)
        for n, img in enumerate(blocks):
            img.save(os.path.join(png_dir, "frame-%03d.png" % n))
    if strip:
        h = blocks[0].height
        img = Image.new("RGB", (blocks[0].width, len(blocks) * (h + GAP) - GAP), (60, 60, 60))
        for n, b in enumerate(blocks):
            img.paste(b, (0, n * (h + GAP)))
        img.save(strip)
    if gif:
        blocks[0].save(gif, save_all=True, append_images=blocks[1:], duration=delay, loop=0)


def main_strings(args, strings):
    frames = decode_strings(args.vcd, strings)
    if not frames:
        sys.exit("ws281x-show.py: no WS281x frames on %s in %s"
                 % (", ".join(name for name, _, _ in strings), args.vcd))
    terminal_strings(frames, strings, args.every)
    if args.png_dir or args.strip or args.gif:
        draw_strings(frames, strings, args.png_dir, args.strip, args.gif, args.delay)
    grb = [name for name, order, _ in strings if order == "grb"]
    print("%d frames of %d string(s), decoded by this tool%s" % (
        len(frames), len(strings),
        "; sigrok's rgb_led_ws281x agrees on %s" % ", ".join(grb) if grb else ""))
    if args.expect and not check_expect(args.expect, frames):
        sys.exit(1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("vcd")
    ap.add_argument("--pin", action="append",
                    help="a string: the VCD signal, its chip's colour order and LEDs, "
                    "NAME[:ORDER[:LEDS]] (default P9_29); several times for several strings")
    ap.add_argument("--png-dir", help="write DIR/frame-NNN.png")
    ap.add_argument("--strip", help="write one PNG, a row per frame")
    ap.add_argument("--gif", help="write an animated GIF")
    ap.add_argument("--delay", type=int, default=40,
                    help="milliseconds per frame of the GIF (default %(default)s)")
    ap.add_argument("--every", type=int, default=1,
                    help="print every Nth frame in the terminal (default %(default)s)")
    ap.add_argument("--expect", help="compare with FILE: a line of #rrggbb words per frame, "
                    "or states and a pattern (see above)")
    args = ap.parse_args()
    if args.every < 1:
        ap.error("--every must be at least 1")
    if not os.path.exists(args.vcd):
        sys.exit("ws281x-show.py: %s: no such file" % args.vcd)
    pins = args.pin or ["P9_29"]
    if len(pins) > 1 or ":" in pins[0]:
        main_strings(args, [parse_pin(p) for p in pins])
        return
    args.pin = pins[0]

    frames = decode(args.vcd, args.pin)
    if not frames:
        sys.exit("ws281x-show.py: no WS281x frames on %s in %s" % (args.pin, args.vcd))
    for n, frame in enumerate(frames):
        if n % args.every == 0:
            print("frame %3d  %s" % (n, terminal_row(frame)))
    if args.png_dir or args.strip or args.gif:
        draw_frames(frames, args.png_dir, args.strip, args.gif, args.delay)
    print("%d frames of %s LEDs" % (len(frames), "/".join(sorted({str(len(f)) for f in frames}))))
    if args.expect:
        with open(args.expect) as f:
            want = [line.split() for line in f if line.strip()]
        got = [["#%02x%02x%02x" % rgb for rgb in frame] for frame in frames]
        same = sum(1 for w, g in zip(want, got) if w == g)
        print("decoded frames identical to the %d sent: %d" % (len(want), same))
        if same != len(want) or len(got) != len(want):
            sys.exit(1)


if __name__ == "__main__":
    main()
