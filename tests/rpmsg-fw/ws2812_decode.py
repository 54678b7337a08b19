#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""Decode WS2812 frames from a prusim event list and compare them.

usage: ws2812_decode.py EVENTS PIN FRAME_HEX...

EVENTS is what "prusim --events" (or --trace-in ... --events) writes:
"CYCLE PIN LEVEL" per line.  The edges of PIN are split into frames at low
times of at least RESET cycles; each bit must be high exactly T0H (0) or T1H
(1) cycles and, unless it is the last of its frame, low exactly T0L or T1L.
Each frame must equal the next FRAME_HEX (GRB bytes, MSB first on the wire),
and every frame must follow at least RESET cycles of low (the first one: low
since cycle 0).  Prints PASS:/FAIL: lines, exits 1 on failure.

This is deliberately independent of the C harness: it reads the simulator
tool's own output.
"""
import sys

T0H, T0L, T1H, T1L, RESET = 70, 160, 140, 120, 60000


def main():
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    path, pin, want = sys.argv[1], sys.argv[2], sys.argv[3:]
    edges = []
    with open(path, encoding="ascii") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            cycle, name, level = line.split()
            if name == pin:
                edges.append((int(cycle), int(level)))

    failed = False

    def fail(msg):
        nonlocal failed
        failed = True
        print(f"FAIL: ws2812 decode of {pin}: {msg}")

    frames, bits, last_fall = [], [], 0
    gaps = []
    for i in range(0, len(edges), 2):
        if i + 1 >= len(edges):
            fail(f"edge {i} at cycle {edges[i][0]} has no falling edge")
            break
        (rise, l1), (fall, l0) = edges[i], edges[i + 1]
        if (l1, l0) != (1, 0):
            fail(f"edges {i}, {i + 1}: levels {l1} {l0}, want 1 0")
            break
        low_before = rise - last_fall
        if bits and low_before >= RESET:
            frames.append(bits)
            bits = []
        if not bits:
            gaps.append(low_before)
        elif low_before != (T1L if bits[-1] else T0L):
            fail(f"cycle {rise}: low {low_before} after a {bits[-1]} bit")
        high = fall - rise
        if high not in (T0H, T1H):
            fail(f"cycle {rise}: high for {high} cycles, neither {T0H} nor {T1H}")
        bits.append(1 if high == T1H else 0)
        last_fall = fall
    if bits:
        frames.append(bits)

    got = []
    for b in frames:
        if len(b) % 8:
            fail(f"a frame of {len(b)} bits")
        got.append(bytes(int("".join(map(str, b[k:k + 8])), 2)
                         for k in range(0, len(b) - 7, 8)).hex())
    if len(got) != len(want):
        fail(f"{len(got)} frames, want {len(want)}")
    for n, (g, w) in enumerate(zip(got, want)):
        if g != w.lower():
            fail(f"frame {n}: {g}, want {w}")
    short = [g for g in gaps if g < RESET]
    if short:
        fail(f"a frame after only {min(short)} cycles low")
    if not failed:
        print(f"PASS: ws2812 decode of {pin} from the prusim event list: {len(got)} frames "
              f"of {len(edges) // 2 // max(len(got), 1)} bits as expected, every bit "
              f"{T0H}/{T0L} or {T1H}/{T1L} cycles, >= {min(gaps) if gaps else 0} cycles "
              "low before each frame")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
