# SPDX-License-Identifier: GPL-2.0-only
"""Guest helpers of the ws281x VM tests: which controller is bound, and our
own decoder of WS281x strings in the simulator's pin trace.

The decoder takes a bit as 1 when its high time is nearer T1H than T0H,
counts every high time that is neither exactly, and ends a frame at a low of
at least half the shortest reset; a frame still running when the trace was
taken is left out, and so is a first fall followed by such a low."""
import glob
import os
import time

import trace
from rpmsg import write_attr

DRV = "/sys/bus/platform/drivers/ws281x"
T0H, T1H = 70, 140		# PRU cycles high for a 0 and a 1
GAP = 5000			# cycles low that end a frame (reset_us >= 50)
ORDERS = {"rgb": (0, 1, 2), "grb": (1, 0, 2), "brg": (2, 0, 1), "grbw": (1, 0, 2, 3)}


def bound():
    """Names of the platform devices the ws281x driver is bound to."""
    return sorted(os.path.basename(p) for p in glob.glob(DRV + "/*")
                  if os.path.islink(p) and not p.endswith("/module"))


def bind_only(name):
    """Unbind every other ws281x controller (the VM's tree has several that
    share PRU0, as overlays on a board would) and bind NAME; return its
    /dev node, or None."""
    for d in bound():
        if d != name:
            write_attr(DRV + "/unbind", d)
    if name not in bound():
        write_attr(DRV + "/bind", name)
    nodes = glob.glob("/sys/bus/platform/devices/%s/ws281x/ws281x*" % name)
    if name not in bound() or len(nodes) != 1:
        return None
    return "/dev/" + os.path.basename(nodes[0])


def gpio_pin(phandle_cell, bit):
    """The trace's pin id of GPIO line BIT of the bank whose phandle is
    given (the banks of the board path's tree, each in its target module)."""
    for node in glob.glob("/proc/device-tree/ocp@44c00000/target-module@*/gpio@0"):
        with open(node + "/phandle", "rb") as f:
            if f.read() == phandle_cell:
                base = int(os.path.dirname(node).rsplit("@", 1)[1], 16)
                return 64 + [0x44e07000, 0x4804c000, 0x481ac000, 0x481ae000].index(base) * 32 + bit
    raise ValueError("no GPIO bank with phandle %s" % phandle_cell.hex())


def gpio_strings(node, leds, order="grb"):
    """[(pin, name, LEDS, ORDER)] of the strings of a controller whose
    strings are all GPIO pins (/proc/device-tree/NODE/string@*), by reg."""
    out = {}
    for sub in glob.glob("/proc/device-tree/%s/string@*" % node):
        with open(sub + "/reg", "rb") as f:
            reg = int.from_bytes(f.read(), "big")
        with open(sub + "/gpios", "rb") as f:
            cells = f.read()
        pin = gpio_pin(cells[0:4], int.from_bytes(cells[4:8], "big"))
        out[reg] = (pin, "gpio%d_%d" % ((pin - 64) // 32, (pin - 64) % 32), leds, order)
    return [out[k] for k in sorted(out)]


def pin_edges(data, pins):
    """{pin: [(cycle, level), ...]} of a raw trace, for the pins asked."""
    _, _, _, origin, count, _, _ = trace.HDR.unpack_from(data)
    want = set(pins)
    out = {p: [] for p in pins}
    body = memoryview(data)[trace.HDR.size:trace.HDR.size + count * trace.REC.size]
    for cycle, pin, level in trace.REC.iter_unpack(body):
        if pin in want:
            out[pin].append((cycle - origin, level))
    return out


def frames_of(edges, end, gap=GAP):
    """The whole frames of one pin's edges as bytes, and the number of
    malformed bits (a high of neither T0H nor T1H, a level repeated, a frame
    whose bits make no whole byte)."""
    frames, bits, bad = [], [], 0
    i = 0
    # an output brought low before its first frame (the firmware does that
    # to what R30 held, then waits a reset): no bit
    if len(edges) > 1 and edges[0][1] == 0 and edges[1][0] - edges[0][0] >= gap:
        i = 1
    while i + 1 < len(edges):
        (t0, l0), (t1, l1) = edges[i], edges[i + 1]
        if (l0, l1) != (1, 0):
            bad += 1
            i += 1
            continue
        if t1 - t0 not in (T0H, T1H):
            bad += 1
        bits.append(1 if t1 - t0 > (T0H + T1H) // 2 else 0)
        nxt = edges[i + 2][0] if i + 2 < len(edges) else None
        if (nxt is None and end - t1 >= gap) or (nxt is not None and nxt - t1 >= gap):
            if len(bits) % 8:
                bad += 1
            else:
                frames.append(bytes(int("".join(map(str, bits[k:k + 8])), 2)
                                    for k in range(0, len(bits), 8)))
            bits = []
        i += 2
    return frames, bad


def decode(data, pins, gap=GAP):
    """{pin: (frames, malformed bits)} of a raw trace."""
    end = trace.end_bytes(data)
    return {p: frames_of(e, end, gap) for p, e in pin_edges(data, pins).items()}


def wire(frame, string, leds, max_leds, bpl, order):
    """The bytes a string of LEDS chips wants for a user frame (string-major,
    MAX_LEDS per string, BPL bytes per LED in R, G, B(, W) order)."""
    idx = ORDERS[order]
    out = bytearray()
    for k in range(leds):
        px = frame[(string * max_leds + k) * bpl:(string * max_leds + k + 1) * bpl]
        out += bytes(px[i] for i in idx)
    return bytes(out)


def read_trace(sim):
    with open(sim + "/trace", "rb") as f:
        return f.read()


def read_settled(sim, pins, gap=GAP, timeout=10):
    """The raw trace once PINS have been quiet for GAP cycles after the last
    edge of any of them (the last frame's reset is on the pins, so the
    decoder takes that frame), or as it is after TIMEOUT seconds."""
    end = time.monotonic() + timeout
    while True:
        data = read_trace(sim)
        last = max((e[-1][0] for e in pin_edges(data, pins).values() if e), default=None)
        if last is None or trace.end_bytes(data) - last >= gap or time.monotonic() >= end:
            return data
        time.sleep(0.05)


def clear_trace(sim):
    with open(sim + "/trace", "w") as f:
        f.write("clear")
