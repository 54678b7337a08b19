#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""Host checks of prukit-pixeld (tools/pixeld/prukit-pixeld): its mapping
and protocol rules, in the process with a clock of our own (Pixeld fed
packets built by pixel_send.py from the standards), and the daemon as a
program (its command line, signals and sockets on loopback).  The VM test
94-pixeld runs it on the devices with real senders; fuzz.py throws bad
input at it.  Prints PASS:/FAIL: lines; exits 1 if any failed."""
import atexit
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.dont_write_bytecode = True  # no __pycache__ in the tree
HERE = os.path.dirname(os.path.realpath(__file__))
DAEMON = os.path.join(HERE, "..", "prukit-pixeld")
sys.path[:0] = [HERE, os.path.join(HERE, "..")]
import pixel_send as ps  # noqa: E402
from prukit_pixeld import config, merge, outputs, protocols, server  # noqa: E402

failed = 0
TMP = tempfile.mkdtemp(prefix="pixeld-check.")
atexit.register(shutil.rmtree, TMP, ignore_errors=True)


def check(name, cond, detail=""):
    global failed
    print(("PASS: " if cond else "FAIL: ") + "pixeld: " + name +
          ("" if cond or detail == "" else ": " + str(detail)), flush=True)
    failed += not cond
    return cond


class Clock:
    def __init__(self):
        self.t = 1000.0

    def __call__(self):
        return self.t


def conf(text, name="t.conf"):
    path = os.path.join(TMP, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def make(text):
    """A Pixeld on TEXT's configuration, its clock, and reader of the
    frames each file output got."""
    clock = Clock()
    px = merge.Pixeld(config.Config(conf(text)), clock=clock)
    return px, clock


def wait_for(cond, timeout=10):
    """Poll COND (a callable) every 20 ms until it is true or TIMEOUT s have
    passed; its last value."""
    end = time.monotonic() + timeout
    while True:
        got = cond()
        if got or time.monotonic() >= end:
            return got
        time.sleep(0.02)


def frames(name, size):
    """Every frame a file output (append) got."""
    try:
        with open(os.path.join(TMP, name), "rb") as f:
            data = f.read()
    except OSError:
        return []
    return [data[i:i + size] for i in range(0, len(data), size)]


def fresh(*names):
    for n in names:
        try:
            os.unlink(os.path.join(TMP, n))
        except OSError:
            pass


def pattern(n, seed=0):
    return bytes((i * 7 + seed * 13 + i // 256) % 256 for i in range(n))


# --- configuration errors --------------------------------------------------------------------
BAD = [("output a file x 10\nmap a e131 universe 0\n", ":2: map a e131: universe is a whole "
        "number from 1 to 63999, not '0'"),
       ("output a file x 10\nmap a e131 channel 513\n", ":2: map a e131: channel is a whole "
        "number from 1 to 512, not '513'"),
       ("output a file x 10\nmap a opc channel 3 at\n", ":2: map a opc: keys and values go in "
        "pairs"),
       ("output a file x 10\nmap a opc channel 0\n", ":2: map a opc: channel is a whole "
        "number from 1 to 255, not '0'"),
       ("output a file x 10\nmap a ddp offset -1\n", ":2: map a ddp: offset is a whole number"),
       ("output a file x 10\nmap a e131 layout zigzag\n", ":2: map a e131: layout is "
        "contiguous"),
       ("output a file x 10\nmap b opc\n", ":2: map: no output 'b' defined above"),
       ("output a file x 10\noutput a file y 10\nmap a opc\n", ":2: output a is defined twice"),
       ("output a ws281x /dev/a /dev/b\nmap a opc\n",
        ":1: output a: 'ws281x /dev/a /dev/b' is not"),
       ("output a file x 10\nmap a opc\nopc maybe\n", ":3: opc is on or off, not 'maybe'"),
       ("output a file x 10\nmap a opc\nopc-port 70000\n", ":3: opc-port is a whole number "
        "from 1 to 65535"),
       ("output a file x 10\nmap a opc\nframe-wait 99\n", ":3: frame-wait is seconds"),
       ("output a file x 10\nmap a opc\nbrightness 50\n", ":3: unknown keyword 'brightness'"),
       ("output a file x 10\n", ": no map line: nothing would be shown")]
for text, want in BAD:
    try:
        config.Config(conf(text))
        got = "accepted"
    except config.ConfigError as e:
        got = str(e)
    check("a configuration with %r is refused: %r" % (text.splitlines()[-1], want),
          want in got and got.startswith(os.path.join(TMP, "t.conf")), got)
try:
    config.Config(os.path.join(TMP, "none.conf"))
    got = ""
except config.ConfigError as e:
    got = str(e)
check("a missing configuration file: named, with the reason", "none.conf: No such file" in got,
      got)
try:
    c = config.Config(os.path.join(HERE, "..", "pixeld.conf"))
    check("the installed configuration (tools/pixeld/pixeld.conf) is valid: /dev/ws281x0 from "
          "universe 1, OPC channel 1 and DDP", [(m.proto, m.output.where) for m in c.maps] ==
          [("e131", "/dev/ws281x0"), ("opc", "/dev/ws281x0"), ("ddp", "/dev/ws281x0")])
except config.ConfigError as e:
    check("the installed configuration (tools/pixeld/pixeld.conf) is valid", False, e)

# --- the wire formats, on their own (prukit_pixeld.protocols) -----------------------------------
d = protocols.parse_e131(ps.e131_data(7, [1, 2, 3], cid=b"C" * 16, seq=9, priority=120,
                                      sync=4, options=0x20))
check("parse_e131: a data packet's source, priority, sync universe, sequence, options, "
      "universe, start code and slots", isinstance(d, protocols.E131Data) and
      d[:7] == (b"C" * 16, 120, 4, 9, 0x20, 7, 0) and bytes(d.slots) == bytes([1, 2, 3]), d)
check("parse_e131: a sync packet", protocols.parse_e131(ps.e131_sync(4, cid=b"C" * 16, seq=3)) ==
      protocols.E131Sync(b"C" * 16, 3, 4))
check("parse_e131: the reasons, as counted", [protocols.parse_e131(x) for x in (
    b"x" * 20, ps.e131_data(1, [1])[:-1], ps.e131_data(1, [1], priority=201))] ==
    ["dropped.truncated", "dropped.length", "dropped.range"])
check("parse_opc: set pixels (a last partial pixel left out), system exclusive ignored",
      (tuple(bytes(x) if isinstance(x, memoryview) else x
             for x in protocols.parse_opc(ps.opc_message(3, bytes(range(7))))),
       protocols.parse_opc(ps.opc_message(3, b"", command=0xFF))) ==
      ((3, bytes(range(6))), "ignored.sysex"))
d = protocols.parse_ddp(ps.ddp_packets(bytes([5]) * 6, offset=30, dtype=0x80)[0])
check("parse_ddp: flags, offset and data, whatever the data type",
      (d.flags & protocols.DDP_PUSH, d.offset, bytes(d.data)) == (1, 30, bytes([5]) * 6), d)

# --- E1.31 layouts ---------------------------------------------------------------------------
fresh("p")
px, clock = make("output p file %s/p 2048 append\nmap p e131 universe 7\n" % TMP)
pic = pattern(6144)
for k in range(12):
    px.feed_e131(ps.e131_data(7 + k, pic[k * 512:(k + 1) * 512]))
got = frames("p", 6144)
check("contiguous: a 64x32 picture over universes 7-18 (12 x 512 channels) is one frame, "
      "exactly; pixels 170, 341 ... straddle two universes", got == [pic], len(got))
check("universes 7-18 are mapped, no other", sorted(px.universes) == list(range(7, 19)))
px.feed_e131(ps.e131_data(19, bytes(512)))
px.feed_e131(ps.e131_data(6, bytes(512)))
check("universes 6 and 19: ignored (e131.ignored.universe 2), nothing kept for them",
      px.stats.get("e131.ignored.universe") == 2 and sorted(px.universes) == list(range(7, 19)))

fresh("q")
px, clock = make("output q file %s/q 400 append\nmap q e131 universe 1 layout pixels\n" % TMP)
u = [pattern(512, k) for k in range(3)]
for k in range(3):
    px.feed_e131(ps.e131_data(1 + k, u[k]))
want = u[0][:510] + u[1][:510] + u[2][:180]
check("layout pixels (RGB): 170 pixels per universe, channels 511-512 unused, 400 pixels over "
      "universes 1-3", frames("q", 1200) == [want])

fresh("r")
px, clock = make("output r file %s/r 300 rgbw append\n"
                 "map r e131 universe 1 channel 4 layout pixels\n" % TMP)
for k in range(3):
    px.feed_e131(ps.e131_data(1 + k, u[k]))
want = u[0][3:3 + 508] + u[1][:512] + u[2][:(300 - 127 - 128) * 4]
check("layout pixels (RGBW), from channel 4: 127 pixels in universe 1 (channels 4-511), "
      "128 in each next one from channel 1", frames("r", 1200) == [want])

fresh("s")
px, clock = make("output s file %s/s 20 rgbw append\n"
                 "map s e131 universe 1 channel 500 pixels 5 at 10\n" % TMP)
px.feed_e131(ps.e131_data(1, pattern(512)))
check("a map across two universes writes nothing until both came",
      frames("s", 80) == [], frames("s", 80))
px.feed_e131(ps.e131_data(2, pattern(512, 1)))
f = frames("s", 80)
want = bytes(40) + pattern(512)[499:] + pattern(512, 1)[:7] + bytes(20)
check("contiguous RGBW from channel 500: 13 + 7 channels, pixel 13 straddling, at pixel 10 "
      "of 20", f == [want], f)

# --- sources, priority, sequence, sync ----------------------------------------------------
fresh("a")
px, clock = make("output a file %s/a 4 append\nmap a e131 universe 1\n" % TMP)
A, B = b"A" * 16, b"B" * 16


def last():
    f = frames("a", 12)
    return f[-1][0] if f else None


px.feed_e131(ps.e131_data(1, [1] * 12, cid=A, seq=0, priority=100))
px.feed_e131(ps.e131_data(1, [2] * 12, cid=B, seq=0, priority=150))
px.feed_e131(ps.e131_data(1, [3] * 12, cid=A, seq=1, priority=100))
check("priority: 150 wins over 100 (the lower's new data not shown)", last() == 2 and
      px.stats.get("e131.lower_priority") == 1, frames("a", 12))
px.feed_e131(ps.e131_data(1, [4] * 12, cid=B, seq=1, priority=150))
clock.t += 2.4
px.feed_e131(ps.e131_data(1, [5] * 12, cid=A, seq=2, priority=100))
px.tick()
check("2.4 s after the higher's last packet: still the higher's", last() == 4)
clock.t += 0.2
px.tick()
check("2.6 s: the higher timed out, the lower's last data shown at once", last() == 5 and
      px.stats.get("e131.timeouts") == 1)
px.feed_e131(ps.e131_data(1, [6] * 12, cid=B, seq=2, priority=150))
px.feed_e131(ps.e131_data(1, [7] * 12, cid=B, seq=3, priority=150, options=0x40))
check("stream terminated (its data not shown): the lower takes over at once", last() == 5 and
      px.stats.get("e131.terminated") == 1, [f[0] for f in frames("a", 12)])
C = b"C" * 16
px.feed_e131(ps.e131_data(1, [8] * 12, cid=C, seq=0, priority=100))
check("equal priority: the source shown first stays", last() == 5)
px.feed_e131(ps.e131_data(1, [20] * 12, cid=b"D" * 16, seq=0, priority=150))
px.feed_e131(ps.e131_data(1, [21] * 12, cid=b"D" * 16, seq=1, priority=150, options=0x40))
check("the winner gone, two of equal priority left: the one known longest shown",
      [f[0] for f in frames("a", 12)][-2:] == [20, 5])
px.feed_e131(ps.e131_data(1, [9] * 12, cid=A, seq=3, priority=100))
px.feed_e131(ps.e131_data(1, [10] * 12, cid=A, seq=2, priority=100))
px.feed_e131(ps.e131_data(1, [11] * 12, cid=A, seq=240, priority=100))
px.feed_e131(ps.e131_data(1, [12] * 12, cid=A, seq=3 + 236, priority=100))
check("sequence: one back is late (dropped), 20 or more back is a restart (taken)",
      [f[0] for f in frames("a", 12)][-2:] == [9, 12] and
      px.stats.get("e131.dropped.late") == 2, [f[0] for f in frames("a", 12)])
check("sequence 255 -> 0 wraps", (px.feed_e131(ps.e131_data(1, [13] * 12, cid=A, seq=255)),
                                  px.feed_e131(ps.e131_data(1, [14] * 12, cid=A, seq=0)),
                                  last())[-1] == 14)

fresh("m")
px, clock = make("output m file %s/m 4 append\nmap m e131 universe 1\nmax-sources 3\n" % TMP)
for k in range(40):
    px.feed_e131(ps.e131_data(1, [k] * 12, cid=b"%16d" % k))
check("max-sources 3: 40 sources, 3 kept, 37 dropped (e131.dropped.sources_full)",
      len(px.universes[1].sources) == 3 and px.stats.get("e131.dropped.sources_full") == 37)
px.feed_e131(ps.e131_data(1, [77] * 12, cid=b"%16d" % 77, priority=150))
check("... a source of a higher priority than theirs is taken all the same, in the place of "
      "the lowest (e131.sources_evicted 1), and shown", frames("m", 12)[-1][0] == 77 and
      len(px.universes[1].sources) == 3 and px.stats.get("e131.sources_evicted") == 1)
px.feed_e131(ps.e131_data(1, [78] * 12, cid=b"%16d" % 78, priority=150))
check("... one of the same priority as the lowest is not", frames("m", 12)[-1][0] == 77 and
      px.stats.get("e131.dropped.sources_full") == 37)
clock.t += 3
px.tick()
px.feed_e131(ps.e131_data(1, [99] * 12, cid=b"%16d" % 99))
check("once they timed out, a new source is taken", frames("m", 12)[-1][0] == 99)

fresh("y")
px, clock = make("output y file %s/y 400 append\nmap y e131 universe 1\n" % TMP)
px.feed_e131(ps.e131_data(1, [1] * 512, sync=9))
px.feed_e131(ps.e131_data(2, [2] * 512, sync=9))
px.feed_e131(ps.e131_data(3, [3] * 176, sync=9))
check("synchronized universes: nothing before the sync packet", frames("y", 1200) == [])
px.feed_e131(ps.e131_sync(8))
check("a sync packet for another universe: ignored", frames("y", 1200) == [] and
      px.stats.get("e131.ignored.sync") == 1)
px.feed_e131(ps.e131_sync(9))
check("the sync packet: all three universes in one frame",
      frames("y", 1200) == [bytes([1] * 512 + [2] * 512 + [3] * 176)])
px.feed_e131(ps.e131_sync(9, seq=0))
check("a repeated sync (same sequence) changes nothing", len(frames("y", 1200)) == 1)
for step in (1, 2, 3):		# the source sends on, the sync packets stopped
    clock.t += 1.3
    for k, n in ((1, 512), (2, 512), (3, 176)):
        px.feed_e131(ps.e131_data(k, [step * 10 + k] * n, sync=9, seq=step))
    px.tick()
    if step == 2:
        check("data waiting 1.3 s for a sync packet: not shown yet",
              len(frames("y", 1200)) == 1)
check("no sync packet for 2.6 s (the source timeout): synchronization lost (e131.sync_lost "
      "1); without Force_Synchronization the data is held, as E1.31 asks",
      px.stats.get("e131.sync_lost") == 1 and len(frames("y", 1200)) == 1)
px.feed_e131(ps.e131_sync(9, seq=1))
check("sync packets again: the newest data shown at once (e131.sync_resumed 1)",
      px.stats.get("e131.sync_resumed") == 1 and
      frames("y", 1200)[1:] == [bytes([31] * 512 + [32] * 512 + [33] * 176)])
px.feed_e131(ps.e131_data(1, [41] * 512, sync=9, seq=4))
check("... and the next data waits for its sync packet again", len(frames("y", 1200)) == 2)


def sync_frames(force):
    """10 s of a 25 fps source naming sync universe 9, whose sync packets
    never come: the frames shown."""
    fresh("ys")
    px, clock = make("output ys file %s/ys 4 append\nmap ys e131 universe 1\n" % TMP)
    for k in range(250):
        px.feed_e131(ps.e131_data(1, [k % 256] * 12, sync=9, seq=k, options=0x20 * force))
        clock.t += 0.04
        px.tick()
    return px, frames("ys", 12)


px, got = sync_frames(True)
check("sync packets lost, Force_Synchronization set: after the source timeout every frame is "
      "shown at once (%d of 250 frames in 10 s; before: one per timeout)" % len(got),
      185 <= len(got) <= 190 and got[-1] == bytes([249]) * 12 and
      px.stats.get("e131.sync_lost") == 1, len(got))
px.feed_e131(ps.e131_sync(9))
px.feed_e131(ps.e131_data(1, [7] * 12, sync=9, seq=250, options=0x20))
check("... sync packets back: synchronized again (the next data waits for its sync packet)",
      frames("ys", 12)[-1] == bytes([249]) * 12 and px.stats.get("e131.sync_resumed") == 1)
px, got = sync_frames(False)
check("sync packets lost, Force_Synchronization clear: held, nothing shown (E1.31 6.2.6), "
      "e131.sync_lost counted once", got == [] and px.stats.get("e131.sync_lost") == 1, len(got))

# sync packets of CIDs whose data names no such sync universe: ignored, not kept
fresh("ya")
px, clock = make("output ya file %s/ya 4 append\nmap ya e131 universe 1\nmax-sources 3\n"
                 % TMP)
L, N = b"L" * 16, b"N" * 16
px.feed_e131(ps.e131_data(1, [1] * 12, cid=L, sync=9))
for k in range(7):
    px.feed_e131(ps.e131_sync(9, cid=bytes([k]) * 16))
check("sync packets of 7 strangers (CIDs whose data names no sync universe 9): ignored, "
      "nothing released, nothing kept", frames("ya", 12) == [] and not px.sync_sources and
      px.stats.get("e131.ignored.sync") == 7, px.sync_sources)
px.feed_e131(ps.e131_sync(9, cid=L))
check("... the data's own sender's sync packet: shown", frames("ya", 12) == [bytes([1]) * 12])

# the table of sync packets' senders ages (once full, it refused new senders for good)
fresh("yt")
px, clock = make("output yt file %s/yt 4 append\nmap yt e131 universe 1\nmax-sources 3\n"
                 % TMP)
for k in range(3):		# senders with a new CID at every start
    cid = b"%16d" % k
    px.feed_e131(ps.e131_data(1, [k] * 12, cid=cid, sync=9))
    px.feed_e131(ps.e131_sync(9, cid=cid))
    clock.t += 3
    px.tick()
clock.t += 100
px.tick()
px.feed_e131(ps.e131_data(1, [9] * 12, cid=N, sync=9))
px.feed_e131(ps.e131_sync(9, cid=N))
check("3 senders came and went (max-sources 3 x 1 universe); 100 s later a new sender's sync "
      "packet is taken at once (the others aged out)",
      frames("yt", 12)[-1:] == [bytes([9]) * 12] and
      not px.stats.get("e131.dropped.sources_full"), [f[0] for f in frames("yt", 12)])

# a source that lost priority: its pending data and sync packet change nothing
fresh("yp")
px, clock = make("output yp file %s/yp 4 append\nmap yp e131 universe 1\n" % TMP)
px.feed_e131(ps.e131_data(1, [1] * 12, cid=A, priority=100, sync=9))
px.feed_e131(ps.e131_data(1, [2] * 12, cid=B, priority=150))
px.feed_e131(ps.e131_sync(9, cid=A))
check("a source that lost priority: its own sync packet does not show its pending data over "
      "the winner's", frames("yp", 12) == [bytes([2]) * 12], frames("yp", 12))

# E1.31's layers: the flags of every one; terminated whatever the preview bit
fresh("yf")
px, clock = make("output yf file %s/yf 4 append\nmap yf e131 universe 1\n" % TMP)
pk = bytearray(ps.e131_data(1, [1] * 12))
pk[38] &= 0x0f
pk[38] |= 0x60
px.feed_e131(bytes(pk))
pk = bytearray(ps.e131_data(1, [1] * 12))
pk[115] &= 0x0f
px.feed_e131(bytes(pk))
pk = bytearray(ps.e131_sync(9))
pk[38] &= 0x0f
px.feed_e131(bytes(pk))
check("flags other than 0x7 in the framing layer (data, sync) and the DMP layer: dropped",
      (px.stats.get("e131.dropped.framing"), px.stats.get("e131.dropped.dmp"),
       frames("yf", 12)) == (2, 1, []))
px.feed_e131(ps.e131_data(1, [3] * 12, cid=A, priority=150))
px.feed_e131(ps.e131_data(1, [4] * 12, cid=B, priority=100))
px.feed_e131(ps.e131_data(1, [5] * 12, cid=A, priority=150, seq=1, options=0xc0))
check("stream terminated with the preview bit set: the source ends all the same (the lower "
      "one's data shown)", frames("yf", 12)[-1:] == [bytes([4]) * 12] and
      px.stats.get("e131.terminated") == 1, frames("yf", 12))

fresh("z")
px, clock = make("output z file %s/z 400 append\nmap z e131 universe 1\n" % TMP)
px.feed_e131(ps.e131_data(1, [1] * 512))
px.feed_e131(ps.e131_data(2, [2] * 512))
clock.t += 0.04
px.tick()
check("unsynchronized: 2 of 3 universes, 40 ms: nothing yet (frame-wait 50 ms)",
      frames("z", 1200) == [])
px.feed_e131(ps.e131_data(3, [3] * 176))
check("the third: one frame", len(frames("z", 1200)) == 1)

# a sender cycling its data through sync universes cannot make the daemon leave groups in use
srv = server.Server(os.path.join(TMP, "none.conf"), False)
px, clock = make("output j file %s/j 1536\nmap j e131 universe 1\n" % TMP)
srv.px, px.on_join, mship = px, srv.join, []


def fake_membership(u, op):
    """Server.membership without the sockets: the groups joined, in order."""
    if op == socket.IP_DROP_MEMBERSHIP:
        srv.joined.pop(u)
        mship.remove(u)
    else:
        srv.joined[u] = [None, 0]
        mship.append(u)
    return True


srv.membership = fake_membership
for k in range(8):		# universes 1-8, each synchronized by its own sync universe
    px.feed_e131(ps.e131_data(1 + k, [k] * 512, cid=A, sync=101 + k))
    px.feed_e131(ps.e131_sync(101 + k, cid=A))
legit = sorted(mship)
for k in range(40):		# universe 9's data names one sync universe after another
    px.feed_e131(ps.e131_data(9, [k] * 512, cid=B, sync=200 + k, seq=k))
    clock.t += 0.02
check("data cycling through 40 sync universes while 8 joined ones have sync packets: none of "
      "the 8 left, the new ones not joined (e131.sync_groups_full 40)",
      legit == list(range(101, 109)) and sorted(mship) == legit and
      srv.stats.get("e131.sync_groups_full") == 40 and not srv.stats.get("e131.sync_groups_left"),
      (sorted(mship), srv.stats.get("e131.sync_groups_full")))
clock.t += 3
px.feed_e131(ps.e131_data(9, [1] * 512, cid=B, sync=300, seq=41))
check("once a joined group had no sync packet for the source timeout, a new one takes its place",
      300 in mship and len(mship) == 8 and srv.stats.get("e131.sync_groups_left") == 1, mship)

# --- each output written at most once per turn of the event loop ------------------------------------
fresh("ob")
px, clock = make("output ob file %s/ob 4 append\nmap ob opc channel 1\nmap ob e131 universe 1\n"
                 % TMP)
px.defer = True
for k in range(16384):
    px.feed_opc(ps.opc_message(1, bytes([k % 251]) * (12 if k % 64 == 0 else 0)))
check("deferred (the event loop's way): 16384 OPC messages of one read write nothing yet",
      frames("ob", 12) == [])
px.flush_ready()
check("... then one frame, the newest data (output.ob.superseded 16383)",
      frames("ob", 12) == [bytes([16320 % 251]) * 12] and
      px.stats.get("output.ob.superseded") == 16383, len(frames("ob", 12)))
px.feed_e131(ps.e131_data(1, [5] * 12, seq=1))
px.feed_e131(ps.e131_data(1, [6] * 12, seq=2))
px.flush_ready()
px.flush_ready()
check("two E1.31 frames in one turn: one write, the second frame whole",
      frames("ob", 12)[1:] == [bytes([6]) * 12], frames("ob", 12))

# --- the E1.31 receive buffer -------------------------------------------------------------------


class FakeSock:
    """getsockopt/setsockopt of SO_RCVBUF under a net.core.rmem_max of CAP."""

    def __init__(self, cap):
        self.cap, self.buf = cap, 212992

    def getsockopt(self, level, opt):
        return self.buf

    def setsockopt(self, level, opt, value):
        self.buf = max(self.buf, min(2 * value, 2 * self.cap))


got, want = server.Server.size_rcvbuf(FakeSock(4194304), 170)
check("170 universes: a receive buffer for 4 frames of them asked (%d KiB), got under an "
      "rmem_max of 4 MiB" % (want >> 10), want == 170 * 4 * 2304 and got >= want, (got, want))
got, want = server.Server.size_rcvbuf(FakeSock(212992), 170)
check("... under Debian's rmem_max (208 KiB): less, and the log says what to raise it to",
      got < want, (got, want))
got, want = server.Server.size_rcvbuf(FakeSock(212992), 103, "DDP", "datagram")
check("DDP, frames of 103 datagrams (24 64x32 panels): 4 of them asked (%d KiB); under "
      "Debian's rmem_max the most it allows, more than the default and a whole frame" % (
          want >> 10), want == 103 * 4 * 2304 and got == 2 * 212992 and got >= 103 * 2304,
      (got, want))

# --- unsynchronized frames: never two mixed ----------------------------------------------------
def torn_run(sends):
    """SENDS: (universe, frame number k, sequence) in order, each universe's
    170 pixels all k; the frames written to a 3-universe output, as the
    list of each one's three universes' k (a frame whole: all three alike)."""
    fresh("t3")
    px, clock = make("output t3 file %s/t3 510 append\nmap t3 e131 universe 1 layout pixels\n"
                     % TMP)
    for u, k, seq in sends:
        px.feed_e131(ps.e131_data(u, [k] * 510, seq=seq))
        clock.t += 0.001
        px.tick()
    clock.t += 0.1		# frame-wait: what was gathered of a last frame is shown
    px.tick()
    return px, [(f[0], f[510], f[1020]) for f in frames("t3", 1530)]


sends = [(2, 10, 10), (3, 10, 10)] + [(u, k, k) for k in range(11, 16) for u in (1, 2, 3)]
px, got = torn_run(sends)
check("a stream met mid-frame (frame 10's universes 2 and 3 first): what came of frame 10 "
      "shown on its own (universe 1 as it was), frames 11-15 whole, never two sent frames "
      "mixed", got == [(0, 10, 10)] + [(k, k, k) for k in range(11, 16)], got)
lockstep = [(u, k, k) for k in range(11, 14) for u in (1, 2, 3)]
sends = lockstep + [(2, 14, 14), (3, 14, 14)] + [(u, 15, 15) for u in (1, 2, 3)]
px, got = torn_run(sends)
check("3 whole frames numbered alike make the output strict; then frame 14's first universe "
      "lost: frame 14's rest dropped (output.t3.incomplete 1), frame 15 whole",
      got == [(k, k, k) for k in (11, 12, 13, 15)] and
      px.stats.get("output.t3.incomplete") == 1, got)
sends = lockstep + [(1, 14, 14), (2, 14, 14), (1, 15, 15), (3, 14, 14), (2, 15, 15),
                    (3, 15, 15)]
px, got = torn_run(sends)
check("strict: a universe of frame 14 arriving after frame 15 began: late (not shown), "
      "frame 15 whole", got == [(k, k, k) for k in (11, 12, 13, 15)] and
      px.stats.get("output.t3.late") == 1, got)
sends = [(u, k, (k + 50 * u) % 256) for k in range(1, 9) for u in (1, 2, 3)]
px, got = torn_run(sends)
check("a sender whose universes are numbered apart (not one number a frame): each universe "
      "taken as it comes, every frame shown, never made strict",
      got == [(k, k, k) for k in range(1, 9)] and not px.strict, got)

# --- OPC ------------------------------------------------------------------------------------------
fresh("o", "o2")
px, clock = make("output o file %s/o 10 rgbw append\noutput o2 file %s/o2 4 append\n"
                 "map o opc channel 1 pixels 4 at 2\nmap o opc channel 2 at 6\n"
                 "map o2 opc channel 2\nmap o ddp\n" % (TMP, TMP))
px.feed_ddp(ps.ddp_packets(b"\xff" * 40)[0])
px.feed_opc(ps.opc_message(1, pattern(15)))
check("OPC channel 1: 4 pixels at 2 of an RGBW output (W off there, the rest as DDP left "
      "it), the 5th pixel sent ignored", frames("o", 40)[1:] == [
          b"\xff" * 8 + b"".join(pattern(15)[i:i + 3] + b"\0" for i in range(0, 12, 3)) +
          b"\xff" * 16])
px.feed_opc(ps.opc_message(0, bytes([9]) * 13))
f = frames("o", 40)[-1]
check("channel 0: every map (both outputs written); a partial pixel ignored",
      len(frames("o", 40)) == 3 and frames("o2", 12) == [bytes([9]) * 12] and
      f[:8] == b"\xff" * 8 and f[8:24] == bytes([9, 9, 9, 0]) * 4 and
      f[24:] == bytes([9, 9, 9, 0]) * 4, f)
px.feed_opc(ps.opc_message(1, bytes(3), command=0xFF))
px.feed_opc(ps.opc_message(1, bytes(3), command=7))
px.feed_opc(ps.opc_message(3, bytes(3)))
px.feed_opc(ps.opc_message(1, bytes(3))[:-1])
px.feed_opc(b"\x01\x00")
c = px.stats
check("OPC: system exclusive, an unknown command, an unmapped channel ignored; a short "
      "message and a truncated header dropped; nothing written",
      (c.get("opc.ignored.sysex"), c.get("opc.ignored.command"), c.get("opc.ignored.channel"),
       c.get("opc.dropped.length"), c.get("opc.dropped.truncated"), len(frames("o", 40))) ==
      (1, 1, 1, 1, 1, 3))

# --- DDP ------------------------------------------------------------------------------------------
fresh("d")
px, clock = make("output d file %s/d 1000 append\nmap d ddp offset 300 pixels 900 at 100\n"
                 % TMP)
data = pattern(3000)
pk = ps.ddp_packets(data, size=1440)
px.feed_ddp(pk[0])
px.feed_ddp(pk[1])
check("DDP: nothing before the push", frames("d", 3000) == [])
check("ddp_bytes(): a DDP frame for the open outputs is 3000 bytes (offset 300, 900 pixels)",
      px.ddp_bytes() == 3000, px.ddp_bytes())
px.feed_ddp(pk[2])
check("DDP, 3 packets, push on the last: bytes 300-2999 at pixel 100, once",
      frames("d", 3000) == [bytes(300) + data[300:3000]], len(frames("d", 3000)))
tc = bytearray(ps.ddp_packets(bytes([5]) * 30, offset=300)[0])
tc[0] |= 0x10
tc[10:10] = b"\0\0\0\0"		# a timecode
px.feed_ddp(bytes(tc))
check("a timecode (14-byte header): the data after it", frames("d", 3000)[-1][300:330] ==
      bytes([5]) * 30)
q = bytearray(ps.ddp_packets(bytes(6))[0])
q[0] |= 0x02
px.feed_ddp(bytes(q))
v = bytearray(ps.ddp_packets(bytes(6))[0])
v[0] = 0x81
px.feed_ddp(bytes(v))
px.feed_ddp(ps.ddp_packets(bytes(6), dest=7)[0])
px.feed_ddp(ps.ddp_packets(bytes(60))[0][:-1])
c = px.stats
check("DDP: a query and another destination ignored; version 2 and a truncated packet dropped",
      (c.get("ddp.ignored.query"), c.get("ddp.ignored.destination"), c.get("ddp.dropped.version"),
       c.get("ddp.dropped.truncated")) == (1, 1, 1, 1))
n = len(frames("d", 3000))
px.feed_ddp(ps.ddp_packets(bytes([7]) * 30, offset=300, dtype=0x0D)[0])
px.feed_ddp(ps.ddp_packets(bytes([8]) * 30, offset=330, dtype=0x2B, push=False)[0])
check("data types 0x0D (ddp-rs's and python-led-ddp's default) and 0x2B: taken, as WLED "
      "takes them", len(frames("d", 3000)) == n + 1 and
      frames("d", 3000)[-1][300:330] == bytes([7]) * 30, len(frames("d", 3000)) - n)
px.feed_ddp(bytes.fromhex("41008001000000000000"))
check("xLights' sync push (flags 0x41, data type 0x80, no data): the data before it written",
      len(frames("d", 3000)) == n + 2 and frames("d", 3000)[-1][330:360] == bytes([8]) * 30)

# --- an output that comes later ---------------------------------------------------------------
later = os.path.join(TMP, "later")
px, clock = make("output l file %s/f 4 append\nmap l opc\n" % later)
px.feed_opc(ps.opc_message(1, bytes([1]) * 12))
check("an output not there: nothing mapped, the message ignored", not px.opc_maps and
      px.stats.get("opc.ignored.channel") == 1)
os.mkdir(later)
clock.t += 4
px.tick()
check("4 s later (retry every 5 s): not yet", not px.opc_maps)
clock.t += 1.1
px.tick()
px.feed_opc(ps.opc_message(1, bytes([2]) * 12))
check("5 s: opened, mapped, written", frames("later/f", 12) == [bytes([2]) * 12])

# --- framebuffer formats ------------------------------------------------------------------------
fbo = outputs.FbOutput("fb", "/dev/null")
fbo.pixels, fbo.buf = 2, bytearray([0xff, 0x80, 0x01, 0x12, 0x34, 0x56])
fbo.fmt, fbo.where_rgb = "32", (2, 1, 0)
check("a framebuffer of 32 bits, red at 16 (XRGB8888, the hub75 driver's): B, G, R, X bytes",
      bytes(fbo.frame()) == bytes([0x01, 0x80, 0xff, 0, 0x56, 0x34, 0x12, 0]))
fbo.where_rgb = (0, 1, 2)
check("32 bits, red at 0 (XBGR8888): R, G, B, X bytes",
      bytes(fbo.frame()) == bytes([0xff, 0x80, 0x01, 0, 0x12, 0x34, 0x56, 0]))
fbo.fmt = "565"
check("RGB565: the top 5, 6, 5 bits, little-endian",
      bytes(fbo.frame()) == bytes([0x00, 0xfc, 0xaa, 0x11]), bytes(fbo.frame()).hex())

# --- the program ----------------------------------------------------------------------------------


def free_port(kind=socket.SOCK_DGRAM):
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


r = subprocess.run([sys.executable, DAEMON, "--help"], capture_output=True, text=True)
check("--help names the configuration file /etc/prukit/pixeld.conf", r.returncode == 0 and
      "/etc/prukit/pixeld.conf" in r.stdout, r.stdout[-200:])
r = subprocess.run([sys.executable, DAEMON, "--config", conf("output a file x 10\n", "b.conf")],
                   capture_output=True, text=True)
check("a configuration with errors: exit 2, the errors, no traceback", r.returncode == 2 and
      "b.conf: no map line" in r.stderr and "Traceback" not in r.stderr, r.stderr)
ports = dict(e=free_port(), o=free_port(socket.SOCK_STREAM), d=free_port())
base = ("output f file %s/run 4 append\nstats-file %s/stats\nlisten 127.0.0.1\n"
        "e131-port %d\nopc-port %d\nddp-port %d\n"
        "output big file %s/big 21845 append\nmap big opc channel 2\n"
        % (TMP, TMP, ports["e"], ports["o"], ports["d"], TMP))
path = conf(base + "map f opc channel 1\n", "run.conf")
r = subprocess.run([sys.executable, DAEMON, "--config", path, "--check"], capture_output=True,
                   text=True)
check("--check: the maps, exit 0", r.returncode == 0 and "opc channel 1 -> output f" in r.stdout,
      r.stdout + r.stderr)
fresh("run")
p = subprocess.Popen([sys.executable, DAEMON, "--config", path], stderr=subprocess.PIPE,
                     text=True)
log = []
while True:
    line = p.stderr.readline()
    log.append(line)
    if not line or "listening" in line:
        break
check("it starts and listens on 127.0.0.1", "listening on 127.0.0.1" in log[-1], log)
# from here on a thread reads the daemon's log, and a check waits for the
# line it expects (logged())
reader = threading.Thread(target=lambda: log.extend(p.stderr), daemon=True)
reader.start()


def logged(text, since):
    """Whether the daemon logged TEXT after its first SINCE lines."""
    return any(text in ln for ln in log[since:])


opc = ps.OpcClient(port=ports["o"])
opc.put_pixels(1, bytes([1]) * 12)
check("OPC on TCP: the frame", wait_for(lambda: frames("run", 12) == [bytes([1]) * 12]),
      frames("run", 12))
big = pattern(65535, 5)
opc.put_pixels(2, big)
end = time.monotonic() + 10
while time.monotonic() < end and not frames("big", 65535):
    time.sleep(0.1)
check("OPC on TCP, the largest message (65535 bytes, 21845 pixels: more than a UDP datagram "
      "holds): the frame", frames("big", 65535) == [big], len(frames("big", 65535)))
with open(path, "a") as f:
    f.write("map f ddp offset x\n")
n = len(log)
p.send_signal(signal.SIGHUP)
hup = wait_for(lambda: logged("the running configuration stays", n))
opc.put_pixels(1, bytes([2]) * 12)
check("SIGHUP with an error: the running configuration stays (the connection too)",
      hup and wait_for(lambda: frames("run", 12)[-1:] == [bytes([2]) * 12]), log[n:])
conf(base + "map f ddp\n", "run.conf")
n = len(log)
p.send_signal(signal.SIGHUP)
hup = wait_for(lambda: logged("reloaded", n))
d = ps.DdpSender(port=ports["d"])
d.frame(bytes([3]) * 12)
check("SIGHUP with a good one: DDP mapped now",
      hup and wait_for(lambda: frames("run", 12)[-1:] == [bytes([3]) * 12]), log[n:])


def stats_now(want_key, want_value, timeout=10):
    """SIGUSR1 until the stats file says WANT_KEY >= WANT_VALUE; the counters."""
    end, got = time.monotonic() + timeout, {}
    while time.monotonic() < end:
        p.send_signal(signal.SIGUSR1)
        time.sleep(0.2)
        try:
            with open(os.path.join(TMP, "stats")) as f:
                got = dict(ln.split() for ln in f if len(ln.split()) == 2)
        except OSError:
            continue
        if int(got.get(want_key, 0)) >= want_value:
            break
    return got


u = ps.OpcClient(port=ports["o"], udp=True)
u.put_pixels(1, bytes([4]) * 12)
# taken and ignored (channel 1 is no longer OPC's) once the counter says so
stats = stats_now("opc.ignored.channel", 1)
check("... and OPC no longer", stats.get("opc.ignored.channel") == "1" and
      frames("run", 12)[-1:] == [bytes([3]) * 12], stats)
check("SIGUSR1: the counters in the stats file", stats.get("ddp.accepted") == "1" and
      stats.get("opc.ignored.channel") == "1" and stats.get("output.f.frames") == "3", stats)
before = stats_now("opc.accepted", 0)
with socket.create_connection(("127.0.0.1", ports["o"]), timeout=5) as c:
    c.sendall(b"".join(ps.opc_message(2, b"") for _ in range(2000)))
    after = stats_now("opc.accepted", int(before.get("opc.accepted", 0)) + 2000)
wrote = int(after.get("output.big.frames", 0)) - int(before.get("output.big.frames", 0))
check("2000 empty OPC messages in one TCP burst: all taken, the 65535-byte frame written %d "
      "times (at most once per turn of the loop; before: 2000)" % wrote,
      int(after.get("opc.accepted", 0)) - int(before.get("opc.accepted", 0)) == 2000 and
      1 <= wrote <= 50, (before, after))
q = subprocess.run([sys.executable, DAEMON, "--config", path], capture_output=True, text=True,
                   timeout=30)
check("a second daemon on the same ports: exit 1, why", q.returncode == 1 and
      "cannot listen" in q.stderr and "Address already in use" in q.stderr, q.stderr)
# datagrams the kernel drops for want of room in the receive buffer: counted


def udp_queued(port):
    """Bytes in the receive queue of the UDP socket bound to PORT
    (/proc/net/udp's rx_queue), None if there is none."""
    for table in ("/proc/net/udp", "/proc/net/udp6"):
        try:
            with open(table) as f:
                rows = [ln.split() for ln in f][1:]
        except OSError:
            continue
        for r in rows:
            if int(r[1].rsplit(":", 1)[1], 16) == port:
                return int(r[4].split(":")[1], 16)
    return None


before = stats_now("opc.accepted", 0)
p.send_signal(signal.SIGSTOP)
with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as tx:
    pk = ps.e131_data(1, bytes(512))
    for _ in range(3000):
        tx.sendto(pk, ("127.0.0.1", ports["e"]))
    p.send_signal(signal.SIGCONT)
    # once the daemon has read what the buffer held, one more datagram, which
    # carries the count of the drops before it
    wait_for(lambda: udp_queued(ports["e"]) == 0)
    tx.sendto(pk, ("127.0.0.1", ports["e"]))


def taken(st):
    return int(st.get("e131.received", 0)) + int(st.get("e131.kernel_drops", 0))


want = taken(before) + 3001
after = stats_now("e131.received", 0)
end = time.monotonic() + 10
while taken(after) < want and time.monotonic() < end:
    after = stats_now("e131.received", 0)
drops = int(after.get("e131.kernel_drops", 0)) - int(before.get("e131.kernel_drops", 0))
check("3000 E1.31 datagrams while the daemon was stopped: what the receive buffer could not "
      "hold counted as e131.kernel_drops (%d), received + dropped = sent" % drops,
      drops > 0 and taken(after) == want, (taken(after) - taken(before), drops))
shares = []
for port in (ports["e"], ports["d"]):
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as other:
        other.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            other.bind(("127.0.0.1", port))
            shares.append(port)
        except OSError:
            pass
check("a program binding the E1.31 or DDP port later with SO_REUSEADDR (olad does) gets "
      "EADDRINUSE: it cannot take the daemon's unicast in silence", shares == [], shares)
six = conf("output f file %s/six 4 append\nmap f opc\nlisten ::\ne131 off\nddp off\n"
           "opc-port %d\n" % (TMP, free_port(socket.SOCK_STREAM)), "six.conf")
port6 = int(open(six).read().split("opc-port ")[1])
p6 = subprocess.Popen([sys.executable, DAEMON, "--config", six], stderr=subprocess.PIPE,
                      text=True)
line = "x"
while line and "listening" not in line:
    line = p6.stderr.readline()
try:
    with socket.create_connection(("::1", port6), timeout=5) as c6:
        c6.sendall(ps.opc_message(1, bytes([6]) * 12))
    # the frame written before the next one comes: frames for one output
    # that arrive together are merged into the newest (a frame that waits)
    wait_for(lambda: len(frames("six", 12)) >= 1)
    OpcClient4 = ps.OpcClient(port=port6, udp=True)
    OpcClient4.put_pixels(1, bytes([4]) * 12)
    OpcClient4.close()
    wait_for(lambda: len(frames("six", 12)) >= 2)
    got6 = frames("six", 12)
except OSError as e:
    got6 = str(e)
p6.terminate()
p6.wait(timeout=10)
check("listen :: takes IPv6 (OPC over TCP to ::1) and IPv4 (UDP to 127.0.0.1)",
      "listening on ::" in line and isinstance(got6, list) and
      sorted(got6) == [bytes([4]) * 12, bytes([6]) * 12],
      (line, got6))


def multicast_run(text, name, netns=False):
    """A daemon on TEXT's configuration (E1.31 universe 5 onto file output
    NAME), in a network namespace of its own with only lo (up, no route)
    when NETNS; an E1.31 datagram sent to universe 5's group through lo.
    (the frames NAME got, the daemon's log)."""
    fresh(name)
    script = conf("""
import fcntl, os, socket, struct, subprocess, sys, time
if %(netns)r:
    sk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    req = struct.pack("40s", b"lo")
    flags = struct.unpack_from("=H", fcntl.ioctl(sk, 0x8913, req), 16)[0]
    fcntl.ioctl(sk, 0x8914, struct.pack("16sH", b"lo", flags | 1).ljust(40, b"\\0"))
d = subprocess.Popen([sys.executable, %(daemon)r, "--config", %(cfg)r],
                     stderr=subprocess.PIPE, text=True)
log = []
while not log or log[-1] and "listening" not in log[-1]:
    log.append(d.stderr.readline())
tx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
tx.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_IF, socket.inet_aton("127.0.0.1"))
tx.sendto(%(pkt)r, ("239.255.0.5", %(port)d))
end = time.monotonic() + 10     # until the frame is written (or 10 s)
while time.monotonic() < end and not (os.path.exists(%(out)r) and
                                      os.path.getsize(%(out)r) >= 12):
    time.sleep(0.02)
d.terminate()
log.append(d.communicate(timeout=10)[1])
print("".join(log))
""" % dict(netns=netns, daemon=DAEMON, cfg=conf(text, name + ".conf"), out=os.path.join(TMP, name),
           pkt=ps.e131_data(5, bytes([5]) * 12), port=int(text.split("e131-port ")[1].split()[0])),
                  name + ".py")
    cmd = ["unshare", "-n", sys.executable, script] if netns else [sys.executable, script]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    return frames(name, 12), r.stdout + r.stderr


mport = free_port()
got, out = multicast_run("output m file %s/mc 4 append\nmap m e131 universe 5\nlisten ::\n"
                         "multicast-interface 127.0.0.1\nopc off\nddp off\ne131-port %d\n"
                         % (TMP, mport), "mc")
check("listen :: receives E1.31 multicast (IPv4 groups reach an IPv4 socket of its own)",
      got == [bytes([5]) * 12], (got, out[-500:]))
mport = free_port()
got, out = multicast_run("output n file %s/nr 4 append\nmap n e131 universe 5\nopc off\n"
                         "ddp off\ne131-port %d\n" % (TMP, mport), "nr", netns=True)
check("no default route (a network namespace with lo only): the group is joined on every "
      "interface instead, the log says so, and multicast arrives", got == [bytes([5]) * 12] and
      "no route to the multicast groups" in out and "127.0.0.1" in out, (got, out[-800:]))
p.send_signal(signal.SIGTERM)
try:
    rc = p.wait(timeout=10)
except subprocess.TimeoutExpired:
    p.kill()
    rc = None
reader.join(timeout=10)     # it reads to the end of the daemon's log
rest = "".join(log)
check("SIGTERM: exit 0, no traceback", rc == 0 and "Traceback" not in rest, rest[-300:])
sys.exit(1 if failed else 0)
