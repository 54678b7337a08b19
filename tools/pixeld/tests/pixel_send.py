# SPDX-License-Identifier: GPL-2.0-only
"""Senders for prukit-pixeld's tests, written from the protocols' own
documents (not from any receiver): an Open Pixel Control client (TCP and
UDP), a DDP sender, and E1.31 packets built byte by byte (for the cases a
real sender does not make: the fuzzer's seeds, late sequence numbers, other
start codes).  The E1.31 sender the VM tests use is PyPI's "sacn" package;
this one checks the daemon against the standard as well.

  OPC (openpixelcontrol.org): a message is channel (1 byte), command (1),
  data length (2, big-endian), data; command 0 sets pixels (R, G, B per
  pixel), 255 is system exclusive; channel 0 is every channel.

  DDP (3waylabs.com/ddp): a 10-byte header - flags (version 1 in bits
  7-6, push 0x01), sequence (low 4 bits), data type (0x0B: 8-bit RGB),
  destination id (1: the default output), data offset (4 bytes,
  big-endian), data length (2) - then the data; 1440 data bytes per
  packet is what senders use.

  E1.31 (ANSI E1.31-2018): a root layer (preamble 0x0010, postamble 0,
  "ASC-E1.17", flags and length, vector 4 data / 8 extended, CID), a
  framing layer (vector 2: source name, priority, sync address, sequence,
  options, universe; extended vector 1: a synchronization packet), a DMP
  layer (vector 2, address type 0xa1, first address 0, increment 1,
  count = 1 + slots, start code, slots)."""
import socket
import struct

E131_PORT, OPC_PORT, DDP_PORT = 5568, 7890, 4048


def flen(n):
    """A PDU's flags and length field: flags 0x7, length N."""
    return 0x7000 | n


def e131_data(universe, slots, cid=b"prukit-test-cid!", seq=0, priority=100, sync=0,
              options=0, start=0, name=b"prukit test"):
    slots = bytes(slots)
    dmp = struct.pack(">HBBHHHB", flen(11 + len(slots)), 0x02, 0xa1, 0, 1, 1 + len(slots),
                      start) + slots
    framing = struct.pack(">HI64sBHBBH", flen(77 + len(dmp)), 0x00000002, name, priority, sync,
                          seq & 255, options, universe) + dmp
    return e131_root(0x00000004, cid, framing)


def e131_sync(sync, cid=b"prukit-test-cid!", seq=0):
    framing = struct.pack(">HIBHH", flen(11), 0x00000001, seq & 255, sync, 0)
    return e131_root(0x00000008, cid, framing)


def e131_root(vector, cid, framing):
    return struct.pack(">HH12sHI16s", 0x0010, 0, b"ASC-E1.17\0\0\0", flen(22 + len(framing)),
                       vector, cid) + framing


def e131_group(universe):
    return "239.255.%d.%d" % (universe >> 8, universe & 255)


def opc_message(channel, data, command=0):
    data = bytes(data)
    return struct.pack(">BBH", channel, command, len(data)) + data


def ddp_packets(data, offset=0, dtype=0x0B, dest=1, seq=1, push=True, size=1440):
    """The packets of one DDP frame: DATA from byte OFFSET, SIZE bytes per
    packet, push on the last."""
    data = bytes(data)
    out = []
    for at in range(0, len(data), size) or [0]:
        part = data[at:at + size]
        last = at + size >= len(data)
        flags = 0x40 | (0x01 if push and last else 0)
        out.append(struct.pack(">BBBBIH", flags, seq & 15, dtype, dest, offset + at,
                               len(part)) + part)
    return out


class OpcClient:
    """OPC over TCP (a connection) or UDP (one message per datagram)."""

    def __init__(self, host="127.0.0.1", port=OPC_PORT, udp=False):
        self.addr = (host, port)
        self.udp = udp
        if udp:
            self.sk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        else:
            self.sk = socket.create_connection(self.addr, timeout=10)

    def put_pixels(self, channel, rgb, command=0):
        msg = opc_message(channel, rgb, command)
        if self.udp:
            self.sk.sendto(msg, self.addr)
        else:
            self.sk.sendall(msg)

    def close(self):
        self.sk.close()


class DdpSender:
    def __init__(self, host="127.0.0.1", port=DDP_PORT):
        self.addr = (host, port)
        self.sk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.seq = 0

    def frame(self, rgb, offset=0, **kw):
        self.seq = self.seq % 15 + 1
        for p in ddp_packets(rgb, offset, seq=self.seq, **kw):
            self.sk.sendto(p, self.addr)

    def close(self):
        self.sk.close()


class E131Sender:
    """Raw E1.31 over UDP, unicast to HOST or multicast."""

    def __init__(self, host="127.0.0.1", port=E131_PORT, cid=b"prukit-test-cid!"):
        self.host, self.port, self.cid = host, port, cid
        self.sk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sk.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 1)
        self.seq = {}

    def send(self, pkt, universe=None, multicast=False):
        dest = e131_group(universe) if multicast else self.host
        self.sk.sendto(pkt, (dest, self.port))

    def data(self, universe, slots, multicast=False, **kw):
        seq = self.seq[universe] = (self.seq.get(universe, -1) + 1) & 255
        kw.setdefault("seq", seq)
        self.send(e131_data(universe, slots, cid=self.cid, **kw), universe, multicast)

    def sync(self, sync, multicast=True):
        seq = self.seq["sync"] = (self.seq.get("sync", -1) + 1) & 255
        self.send(e131_sync(sync, cid=self.cid, seq=seq), sync, multicast)

    def close(self):
        self.sk.close()
