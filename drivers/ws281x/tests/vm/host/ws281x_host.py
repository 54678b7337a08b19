# SPDX-License-Identifier: GPL-2.0-only
"""Host-side checks shared by the ws281x VM tests' host halves: a guest
trace turned into VCD and pin events by the prusim tool, decoded by sigrok's
own rgb_led_ws281x decoder (sigrok-cli), and every edge checked against the
driver's schedule to the PRU cycle: 1250 ns per bit, high 350 ns for a 0 and
700 ns for a 1, at least 300 us low between frames."""
import importlib.util
import os
import subprocess

TOP = os.path.realpath(os.path.join(os.path.dirname(__file__), "../../../../.."))
PRUSIM = os.path.join(TOP, "out/tools/prusim")
NS = 5				# ns per PRU cycle
SLOT, T0H, T1H, RESET = 1250, 350, 700, 300000


class Checker:
    """PASS:/FAIL: lines; .failed once any check failed."""

    def __init__(self):
        self.failed = False

    def __call__(self, name, cond, detail=""):
        tail = "" if cond or not detail else ": " + str(detail)
        print(("PASS: " if cond else "FAIL: ") + name + tail)
        self.failed = self.failed or not cond
        return cond


def convert(trace):
    """VCD and pin-event files of a raw guest trace (X.bin -> X.vcd, X.events)."""
    base = trace[:-len(".bin")]
    r = subprocess.run([PRUSIM, "--trace-in", trace, "--events", base + ".events",
                        "--vcd", base + ".vcd"], capture_output=True, text=True)
    if r.returncode:
        raise RuntimeError("prusim --trace-in %s: %s" % (trace, r.stderr.strip()))
    return base + ".events", base + ".vcd"


def _show():
    """tools/ws281x-show.py, which has sigrok-cli's rgb_led_ws281x runner."""
    spec = importlib.util.spec_from_file_location(
        "ws281x_show", os.path.join(TOP, "tools/ws281x-show.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def sigrok_frames(vcd, pins):
    """{pin: the frames sigrok's rgb_led_ws281x decodes on it}, one decoder
    per pin in one sigrok-cli run; a frame is a list of "#rrggbb" (sigrok
    assumes GRB on the wire).  Sampled at 20 MHz, idle times shortened to
    100 us: exact timing is checked here, from the events, not by sigrok."""
    if isinstance(pins, str):
        return sigrok_frames(vcd, [pins])[pins]
    got = _show().sigrok_strings(vcd, pins, compress=20000, downsample=10)
    return {pin: [["#%02x%02x%02x" % led for led in frame] for frame in frames]
            for pin, frames in got.items()}


def grb_as_sigrok(wire):
    """What sigrok prints for GRB wire bytes: "#rrggbb" per LED."""
    return ["#%02x%02x%02x" % (wire[k + 1], wire[k], wire[k + 2])
            for k in range(0, len(wire) - 2, 3)]


def pin_edges(events):
    """{pin name: [(ns, level), ...]} of a prusim --events file."""
    out = {}
    with open(events) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            cycle, pin, level = line.split()
            out.setdefault(pin, []).append((int(cycle) * NS, int(level)))
    return out


def bank_offset_ns(pin):
    """Where the firmware's edges land after the slot's start: R30 pins at
    once, GPIO bank b 18 + 8b cycles later (ws281x_send.S)."""
    if pin.startswith("gpio"):
        return (18 + 8 * int(pin[4])) * NS
    return 0


def exact_timing(check, name, edges, reset=RESET, tol=0):
    """Every high T0H or T1H and every rise one SLOT after the one before
    within a frame, within tol ns (0: exactly), and the lows between
    frames >= reset."""
    # an output brought low before its first frame (first_low() in the
    # firmware): a fall, then at least a reset's low, is no bit
    if len(edges) > 1 and edges[0][1] == 0 and edges[1][0] - edges[0][0] >= reset:
        edges = edges[1:]
    herr, perr, resets, bad = 0, 0, [], 0
    highs, periods = set(), set()
    for i in range(0, len(edges) - 1, 2):
        (t0, l0), (t1, l1) = edges[i], edges[i + 1]
        if (l0, l1) != (1, 0):
            bad += 1
            continue
        h = t1 - t0
        highs.add(h)
        herr = max(herr, min(abs(h - T0H), abs(h - T1H)))
        if i + 2 < len(edges):
            gap = edges[i + 2][0] - t0
            if gap - h >= 50000:
                resets.append(edges[i + 2][0] - t1)
            else:
                periods.add(gap)
                perr = max(perr, abs(gap - SLOT))
    if tol:
        what = "every high within %d ns of 350/700 (worst %d), every bit within %d ns of " \
            "1250 (worst %d)" % (tol, herr, tol, perr)
    else:
        what = "every high %s ns (350 or 700), every bit %s ns (1250)" % (
            sorted(highs)[:6], sorted(periods)[:6])
    check("%s: %d bits, %s" % (name, len(edges) // 2, what),
          len(edges) > 0 and not bad and herr <= tol and perr <= tol)
    if resets:
        check("%s: the low between frames is at least %d us (shortest %.1f us)"
              % (name, reset // 1000, min(resets) / 1000), min(resets) >= reset)
    return max(herr, perr)


def rises_together(check, name, by_pin, tol=0):
    """Strings of one core share the bit slot: every rise of each pin is
    also a rise of the core's longest string, moved by the pins' documented
    offsets (bank_offset_ns), within tol ns."""
    rises = {pin: sorted(t - bank_offset_ns(pin) for t, lv in edges if lv == 1)
             for pin, edges in by_pin.items()}
    longest = max(rises.values(), key=len)
    worst = {}
    for pin, r in rises.items():
        # each rise against the nearest rise of the longest string
        j, w = 0, 0
        for t in r:
            while j + 1 < len(longest) and abs(longest[j + 1] - t) <= abs(longest[j] - t):
                j += 1
            w = max(w, abs(longest[j] - t) if longest else 1 << 30)
        worst[pin] = w
    check("%s: the %d strings rise together, every rise within %d ns of the longest "
          "string's (worst %d ns)" % (name, len(by_pin), tol, max(worst.values())),
          len(longest) > 0 and max(worst.values()) <= tol,
          {p: w for p, w in worst.items() if w > tol})
