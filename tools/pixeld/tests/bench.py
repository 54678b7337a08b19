#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""prukit-pixeld's figures for make bench (tools/pixeld/tests/bench.sh).
Prints BENCH: lines, and FAIL: lines (exit 1) for what did not hold.

  bench.py ir WORK
      The parse + map cost per pixel, in instructions counted by
      callgrind: an E1.31 universe of 170 pixels, an OPC message of 480
      pixels and a DDP packet of 1440 bytes (480 pixels) with push, fed
      to the daemon's Pixeld in-process (feed_e131/feed_opc/feed_ddp),
      each making a whole frame of a file output on /dev/null.  Python
      runs under callgrind twice, with N1 and N2 packets; the difference
      of the two totals, over (N2 - N1) x the pixels of a packet, leaves
      the interpreter's start-up and the set-up out.  It is the CPython
      interpreter's instructions on this host (x86-64), not a board's.
      Each run checks that every packet was accepted and made one frame,
      so the figure is of the path that shows pixels, not of a drop.

  bench.py rate WORK [SECONDS]
      Universes per second the daemon handles on one host core: the
      daemon as a subprocess mapping 170 universes (48 strings x 600
      pixels, 28800 pixels, 170 per universe) onto a file output on
      /dev/null; this process blasts whole frames of valid E1.31
      universes at it over loopback for SECONDS (default 4).  The figure
      is the daemon's accepted universes (its counters) over its CPU
      time (utime + stime of /proc/PID/stat); the wire rate of 48 strings
      of 600 pixels (170 universes x 54 frames per second = 9180
      universes/s) is then given as the fraction of one core it needs.

  bench.py feed PROTO N WORK
      The in-process workload the ir part runs under callgrind."""
import sys

sys.dont_write_bytecode = True  # noqa: E402 (no __pycache__ in the tree)

import os
import platform
import random
import re
import signal
import socket
import subprocess
import time
import types

HERE = os.path.dirname(os.path.abspath(__file__))
DAEMON = os.path.join(os.path.dirname(HERE), "prukit-pixeld")
sys.path.insert(0, HERE)
import pixel_send as ps  # noqa: E402

PYTHON = "/usr/bin/python3"
WIRE_UPS = 170 * 54		# 48 strings x 600 pixels at the wire's 54 fps
FEEDS = {"e131": 170, "opc": 480, "ddp": 480}	# pixels per packet
N1, N2 = 300, 1800


def load_daemon():
    """The daemon's package (tools/pixeld/prukit_pixeld): its Config and Pixeld."""
    sys.path.insert(0, os.path.dirname(HERE))
    from prukit_pixeld import config, merge
    return types.SimpleNamespace(Config=config.Config, Pixeld=merge.Pixeld)


# ----------------------------------------------------------------- the ir part

def feed(proto, n, work):
    """N packets of PROTO through Pixeld, in-process (run under callgrind).
    The packets are made before, the same way whatever N."""
    px_mod = load_daemon()
    rng = random.Random(1)
    pixels = FEEDS[proto]
    cfg = os.path.join(work, "feed-%s.conf" % proto)
    where = {"e131": "universe 1 pixels 170", "opc": "channel 1", "ddp": "offset 0"}[proto]
    with open(cfg, "w") as f:
        f.write("output f file /dev/null %d\nmap f %s %s\n" % (pixels, proto, where))
    px = px_mod.Pixeld(px_mod.Config(cfg))
    if proto == "e131":
        pkts = [ps.e131_data(1, rng.randbytes(510), seq=s) for s in range(256)]
        fn = px.feed_e131
    elif proto == "opc":
        pkts = [ps.opc_message(1, rng.randbytes(1440))] * 256
        fn = px.feed_opc
    else:
        pkts = [ps.ddp_packets(rng.randbytes(1440), seq=s % 15 + 1)[0] for s in range(256)]
        fn = px.feed_ddp
    for i in range(n):
        fn(pkts[i & 255])
    got = (px.stats.get(proto + ".accepted"), px.stats.get("output.f.frames"))
    if got != (n, n):
        print("FAIL: %s: %d packets fed: %d accepted, %d frames written (want %d each)"
              % (proto, n, got[0], got[1], n))
        return 1
    return 0


def callgrind_total(work, proto, n):
    out = os.path.join(work, "ir-%s-%d" % (proto, n))
    env = dict(os.environ, PYTHONHASHSEED="0", PYTHONDONTWRITEBYTECODE="1")
    cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=%s.callgrind" % out,
           PYTHON, os.path.abspath(__file__), "feed", proto, str(n), work]
    with open(out + ".log", "w") as log:
        r = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
    text = open(out + ".log").read()
    if r.returncode != 0:
        print(text[-3000:], end="")
        print("FAIL: %s under callgrind (exit %d; %s.log)" % (" ".join(cmd), r.returncode, out))
        return None
    with open(out + ".callgrind") as f:
        for line in f:
            m = re.match(r"(?:summary|totals):\s*(\d+)", line)
            if m:
                return int(m.group(1))
    print("FAIL: no total in %s.callgrind" % out)
    return None


def ir(work):
    ok = True
    what = {"e131": "an E1.31 universe of 170 pixels",
            "opc": "an OPC message of 480 pixels (1440 bytes, channel 1)",
            "ddp": "a DDP packet of 1440 bytes (480 pixels) with push"}
    for proto, pixels in FEEDS.items():
        a, b = callgrind_total(work, proto, N1), callgrind_total(work, proto, N2)
        if a is None or b is None or b <= a:
            ok = False
            if a is not None and b is not None:
                print("FAIL: %s: %d packets took %d instructions, %d packets %d"
                      % (proto, N1, a, N2, b))
            continue
        per = (b - a) / (N2 - N1)
        print("BENCH: pixeld %s parse + map: %.0f instructions per pixel (%.0f per packet: %s, "
              "through Pixeld.feed_%s into a frame written to /dev/null; callgrind, "
              "(%d - %d instructions) / (%d - %d packets); CPython %s's instructions in user "
              "space on this host, %s, not a board's)"
              % (proto.upper() if proto != "e131" else "E1.31", per / pixels, per, what[proto],
                 proto, b, a, N2, N1, platform.python_version(), platform.machine()))
    return 0 if ok else 1


# ---------------------------------------------------------------- the rate part

def free_udp_port():
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def udp_row(port):
    """(rx_queue bytes, drops) of the socket on 127.0.0.1:PORT."""
    with open("/proc/net/udp") as f:
        for line in f:
            w = line.split()
            if w[1] == "0100007F:%04X" % port:
                return int(w[4].split(":")[1], 16), int(w[12])
    return 0, 0


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        w = f.read().rsplit(")", 1)[1].split()
    return (int(w[11]) + int(w[12])) / os.sysconf("SC_CLK_TCK")


class Stats:
    def __init__(self, proc, path):
        self.proc, self.path, self.serial = proc, path, 0

    def read(self, timeout=5):
        """The counters, dumped anew (SIGUSR1) and read from the stats file."""
        os.kill(self.proc.pid, signal.SIGUSR1)
        end = time.monotonic() + timeout
        while time.monotonic() < end and self.proc.poll() is None:
            try:
                with open(self.path) as f:
                    lines = f.read().splitlines()
            except FileNotFoundError:
                lines = []
            if lines and int(lines[0].split()[1]) > self.serial:
                self.serial = int(lines[0].split()[1])
                return {k: int(v) for k, v in (ln.split() for ln in lines[1:])}
            time.sleep(0.005)
        raise RuntimeError("no stats from the daemon within %d s of SIGUSR1" % timeout)


def rate(work, seconds):
    port = free_udp_port()
    stats_path = os.path.join(work, "rate.stats")
    cfg = os.path.join(work, "rate.conf")
    with open(cfg, "w") as f:
        f.write("listen 127.0.0.1\ne131-port %d\nopc off\nddp off\nstats-file %s\n"
                "output f file /dev/null 28800\nmap f e131 universe 1 pixels 28800 "
                "layout pixels\n" % (port, stats_path))
    for old in (stats_path, stats_path + ".tmp"):
        if os.path.exists(old):
            os.unlink(old)		# a run before's: its serial is not this daemon's
    log = open(os.path.join(work, "rate.log"), "wb")
    proc = subprocess.Popen([PYTHON, DAEMON, "--config", cfg], stdout=log,
                            stderr=subprocess.STDOUT)
    try:
        end = time.monotonic() + 10
        while b"listening on" not in open(log.name, "rb").read():
            if proc.poll() is not None or time.monotonic() > end:
                print(open(log.name).read(), end="")
                print("FAIL: the daemon did not start")
                return 1
            time.sleep(0.02)
        st = Stats(proc, stats_path)
        rng = random.Random(2)
        tpl = [bytearray(ps.e131_data(u, rng.randbytes(510))) for u in range(1, 171)]
        sk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        addr = ("127.0.0.1", port)
        seq = [0]

        def blast(t):
            sent, stop = 0, time.monotonic() + t
            while time.monotonic() < stop:
                s = seq[0] = (seq[0] + 1) & 255
                for p in tpl:
                    p[111] = s
                    sk.sendto(p, addr)
                sent += len(tpl)
            return sent

        def drain():
            stop = time.monotonic() + 5
            while udp_row(port)[0] and time.monotonic() < stop:
                time.sleep(0.01)

        blast(0.5)
        drain()
        a, cpu_a, t_a, drops_a = st.read(), cpu_seconds(proc.pid), time.monotonic(), \
            udp_row(port)[1]
        sent = blast(seconds)
        drain()
        cpu_b, t_b, drops_b = cpu_seconds(proc.pid), time.monotonic(), udp_row(port)[1]
        b = st.read()
    finally:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        log.close()

    def d(k):
        return b.get(k, 0) - a.get(k, 0)

    acc, frames, cpu, wall = d("e131.accepted"), d("output.f.frames"), cpu_b - cpu_a, t_b - t_a
    if acc <= 0 or frames <= 0 or cpu <= 0 or d("e131.received") != acc:
        print("FAIL: rate: %d universes sent, %d received, %d accepted, %d frames, %.2f CPU s"
              % (sent, d("e131.received"), acc, frames, cpu))
        return 1
    ups = acc / cpu
    print("BENCH: pixeld E1.31 on one host core: %.0f universes per CPU-second (%d universes "
          "of 170 pixels accepted and %d whole frames of 48 x 600 pixels written to /dev/null "
          "in %.2f s of the daemon's CPU time; %.0f%% of one core busy over %.2f s; the sender "
          "blasted %d universes over loopback, the kernel dropped %d; CPython %s, %s)"
          % (ups, acc, frames, cpu, 100 * cpu / wall, wall, sent, drops_b - drops_a,
             platform.python_version(), platform.machine()))
    print("BENCH: pixeld E1.31, 48 strings x 600 pixels at the wire rate (170 universes x 54 "
          "fps = %d universes/s): %.3f of one such host core (%.1f%%)"
          % (WIRE_UPS, WIRE_UPS / ups, 100 * WIRE_UPS / ups))
    return 0


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "ir":
        return ir(sys.argv[2])
    if len(sys.argv) >= 3 and sys.argv[1] == "rate":
        return rate(sys.argv[2], float(sys.argv[3]) if len(sys.argv) > 3 else 4.0)
    if len(sys.argv) == 5 and sys.argv[1] == "feed":
        return feed(sys.argv[2], int(sys.argv[3]), sys.argv[4])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
