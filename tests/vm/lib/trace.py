# SPDX-License-Identifier: GPL-2.0-only
"""Read the simulator's binary pin trace (sim/prusim_trace.h) in the guest."""
import struct

HDR = struct.Struct("<8sIIQQQQ")
REC = struct.Struct("<QHB5x")


def read(path):
    """Return (origin, dropped, [(cycle - origin, pin, level), ...])."""
    with open(path, "rb") as f:
        return read_bytes(f.read())


def read_bytes(data):
    """read() of a trace already in memory."""
    magic, version, rec_size, origin, count, dropped, _end = HDR.unpack_from(data)
    if magic != b"PRUTRACE" or version != 2 or rec_size != REC.size:
        raise ValueError("not a version 2 prusim trace")
    if len(data) != HDR.size + count * REC.size:
        raise ValueError("trace size does not match its record count")
    events = []
    for i in range(count):
        cycle, pin, level = REC.unpack_from(data, HDR.size + i * REC.size)
        events.append((cycle - origin, pin, level))
    return origin, dropped, events


def edges(events, pin):
    """Cycles (relative) and levels of the changes of one pin."""
    return [(c, lv) for c, p, lv in events if p == pin]


def end_bytes(data):
    """The cycle (relative, as the events) the trace was taken at."""
    _, _, _, origin, _, _, end = HDR.unpack_from(data)
    return end - origin
