# SPDX-License-Identifier: GPL-2.0-only
"""Source merging: which source's data each output shows, and when.  E1.31
sources by priority, sequence and sync packets, OPC messages and DDP
pushes, each turned into whole frames of the outputs (Pixeld)."""
import time

from . import protocols as p
from .common import Stats, log


# ------------------------------------------------------------------------- E1.31

class Source:
    __slots__ = ("cid", "priority", "seq", "last", "data", "sync", "force", "order")

    def __init__(self, cid, order):
        self.cid, self.order = cid, order
        self.seq = None
        self.data = None


class Staged:
    """The universes gathered for an output's next unsynchronized frame,
    not shown yet: {universe number: (Universe, data)}, the source and the
    one sequence number they came with (None if they differ)."""
    __slots__ = ("first", "seq", "cid", "unis")

    def __init__(self, now):
        self.first, self.seq, self.cid, self.unis = now, None, None, {}


class Universe:
    """One mapped universe: its sources and its segments, (map, offset in
    the universe's 512 slots, offset in the map's stream, length)."""

    def __init__(self, number):
        self.number = number
        self.sources = {}
        self.winner = None
        self.segments = []
        self.outputs = set()


def e131_segments(m):
    """[(universe, slot offset, stream offset, length)] of an E1.31 map.
    contiguous: the channels run on through the next universes' 512;
    pixels: each universe holds whole pixels only (170 RGB, 128 RGBW),
    the next universes from their channel 1."""
    size = m.pixels * m.nbpp
    u, slot, done, segs = m.kw["universe"], m.kw["channel"] - 1, 0, []
    while done < size and u <= 63999:
        room = 512 - slot
        if m.kw["layout"] == "pixels":
            room -= room % m.nbpp
        n = min(room, size - done)
        if n > 0:
            segs.append((u, slot, done, n))
        done += n
        u, slot = u + 1, 0
    return segs


# ---------------------------------------------------------------------- the daemon

class Pixeld:
    """The receivers and the outputs: feed_e131/feed_opc/feed_ddp take one
    datagram or message (the event loop's, or a bench's or test's)."""

    def __init__(self, config, stats=None, clock=time.monotonic):
        self.cfg = config
        self.s = config.settings
        self.stats = stats or Stats()
        self.clock = clock
        self.outputs = config.outputs
        self.maps = config.maps
        self.universes = {}
        self.opc_maps = {}
        self.ddp_maps = []
        self.pending_sync = {}		# sync universe -> {universe: (source, data, time)}
        self.pending_of = {}		# universe -> the sync universe it waits for
        self.sync_sources = {}		# (cid, sync universe) -> [last sequence, time]
        self.sync_seen = {}		# sync universe -> time of its last sync packet
        self.sync_lost = set()		# sync universes whose sync packets stopped
        self.partial = {}		# output -> Staged: its next unsynchronized frame
        self.strict = set()		# outputs whose universes come numbered alike
        self.misses = {}		# output -> frames in a row not gathered whole
        self.streak = {}		# output -> whole frames of one number in a row
        self.touched = set()		# outputs DDP changed since its last push
        # defer: frames complete are kept in .ready and written by
        # flush_ready(), once per turn of the event loop (the newest of each
        # output); else written at once (the tests' and benches' default)
        self.defer = False
        self.ready = {}			# output -> True, in the order they completed
        self.order = 0
        self.e131_outputs = {}
        self.on_join = None
        self.on_ddp = None
        self.on_pending = None
        self.attach_all(self.clock())

    # --- outputs and maps
    def attach_all(self, now):
        """Open the outputs that are there; (re)build the maps of the
        ones that opened."""
        changed = False
        for out in self.outputs.values():
            if out.fd is None and out.attach(now):
                changed = True
        if changed:
            self.build()

    def build(self):
        old = self.universes
        self.partial = {}
        self.universes, self.opc_maps, self.ddp_maps = {}, {}, []
        for m in self.maps:
            out = m.output
            if out.fd is None:
                m.pixels = 0
                continue
            m.nbpp = m.fmt_nbpp or out.bpp
            m.resolve()
            if not m.pixels:
                continue
            if m.proto == "e131":
                for u, slot, at, n in e131_segments(m):
                    uni = self.universes.get(u)
                    if uni is None:
                        uni = self.universes[u] = old.get(u) or Universe(u)
                        uni.segments, uni.outputs = [], set()
                    uni.segments.append((m, slot, at, n))
                    uni.outputs.add(out)
            elif m.proto == "opc":
                self.opc_maps.setdefault(m.kw["channel"], []).append(m)
            else:
                self.ddp_maps.append(m)
        self.e131_outputs = {}
        for uni in self.universes.values():
            for out in uni.outputs:
                self.e131_outputs.setdefault(out, set()).add(uni.number)
        if self.on_join:
            self.on_join(sorted(set(self.universes) | set(self.s["sync-universes"])))
        if self.on_ddp:
            self.on_ddp(self.ddp_bytes())

    def ddp_bytes(self):
        """The bytes of a DDP frame of every open output DDP feeds."""
        return max((m.kw["offset"] + len(m.stream) for m in self.ddp_maps), default=0)

    def flush(self, outputs):
        """OUTPUTS have a complete frame: put their maps' data into their
        frames (what comes later for them waits for the next flush), and
        write them, now or (.defer) at flush_ready()."""
        for out in outputs:
            self.partial.pop(out, None)
            if out.fd is None:
                continue
            for m in self.maps:
                if m.output is out and m.dirty:
                    m.apply()
            if self.defer:
                if out in self.ready:
                    self.stats.add("output.%s.superseded" % out.name)
                self.ready[out] = True
            else:
                self.write(out)

    def flush_ready(self):
        """Write each output whose frame completed since the last call, once."""
        ready, self.ready = self.ready, {}
        for out in ready:
            if out.fd is not None:
                self.write(out)

    def write(self, out):
        if out.write(self.stats) is False and out.pending and self.on_pending:
            self.on_pending(out)

    # --- E1.31
    def feed_e131(self, pkt, now=None):
        """One E1.31 datagram."""
        st = self.stats
        st.add("e131.received")
        now = self.clock() if now is None else now
        d = p.parse_e131(pkt)
        if isinstance(d, str):
            return st.add("e131." + d)
        if isinstance(d, p.E131Sync):
            return self.feed_e131_sync(d, now)
        cid, prio, sync, seq, opts, unum, start = d[:7]
        uni = self.universes.get(unum)
        if uni is None:
            return st.add("e131.ignored.universe")
        if start != 0:
            return st.add("e131.ignored.start_code")
        src = uni.sources.get(cid)
        if src is not None and src.seq is not None and -20 < (seq - src.seq + 128) % 256 - 128 <= 0:
            return st.add("e131.dropped.late")
        # a source ends its stream whatever else the packet says (preview too)
        if opts & p.OPT_TERMINATED:
            st.add("e131.accepted")
            if src is not None:
                st.add("e131.terminated")
                self.lose_source(uni, src, now)
            return None
        if opts & p.OPT_PREVIEW:
            return st.add("e131.ignored.preview")
        if src is None:
            if len(uni.sources) >= self.s["max-sources"]:
                # a flood of sources cannot lock out one of a higher
                # priority: it takes the place of the lowest (the newest of those)
                low = min(uni.sources.values(), key=lambda s: (s.priority, -s.order))
                if low.priority >= prio:
                    return st.add("e131.dropped.sources_full")
                st.add("e131.sources_evicted")
                self.lose_source(uni, low, now)
            self.order += 1
            src = uni.sources[cid] = Source(cid, self.order)
        st.add("e131.accepted")
        src.seq, src.priority, src.last, src.sync = seq, prio, now, sync
        src.force = bool(opts & p.OPT_FORCE_SYNC)
        src.data = bytes(d.slots)
        if self.pick(uni) is src:
            self.show(uni, src, now)
        else:
            st.add("e131.lower_priority")
        return None

    def pick(self, uni):
        """The winning source: the highest priority; among equals the one
        already winning, else the one known longest (no merging)."""
        if not uni.sources:
            uni.winner = None
            return None
        top = max(s.priority for s in uni.sources.values())
        if uni.winner is None or uni.winner.cid not in uni.sources or \
                uni.winner.priority != top:
            uni.winner = min((s for s in uni.sources.values() if s.priority == top),
                             key=lambda s: s.order)
        return uni.winner

    def lose_source(self, uni, src, now):
        del uni.sources[src.cid]
        was = uni.winner
        addr = self.pending_of.get(uni.number)
        if addr is not None and self.pending_sync[addr][uni.number][0] is src:
            self.unpend(uni.number)
        new = self.pick(uni)
        if new is not None and new is not was and new.data is not None:
            self.show(uni, new, now)

    def unpend(self, unum):
        """UNUM waits for no sync packet any more (a universe waits for one
        sync universe at most: what pends is bounded by the maps)."""
        addr = self.pending_of.pop(unum)
        pend = self.pending_sync[addr]
        del pend[unum]
        if not pend:
            del self.pending_sync[addr]

    def show(self, uni, src, now):
        """SRC, the universe's winner, sent data: show it, or keep it for its
        sync packet.  What waited for a sync packet before from another
        source (one that lost priority), or for another sync universe, is
        dropped: the newest data of the winner replaces it."""
        addr = self.pending_of.get(uni.number)
        if addr is not None and (addr != src.sync or
                                 self.pending_sync[addr][uni.number][0] is not src):
            self.unpend(uni.number)
        # E1.31's Force_Synchronization: once its sync packets stopped, a
        # source that sets it is shown unsynchronized until they return
        if src.sync and not (src.force and src.sync in self.sync_lost):
            # waiting since the first data after the last sync packet
            pend = self.pending_sync.setdefault(src.sync, {})
            since = pend[uni.number][2] if uni.number in pend else now
            pend[uni.number] = (src, src.data, since)
            self.pending_of[uni.number] = src.sync
            if self.on_join and src.sync not in self.universes:
                self.on_join([src.sync], dynamic=True)
            return
        for out in uni.outputs:
            self.stage(out, uni, src, now)

    def stage(self, out, uni, src, now):
        """Unsynchronized data of UNI (from SRC, its winner) for OUT's next
        frame, shown once every universe of the output came.

        Senders number the universes of a frame alike (their counters run in
        step); an output whose last 3 frames came so, all from one source,
        is strict: a frame is one sequence number's universes, data with a
        newer number starts the next frame, and what came of the one before,
        incomplete (a datagram lost), is dropped, never shown with it
        (output.NAME.incomplete); a universe of a frame already left behind
        is late (output.NAME.late).  3 incomplete frames in a row make it
        loose again.  Loose (at first, and for senders that number each
        universe on its own or send only what changed): each universe is
        taken as it comes; what came of a frame whose universes were
        numbered alike is shown on its own, at once, when a universe with
        the next number comes (a stream met mid-frame, a datagram lost), so
        that the next frame is gathered whole; the rest is shown frame-wait
        after its first universe."""
        seq = src.seq
        st = self.partial.get(out)
        if st is None:
            st = self.partial[out] = Staged(now)
        elif st.unis and out in self.strict and (seq != st.seq or src.cid != st.cid):
            if src.cid == st.cid and (seq - st.seq) % 256 >= 128:
                self.stats.add("output.%s.late" % out.name)	# its frame has gone
                return
            self.stats.add("output.%s.incomplete" % out.name)
            self.missed(out)
            st = self.partial[out] = Staged(now)
        elif st.unis and out not in self.strict and st.seq is not None and \
                src.cid == st.cid and (seq - st.seq) % 256 == 1 and uni.number not in st.unis:
            # the rest of a frame numbered alike, the next one begins
            self.stats.add("output.%s.incomplete" % out.name)
            self.show_staged(out, self.partial.pop(out))
            st = self.partial[out] = Staged(now)
        # st.seq: the one number of the universes gathered, None if they differ
        st.seq = seq if not st.unis or (st.seq == seq and st.cid == src.cid) else None
        st.cid = src.cid
        st.unis[uni.number] = (uni, src.data)
        if len(st.unis) == len(self.e131_outputs[out]):
            del self.partial[out]
            self.misses[out] = 0
            self.streak[out] = self.streak.get(out, 0) + 1 if st.seq is not None else 0
            if out not in self.strict and self.streak[out] >= 3:
                self.strict.add(out)
                log("output %s: its E1.31 universes come as whole frames of one sequence "
                    "number: a frame is one number's from now on" % out.name)
            self.show_staged(out, st)

    def show_staged(self, out, st):
        for uni, data in st.unis.values():
            self.put(uni, data)
        self.flush([out])

    def missed(self, out):
        """A frame of strict OUT was not gathered whole."""
        self.misses[out] = self.misses.get(out, 0) + 1
        if self.misses[out] >= 3:
            self.strict.discard(out)
            self.streak[out] = 0
            log("output %s: its E1.31 universes no longer come as whole frames of one "
                "sequence number (3 in a row did not): each universe shown as it comes"
                % out.name)

    def put(self, uni, data):
        for m, slot, at, n in uni.segments:
            chunk = data[slot:slot + n]
            m.stream[at:at + len(chunk)] = chunk
            m.dirty = True

    def feed_e131_sync(self, d, now):
        """An E1.31 synchronization packet."""
        st = self.stats
        cid, seq, addr = d
        # only a source whose data names ADDR: it releases its own data only
        if not self.names_sync(cid, addr):
            return st.add("e131.ignored.sync")
        key = (cid, addr)
        last = self.sync_sources.get(key)
        if last is not None and -20 < (seq - last[0] + 128) % 256 - 128 <= 0:
            return st.add("e131.dropped.late")
        if key not in self.sync_sources and len(self.sync_sources) >= self.sync_room():
            self.age_sync_sources(now)
            if len(self.sync_sources) >= self.sync_room():
                return st.add("e131.dropped.sources_full")
        self.sync_sources[key] = [seq, now]
        st.add("e131.accepted")
        st.add("e131.sync")
        self.sync_seen[addr] = now
        if addr in self.sync_lost:
            self.sync_lost.discard(addr)
            st.add("e131.sync_resumed")
            log("E1.31: sync packets for universe %d are back: synchronized again" % addr)
        # a sync packet releases its own sender's data only
        self.release(addr, lambda src: src.cid == cid)
        return None

    def names_sync(self, cid, addr):
        """Whether source CID's data names sync universe ADDR."""
        if any(src.cid == cid for src, _, _ in self.pending_sync.get(addr, {}).values()):
            return True
        return any(src.sync == addr for uni in self.universes.values()
                   for src in (uni.sources.get(cid),) if src is not None)

    def sync_room(self):
        """Sync packets' (CID, sync universe) pairs kept: bounded by the maps."""
        return self.s["max-sources"] * max(1, len(self.universes))

    def age_sync_sources(self, now):
        """Forget the senders of sync packets quiet for the source timeout."""
        timeout = self.s["source-timeout"]
        for key in [k for k, (_, t) in self.sync_sources.items() if now - t > timeout]:
            del self.sync_sources[key]
        for addr in [a for a, t in self.sync_seen.items()
                     if now - t > timeout and a not in self.pending_sync]:
            del self.sync_seen[addr]

    def release(self, addr, take):
        """Show what waits for sync universe ADDR from the sources TAKE(source)
        is true of."""
        pend = self.pending_sync.get(addr)
        if not pend:
            return
        outs = set()
        for unum, (src, data, _) in list(pend.items()):
            if not take(src):
                continue
            self.unpend(unum)
            uni = self.universes.get(unum)
            if uni is not None:
                self.put(uni, data)
                outs |= uni.outputs
        self.flush(outs)

    # --- OPC
    def feed_opc(self, msg):
        """One whole OPC message (header included)."""
        st = self.stats
        st.add("opc.received")
        d = p.parse_opc(msg)
        if isinstance(d, str):
            return st.add("opc." + d)
        chan, data = d
        maps = [m for ms in self.opc_maps.values() for m in ms] if chan == 0 \
            else self.opc_maps.get(chan)
        if not maps:
            return st.add("opc.ignored.channel")
        st.add("opc.accepted")
        for m in maps:
            n = min(len(data), len(m.stream))
            m.stream[:n] = data[:n]
            m.dirty = True
        self.flush({m.output for m in maps})
        return None

    # --- DDP
    def feed_ddp(self, pkt):
        """One DDP datagram."""
        st = self.stats
        st.add("ddp.received")
        d = p.parse_ddp(pkt)
        if isinstance(d, str):
            return st.add("ddp." + d)
        flags, offset, data = d
        length = len(data)
        st.add("ddp.accepted")
        for m in self.ddp_maps:
            lo = m.kw["offset"]
            a, b = max(offset, lo), min(offset + length, lo + len(m.stream))
            if a < b:
                m.stream[a - lo:b - lo] = data[a - offset:b - offset]
                m.dirty = True
                self.touched.add(m.output)
        if flags & p.DDP_PUSH:
            outs, self.touched = self.touched, set()
            self.flush(outs)
        return None

    # --- time
    def tick(self, now=None):
        """Source timeouts, unsynchronized frames waiting too long for
        their other universes, sync packets that never came; devices that
        came back."""
        now = self.clock() if now is None else now
        timeout = self.s["source-timeout"]
        for uni in self.universes.values():
            for src in [s for s in uni.sources.values() if now - s.last > timeout]:
                self.stats.add("e131.timeouts")
                self.lose_source(uni, src, now)
        for out in [o for o, st in self.partial.items() if now - st.first > self.s["frame-wait"]]:
            # a sender that sends only what changed, or the last frame's
            # datagram lost: what came is shown
            self.stats.add("output.%s.partial" % out.name)
            if out in self.strict:
                self.missed(out)
            self.show_staged(out, self.partial.pop(out))
        for addr in [a for a, p in self.pending_sync.items()
                     if any(now - t > timeout for _, _, t in p.values()) and
                     now - self.sync_seen.get(a, now - 2 * timeout) > timeout]:
            self.sync_lost_at(addr)
        self.age_sync_sources(now)
        self.attach_all(now)

    def sync_lost_at(self, addr):
        """Data waited the source timeout for a sync packet of ADDR, and none
        came in that time: synchronization is lost (E1.31 11.1).  Sources
        that set Force_Synchronization are shown unsynchronized from now on
        (their newest data at once); the others are held, as E1.31 asks,
        until sync packets come again."""
        if addr not in self.sync_lost:
            self.sync_lost.add(addr)
            self.stats.add("e131.sync_lost")
            log("E1.31: no sync packet for universe %d in %.1f s: synchronization lost; "
                "sources with Force_Synchronization are shown unsynchronized, the others "
                "held until sync packets come again" % (addr, self.s["source-timeout"]))
        self.release(addr, lambda src: src.force)

    def close(self):
        for out in self.outputs.values():
            out.close()
