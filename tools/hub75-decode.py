#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""Decode the pins of a HUB75 RGB LED matrix into the picture it shows.

An independent model of the panel, fed with the pin changes recorded by
the QEMU PRU-ICSS / prusim (binary trace, sim/prusim_trace.h) or with a list of
(cycle, pin, level) changes.  Cycles are PRU cycles of 5 ns.

    hub75-decode.py TRACE --map pocketscroller|bone-r30|JSON|sig=pin,...
                    [--width 64] [--height 32] [--scan 16] [--chain N]
                    [--row-address binary|direct] [--panel generic|fm6126a]
                    [--window T0:T1 | --pulses N] [--initial sig=level,...]
                    [--lsb CYCLES] [--max-level L] [--png OUT [--scale K]]
                    [--json OUT] [--print]

Pins.  A pin id is C*32+B for bit B of R30 of PRU core C, 64+K*32+B for
bit B of GPIO bank K ("pruC.B" and "gpioK.B" are accepted too).  A pin map
names the pin of each signal: r1 g1 b1 r2 g2 b2 (data of the top and the
bottom half), a b c d e (row address: the first log2(scan) are needed,
all the map has are used), clk, lat and oe.  Built in: "pocketscroller"
and "bone-r30" (see MAPS).

Initial levels.  Trace records are changes, so a pin is at the inverse of
its first record's level before it; a pin without any record is at the level
given by --initial / the `initial` dict (default 0) and is reported.

Records.  Several records may share a cycle; a pin's last record of a cycle
gives its level and a record that does not change the level is ignored.

The model.  Geometry: panel W x H, scan S (H == 2*S), chain of C panels, so
N = W*C shift positions and a chain image of H rows by N columns.  All the
changes recorded at one cycle happen together, and whatever happens at cycle
c sees the other pins as they were BEFORE cycle c:
  - shift register: a rising edge of clk pushes the six data levels in; a
    data line changing at the same cycle as the edge is not seen (counted as
    `setup_violations`, once per edge).  The last N values are kept: column
    x is the x-th of the last N clocked (oldest = 0, newest = N-1); zeros
    while fewer than N were clocked.  A rising clk while lat is high counts
    as `clk_while_lat`.
  - latch: a falling edge of lat copies the shift register (as it was before
    the cycle, i.e. without a clk edge of the same cycle) to the outputs.
    With panel "fm6126a" (--panel), not if clk rose 4 or more times while
    lat was high: then it is a register write of an FM6126A-class driver
    chip (the chip counts the
    clocks: 11 for its register 1, 12 for 2, 10 for an FM6127's 3) and the
    outputs keep their bits.  Each 16 columns are one chip: its word is
    their bits, column 16k first as bit 15 (`registers()`).
  - display: the address is a + 2b + 4c + 8d + 16e, of every address line
    the map has (also those beyond log2(S): a wired "e" of a 1/16 scan map
    going high shows as `bad_address`); with row address "direct" (outdoor
    panels' direct row select: S lines a, b, ... for S <= 4) it is the one
    line that is low (none or several: `bad_address`).  While oe == 0 (active
    low), rows `address` (r1 g1 b1) and `address + S` (r2 g2 b2) show the
    latched bits; the lit time is summed in cycles per pixel and colour,
    over the lit time inside the window [t0, t1).  From cycle c on the state
    after cycle c's changes holds.  Lit with address >= S: `bad_address`
    (per lit stretch, nothing integrated).  The trace is complete up to its
    `end`: a pulse still on then is cut there.
  - faults, counted once per cycle in the window: an address line or lat
    changing while lit (oe low before and after the cycle) is `ghosting`;
    a rising clk then is `clk_while_lit` (harmless, reported apart); an
    address or lat change at the very cycle oe changes is `oe_coincident`
    (a race on real hardware, no effect on the model).
  - oe pulses: (start, end, address), the address as the pulse starts; end
    is None if oe is still low when the trace ends.

Output.  A summary: oe pulses and their durations (the bit planes of binary
code modulation), clock statistics (bursts are maximal runs of rising edges
no more than 2x the minimum period apart), latches, refresh (a frame starts
with each pulse of address 0 whose previous pulse had another address) and
the fault counts.  --lsb CYCLES turns on-times into levels (cycles / LSB,
rounded; the largest deviation from an integer is shown).  --png draws the
chain image, each LED a KxK block (--scale, default 8) with a 1 px dark gap,
scaled so that --max-level (or else the brightest value) is 255; it needs
Debian's python3-pil.  --json writes everything, --print the image as text.

Window.  --window T0:T1 in cycles relative to the trace origin (either may be
left out: trace start / end).  --pulses N: T0 is the start of the first oe
pulse whose address is 0, T1 the start of the Nth pulse after it (so exactly
N pulses start in [T0, T1) and each keeps the dark time after it), or the end
of the last pulse (the trace end if still on) when there is none.
"""
import argparse
import bisect
import collections
import json
import struct
import sys

HDR = struct.Struct("<8sIIQQQQ")
REC = struct.Struct("<QHB5x")
CYCLE_HZ = 200e6

DATA = ("r1", "g1", "b1", "r2", "g2", "b2")	# bit i of a data word
ADDR = ("a", "b", "c", "d", "e")		# address bit i
SIGNALS = DATA + ADDR + ("clk", "lat", "oe")
FAULTS = ("setup_violations", "clk_while_lat", "ghosting", "clk_while_lit",
          "oe_coincident")


def r30(core, bit):
    """Pin id of bit BIT of R30 of PRU core CORE."""
    return core * 32 + bit


def gpio(bank, bit):
    """Pin id of bit BIT of GPIO bank BANK."""
    return 64 + bank * 32 + bit


MAPS = {
    "pocketscroller": dict(lat=r30(0, 0), clk=r30(0, 1), a=r30(0, 2), b=r30(0, 3),
                           c=r30(0, 4), d=r30(0, 5), oe=r30(0, 7),
                           r1=gpio(1, 20), g1=gpio(1, 28), b1=gpio(1, 25),
                           r2=gpio(1, 26), g2=gpio(1, 27), b2=gpio(1, 18)),
    "bone-r30": {s: r30(1, b) for b, s in enumerate(
        ("r1", "g1", "b1", "r2", "g2", "b2", "clk", "lat", "oe",
         "a", "b", "c", "d", "e"))},
}


class UserError(Exception):
    """Bad input: reported in one line, exit status 2."""


# ---------------------------------------------------------------- input

def read_trace_bytes(data, with_end=False):
    """(origin, dropped, [(cycle - origin, pin, level), ...]) of a binary
    trace in memory; with WITH_END a 4th item, the end (relative)."""
    if len(data) < HDR.size or data[:8] != b"PRUTRACE":
        raise UserError("not a prusim trace (no PRUTRACE header)")
    _, version, rec_size, origin, count, dropped, end = HDR.unpack_from(data)
    if version != 2 or rec_size != REC.size:
        raise UserError("unsupported prusim trace version %d (record size %d)"
                        % (version, rec_size))
    if len(data) != HDR.size + count * REC.size:
        raise UserError("trace size does not match its record count %d" % count)
    events = [(c - origin, p, lv) for c, p, lv in REC.iter_unpack(data[HDR.size:])]
    return (origin, dropped, events, end - origin) if with_end else (origin, dropped, events)


def read_trace(path, with_end=False):
    """read_trace_bytes() of the file PATH."""
    with open(path, "rb") as f:
        return read_trace_bytes(f.read(), with_end)


def write_trace(path, events, origin=0, dropped=0, end=None):
    """Write EVENTS [(cycle - origin, pin, level)] as a binary trace."""
    last = max((c for c, _, _ in events), default=0)
    end = max(last, 0) if end is None else end
    with open(path, "wb") as f:
        f.write(HDR.pack(b"PRUTRACE", 2, REC.size, origin, len(events), dropped,
                         origin + end))
        for c, p, lv in events:
            f.write(REC.pack(origin + c, p, lv))


def parse_pin(text):
    """A pin id from an int, "pruC.B" or "gpioK.B"."""
    t = str(text).strip().lower()
    try:
        for prefix, fn in (("pru", r30), ("gpio", gpio)):
            if t.startswith(prefix):
                unit, bit = t[len(prefix):].split(".")
                return fn(int(unit), int(bit))
        return int(t, 0)
    except ValueError:
        raise UserError("bad pin %r (want a number, pruC.B or gpioK.B)" % text) from None


def parse_map(text):
    """A pin map {signal: pin id} from a built-in name, JSON text, a JSON file
    or "sig=pin,..."."""
    if text in MAPS:
        return dict(MAPS[text])
    if text.lstrip().startswith("{") or text.endswith(".json"):
        try:
            if text.lstrip().startswith("{"):
                obj = json.loads(text)
            else:
                with open(text) as f:
                    obj = json.load(f)
        except (OSError, ValueError) as e:
            raise UserError("pin map %s: %s" % (text, e)) from None
        if not isinstance(obj, dict):
            raise UserError("pin map: JSON must be an object {signal: pin}")
        pairs = obj.items()
    elif "=" in text:
        pairs = [kv.split("=", 1) for kv in text.split(",") if kv.strip()]
        if any(len(kv) != 2 for kv in pairs):
            raise UserError("bad pin map %r (want sig=pin,...)" % text)
    else:
        raise UserError("unknown pin map %r (built in: %s; or JSON, or sig=pin,...)"
                        % (text, ", ".join(MAPS)))
    out = {}
    for sig, pin in pairs:
        sig = sig.strip().lower()
        if sig not in SIGNALS:
            raise UserError("pin map: unknown signal %r (known: %s)" % (sig, " ".join(SIGNALS)))
        out[sig] = parse_pin(pin)
    return out


# ---------------------------------------------------------------- model

class Decoder:
    """The panel model of the module docstring, run once over EVENTS
    [(cycle, pin, level)] (relative cycles); query it with the methods."""

    def __init__(self, events, pinmap, width, height, scan, chain=1,
                 initial=None, end=None, row_address="binary", panel="generic"):
        if scan < 1 or scan > 32 or scan & (scan - 1):
            raise UserError("scan %d: must be a power of two up to 32" % scan)
        if row_address not in ("binary", "direct") or (row_address == "direct" and scan > 4):
            raise UserError("row address %s with scan %d: binary, or direct up to 4"
                            % (row_address, scan))
        if panel not in ("generic", "fm6126a"):
            raise UserError("panel %s: generic or fm6126a" % panel)
        self.direct = row_address == "direct"
        self.fm6126a = panel == "fm6126a"
        if height != 2 * scan:
            raise UserError("height %d != 2 * scan %d" % (height, scan))
        if width < 1 or chain < 1:
            raise UserError("width and chain must be at least 1")
        self.width, self.height, self.scan, self.chain = width, height, scan, chain
        self.n = width * chain
        lines = scan if self.direct else scan.bit_length() - 1
        needed = DATA + ADDR[:lines] + ("clk", "lat", "oe")
        missing = [s for s in needed if s not in pinmap]
        if missing:
            raise UserError("pin map lacks " + " ".join(missing))
        self.addr_sigs = tuple(s for s in ADDR[:lines] if s in pinmap) if self.direct else \
            tuple(s for s in ADDR if s in pinmap)
        self.pinmap = {s: int(pinmap[s]) for s in SIGNALS if s in pinmap}
        self.bypin = collections.defaultdict(list)
        for s, p in self.pinmap.items():
            self.bypin[p].append(s)
        evs = sorted((e for e in events if e[1] in self.bypin), key=lambda e: e[0])
        self.records = len(evs)
        initial = initial or {}
        first = {}
        for _, p, lv in evs:
            first.setdefault(p, 1 if lv else 0)
        self.initial_levels = {}
        self.pins_without_records = []
        for s, p in self.pinmap.items():
            if p in first:
                self.initial_levels[s] = 1 - first[p]
            else:
                self.initial_levels[s] = 1 if initial.get(s, initial.get(p, 0)) else 0
                self.pins_without_records.append((s, p))
        self.start = min(0, evs[0][0]) if evs else 0
        last = evs[-1][0] if evs else 0
        if end is not None and end < last:
            raise UserError("trace end %d before its last record %d" % (end, last))
        self.end = max(last, 0) if end is None else end
        self._run(evs)

    def _address(self, lv):
        if self.direct:
            low = [i for i, s in enumerate(self.addr_sigs) if not lv[s]]
            return low[0] if len(low) == 1 else self.scan
        return sum(lv[s] << ADDR.index(s) for s in self.addr_sigs)

    def _run(self, evs):
        """One pass: pulses, edges, fault cycles and the lit stretches
        (start, end, address, latched words)."""
        lv = dict(self.initial_levels)
        shift = collections.deque([0] * self.n, maxlen=self.n)
        latched = tuple(shift)
        addr = self._address(lv)
        self.pulses, self.lat_falls, self.clk_rises, self.clk_falls = [], [], [], []
        self.segments, self.commands = [], []
        lat_clocks = 0
        self.marks = {k: [] for k in FAULTS}
        lit_since = self.start
        if lv["oe"] == 0:
            self.pulses.append([self.start, None, addr])
        addr_set, data_set = set(self.addr_sigs), set(DATA)
        i = 0
        while i < len(evs):
            c = evs[i][0]
            new = {}
            while i < len(evs) and evs[i][0] == c:
                for s in self.bypin[evs[i][1]]:
                    new[s] = 1 if evs[i][2] else 0
                i += 1
            ch = {s: v for s, v in new.items() if v != lv[s]}
            if not ch:
                continue
            oe_pre, oe_post = lv["oe"], ch.get("oe", lv["oe"])
            lit_across = oe_pre == 0 and oe_post == 0
            lat_fall = ch.get("lat") == 0
            addr_change = not addr_set.isdisjoint(ch)
            if oe_pre == 0 and ("oe" in ch or addr_change or lat_fall) and c > lit_since:
                self.segments.append((lit_since, c, addr, latched))
            if addr_change or "lat" in ch:
                if lit_across:
                    self.marks["ghosting"].append(c)
                elif "oe" in ch:
                    self.marks["oe_coincident"].append(c)
            if lat_fall:			# before this cycle's shift
                if self.fm6126a and lat_clocks >= 4:
                    self.commands.append((c, lat_clocks, tuple(shift)))
                else:
                    latched = tuple(shift)
                self.lat_falls.append(c)
            elif ch.get("lat") == 1:
                lat_clocks = 0
            if ch.get("clk") == 1:
                self.clk_rises.append(c)
                if not data_set.isdisjoint(ch):
                    self.marks["setup_violations"].append(c)
                if lv["lat"]:
                    self.marks["clk_while_lat"].append(c)
                    lat_clocks += 1
                if lit_across:
                    self.marks["clk_while_lit"].append(c)
                shift.append(sum(lv[s] << b for b, s in enumerate(DATA)))
            elif ch.get("clk") == 0:
                self.clk_falls.append(c)
            lv.update(ch)
            if oe_post == 0 and ("oe" in ch or addr_change or lat_fall):
                lit_since, addr = c, self._address(lv)
            if oe_pre == 1 and oe_post == 0:
                self.pulses.append([c, None, addr])
            elif oe_pre == 0 and oe_post == 1:
                self.pulses[-1][1] = c
        if lv["oe"] == 0 and self.end > lit_since:
            self.segments.append((lit_since, self.end, addr, latched))
        self.pulses = [tuple(p) for p in self.pulses]

    def registers(self, t0=None, t1=None):
        """The register writes in [t0, t1): [(cycle, latch clocks,
        {line: [word of chip 0, chip 1, ...]})], a chip per 16 columns."""
        t0, t1 = self._window(t0, t1)
        out = []
        for c, clocks, cols in self.commands:
            if not t0 <= c < t1:
                continue
            words = {}
            for b, line in enumerate(DATA):
                words[line] = [sum((cols[16 * k + j] >> b & 1) << (15 - j) for j in range(16))
                               for k in range(self.n // 16)]
            out.append((c, clocks, words))
        return out

    def _window(self, t0, t1):
        return (self.start if t0 is None else t0, self.end if t1 is None else t1)

    def oe_pulses(self, t0=None, t1=None):
        """[(start, end or None, address)] of the oe-low pulses starting in
        [t0, t1) (default: all)."""
        t0, t1 = self._window(t0, t1)
        return [p for p in self.pulses if t0 <= p[0] < t1]

    def latches(self, t0=None, t1=None):
        """Cycles of the falling edges of lat in [t0, t1)."""
        t0, t1 = self._window(t0, t1)
        return [c for c in self.lat_falls if t0 <= c < t1]

    def integrate(self, t0=None, t1=None):
        """A dict: on[y][x] = (r, g, b) lit cycles in [t0, t1), the fault
        counts (FAULTS, bad_address), lit_cycles, latches, clk_edges,
        pulses, pins_without_records [(signal, pin)] and window (t0, t1)."""
        t0, t1 = self._window(t0, t1)
        on = [[[0, 0, 0] for _ in range(self.n)] for _ in range(self.height)]
        bad = lit = 0
        for s, e, a, words in self.segments:
            s, e = max(s, t0), min(e, t1)
            if e <= s:
                continue
            if a >= self.scan:
                bad += 1
                continue
            d = e - s
            lit += d
            top, bottom = on[a], on[a + self.scan]
            for x, w in enumerate(words):
                if w:
                    for ch in range(3):
                        if w >> ch & 1:
                            top[x][ch] += d
                        if w >> (ch + 3) & 1:
                            bottom[x][ch] += d
        res = {k: sum(1 for c in v if t0 <= c < t1) for k, v in self.marks.items()}
        res.update(on=[[tuple(px) for px in row] for row in on], bad_address=bad,
                   lit_cycles=lit, latches=len(self.latches(t0, t1)),
                   clk_edges=sum(1 for c in self.clk_rises if t0 <= c < t1),
                   pulses=len(self.oe_pulses(t0, t1)),
                   pins_without_records=list(self.pins_without_records),
                   window=(t0, t1))
        return res

    def clock_stats(self, t0=None, t1=None):
        """Rising clk edges in [t0, t1): a dict with edges, min_period,
        max_period, min_high, min_low (cycles, None if unknown), bursts
        [(first, last, edges)], inst_hz (200 MHz / min_period) and burst_hz
        (mean clock within the bursts)."""
        t0, t1 = self._window(t0, t1)
        rises = [c for c in self.clk_rises if t0 <= c < t1]
        falls = [c for c in self.clk_falls if t0 <= c < t1]
        periods = [b - a for a, b in zip(rises, rises[1:])]

        def min_gap(starts, ends):
            gaps = []
            for s in starts:
                k = bisect.bisect_right(ends, s)
                if k < len(ends):
                    gaps.append(ends[k] - s)
            return min(gaps, default=None)

        out = dict(edges=len(rises), min_period=min(periods, default=None),
                   max_period=max(periods, default=None),
                   min_high=min_gap(rises, falls), min_low=min_gap(falls, rises),
                   bursts=[], inst_hz=None, burst_hz=None)
        if not periods:
            return out
        limit, first = 2 * out["min_period"], 0
        for k in range(1, len(rises) + 1):
            if k == len(rises) or rises[k] - rises[k - 1] > limit:
                if k - first > 1:
                    out["bursts"].append((rises[first], rises[k - 1], k - first))
                first = k
        out["inst_hz"] = CYCLE_HZ / out["min_period"]
        span = sum(b[1] - b[0] for b in out["bursts"])
        out["burst_hz"] = CYCLE_HZ * sum(b[2] - 1 for b in out["bursts"]) / span
        return out

    def planes_timing(self, t0=None, t1=None):
        """planes_timing() of the pulses in [t0, t1)."""
        t0, t1 = self._window(t0, t1)
        return planes_timing(self.pulses, t0, t1)

    def frame_starts(self, t0=None, t1=None):
        """Starts of the pulses of address 0 whose previous pulse had another
        address (or that are the first)."""
        out, prev = [], None
        for s, _, a in self.pulses:
            if a == 0 and prev != 0:
                out.append(s)
            prev = a
        t0, t1 = self._window(t0, t1)
        return [s for s in out if t0 <= s < t1]

    def window_for_pulses(self, n):
        """(t0, t1) of --pulses N (see the module docstring)."""
        k = next((i for i, p in enumerate(self.pulses) if p[2] == 0), None)
        if k is None or len(self.pulses) - k < n or n < 1:
            raise UserError("fewer than %d oe pulses from the first one of address 0" % n)
        if k + n < len(self.pulses):
            return self.pulses[k][0], self.pulses[k + n][0]
        last = self.pulses[k + n - 1][1]
        return self.pulses[k][0], self.end if last is None else last


def planes_timing(pulses, t0=None, t1=None):
    """{duration: count} of the finished PULSES [(start, end, address)] lying
    in [t0, t1)."""
    hist = collections.Counter()
    for s, e, _ in pulses:
        if e is not None and (t0 is None or s >= t0) and (t1 is None or e <= t1):
            hist[e - s] += 1
    return dict(sorted(hist.items()))


def to_levels(on, lsb_cycles):
    """(levels[y][x] = (r, g, b) ints, max deviation): lit cycles divided by
    LSB_CYCLES and rounded; the deviation is the largest |value - round|."""
    dev, levels = 0.0, []
    for row in on:
        out = []
        for px in row:
            vals = [v / lsb_cycles for v in px]
            q = tuple(int(round(v)) for v in vals)
            dev = max([dev] + [abs(v - r) for v, r in zip(vals, q)])
            out.append(q)
        levels.append(out)
    return levels, dev


# ---------------------------------------------------------------- output

def write_png(path, img, scale, maxval):
    """Draw IMG (rows of (r, g, b)) as KxK blocks with 1 px dark gaps."""
    try:
        from PIL import Image		# only when a picture is asked for
    except ImportError:
        raise UserError("--png needs python3-pil (apt-get install python3-pil; "
                        "run with /usr/bin/python3)") from None
    if not maxval:
        maxval = max((v for row in img for px in row for v in px), default=0) or 1
    pitch = scale + 1
    pic = Image.new("RGB", (len(img[0]) * pitch + 1, len(img) * pitch + 1), (24, 24, 24))
    for y, row in enumerate(img):
        for x, px in enumerate(row):
            col = tuple(min(255, int(round(v * 255 / maxval))) for v in px)
            pic.paste(col, (x * pitch + 1, y * pitch + 1, x * pitch + 1 + scale,
                            y * pitch + 1 + scale))
    pic.save(path)


def print_image(img):
    """The image as text: a line per row, "rgb" hex digits per LED when all
    values are below 16, else "r,g,b"."""
    small = all(v < 16 for row in img for px in row for v in px)
    for row in img:
        print(" ".join("%x%x%x" % px if small else "%d,%d,%d" % px for px in row))


def summary(dec, res, clk, t0, t1):
    """Lines of the text summary."""
    us = lambda c: "%.3f us" % (c / CYCLE_HZ * 1e6)
    hist = dec.planes_timing(t0, t1)
    pulses = dec.oe_pulses(t0, t1)
    lines = ["window [%d, %d) cycles (%s), %d records on mapped pins"
             % (t0, t1, us(t1 - t0), dec.records),
             "oe pulses: %d, durations (cycles x count): %s" % (
                 len(pulses), " ".join("%dx%d" % kv for kv in hist.items()) or "-"),
             "addresses lit: %s" % (" ".join(str(a) for a in sorted({p[2] for p in pulses}))
                                   or "-"),
             "latches: %d, lit cycles (all rows): %d" % (res["latches"], res["lit_cycles"])]
    if clk["edges"] > 1:
        lines.append("clock: %d rising edges, period %d..%d, min high %s, min low %s, "
                     "%.2f MHz peak, %.2f MHz mean in %d bursts"
                     % (clk["edges"], clk["min_period"], clk["max_period"], clk["min_high"],
                        clk["min_low"], clk["inst_hz"] / 1e6, clk["burst_hz"] / 1e6,
                        len(clk["bursts"])))
    else:
        lines.append("clock: %d rising edges" % clk["edges"])
    frames = dec.frame_starts(t0, t1)
    if len(frames) > 1:
        per = (frames[-1] - frames[0]) / (len(frames) - 1)
        lines.append("refresh: %d frame starts, %.0f cycles apart: %.1f Hz, rows %.1f kHz"
                     % (len(frames), per, CYCLE_HZ / per, CYCLE_HZ * dec.scan / per / 1e3))
    else:
        lines.append("refresh: %d frame start(s) in the window" % len(frames))
    for c, clocks, words in dec.registers(t0, t1):
        lines.append("register write at %d (%d clocks with lat high): %s" % (
            c, clocks, " ".join("%s %s" % (k, ",".join("%04x" % w for w in sorted(set(v))))
                                for k, v in words.items())))
    lines.append("faults: " + ", ".join("%s %d" % (k, res[k])
                                         for k in FAULTS + ("bad_address",)))
    if res["pins_without_records"]:
        lines.append("pins without records: " + ", ".join(
            "%s (%d) = %d" % (s, p, dec.initial_levels[s])
            for s, p in res["pins_without_records"]))
    return lines


def parse_window(text):
    try:
        a, b = text.split(":")
        return (int(a, 0) if a.strip() else None, int(b, 0) if b.strip() else None)
    except ValueError:
        raise UserError("bad --window %r (want T0:T1)" % text) from None


def main(argv=None):
    ap = argparse.ArgumentParser(prog="hub75-decode.py", description=__doc__.split("\n")[0])
    ap.add_argument("trace")
    ap.add_argument("--map", required=True)
    ap.add_argument("--width", type=int, default=64)
    ap.add_argument("--height", type=int, default=32)
    ap.add_argument("--scan", type=int, default=16)
    ap.add_argument("--chain", type=int, default=1)
    ap.add_argument("--row-address", default="binary", choices=("binary", "direct"))
    ap.add_argument("--panel", default="generic", choices=("generic", "fm6126a"))
    win = ap.add_mutually_exclusive_group()
    win.add_argument("--window")
    win.add_argument("--pulses", type=int)
    ap.add_argument("--initial", default="", help="sig=level,... of pins without records")
    ap.add_argument("--lsb", type=float)
    ap.add_argument("--max-level", type=float)
    ap.add_argument("--png")
    ap.add_argument("--scale", type=int, default=8)
    ap.add_argument("--json")
    ap.add_argument("--print", action="store_true")
    args = ap.parse_args(argv)
    try:
        if args.scale < 1 or (args.lsb is not None and args.lsb <= 0):
            raise UserError("--scale and --lsb must be positive")
        pinmap = parse_map(args.map)
        initial = {}
        for kv in filter(None, args.initial.split(",")):
            sig, _, level = kv.partition("=")
            if sig.strip() not in SIGNALS or level.strip() not in ("0", "1"):
                raise UserError("bad --initial %r (want sig=0|1,...)" % kv)
            initial[sig.strip()] = int(level)
        try:
            _, dropped, events, end = read_trace(args.trace, with_end=True)
        except OSError as e:
            raise UserError("%s: %s" % (args.trace, e.strerror or e)) from None
        if dropped:
            print("hub75-decode.py: warning: %d records dropped, initial levels may be wrong"
                  % dropped, file=sys.stderr)
        dec = Decoder(events, pinmap, args.width, args.height, args.scan, args.chain,
                      initial, end, args.row_address, args.panel)
        if args.pulses is not None:
            t0, t1 = dec.window_for_pulses(args.pulses)
        else:
            t0, t1 = dec._window(*(parse_window(args.window) if args.window else (None, None)))
        res = dec.integrate(t0, t1)
        clk = dec.clock_stats(t0, t1)
        print("\n".join(summary(dec, res, clk, t0, t1)))
        img, dev = res["on"], None
        if args.lsb:
            img, dev = to_levels(res["on"], args.lsb)
            print("levels: LSB %g cycles, max %d, largest deviation %.3f"
                  % (args.lsb, max(v for row in img for px in row for v in px), dev))
        if args.print:
            print_image(img)
        if args.json:
            out = dict(res, clock=clk, planes=dec.planes_timing(t0, t1),
                       geometry=dict(width=args.width, height=args.height, scan=args.scan,
                                     chain=args.chain), frame_starts=dec.frame_starts(t0, t1),
                       oe_pulses=dec.oe_pulses(t0, t1))
            if args.lsb:
                out.update(lsb=args.lsb, levels=img, max_deviation=dev)
            try:
                with open(args.json, "w") as f:
                    json.dump(out, f)
            except OSError as e:
                raise UserError("%s: %s" % (args.json, e.strerror or e)) from None
        if args.png:
            try:
                write_png(args.png, img, args.scale, args.max_level)
            except OSError as e:
                raise UserError("%s: %s" % (args.png, e)) from None
    except UserError as e:
        print("hub75-decode.py: %s" % e, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
