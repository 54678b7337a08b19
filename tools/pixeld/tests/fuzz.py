#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""A time-bounded fuzzer of prukit-pixeld's receivers, on the host over
loopback: E1.31 (UDP), OPC (UDP and TCP) and DDP (UDP).

The daemon runs as a subprocess (with the descriptor limit systemd gives a
service, a soft RLIMIT_NOFILE of 1024) on a temporary configuration: high
free ports on 127.0.0.1, three file outputs in a temporary directory (E1.31
universes 7 and 8 onto 200 pixels, OPC channel 3 onto 300, DDP onto 480),
max-sources 4, opc-max-clients 4, source-timeout 1 s and a stats file read
after SIGUSR1.  The phases, each given a share of --seconds:

  - E1.31: valid data, sync and discovery packets and their mutations
    (truncated, extended, bits flipped, fields set to other values: the
    vectors, flags and lengths, preamble, ACN identifier, address type,
    counts, out-of-range universes, priorities and sync addresses, other
    start codes, the preview and terminated options), and random bytes;
  - a flood of hundreds of new CIDs on a mapped universe: at most
    max-sources of them are taken (the rest dropped.sources_full) and each
    one taken leaves when it times out;
  - data packets naming up to 2000 different synchronization addresses,
    from one winning source (enough for the descriptors to show it if the
    daemon keeps something per address: a multicast join is 1/20 of a
    socket);
  - OPC over UDP: valid messages and their mutations, random bytes;
  - OPC over TCP: more idle clients than opc-max-clients (the ones quiet
    longest are evicted: exactly those see the connection closed), one
    client sending 10 MB in one sendall, clients sending whole messages
    then half of one and hanging up (FIN, or RST), streams of mutated
    messages;
  - DDP: valid packets (push or not, timecode, query/reply/storage flags,
    other versions, data types, destinations and offsets) and their
    mutations, random bytes.

What is checked, each time against what was sent, never against the
daemon's own word alone:

  - after each phase the daemon is alive and shows a known frame exactly:
    a fresh random frame sent in each protocol (OPC over UDP and TCP) is
    the whole content of its file output, byte for byte;
  - the counters add up: for each protocol, received = accepted + the
    dropped.* + the ignored.*, and every datagram sent is either received
    or counted as dropped by the kernel (the drops column of /proc/net/udp
    for the daemon's port; sends are paced on the socket's receive queue so
    that the kernel should drop none); OPC's received also counts exactly
    the whole messages of the TCP streams (a stream's trailing part
    message is not one);
  - the state stays bounded: VmRSS after a warm-up and at the end (less
    than --rss-bound kB more), and the daemon's open descriptors from the
    start to the end (at most 2 more: the configuration bounds them);
  - SIGTERM ends it with status 0, and its log holds no traceback.

Prints PASS:/FAIL:/INFO: lines; exits 1 if a check failed.  A run is
repeated with its --seed (printed first); when the daemon dies, the last
256 datagrams and TCP streams sent are left in the work directory
(last-sent.txt), which a failed run keeps.

usage: fuzz.py [--seconds S] [--seed N] [--daemon PATH] [--rss-bound KB] [--keep]"""
import sys

sys.dont_write_bytecode = True  # noqa: E402 (no __pycache__ in the tree)

import argparse
import collections
import os
import random
import resource
import select
import shutil
import signal
import socket
import struct
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import pixel_send as ps  # noqa: E402

PYTHON = "/usr/bin/python3"
PROTOS = ("e131", "opc", "ddp")
MAX_SOURCES, OPC_MAX_CLIENTS, SOURCE_TIMEOUT = 4, 4, 1.0
E_UNI, E_PIXELS, O_CHAN, O_PIXELS, D_PIXELS = 7, 200, 3, 300, 480
UDP_MAX = 65507
FD_SLACK = 2

failures = []


class Gone(Exception):
    """The daemon died (a FAIL: line said so): the run stops."""


def say(kind, msg):
    print("%s: %s" % (kind, msg), flush=True)


def check(ok, msg):
    if ok:
        say("PASS", msg)
    else:
        say("FAIL", msg)
        failures.append(msg)
    return ok


# ------------------------------------------------------------------ the daemon

def free_port(rng, tcp_too):
    """A high port free for UDP (and TCP) on 127.0.0.1, not a default one."""
    for _ in range(200):
        port = rng.randrange(20000, 60000)
        kinds = (socket.SOCK_DGRAM, socket.SOCK_STREAM) if tcp_too else (socket.SOCK_DGRAM,)
        socks = []
        try:
            for k in kinds:
                s = socket.socket(socket.AF_INET, k)
                socks.append(s)
                s.bind(("127.0.0.1", port))
            return port
        except OSError:
            continue
        finally:
            for s in socks:
                s.close()
    raise RuntimeError("no free port")


def udp_table():
    """{port on 127.0.0.1: (rx_queue bytes, drops)} from /proc/net/udp."""
    t = {}
    with open("/proc/net/udp") as f:
        next(f)
        for line in f:
            w = line.split()
            addr, port = w[1].split(":")
            if addr == "0100007F":
                t[int(port, 16)] = (int(w[4].split(":")[1], 16), int(w[12]))
    return t


class Daemon:
    def __init__(self, path, work, rng):
        self.work = work
        self.ports = {"e131": free_port(rng, False), "opc": free_port(rng, True),
                      "ddp": free_port(rng, False)}
        self.stats_path = os.path.join(work, "stats")
        self.files = {"e": (os.path.join(work, "e131.out"), E_PIXELS * 3),
                      "o": (os.path.join(work, "opc.out"), O_PIXELS * 3),
                      "d": (os.path.join(work, "ddp.out"), D_PIXELS * 3)}
        self.cfg = os.path.join(work, "pixeld.conf")
        with open(self.cfg, "w") as f:
            f.write("""# fuzz.py's configuration
listen 127.0.0.1
e131-port %d
opc-port %d
ddp-port %d
stats-file %s
max-sources %d
opc-max-clients %d
source-timeout %g
output e file %s %d
map e e131 universe %d pixels %d
output o file %s %d
map o opc channel %d
output d file %s %d
map d ddp offset 0
""" % (self.ports["e131"], self.ports["opc"], self.ports["ddp"], self.stats_path,
                MAX_SOURCES, OPC_MAX_CLIENTS, SOURCE_TIMEOUT,
                self.files["e"][0], E_PIXELS, E_UNI, E_PIXELS,
                self.files["o"][0], O_PIXELS, O_CHAN, self.files["d"][0], D_PIXELS))
        self.log_path = os.path.join(work, "pixeld.log")
        self.log = open(self.log_path, "wb")

        def limits():
            hard = resource.getrlimit(resource.RLIMIT_NOFILE)[1]
            resource.setrlimit(resource.RLIMIT_NOFILE, (min(1024, hard), hard))

        self.proc = subprocess.Popen([PYTHON, path, "--config", self.cfg], stdout=self.log,
                                     stderr=subprocess.STDOUT, preexec_fn=limits)
        self.pid = self.proc.pid
        self.serial = 0
        end = time.monotonic() + 10
        while b"listening on" not in self.log_text():
            if self.proc.poll() is not None or time.monotonic() > end:
                raise RuntimeError("the daemon did not start:\n" + self.log_text().decode())
            time.sleep(0.02)

    def log_text(self):
        with open(self.log_path, "rb") as f:
            return f.read()

    def alive(self):
        return self.proc.poll() is None

    def stats(self):
        """The counters, dumped anew (SIGUSR1) and read from the stats file."""
        if not self.alive():
            raise RuntimeError("the daemon is gone (exit %s)" % self.proc.returncode)
        os.kill(self.pid, signal.SIGUSR1)
        end = time.monotonic() + 5
        while time.monotonic() < end:
            try:
                with open(self.stats_path) as f:
                    lines = f.read().splitlines()
            except FileNotFoundError:
                lines = []
            if lines and lines[0].startswith("serial "):
                serial = int(lines[0].split()[1])
                if serial > self.serial:
                    self.serial = serial
                    return {k: int(v) for k, v in (ln.split() for ln in lines[1:])}
            if not self.alive():
                raise RuntimeError("the daemon is gone (exit %s)" % self.proc.returncode)
            time.sleep(0.005)
        raise RuntimeError("no stats dump within 5 s of SIGUSR1")

    def rss_kb(self):
        with open("/proc/%d/status" % self.pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        return -1

    def fds(self):
        """(open descriptors, of them sockets)."""
        fds = os.listdir("/proc/%d/fd" % self.pid)
        socks = 0
        for fd in fds:
            try:
                socks += os.readlink("/proc/%d/fd/%s" % (self.pid, fd)).startswith("socket:")
            except OSError:
                pass
        return len(fds), socks


# ------------------------------------------------------------------- senders

class Traffic:
    """Every datagram and TCP message sent, per protocol; UDP sends paced on
    the daemon socket's receive queue."""

    def __init__(self, d):
        self.d = d
        self.udp_sent = dict.fromkeys(PROTOS, 0)
        self.tcp_msgs = 0
        self.sk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sk.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 1 << 20)
        self.burst = dict.fromkeys(PROTOS, 0)
        self.last_e131 = 0.0
        self.send_errors = 0
        self.last = collections.deque(maxlen=256)	# what was sent last, for a post-mortem

    def drain(self, proto, limit, timeout=3.0):
        port = self.d.ports[proto]
        end = time.monotonic() + timeout
        while True:
            q = udp_table().get(port, (0, 0))[0]
            if q <= limit or time.monotonic() > end or not self.d.alive():
                return
            time.sleep(0.0002)

    def udp(self, proto, pkt):
        pkt = pkt[:UDP_MAX]
        big = len(pkt) > 4096
        if big or self.burst[proto] >= 16:
            self.drain(proto, 0 if big else 48 * 1024)
            self.burst[proto] = 0
        try:
            n = self.sk.sendto(pkt, ("127.0.0.1", self.d.ports[proto]))
        except OSError as e:
            self.send_errors += 1
            say("INFO", "%s: a datagram of %d bytes not sent: %s" % (proto, len(pkt), e))
            return
        self.last.append((proto, pkt))
        if n == len(pkt):
            self.udp_sent[proto] += 1
            self.burst[proto] += 1
        if proto == "e131":
            self.last_e131 = time.monotonic()

    def tcp_stream(self, data, how="fin", timeout=20.0):
        """Send DATA on a new connection and hang up; with FIN, wait until
        the daemon closes its end (it has read everything).  The whole
        messages in DATA are counted as sent."""
        self.last.append(("opc-tcp", data[:70000]))
        try:
            s = socket.create_connection(("127.0.0.1", self.d.ports["opc"]), timeout=timeout)
        except OSError as e:
            say("INFO", "OPC TCP: connecting: %s" % e)
            return False
        try:
            s.sendall(data)
            if how == "rst":
                s.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
                s.close()
                return True
            s.shutdown(socket.SHUT_WR)
            while s.recv(65536):
                pass
        except OSError as e:
            say("INFO", "OPC TCP stream of %d bytes: %s" % (len(data), e))
            return False
        finally:
            s.close()
        self.tcp_msgs += opc_messages(data)
        return True


def opc_messages(data):
    """The whole OPC messages a stream holds (as the protocol frames it)."""
    i, n = 0, 0
    while len(data) - i >= 4:
        need = 4 + (data[i + 2] << 8 | data[i + 3])
        if len(data) - i < need:
            break
        i += need
        n += 1
    return n


# ---------------------------------------------------------------- mutations

INTERESTING = (0, 1, 2, 0x7f, 0x80, 0xfe, 0xff)


def mutate(rng, pkt, fields):
    """Byte-level and field-level mutations of PKT; FIELDS: (offset, size)
    of the protocol's header fields."""
    b = bytearray(pkt)
    for _ in range(rng.choice((1, 1, 1, 2, 3))):
        op = rng.randrange(9)
        if op == 0 and b:
            for _ in range(rng.randrange(1, 9)):
                i = rng.randrange(len(b) * 8)
                b[i >> 3] ^= 1 << (i & 7)
        elif op == 1:
            del b[rng.randrange(len(b) + 1):]
        elif op == 2:
            b += bytes(rng.randrange(256) for _ in range(rng.randrange(1, 80)))
        elif op == 3 and b:
            b[rng.randrange(len(b))] = rng.choice(INTERESTING)
        elif op in (4, 5, 6) and fields:
            at, size = rng.choice(fields)
            if at + size > len(b):
                continue
            old = int.from_bytes(b[at:at + size], "big")
            top = (1 << 8 * size) - 1
            v = rng.choice((0, 1, top, top >> 1, old + 1, old - 1, old ^ 0x8000,
                            rng.randrange(top + 1), old & 0x0fff, (old & 0x0fff) | 0x7000))
            b[at:at + size] = (v & top).to_bytes(size, "big")
        elif op == 7 and b:
            i = rng.randrange(len(b))
            del b[i:i + rng.randrange(1, 16)]
        elif op == 8:
            i = rng.randrange(len(b) + 1)
            b[i:i] = bytes(rng.randrange(256) for _ in range(rng.randrange(1, 16)))
    return bytes(b)


def random_bytes(rng, lo, hi):
    return rng.randbytes(rng.randrange(lo, hi + 1))


E131_FIELDS = [(0, 2), (2, 2), (4, 12), (16, 2), (18, 4), (22, 16), (38, 2), (40, 4),
               (108, 1), (109, 2), (111, 1), (112, 1), (113, 2), (115, 2), (117, 1),
               (118, 1), (119, 2), (121, 2), (123, 2), (125, 1),
               (44, 1), (45, 2), (47, 2)]		# the last: a sync packet's
OPC_FIELDS = [(0, 1), (1, 1), (2, 2)]
DDP_FIELDS = [(0, 1), (1, 1), (2, 1), (3, 1), (4, 4), (8, 2), (10, 4)]


def e131_discovery(cid, universes, page=0, last=0):
    disc = struct.pack(">HIBB", ps.flen(8 + 2 * len(universes)), 1, page, last) + \
        b"".join(struct.pack(">H", u) for u in universes)
    framing = struct.pack(">HI64sI", ps.flen(74 + len(disc)), 2, b"fuzz", 0) + disc
    return ps.e131_root(8, cid, framing)


class E131Gen:
    def __init__(self, rng):
        self.rng = rng
        self.cids = [rng.randbytes(16) for _ in range(6)]
        self.seq = {}

    def seed(self):
        rng = self.rng
        cid = rng.choice(self.cids) if rng.random() < 0.9 else rng.randbytes(16)
        seq = self.seq[cid] = (self.seq.get(cid, 0) +
                               rng.choice((1, 1, 1, 1, 0, -1, -5, -25, 100))) & 255
        k = rng.random()
        if k < 0.75:
            uni = rng.choice((E_UNI, E_UNI, E_UNI + 1, E_UNI + 1, 1, E_UNI + 2, 0, 63999,
                              64000, 65535, rng.randrange(65536)))
            n = rng.choice((512, 512, 88, 0, 1, 513, rng.randrange(600)))
            return ps.e131_data(
                uni, rng.randbytes(n), cid=cid, seq=seq,
                priority=rng.choice((100, 100, 100, 0, 200, 201, 255, rng.randrange(256))),
                sync=rng.choice((0,) * 8 + (E_UNI, 1, 63999, 64000, 65535,
                                            rng.randrange(1, 64000))),
                options=rng.choice((0,) * 6 + (0x80, 0x40, 0xc0, 0x20, rng.randrange(256))),
                start=rng.choice((0,) * 8 + (0xdd, 0xcc, 0x17, rng.randrange(256))))
        if k < 0.9:
            return ps.e131_sync(rng.choice((E_UNI, 1, 63999, 64000, 0, rng.randrange(65536))),
                                cid=cid, seq=seq)
        return e131_discovery(cid, sorted(rng.randrange(1, 64000)
                                          for _ in range(rng.randrange(0, 600))))

    def packet(self):
        return seeded(self.rng, self.seed, E131_FIELDS)


def opc_seed(rng, big=65535):
    chan = rng.choice((O_CHAN, O_CHAN, O_CHAN, 0, 1, 255, rng.randrange(256)))
    cmd = rng.choice((0,) * 6 + (0xff, 1, 2, rng.randrange(256)))
    n = rng.choice((O_PIXELS * 3, O_PIXELS * 3, 0, 1, 2, 3, 4, rng.randrange(1500),
                    rng.randrange(big + 1)))
    data = rng.randbytes(n)
    if cmd == 0xff and rng.random() < 0.5:
        data = struct.pack(">HH", 1, rng.randrange(4)) + data
    return ps.opc_message(chan, data[:65535], cmd)


def seeded(rng, seed, fields):
    """Random bytes (4.5 %), a valid-looking packet from SEED() (30.5 %) or
    one mutated in FIELDS (65 %)."""
    r = rng.random()
    if r < 0.04:
        return random_bytes(rng, 0, 700)
    if r < 0.045:
        return random_bytes(rng, 1400, UDP_MAX)
    p = seed()
    return p if r < 0.35 else mutate(rng, p, fields)


def opc_packet(rng):
    return seeded(rng, lambda: opc_seed(rng, UDP_MAX - 4), OPC_FIELDS)


def ddp_seed(rng):
    flags = rng.choice((0x41, 0x41, 0x40, 0x51, 0x50, 0x42, 0x44, 0x48, 0x43, 0x01, 0x81,
                        0xc1, rng.randrange(256)))
    dtype = rng.choice((0x0b, 0x0b, 0x00, 0x01, 0x1b, 0x1a, 0x0c, rng.randrange(256)))
    dest = rng.choice((1, 1, 1, 255, 0, 2, 246, 250, 251, 254, rng.randrange(256)))
    offset = rng.choice((0, 0, 720, 1437, 1439, 1440, 1 << 31, (1 << 32) - 1,
                         rng.randrange(3000), rng.randrange(1 << 32)))
    n = rng.choice((1440, 1440, 720, 0, 1, 3, rng.randrange(1500),
                    rng.randrange(UDP_MAX - 14)))
    tc = rng.randbytes(4) if flags & 0x10 else b""
    return struct.pack(">BBBBIH", flags, rng.randrange(256), dtype, dest, offset, n) + tc + \
        rng.randbytes(n)


def ddp_packet(rng):
    return seeded(rng, lambda: ddp_seed(rng), DDP_FIELDS)


# ------------------------------------------------------------------- checks

class Fuzz:
    def __init__(self, d, rng, deadline):
        self.d, self.rng, self.deadline = d, rng, deadline
        self.t = Traffic(d)
        self.e131 = E131Gen(rng)
        self.checker_cid = b"fuzz-checker-cid"
        self.checker_seq = {}

    def wait_e131_quiet(self):
        """Until every E1.31 source the fuzz made has timed out, and with it
        whatever waited for a sync packet or for a frame's other universe."""
        t = self.t.last_e131 + SOURCE_TIMEOUT + 0.3 - time.monotonic()
        if t > 0:
            time.sleep(t)

    def file_is(self, name, want, timeout=2.0):
        path, size = self.d.files[name]
        assert len(want) == size
        end = time.monotonic() + timeout
        got = b""
        while time.monotonic() < end:
            try:
                with open(path, "rb") as f:
                    got = f.read()
            except FileNotFoundError:
                got = b""
            if got == want:
                return True, ""
            time.sleep(0.005)
        diff = next((i for i, (a, b) in enumerate(zip(got, want)) if a != b), min(len(got),
                                                                                  len(want)))
        return False, "file %s: %d bytes (want %d), first difference at byte %d" % (
            os.path.basename(path), len(got), len(want), diff)

    def frames(self, tag, which=("e131", "opc-udp", "opc-tcp", "ddp")):
        """The daemon is alive and shows a fresh known frame exactly, sent in
        each protocol."""
        if not check(self.d.alive(), "%s: the daemon is alive" % tag):
            raise Gone()
        rng, ok, why = self.rng, True, []
        if "e131" in which:
            self.wait_e131_quiet()
            pix = rng.randbytes(E_PIXELS * 3)
            for u, part in ((E_UNI, pix[:512]), (E_UNI + 1, pix[512:] + rng.randbytes(424))):
                seq = self.checker_seq[u] = (self.checker_seq.get(u, 0) + 1) & 255
                self.t.udp("e131", ps.e131_data(u, part, cid=self.checker_cid, seq=seq))
            good, w = self.file_is("e", pix)
            ok &= good
            why += [] if good else ["E1.31: " + w]
        if "opc-udp" in which:
            pix = rng.randbytes(O_PIXELS * 3)
            self.t.udp("opc", ps.opc_message(O_CHAN, pix))
            good, w = self.file_is("o", pix)
            ok &= good
            why += [] if good else ["OPC UDP: " + w]
        if "opc-tcp" in which:
            pix = rng.randbytes(O_PIXELS * 3)
            self.t.tcp_stream(ps.opc_message(O_CHAN, pix + rng.randbytes(30)))
            good, w = self.file_is("o", pix)
            ok &= good
            why += [] if good else ["OPC TCP: " + w]
        if "ddp" in which:
            pix = rng.randbytes(D_PIXELS * 3)
            for p in ps.ddp_packets(pix, size=720, seq=rng.randrange(1, 16)):
                self.t.udp("ddp", p)
            good, w = self.file_is("d", pix)
            ok &= good
            why += [] if good else ["DDP: " + w]
        return check(ok, "%s: a known frame in %s is shown exactly%s" % (
            tag, ", ".join(which), "" if ok else " (" + "; ".join(why) + ")"))

    def counters(self, tag):
        """received = accepted + dropped.* + ignored.*, per protocol; sent =
        received + the kernel's drops (UDP), plus the TCP streams' whole
        messages (OPC)."""
        end = time.monotonic() + 5
        while True:
            st = self.d.stats()
            tab = udp_table()
            drops = {p: tab.get(self.d.ports[p], (0, 0))[1] for p in PROTOS}
            want = {p: self.t.udp_sent[p] - drops[p] for p in PROTOS}
            want["opc"] += self.t.tcp_msgs
            if all(st.get(p + ".received", 0) == want[p] for p in PROTOS) or \
                    time.monotonic() > end:
                break
            time.sleep(0.05)
        ok = True
        for p in PROTOS:
            rec = st.get(p + ".received", 0)
            parts = {k: v for k, v in st.items() if k == p + ".accepted" or
                     k.startswith(p + ".dropped.") or k.startswith(p + ".ignored.")}
            ok &= check(rec == sum(parts.values()),
                        "%s: %s.received %d = accepted + dropped.* + ignored.* (%d)"
                        % (tag, p, rec, sum(parts.values())))
            extra = " + %d TCP messages" % self.t.tcp_msgs if p == "opc" else ""
            ok &= check(rec == want[p],
                        "%s: %s: %d datagrams sent%s = %d received + %d dropped by the "
                        "kernel" % (tag, p, self.t.udp_sent[p], extra, rec, drops[p]))
        return st

    # --- phases
    def slice_end(self, share):
        """This phase's end: SHARE of the time left to the deadline (less
        a second for the last checks)."""
        return time.monotonic() + max(0.2, (self.deadline - 1 - time.monotonic()) * share)

    def run_udp(self, proto, gen, end):
        n = 0
        while time.monotonic() < end:
            for _ in range(32):
                self.t.udp(proto, gen())
                n += 1
            if not self.d.alive():
                break
        return n

    def e131_mutations(self, end):
        n = self.run_udp("e131", self.e131.packet, end)
        say("INFO", "E1.31: %d datagrams (mutations of data, sync and discovery packets, "
            "random bytes)" % n)

    def e131_flood(self, cids=300):
        """CIDS new sources, one packet each, on a mapped universe: at most
        max-sources are kept (one of a higher priority than the lowest kept
        takes its place), and each one taken times out or was evicted."""
        self.wait_e131_quiet()
        a = self.d.stats()
        rng = self.rng
        for _ in range(cids):
            self.t.udp("e131", ps.e131_data(E_UNI, rng.randbytes(512), cid=rng.randbytes(16),
                                            seq=rng.randrange(256),
                                            priority=rng.randrange(201)))
        self.t.drain("e131", 0)
        b = self.d.stats()
        took = b.get("e131.accepted", 0) - a.get("e131.accepted", 0)
        full = b.get("e131.dropped.sources_full", 0) - a.get("e131.dropped.sources_full", 0)
        tmo = b.get("e131.timeouts", 0) - a.get("e131.timeouts", 0)
        ev = b.get("e131.sources_evicted", 0) - a.get("e131.sources_evicted", 0)
        check(took + full == cids and took <= MAX_SOURCES + tmo + ev and took >= 1,
              "E1.31 flood of %d new CIDs on universe %d: %d taken (max-sources %d, %d timed "
              "out meanwhile, %d evicted by higher priorities), %d dropped.sources_full"
              % (cids, E_UNI, took, MAX_SOURCES, tmo, ev, full))
        self.wait_e131_quiet()
        c = self.d.stats()
        gone = c.get("e131.timeouts", 0) - a.get("e131.timeouts", 0)
        ev = c.get("e131.sources_evicted", 0) - a.get("e131.sources_evicted", 0)
        check(gone + ev == took, "E1.31 flood: each of the %d sources taken timed out (%d "
              "timeouts) or was evicted (%d)" % (took, gone, ev))

    def e131_sync_addresses(self, end, most=2000):
        """One winning source whose data packets name a new synchronization
        address each time (at most MOST of them)."""
        rng = self.rng
        cid = rng.randbytes(16)
        addrs = rng.sample(range(1, 64000), most)
        n = 0
        for n, s in enumerate(addrs, 1):
            self.t.udp("e131", ps.e131_data(E_UNI, rng.randbytes(512), cid=cid, seq=n,
                                            priority=200, sync=s))
            if n % 32 == 0 and (time.monotonic() > end or not self.d.alive()):
                break
        say("INFO", "E1.31: %d data packets naming as many synchronization addresses" % n)

    def opc_udp(self, end):
        n = self.run_udp("opc", lambda: opc_packet(self.rng), end)
        say("INFO", "OPC UDP: %d datagrams" % n)

    def ddp(self, end):
        n = self.run_udp("ddp", lambda: ddp_packet(self.rng), end)
        say("INFO", "DDP: %d datagrams" % n)

    def opc_idle_clients(self, extra=8):
        """OPC_MAX_CLIENTS + EXTRA clients connect and send nothing: the
        EXTRA quiet longest (the first) are evicted, and only they; a new
        client is still served."""
        a = self.d.stats()
        n = OPC_MAX_CLIENTS + extra
        socks = []
        for _ in range(n):
            socks.append(socket.create_connection(("127.0.0.1", self.d.ports["opc"]), 5))
            time.sleep(0.03)
        end = time.monotonic() + 3
        while True:
            b = self.d.stats()
            conns = b.get("opc.connections", 0) - a.get("opc.connections", 0)
            if conns >= n or time.monotonic() > end:
                break
            time.sleep(0.05)
        evicted = b.get("opc.clients_evicted", 0) - a.get("opc.clients_evicted", 0)
        closed = []
        for i, s in enumerate(socks):
            r, _, _ = select.select([s], [], [], 0.3 if i < extra else 0.05)
            if r:
                try:
                    eof = s.recv(1) == b""
                except OSError:
                    eof = True
                if eof:
                    closed.append(i)
        check(conns == n and evicted == extra and closed == list(range(extra)),
              "OPC TCP: %d idle clients (opc-max-clients %d): %d connections, %d evicted, "
              "closed by the daemon: clients %s (want the first %d)"
              % (n, OPC_MAX_CLIENTS, conns, evicted, closed, extra))
        self.frames("OPC TCP with %d idle clients connected" % OPC_MAX_CLIENTS, ("opc-tcp",))
        for s in socks:
            s.close()

    def opc_big(self, size=10 << 20):
        """10 MB in one sendall: whole messages of 65535 bytes for half of it,
        random bytes after."""
        rng = self.rng
        msg = ps.opc_message(O_CHAN, rng.randbytes(65535))
        half = msg * (size // 2 // len(msg))
        data = half + rng.randbytes(size - len(half))
        t0 = time.monotonic()
        sent = self.t.tcp_stream(data, timeout=60)
        check(sent, "OPC TCP: one client sent %d bytes in one sendall (%d whole messages), "
              "read to the end by the daemon in %.2f s"
              % (len(data), opc_messages(data), time.monotonic() - t0))

    def opc_half(self, conns=60):
        """Clients sending whole messages, then half of one, then hanging up."""
        rng = self.rng
        for i in range(conns):
            data = b"".join(opc_seed(rng, 3000) for _ in range(rng.randrange(4)))
            n = rng.randrange(1, 65536)
            part = struct.pack(">BBH", O_CHAN, 0, n) + rng.randbytes(rng.randrange(n))
            part = part[:rng.choice((1, 2, 3, len(part), len(part)))]
            rst = not data and rng.random() < 0.5
            self.t.tcp_stream(data + part, "rst" if rst else "fin")
        say("INFO", "OPC TCP: %d clients sent whole messages then half of one and hung up "
            "(some with RST)" % conns)

    def opc_streams(self, end):
        rng, conns = self.rng, 0
        while time.monotonic() < end:
            msgs = []
            for _ in range(rng.randrange(1, 60)):
                r = rng.random()
                m = opc_seed(rng, 5000)
                msgs.append(random_bytes(rng, 0, 300) if r < 0.05 else
                            m if r < 0.5 else mutate(rng, m, OPC_FIELDS))
            self.t.tcp_stream(b"".join(msgs))
            conns += 1
        say("INFO", "OPC TCP: %d connections of mutated message streams" % conns)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=40, help="the total budget (default 40)")
    ap.add_argument("--seed", type=int, default=None)
    ap.add_argument("--daemon", default=os.path.join(os.path.dirname(HERE), "prukit-pixeld"),
                    help="the daemon to run (default: the tree's)")
    ap.add_argument("--rss-bound", type=int, default=3072,
                    help="kB VmRSS may grow from after the warm-up to the end (3072)")
    ap.add_argument("--keep", action="store_true", help="keep the work directory")
    args = ap.parse_args()
    seed = args.seed if args.seed is not None else random.SystemRandom().randrange(1 << 32)
    rng = random.Random(seed)
    say("INFO", "seed %d (--seed %d repeats this run), budget %g s, daemon %s"
        % (seed, seed, args.seconds, args.daemon))
    work = tempfile.mkdtemp(prefix="pixeld-fuzz.")
    t0 = time.monotonic()
    deadline = t0 + args.seconds
    d = fz = None
    try:
        d = Daemon(args.daemon, work, rng)
        say("INFO", "ports: E1.31 %(e131)d, OPC %(opc)d, DDP %(ddp)d" % d.ports)
        fz = Fuzz(d, rng, deadline)
        fds0 = d.fds()
        fz.frames("start")
        fz.counters("start")

        # warm-up: a little of everything, then the baseline of the memory
        w_end = time.monotonic() + min(1.5, args.seconds * 0.04)
        while time.monotonic() < w_end:
            for proto, gen in (("e131", fz.e131.packet), ("opc", lambda: opc_packet(rng)),
                               ("ddp", lambda: ddp_packet(rng))):
                for _ in range(16):
                    fz.t.udp(proto, gen())
        fz.opc_half(5)
        fz.t.tcp_stream(ps.opc_message(O_CHAN, rng.randbytes(65535)) * 16 + rng.randbytes(65536))
        fz.frames("warm-up")
        rss0 = d.rss_kb()

        # the phases' shares of the time left (the waits for E1.31 sources
        # to time out come out of it)
        fz.e131_mutations(fz.slice_end(0.22))
        fz.e131_flood()
        fz.e131_sync_addresses(fz.slice_end(0.08))
        fz.frames("E1.31")
        fz.counters("E1.31")

        fz.opc_udp(fz.slice_end(0.25))
        fz.frames("OPC UDP", ("opc-udp", "opc-tcp"))
        fz.counters("OPC UDP")

        fz.opc_idle_clients()
        fz.opc_big()
        fz.opc_half()
        fz.opc_streams(fz.slice_end(0.25))
        fz.frames("OPC TCP", ("opc-udp", "opc-tcp"))
        fz.counters("OPC TCP")

        fz.ddp(fz.slice_end(0.9))
        fz.frames("DDP")
        st = fz.counters("end")

        rss1, fds1 = d.rss_kb(), d.fds()
        check(rss1 - rss0 < args.rss_bound,
              "memory: VmRSS %d kB after the warm-up, %d kB at the end: %+d kB (bound %d kB)"
              % (rss0, rss1, rss1 - rss0, args.rss_bound))
        check(fds1[0] - fds0[0] <= FD_SLACK,
              "descriptors: %d open at the start (%d sockets), %d at the end (%d sockets; "
              "bound: %d more)" % (fds0 + fds1 + (FD_SLACK,)))
        for p in PROTOS:
            parts = sorted(((v, k) for k, v in st.items() if k.startswith(p + ".") and
                            k != p + ".received"), reverse=True)
            say("INFO", "%s: received %d: %s" % (p, st.get(p + ".received", 0),
                                                 ", ".join("%s %d" % (k[len(p) + 1:], v)
                                                           for v, k in parts)))
        say("INFO", "UDP sends refused by the host: %d" % fz.t.send_errors)
    except Gone:
        pass
    except (RuntimeError, OSError) as e:
        check(False, "%s: %s" % (type(e).__name__, e))
    finally:
        if d is not None:
            if d.alive():
                d.proc.send_signal(signal.SIGTERM)
                try:
                    rc = d.proc.wait(10)
                except subprocess.TimeoutExpired:
                    d.proc.kill()
                    rc = d.proc.wait()
                check(rc == 0, "SIGTERM: the daemon exited with status %d" % rc)
            else:
                check(False, "the daemon exited on its own, status %s" % d.proc.returncode)
                if fz is not None:
                    with open(os.path.join(work, "last-sent.txt"), "w") as f:
                        for proto, pkt in fz.t.last:
                            f.write("%s %s\n" % (proto, pkt.hex()))
                    say("INFO", "the last %d datagrams and TCP streams sent, oldest first, "
                        "protocol and hex, are in %s/last-sent.txt" % (len(fz.t.last), work))
            text = d.log_text().decode(errors="replace")
            if not check("Traceback" not in text, "the daemon's log holds no traceback"):
                i = text.find("Traceback")
                print(text[i:i + 3000], end="")
            d.log.close()
        if args.keep or failures:
            say("INFO", "work directory kept: %s" % work)
        else:
            shutil.rmtree(work, ignore_errors=True)
    say("INFO", "%.1f s" % (time.monotonic() - t0))
    if failures:
        say("FAIL", "%d check(s) failed" % len(failures))
        return 1
    say("PASS", "prukit-pixeld fuzz: every check held")
    return 0


if __name__ == "__main__":
    sys.exit(main())
