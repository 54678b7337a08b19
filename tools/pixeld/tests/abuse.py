#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""prukit-pixeld under abuse, on loopback: a legitimate E1.31 sender's
frames while others do what broke the daemon before (issue 38):

  - sync packets and data of a flood of random CIDs on the mapped
    universes (at a lower priority than the legitimate sender's);
  - a source whose data names a sync universe whose sync packets never
    come (lost sync), at a lower priority;
  - floods of tiny (empty) OPC messages over TCP, onto another output;
  - data naming one sync universe after another, on another universe.

Every abuser is bounded (packets per second, seconds).  The legitimate
sender sends FRAMES frames of 3 universes (510 pixels; every byte of frame
k is k) at 50 fps to a FIFO output read here, which timestamps each frame
as it comes out of the daemon.

  abuse.py check WORK
      make check's part: with the abuse, every frame the output shows is
      one of the sender's, whole (never two mixed), in order, the last one
      last, at least half of them shown; the abusers' packets were taken
      or counted as dropped; the daemon's memory did not grow past 8 MiB.
      Prints PASS:/FAIL: lines; exits 1 if any failed.

  abuse.py bench WORK
      make bench's figure: the time from the arrival of a frame's last
      universe (its send over loopback) to the frame's write (read from
      the FIFO), median and 99th percentile, without and with the abuse.
      Prints BENCH: lines."""
import sys

sys.dont_write_bytecode = True  # noqa: E402 (no __pycache__ in the tree)

import os
import random
import signal
import socket
import subprocess
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DAEMON = os.environ.get("PIXELD", os.path.join(os.path.dirname(HERE), "prukit-pixeld"))
sys.path.insert(0, HERE)
import bench  # noqa: E402 (its reader of the daemon's counters)
import pixel_send as ps  # noqa: E402

PYTHON = "/usr/bin/python3"
PIXELS = 510			# 3 universes of 170
FRAMES = 250			# 5 s at 50 fps
FPS = 50
failed = 0


def check(name, cond, detail=""):
    global failed
    print(("PASS: " if cond else "FAIL: ") + "pixeld abuse: " + name +
          ("" if cond or detail == "" else ": " + str(detail)), flush=True)
    failed += not cond
    return cond


def free_port(kind):
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def rss_kib(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


class Daemon:
    """The daemon on loopback, its output a FIFO read by a thread that
    keeps (time, frame) of each frame."""

    def __init__(self, work):
        self.work = work
        self.ports = dict(e=free_port(socket.SOCK_DGRAM), o=free_port(socket.SOCK_STREAM),
                          d=free_port(socket.SOCK_DGRAM))
        self.fifo = os.path.join(work, "strip.fifo")
        if os.path.exists(self.fifo):
            os.unlink(self.fifo)
        os.mkfifo(self.fifo)
        self.stats_path = os.path.join(work, "abuse.stats")
        for old in (self.stats_path, self.stats_path + ".tmp"):
            if os.path.exists(old):
                os.unlink(old)		# a run before's: its serial is not this daemon's
        cfg = os.path.join(work, "abuse.conf")
        with open(cfg, "w") as f:
            f.write("listen 127.0.0.1\ne131-port %d\nopc-port %d\nddp-port %d\n"
                    "stats-file %s\nmax-sources 4\n"
                    "output strip file %s %d append\nmap strip e131 universe 1 layout pixels\n"
                    "output other file /dev/null 170\nmap other opc channel 2\n"
                    "map other e131 universe 20\n"
                    % (self.ports["e"], self.ports["o"], self.ports["d"], self.stats_path,
                       self.fifo, PIXELS))
        self.frames = []
        self.reader = threading.Thread(target=self.read, daemon=True)
        self.reader.start()		# the daemon's open of the FIFO waits for it
        self.log = open(os.path.join(work, "abuse.log"), "wb")
        self.proc = subprocess.Popen([PYTHON, DAEMON, "--config", cfg], stdout=self.log,
                                     stderr=subprocess.STDOUT)
        end = time.monotonic() + 20
        while b"listening on" not in open(self.log.name, "rb").read():
            if self.proc.poll() is not None or time.monotonic() > end:
                raise RuntimeError("the daemon did not start: " +
                                   open(self.log.name).read()[-2000:])
            time.sleep(0.02)
        self.counters = bench.Stats(self.proc, self.stats_path)

    def read(self):
        size = PIXELS * 3
        with open(self.fifo, "rb", buffering=0) as f:
            buf = b""
            while True:
                data = f.read(65536)
                if not data:
                    return
                now = time.monotonic()
                buf += data
                while len(buf) >= size:
                    self.frames.append((now, buf[:size]))
                    buf = buf[size:]

    def stats(self):
        return self.counters.read(timeout=10)

    def stop(self):
        self.proc.send_signal(signal.SIGTERM)
        try:
            rc = self.proc.wait(20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            rc = None
        self.reader.join(10)
        self.log.close()
        return rc


def legit(port, sent):
    """FRAMES frames at FPS: (time the last universe of frame k was sent)
    appended to SENT."""
    tx = ps.E131Sender(port=port, cid=b"legitimate-cid!!")
    start = time.monotonic()
    for k in range(FRAMES):
        frame = bytes([k % 256]) * (PIXELS * 3)
        for u in range(3):
            tx.data(1 + u, frame[u * 510:(u + 1) * 510], priority=150)
        sent.append(time.monotonic())
        delay = start + (k + 1) / FPS - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    tx.close()


def abusers(ports, stop, counts, seed):
    """The abusers, bounded: each sends at most its rate until STOP."""
    rng = random.Random(seed)
    e = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    eaddr = ("127.0.0.1", ports["e"])
    opc = socket.create_connection(("127.0.0.1", ports["o"]), timeout=10)
    tiny = ps.opc_message(2, b"") * 4096		# 16 KiB of empty messages
    lost = ps.E131Sender(port=ports["e"], cid=b"lost-sync-cid!!!")
    n = 0
    while not stop.is_set():
        t0 = time.monotonic()
        for _ in range(20):		# random CIDs: data and sync packets
            cid = rng.randbytes(16)
            e.sendto(ps.e131_data(rng.randint(1, 3), rng.randbytes(510), cid=cid,
                                  priority=100, sync=7), eaddr)
            e.sendto(ps.e131_sync(7, cid=cid), eaddr)
            counts["e131"] += 2
        for u in range(3):		# lost sync: sync universe 9 never comes
            lost.data(1 + u, bytes(510), priority=120, sync=9)
            counts["e131"] += 1
        # data cycling through sync universes
        e.sendto(ps.e131_data(20, bytes(510), sync=100 + n % 400, seq=n), eaddr)
        counts["e131"] += 1
        if n % 5 == 0:
            opc.sendall(tiny)
            counts["opc"] += 4096
        n += 1
        # 10 ms turns: about 6400 datagrams and 82000 OPC messages a second
        delay = t0 + 0.01 - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    opc.close()
    e.close()
    lost.close()


def run(work, abuse, seed=1):
    """One run: (sent times, frames read, stats, rss growth KiB, exit code)."""
    d = Daemon(work)
    stop, counts = threading.Event(), {"e131": 0, "opc": 0}
    try:
        st0 = d.stats()
        rss0 = rss_kib(d.proc.pid)
        ab = None
        if abuse:
            ab = threading.Thread(target=abusers, args=(d.ports, stop, counts, seed),
                                  daemon=True)
            ab.start()
            time.sleep(0.5)
        sent = []
        legit(d.ports["e"], sent)
        time.sleep(0.5)
        stop.set()
        if ab:
            ab.join(20)
        time.sleep(0.5)
        rss1 = rss_kib(d.proc.pid)
        st1 = d.stats()
    finally:
        stop.set()
        rc = d.stop()
    st = {k: st1.get(k, 0) - st0.get(k, 0) for k in st1}
    return sent, d.frames, st, rss1 - rss0, counts, rc


def shown(frames):
    """The frame numbers shown, None for a frame that is no frame of the
    sender's (two mixed: torn)."""
    out = []
    for _, f in frames:
        out.append(f[0] if f.count(f[0]) == len(f) else None)
    return out


def latencies(sent, frames):
    """Seconds from the send of frame k's last universe to its write, for
    each frame written (frame numbers are k % 256: one per 5 s run)."""
    return [t - sent[f[0]] for t, f in frames
            if f.count(f[0]) == len(f) and f[0] < len(sent)]


def pct(v, p):
    v = sorted(v)
    return v[min(len(v) - 1, int(p / 100 * len(v)))] if v else float("nan")


def do_check(work):
    sent, frames, st, grow, counts, rc = run(work, abuse=True)
    got = shown(frames)
    # before the sender's first frame the abusers were the only sources
    got = got[got.index(0):] if 0 in got else got
    whole = [k for k in got if k is not None]
    check("with the abuse (%d E1.31 datagrams and %d OPC messages of abusers): every frame "
          "shown is one of the sender's, whole (%d shown, %d torn)"
          % (counts["e131"], counts["opc"], len(got), got.count(None)),
          got and None not in got, got[:20])
    check("... in order, the last one last", whole == sorted(whole) and
          whole[-1:] == [(FRAMES - 1) % 256], whole[-5:])
    check("... at least half of the %d frames shown (%d)" % (FRAMES, len(set(whole))),
          len(set(whole)) >= FRAMES // 2)
    taken = st.get("e131.received", 0) + st.get("e131.kernel_drops", 0)
    check("the abusers' E1.31 datagrams and the sender's all reached the daemon or were counted "
          "as the kernel's drops (%d of %d; %d dropped by the kernel, %d full source tables, "
          "%d sync groups refused)"
          % (taken, counts["e131"] + 3 * FRAMES, st.get("e131.kernel_drops", 0),
             st.get("e131.dropped.sources_full", 0), st.get("e131.sync_groups_full", 0)),
          taken == counts["e131"] + 3 * FRAMES, st)
    check("the OPC floods taken (%d messages of %d) and written at most once per turn of the "
          "loop (%d writes of the other output)" % (st.get("opc.accepted", 0), counts["opc"],
                                                   st.get("output.other.frames", 0)),
          st.get("opc.accepted", 0) == counts["opc"] and
          st.get("output.other.frames", 0) < counts["opc"] // 100, st)
    check("the daemon's memory grew %d KiB (at most 8 MiB)" % grow, grow <= 8192)
    check("SIGTERM: exit 0", rc == 0, rc)
    return 1 if failed else 0


def do_bench(work):
    for abuse in (False, True):
        sent, frames, st, _, counts, rc = run(work, abuse)
        lat = latencies(sent, frames)
        if rc != 0 or len(lat) < FRAMES // 2:
            print("FAIL: pixeld latency bench%s: %d frames written of %d (exit %s)"
                  % (" under abuse" if abuse else "", len(lat), FRAMES, rc))
            return 1
        what = ("under abuse (random-CID data and sync floods, lost sync, 4096-message OPC "
                "floods, sync universes cycling: %d E1.31 datagrams, %d OPC messages)"
                % (counts["e131"], counts["opc"]) if abuse else "alone")
        print("BENCH: pixeld packet-to-write latency %s: median %.2f ms, 99th percentile "
              "%.2f ms (%d frames of 3 universes at %d fps over loopback: from the send of a "
              "frame's last universe to the frame's read from the daemon's FIFO output; "
              "%d of %d frames written; host time on a shared machine)"
              % (what, 1000 * pct(lat, 50), 1000 * pct(lat, 99), FRAMES, FPS, len(lat),
                 FRAMES))
    return 0


def main():
    if len(sys.argv) == 3 and sys.argv[1] in ("check", "bench"):
        os.makedirs(sys.argv[2], exist_ok=True)
        return do_check(sys.argv[2]) if sys.argv[1] == "check" else do_bench(sys.argv[2])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
