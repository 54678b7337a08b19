#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""Helpers of run.sh for prusim's binary pin traces and event lists.

  tracecheck.py agree VCD EVENTS
      exit 0 if the VCD shows exactly the changes of the event list: pins
      declared, levels at time 0 (from events before the origin, i.e. with
      a negative cycle), and per cycle the last level of each pin that
      moved.  Prints what differs otherwise.
  tracecheck.py patch IN OUT FIELD=VALUE...
      copy a binary trace, changing header fields (magic, version,
      rec_size, origin, count, dropped, end) or record fields (recN.cycle,
      recN.pin, recN.level, recN.reserved); values are numbers, magic is
      text.
"""

import struct
import sys

HDR = struct.Struct("<8sIIQQQQ")
REC = struct.Struct("<QHB5s")
HDR_FIELDS = ("magic", "version", "rec_size", "origin", "count", "dropped", "end")
REC_FIELDS = ("cycle", "pin", "level", "reserved")


def read_events(path):
    events = []
    with open(path) as f:
        for line in f:
            cycle, name, level = line.split()
            events.append((int(cycle), name, int(level)))
    return events


def expected_vcd(events):
    """(initial levels, [(time, {name: level})]) that a VCD of the events shows"""
    level = {name: 0 for _, name, _ in events}
    for cycle, name, lv in events:
        if cycle < 0:
            level[name] = lv
    initial = dict(level)
    changes, i = [], 0
    later = [e for e in events if e[0] >= 0]
    while i < len(later):
        t = later[i][0]
        final = {}
        while i < len(later) and later[i][0] == t:
            final[later[i][1]] = later[i][2]
            i += 1
        moved = {n: v for n, v in final.items() if level[n] != v}
        level.update(final)
        if moved:
            changes.append((t, moved))
    return initial, changes


def parse_vcd(path):
    ids, initial, changes, t, in_dump = {}, {}, [], None, False
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.startswith("$var"):
                parts = line.split()
                ids[parts[3]] = parts[4]
            elif line == "$dumpvars":
                in_dump = True
            elif line == "$end" and in_dump:
                in_dump = False
            elif line.startswith("#"):
                t = int(line[1:])
            elif line and line[0] in "01":
                name, lv = ids[line[1:]], int(line[0])
                if in_dump:
                    initial[name] = lv
                elif changes and changes[-1][0] == t:
                    changes[-1][1][name] = lv
                else:
                    changes.append((t, {name: lv}))
    return initial, changes


def agree(vcd, events_path):
    want = expected_vcd(read_events(events_path))
    got = parse_vcd(vcd)
    if want[0] != got[0]:
        print(f"initial levels: VCD {got[0]}, events {want[0]}")
        return 1
    for w, g in zip(want[1], got[1]):
        if w != g:
            print(f"first difference: VCD {g}, events {w}")
            return 1
    if len(want[1]) != len(got[1]):
        print(f"VCD has {len(got[1])} time stamps with changes, events {len(want[1])}")
        return 1
    return 0


def patch(src, dst, assignments):
    data = bytearray(open(src, "rb").read())
    hdr = list(HDR.unpack_from(data, 0))
    for a in assignments:
        key, val = a.split("=", 1)
        if key in HDR_FIELDS:
            hdr[HDR_FIELDS.index(key)] = val.encode() if key == "magic" else int(val, 0)
            continue
        rec, field = key.split(".")
        off = HDR.size + int(rec[3:]) * REC.size
        r = list(REC.unpack_from(data, off))
        idx = REC_FIELDS.index(field)
        r[idx] = int(val, 0).to_bytes(5, "little") if field == "reserved" else int(val, 0)
        REC.pack_into(data, off, *r)
    HDR.pack_into(data, 0, *hdr)
    open(dst, "wb").write(data)
    return 0


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "agree":
        return agree(sys.argv[2], sys.argv[3])
    if len(sys.argv) >= 5 and sys.argv[1] == "patch":
        return patch(sys.argv[2], sys.argv[3], sys.argv[4:])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
