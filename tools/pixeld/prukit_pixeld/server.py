# SPDX-License-Identifier: GPL-2.0-only
"""The event loop around a Pixeld: its sockets (UDP for E1.31, OPC and DDP,
TCP for OPC), multicast groups, signals and the command line."""
import argparse
import errno
import fcntl
import os
import selectors
import signal
import socket
import struct
import sys
import time

from . import VERSION
from .common import Stats, log
from .config import Config, ConfigError
from .merge import Pixeld

CONFIG = "/etc/prukit/pixeld.conf"
MAX_UDP = 65536
SO_RXQ_OVFL = getattr(socket, "SO_RXQ_OVFL", 40)	# <asm-generic/socket.h>
# Kernel memory a received datagram (E1.31's 638 bytes, DDP's 1450 at most)
# takes from the socket's receive buffer (its skb's truesize: 1280 bytes on
# loopback for E1.31, up to 2304 with the 2 KiB buffers of a board's
# Ethernet driver), and the frames the buffer must hold while the daemon is
# busy: of every mapped universe (E1.31), of the bytes DDP feeds (DDP)
UDP_TRUESIZE = 2304
RCVBUF_FRAMES = 4
DDP_DATA = 1440			# pixel bytes a DDP datagram carries (senders' usual most)
JOINS_PER_SOCKET = 20			# net.ipv4.igmp_max_memberships' default
SYNC_JOINS = 8				# sync groups joined as data names them


SIOCGIFFLAGS, SIOCGIFADDR, IFF_UP = 0x8913, 0x8915, 0x1


def ipv4_addresses():
    """The IPv4 addresses of the interfaces that are up."""
    out = []
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sk:
        for _, name in socket.if_nameindex():
            req = struct.pack("40s", name.encode()[:15])
            try:
                flags = struct.unpack_from("=H", fcntl.ioctl(sk, SIOCGIFFLAGS, req), 16)[0]
                if flags & IFF_UP:
                    out.append(socket.inet_ntoa(fcntl.ioctl(sk, SIOCGIFADDR, req)[20:24]))
            except OSError:
                continue		# no IPv4 address
    return out


# ------------------------------------------------------------------- the event loop

class Server:
    """The sockets around a Pixeld: UDP for E1.31, OPC and DDP, TCP for
    OPC; one thread, a selector."""

    def __init__(self, cfg_path, verbose):
        self.cfg_path, self.verbose = cfg_path, verbose
        self.sel = selectors.DefaultSelector()
        self.stats = Stats()
        self.socks = []
        self.joiners = []		# [socket, groups joined on it]
        self.joined = {}		# universe -> its joiner
        self.dynamic = {}		# sync universe joined as data named it -> when
        self.clients = {}
        self.kernel_drops = {}		# UDP socket -> its drops reported so far
        self.ddp_socks, self.ddp_sized = [], 0	# DDP's sockets, the frame they are for
        self.said_no_route = False
        self.reload_asked = self.stats_asked = self.stop_asked = False
        self.px = None

    def start(self, cfg):
        for out in cfg.outputs.values():
            out.on_close = self.forget_output
        self.px = Pixeld(cfg, self.stats)
        self.px.on_pending = self.want_write
        self.px.defer = True
        s = cfg.settings
        addr = s["listen"]
        if s["e131"]:
            self.udp(addr, s["e131-port"], self.px.feed_e131, "E1.31",
                     max(1, len(self.px.universes)))
            self.px.on_join = self.join
            self.join(sorted(set(self.px.universes) | set(s["sync-universes"])))
        if s["opc"]:
            self.udp(addr, s["opc-port"], self.px.feed_opc, "OPC")
            self.tcp(addr, s["opc-port"])
        if s["ddp"]:
            self.udp(addr, s["ddp-port"], self.px.feed_ddp, "DDP")
            self.px.on_ddp = self.size_ddp
            self.size_ddp(self.px.ddp_bytes())
        log("listening on %s: %s" % (addr, ", ".join(
            "%s %s %d" % p for p in [("E1.31", "UDP", s["e131-port"])] * s["e131"] +
            [("OPC", "TCP+UDP", s["opc-port"])] * s["opc"] +
            [("DDP", "UDP", s["ddp-port"])] * s["ddp"])))

    def family(self, addr):
        return socket.AF_INET6 if ":" in addr else socket.AF_INET

    def udp(self, addr, port, feed, what, universes=0):
        """The UDP socket of a protocol on ADDR.  On "::", two: IPv6 only,
        and IPv4 on 0.0.0.0, as IPv4 multicast (E1.31's groups, joined on
        sockets of their own) reaches IPv4 sockets only, not a dual-stack
        IPv6 one."""
        if addr == "::":
            self.udp_socket("::", port, feed, what, universes, v6only=True)
            addr = "0.0.0.0"
        self.udp_socket(addr, port, feed, what, universes)

    def udp_socket(self, addr, port, feed, what, universes, v6only=False):
        sk = socket.socket(self.family(addr), socket.SOCK_DGRAM)
        # no SO_REUSEADDR: a program bound to the port later (olad, a second
        # daemon) would take every unicast datagram in silence; it gets
        # EADDRINUSE instead, and one bound before makes this one exit
        if ":" in addr:
            sk.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_V6ONLY, int(v6only))
        sk.bind((addr, port))
        sk.setblocking(False)
        if universes:
            self.size_rcvbuf(sk, universes)
        if what == "DDP":
            self.ddp_socks.append(sk)
        # each datagram says how many the kernel dropped before it, for
        # want of room in the receive buffer
        sk.setsockopt(socket.SOL_SOCKET, SO_RXQ_OVFL, 1)
        self.kernel_drops[sk] = 0
        prefix = {"E1.31": "e131", "OPC": "opc", "DDP": "ddp"}[what]
        self.sel.register(sk, selectors.EVENT_READ, ("udp", feed, prefix))
        self.socks.append(sk)

    def size_ddp(self, nbytes):
        """The DDP sockets' receive buffers for frames of NBYTES (what the
        open outputs DDP feeds take), a datagram per DDP_DATA bytes: a
        sender puts a whole frame on the wire at once, push flag last, and
        the default buffer holds about 90 of its datagrams (126 KiB of
        pixels; a frame of 24 64x32 panels takes 144 KiB)."""
        if not nbytes or nbytes == self.ddp_sized:
            return
        self.ddp_sized = nbytes
        for sk in self.ddp_socks:
            self.size_rcvbuf(sk, -(-nbytes // DDP_DATA), "DDP", "datagram")

    @staticmethod
    def size_rcvbuf(sk, datagrams, what="E1.31", per="universe"):
        """A receive buffer for RCVBUF_FRAMES frames of DATAGRAMS datagrams
        (E1.31: a universe each): the default (208 KiB, 166 E1.31
        datagrams) drops part of every frame of 170 universes at 54 fps.
        The kernel caps it at net.core.rmem_max (208 KiB on Debian) for a
        daemon without CAP_NET_ADMIN: the log says what to raise it to.
        Returns (bytes got, bytes wanted)."""
        want = datagrams * RCVBUF_FRAMES * UDP_TRUESIZE
        got = sk.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF)
        if got < want:
            # the kernel doubles what it is asked for (its own overhead)
            sk.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, (want + 1) // 2)
            got = sk.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF)
        many = "%d %s%s" % (datagrams, per, "s" * (datagrams > 1))
        if got < want:
            log("%s: a receive buffer of %d KiB, %d KiB wanted for frames of %s (%d "
                "frames): datagrams will be dropped while the daemon is busy "
                "(%s.kernel_drops); raise net.core.rmem_max to %d or more (sysctl.d: "
                "net.core.rmem_max = %d)" % (what, got >> 10, want >> 10, many, RCVBUF_FRAMES,
                                            what.replace(".", "").lower(), want, want))
        else:
            log("%s: a receive buffer of %d KiB for frames of %s (%d frames)"
                % (what, got >> 10, many, RCVBUF_FRAMES))
        return got, want

    def receive(self, sk, prefix):
        """One datagram and the kernel's drops before it (SO_RXQ_OVFL,
        counted as PREFIX.kernel_drops); None when there is none."""
        pkt, anc, _, _ = sk.recvmsg(MAX_UDP, socket.CMSG_SPACE(4))
        for level, kind, data in anc:
            if level == socket.SOL_SOCKET and kind == SO_RXQ_OVFL and len(data) >= 4:
                total = struct.unpack("=I", data[:4])[0]
                new = (total - self.kernel_drops[sk]) & 0xffffffff
                if new:
                    self.stats.add(prefix + ".kernel_drops", new)
                self.kernel_drops[sk] = total
        return pkt

    def tcp(self, addr, port):
        sk = socket.socket(self.family(addr), socket.SOCK_STREAM)
        sk.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        if ":" in addr:
            sk.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_V6ONLY, 0)
        sk.bind((addr, port))
        sk.listen(8)
        sk.setblocking(False)
        self.sel.register(sk, selectors.EVENT_READ, ("accept", None, None))
        self.socks.append(sk)

    def join(self, universes, dynamic=False):
        """IPv4 multicast groups 239.255.hi.lo of UNIVERSES.  The E1.31
        socket receives every group the host joined on its port (Linux's
        IP_MULTICAST_ALL, on by default), so the groups are joined on
        sockets of their own, 20 each (igmp_max_memberships).  DYNAMIC:
        sync universes data packets name, SYNC_JOINS of them at most.  A
        group whose sync packets came within the source timeout, or that
        data waits for, is kept: a new one takes the place of the group
        quiet longest among the others, or is not joined while there is
        none (data naming one sync universe after another cannot make the
        daemon leave a group in use)."""
        for u in universes:
            if u in self.joined:
                continue
            if dynamic and len(self.dynamic) >= SYNC_JOINS:
                idle = self.idle_sync_group()
                if idle is None:
                    self.stats.add("e131.sync_groups_full")
                    continue
                self.leave(idle)
                self.stats.add("e131.sync_groups_left")
            if self.membership(u, socket.IP_ADD_MEMBERSHIP) and dynamic:
                self.dynamic[u] = self.px.clock()

    def idle_sync_group(self):
        """The dynamic sync group quiet longest (no sync packet within the
        source timeout, no data waiting for it), or None."""
        px, now = self.px, self.px.clock()
        idle = [(px.sync_seen.get(u, joined), u) for u, joined in self.dynamic.items()
                if u not in px.pending_sync and
                now - px.sync_seen.get(u, joined) > px.s["source-timeout"]]
        return min(idle)[1] if idle else None

    def membership(self, u, op):
        """Join (IP_ADD_MEMBERSHIP) or leave group U on joiner sockets.  With
        the default multicast-interface, 0.0.0.0, the kernel picks the
        interface the route to the group leaves by; where there is none (no
        default route: ENODEV), the group is joined on every interface that
        is up with an IPv4 address instead."""
        group = socket.inet_aton("239.255.%d.%d" % (u >> 8, u & 255))
        if op == socket.IP_DROP_MEMBERSHIP:
            for sk, iface in self.joined.pop(u):
                self.set_membership(sk, op, group + socket.inet_aton(iface), u)
                sk[1] -= 1
            return True
        iface = self.px.s["multicast-interface"]
        err = self.join_on(u, group, [iface])
        if err == errno.ENODEV and iface == "0.0.0.0":
            addrs = ipv4_addresses()
            err = self.join_on(u, group, addrs)
            if not err:
                self.stats.add("e131.joins_per_interface")
                if not self.said_no_route:
                    self.said_no_route = True
                    log("no route to the multicast groups (no default route?): joined on "
                        "every interface instead (%s); multicast-interface ADDRESS picks one"
                        % ", ".join(addrs))
        if err:
            log("joining 239.255.%d.%d (universe %d): %s" % (u >> 8, u & 255, u,
                                                           os.strerror(err)))
            return False
        return True

    def join_on(self, u, group, ifaces):
        """Join GROUP on each of IFACES (addresses); 0 if one took it, else
        the errno of the last refusal."""
        err, joined = errno.ENODEV, []
        for iface in ifaces:
            sk = next((j for j in self.joiners if j[1] < JOINS_PER_SOCKET), None)
            if sk is None:
                sk = [socket.socket(socket.AF_INET, socket.SOCK_DGRAM), 0]
                self.joiners.append(sk)
            err = self.set_membership(sk, socket.IP_ADD_MEMBERSHIP,
                                      group + socket.inet_aton(iface), u, quiet=True)
            if not err:
                sk[1] += 1
                joined.append((sk, iface))
        if joined:
            self.joined[u] = joined
            return 0
        return err

    @staticmethod
    def set_membership(sk, op, mreq, u, quiet=False):
        try:
            sk[0].setsockopt(socket.IPPROTO_IP, op, mreq)
        except OSError as e:
            if not quiet:
                log("leaving 239.255.%d.%d (universe %d): %s" % (u >> 8, u & 255, u,
                                                              e.strerror))
            return e.errno
        return 0

    def leave(self, u):
        del self.dynamic[u]
        self.membership(u, socket.IP_DROP_MEMBERSHIP)

    def stop_listening(self):
        for sk in self.socks + list(self.clients):
            self.sel.unregister(sk)
            sk.close()
        for sk, _ in self.joiners:
            sk.close()
        self.socks, self.clients, self.joiners = [], {}, []
        self.ddp_socks, self.ddp_sized = [], 0
        self.kernel_drops = {}
        self.joined, self.dynamic = {}, {}
        self.px.close()

    def want_write(self, out):
        """Be told when OUT's device takes a frame (its newest waits)."""
        try:
            self.sel.register(out.fd, selectors.EVENT_WRITE, ("output", out, None))
        except KeyError:
            pass

    def forget_output(self, out):
        """OUT's device is being closed: no more waiting for it."""
        try:
            self.sel.unregister(out.fd)
        except (KeyError, ValueError):
            pass

    def accept(self, lsk):
        try:
            sk, peer = lsk.accept()
        except OSError:
            return
        if len(self.clients) >= self.px.s["opc-max-clients"]:
            # the one quiet longest makes room
            old = min(self.clients, key=lambda c: self.clients[c][1])
            self.stats.add("opc.clients_evicted")
            self.drop_client(old)
        sk.setblocking(False)
        self.clients[sk] = [bytearray(), time.monotonic()]
        self.sel.register(sk, selectors.EVENT_READ, ("client", None, None))
        self.stats.add("opc.connections")
        if self.verbose:
            log("OPC client %s connected" % (peer,))

    def drop_client(self, sk):
        self.sel.unregister(sk)
        del self.clients[sk]
        sk.close()

    def client(self, sk):
        try:
            data = sk.recv(65536)
        except (BlockingIOError, InterruptedError):
            return
        except OSError:
            data = b""
        if not data:
            self.drop_client(sk)
            return
        st = self.clients[sk]
        st[1] = time.monotonic()
        buf = st[0]
        buf += data
        while len(buf) >= 4:
            need = 4 + (buf[2] << 8 | buf[3])
            if len(buf) < need:
                break
            self.px.feed_opc(bytes(buf[:need]))
            del buf[:need]

    def run(self):
        tick = 0.05
        next_tick = time.monotonic() + tick
        while not self.stop_asked:
            for key, mask in self.sel.select(max(0.0, next_tick - time.monotonic())):
                kind, arg, _ = key.data
                if kind == "udp":
                    for _ in range(64):
                        try:
                            pkt = self.receive(key.fileobj, key.data[2])
                        except (BlockingIOError, InterruptedError):
                            break
                        except OSError:
                            break
                        arg(pkt)
                elif kind == "accept":
                    self.accept(key.fileobj)
                elif kind == "client":
                    if key.fileobj in self.clients:
                        self.client(key.fileobj)
                elif kind == "output":
                    # (an event of this batch may have closed it already)
                    if arg.fd == key.fileobj and arg.pending:
                        self.forget_output(arg)
                        self.px.flush([arg])
            now = time.monotonic()
            if now >= next_tick:
                self.px.tick(now)
                next_tick = now + tick
            # each output at most once per turn, whatever a burst brought
            self.px.flush_ready()
            if self.stats_asked:
                self.stats_asked = False
                self.dump_stats()
            if self.reload_asked:
                self.reload_asked = False
                self.reload()
        self.dump_stats()
        self.stop_listening()

    def dump_stats(self):
        text = self.stats.text()
        path = self.px.s["stats-file"]
        if path:
            try:
                with open(path + ".tmp", "w") as f:
                    f.write(text)
                os.replace(path + ".tmp", path)
            except OSError as e:
                log("stats file %s: %s" % (path, e.strerror))
        log("stats: " + ", ".join(ln.replace(" ", " = ") for ln in text.splitlines()[1:]))

    def reload(self):
        try:
            cfg = Config(self.cfg_path)
        except ConfigError as e:
            log("SIGHUP: %s has errors; the running configuration stays:\n%s"
                % (self.cfg_path, e))
            return
        self.stop_listening()
        try:
            self.start(cfg)
        except OSError as e:
            log("SIGHUP: %s; exiting (systemd restarts it)" % e)
            sys.exit(1)
        log("SIGHUP: %s reloaded" % self.cfg_path)


def main():
    ap = argparse.ArgumentParser(
        prog="prukit-pixeld",
        description="E1.31 (sACN), Open Pixel Control and DDP onto prukit's NeoPixel strings "
        "(/dev/ws281xN) and HUB75 matrix (/dev/fbN).",
        epilog="The configuration file (default %s) says which network channels go to which "
        "pixels; its comments and prukit-pixeld(8) explain it.  SIGHUP reloads it, SIGUSR1 "
        "writes the counters." % CONFIG)
    ap.add_argument("--config", default=CONFIG, metavar="FILE",
                    help="the configuration file (default: %(default)s)")
    ap.add_argument("--check", action="store_true",
                    help="read the configuration, print what it maps and exit")
    ap.add_argument("--verbose", action="store_true", help="log connections")
    ap.add_argument("--version", action="version", version="prukit-pixeld " + VERSION)
    args = ap.parse_args()
    try:
        cfg = Config(args.config)
    except ConfigError as e:
        print("prukit-pixeld: the configuration has errors:\n%s" % e, file=sys.stderr)
        return 2
    if args.check:
        for m in cfg.maps:
            print("%s: %s %s -> output %s (%s) from pixel %d"
                  % (m.line, m.proto, " ".join("%s %s" % kv for kv in sorted(m.kw.items())
                                               if kv[0] != "at"),
                     m.output.name, m.output.where, m.at))
        return 0
    srv = Server(args.config, args.verbose)

    def on_signal(signum, _):
        if signum == signal.SIGHUP:
            srv.reload_asked = True
        elif signum == signal.SIGUSR1:
            srv.stats_asked = True
        else:
            srv.stop_asked = True

    for sig in (signal.SIGHUP, signal.SIGUSR1, signal.SIGTERM, signal.SIGINT):
        signal.signal(sig, on_signal)
    try:
        srv.start(cfg)
    except OSError as e:
        log("cannot listen: %s" % e)
        return 1
    srv.run()
    return 0

