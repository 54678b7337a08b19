# SPDX-License-Identifier: GPL-2.0-only
"""The wire formats prukit-pixeld takes: E1.31 (ANSI E1.31-2018: data and
universe synchronization packets), Open Pixel Control and DDP.  Each parse
function checks one datagram or message and returns what it carries, or
the reason it is not taken ("dropped.REASON": malformed; "ignored.REASON":
well formed but not for a receiver), as the counters name it."""
import collections
import struct

E131_PORT, OPC_PORT, DDP_PORT = 5568, 7890, 4048
ACN_ID = b"ASC-E1.17\0\0\0"
ROOT_DATA, ROOT_EXTENDED = 0x00000004, 0x00000008
FRAMING_DATA, EXTENDED_SYNC, EXTENDED_DISCOVERY = 0x00000002, 0x00000001, 0x00000002
OPT_PREVIEW, OPT_TERMINATED, OPT_FORCE_SYNC = 0x80, 0x40, 0x20
DDP_PUSH, DDP_QUERY, DDP_REPLY, DDP_STORAGE, DDP_TIMECODE = 0x01, 0x02, 0x04, 0x08, 0x10
DDP_IDS = (1, 255)			# the default output device, all devices
OPC_SET, OPC_SYSEX = 0x00, 0xFF

E131_ROOT = struct.Struct(">HH12sHI16s")
E131_FRAMING = struct.Struct(">HI64sBHBBH")
E131_DMP = struct.Struct(">HBBHHHB")
E131_SYNC = struct.Struct(">HIBHH")
DDP_HDR = struct.Struct(">BBBBIH")

# An E1.31 data packet: its source, priority, sync universe, sequence
# number, options, universe, start code and slots (a memoryview)
E131Data = collections.namedtuple("E131Data", "cid priority sync seq options universe start "
                                  "slots")
# An E1.31 synchronization packet: its source, sequence number and sync universe
E131Sync = collections.namedtuple("E131Sync", "cid seq sync")
# An OPC "set pixel colours" message: its channel and data (a memoryview)
OpcSet = collections.namedtuple("OpcSet", "channel data")
# A DDP data packet: its flags, byte offset and data (a memoryview)
DdpData = collections.namedtuple("DdpData", "flags offset data")


def parse_e131(pkt):
    """An E1.31 datagram: E131Data, E131Sync or the reason it is not taken."""
    n = len(pkt)
    if n < 38:
        return "dropped.truncated"
    pre, post, acn, rfl, rvec, cid = E131_ROOT.unpack_from(pkt)
    if pre != 0x0010 or post != 0 or acn != ACN_ID:
        return "dropped.not_acn"
    if rfl & 0x0fff != n - 16 or rfl >> 12 != 7:
        return "dropped.length"
    if rvec == ROOT_EXTENDED:
        return parse_e131_extended(pkt, cid)
    if rvec != ROOT_DATA:
        return "dropped.vector"
    if n < 126:
        return "dropped.truncated"
    ffl, fvec, _, prio, sync, seq, opts, unum = E131_FRAMING.unpack_from(pkt, 38)
    if ffl & 0x0fff != n - 38 or ffl >> 12 != 7 or fvec != FRAMING_DATA:
        return "dropped.framing"
    dfl, dvec, atype, first, inc, count, start = E131_DMP.unpack_from(pkt, 115)
    if dfl & 0x0fff != n - 115 or dfl >> 12 != 7 or dvec != 0x02 or atype != 0xa1 or \
            first != 0 or inc != 1 or not 1 <= count <= 513 or count != n - 125:
        return "dropped.dmp"
    if prio > 200 or not 1 <= unum <= 63999 or sync > 63999:
        return "dropped.range"
    return E131Data(cid, prio, sync, seq, opts, unum, start, memoryview(pkt)[126:])


def parse_e131_extended(pkt, cid):
    """The extended packets: synchronization (taken), discovery (ignored)."""
    if len(pkt) < 44:
        return "dropped.truncated"
    ffl, fvec = struct.unpack_from(">HI", pkt, 38)
    if ffl & 0x0fff != len(pkt) - 38 or ffl >> 12 != 7:
        return "dropped.framing"
    if fvec == EXTENDED_DISCOVERY:
        return "ignored.discovery"
    if fvec != EXTENDED_SYNC:
        return "dropped.vector"
    if len(pkt) != 49:
        return "dropped.framing"
    _, _, seq, addr, _ = E131_SYNC.unpack_from(pkt, 38)
    return E131Sync(cid, seq, addr)


def parse_opc(msg):
    """One whole OPC message (header included): OpcSet or the reason."""
    if len(msg) < 4:
        return "dropped.truncated"
    chan, cmd, length = struct.unpack_from(">BBH", msg)
    if len(msg) != 4 + length:
        return "dropped.length"
    if cmd == OPC_SYSEX:
        return "ignored.sysex"
    if cmd != OPC_SET:
        return "ignored.command"
    return OpcSet(chan, memoryview(msg)[4:4 + length - length % 3])


def parse_ddp(pkt):
    """A DDP datagram: DdpData or the reason.  Any data type is taken, as
    WLED takes them: the maps say what the bytes are, and a push without
    data (xLights' sync: data type 0x80) carries no pixels."""
    if len(pkt) < 10:
        return "dropped.truncated"
    flags, _, _, dest, offset, length = DDP_HDR.unpack_from(pkt)
    if flags >> 6 != 1:
        return "dropped.version"
    hdr = 14 if flags & DDP_TIMECODE else 10
    if len(pkt) < hdr + length:
        return "dropped.truncated"
    if flags & (DDP_QUERY | DDP_REPLY | DDP_STORAGE):
        return "ignored.query"
    if dest not in DDP_IDS:
        return "ignored.destination"
    return DdpData(flags, offset, memoryview(pkt)[hdr:hdr + length])
