#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""Draw a pin trace as a waveform: in the terminal and as a PNG.

Input is the text event list the prusim tool writes with --events
("CYCLE PIN_NAME LEVEL" per line, cycles of 5 ns relative to the start of
the firmware), e.g. converted from the QEMU PRU-ICSS's trace with
    prusim --trace-in trace.bin --events trace.events

    prusim-wave.py EVENTS [--from CYCLE] [--cycles N] [--width COLUMNS]
                   [--png FILE] [--pins NAME,NAME,...]

The PNG needs Debian's python3-pil (run with /usr/bin/python3).
"""
import argparse
import sys

NS_PER_CYCLE = 5


def read_events(path):
    """{pin: [(cycle, level), ...]} in file order, and the pin order."""
    pins, order = {}, []
    with open(path) as f:
        for n, line in enumerate(f, 1):
            parts = line.split()
            if len(parts) != 3 or parts[2] not in ("0", "1"):
                sys.exit(f"{path}:{n}: expected 'CYCLE PIN LEVEL'")
            cycle, pin, level = int(parts[0]), parts[1], int(parts[2])
            if pin not in pins:
                pins[pin] = []
                order.append(pin)
            pins[pin].append((cycle, level))
    return pins, order


def level_at(changes, cycle):
    """Level of a pin at a cycle (0 before its first change)."""
    level = 0
    for c, lv in changes:
        if c > cycle:
            break
        level = lv
    return level


def fmt_time(cycles):
    ns = cycles * NS_PER_CYCLE
    if ns >= 1000000:
        return f"{ns / 1000000:g} ms"
    if ns >= 1000:
        return f"{ns / 1000:g} us"
    return f"{ns} ns"


def terminal(pins, order, start, cycles, width):
    """One row per pin; each column covers cycles/width cycles."""
    label = max(len(p) for p in order) + 1
    step = cycles / width
    lines = []
    for pin in order:
        row = []
        for col in range(width):
            a = start + int(col * step)
            b = start + int((col + 1) * step)
            lo = level_at(pins[pin], a)
            edges = [lv for c, lv in pins[pin] if a < c < b]
            if edges or level_at(pins[pin], b - 1) != lo:
                row.append("┃")
            else:
                row.append("▀" if lo else "▁")
        lines.append(f"{pin:<{label}}" + "".join(row))
    ruler = f"{'':<{label}}|{fmt_time(start):<{width // 2}}{fmt_time(start + cycles):>{width - width // 2 - 1}}"
    return "\n".join(lines + [ruler])


def png(pins, order, start, cycles, path):
    from PIL import Image, ImageDraw, ImageFont

    font = ImageFont.load_default()
    row_h, margin, label_w, plot_w = 36, 10, 70, 1200
    h = margin * 2 + row_h * len(order) + 24
    w = label_w + plot_w + margin * 2
    img = Image.new("RGB", (w, h), (16, 16, 24))
    d = ImageDraw.Draw(img)
    x0 = margin + label_w

    def x_of(c):
        return x0 + (c - start) * plot_w / cycles

    for i, pin in enumerate(order):
        top = margin + i * row_h
        hi, lo = top + 6, top + row_h - 8
        d.text((margin, top + row_h // 2 - 6), pin, fill=(220, 220, 220), font=font)
        d.line([(x0, lo + 4), (x0 + plot_w, lo + 4)], fill=(40, 40, 56))
        pts = []
        level = level_at(pins[pin], start)
        pts.append((x0, hi if level else lo))
        for c, lv in pins[pin]:
            if c <= start or c >= start + cycles:
                continue
            x = x_of(c)
            pts.append((x, hi if level else lo))
            level = lv
            pts.append((x, hi if level else lo))
        pts.append((x0 + plot_w, hi if level else lo))
        d.line(pts, fill=(80, 220, 120), width=2)
    # time axis
    ay = margin + row_h * len(order) + 4
    d.line([(x0, ay), (x0 + plot_w, ay)], fill=(160, 160, 160))
    for k in range(11):
        c = start + cycles * k // 10
        x = x_of(c)
        d.line([(x, ay), (x, ay + 4)], fill=(160, 160, 160))
        t = fmt_time(c - start)
        d.text((x - 3 * len(t), ay + 6), t, fill=(160, 160, 160), font=font)
    img.save(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("events")
    ap.add_argument("--from", dest="start", type=int, default=0)
    ap.add_argument("--cycles", type=int, default=0)
    ap.add_argument("--width", type=int, default=100)
    ap.add_argument("--png")
    ap.add_argument("--pins")
    args = ap.parse_args()

    pins, order = read_events(args.events)
    if args.pins:
        order = [p for p in args.pins.split(",") if p in pins]
    if not order:
        sys.exit(f"{args.events}: no pin changes")
    cycles = args.cycles or max(c for p in order for c, _ in pins[p]) - args.start + 1
    print(terminal(pins, order, args.start, cycles, args.width))
    if args.png:
        png(pins, order, args.start, cycles, args.png)


if __name__ == "__main__":
    main()
