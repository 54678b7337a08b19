#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""Show the frames of a WS281x ("NeoPixel") string from a recorded pin.

The pin is decoded by sigrok's own rgb_led_ws281x decoder (sigrok-cli,
Debian package sigrok-cli) from a VCD file, e.g. one made from pru_sim's
trace with "prusim --trace-in trace.bin --vcd trace.vcd".  Each frame is
printed as a row of coloured blocks (24-bit colour terminals) and can be
written as PNG pictures.

    ws281x-show.py VCD [--pin P9_29] [--png-dir DIR] [--strip FILE]
                   [--gif FILE] [--every N] [--expect FILE]

--png-dir writes DIR/frame-NNN.png, one strip of LEDs per frame; --strip
one PNG with a row per frame; --gif an animation.  Pictures need Debian's
python3-pil (run with /usr/bin/python3).  --expect compares the frames with
FILE, a line of "#rrggbb" words per frame (what
firmware/rpmsg-neopixel/rainbow.py --print writes), and exits 1 unless every
frame matches.
"""
import argparse
import os
import re
import subprocess
import sys

LED = 24		# pixels per LED in the pictures


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


def terminal_row(frame):
    """Coloured blocks, two columns per LED; dark grey shade for an LED off."""
    return "".join("\033[38;2;%d;%d;%dm██" % rgb if any(rgb) else "\033[38;2;64;64;64m░░"
                   for rgb in frame) + "\033[0m"


def draw_frames(frames, png_dir, strip, gif):
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
        rows[0].save(gif, save_all=True, append_images=rows[1:], duration=40, loop=0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("vcd")
    ap.add_argument("--pin", default="P9_29", help="the VCD signal (default %(default)s)")
    ap.add_argument("--png-dir", help="write DIR/frame-NNN.png")
    ap.add_argument("--strip", help="write one PNG, a row per frame")
    ap.add_argument("--gif", help="write an animated GIF")
    ap.add_argument("--every", type=int, default=1,
                    help="print every Nth frame in the terminal (default %(default)s)")
    ap.add_argument("--expect", help="compare with FILE, a line of #rrggbb words per frame")
    args = ap.parse_args()
    if args.every < 1:
        ap.error("--every must be at least 1")
    if not os.path.exists(args.vcd):
        sys.exit("ws281x-show.py: %s: no such file" % args.vcd)

    frames = decode(args.vcd, args.pin)
    if not frames:
        sys.exit("ws281x-show.py: no WS281x frames on %s in %s" % (args.pin, args.vcd))
    for n, frame in enumerate(frames):
        if n % args.every == 0:
            print("frame %3d  %s" % (n, terminal_row(frame)))
    if args.png_dir or args.strip or args.gif:
        draw_frames(frames, args.png_dir, args.strip, args.gif)
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
