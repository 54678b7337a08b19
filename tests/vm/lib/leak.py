# SPDX-License-Identifier: GPL-2.0-only
"""How every VM test measures leaks, the same way everywhere: run N cycles
of what could leak, and after a warm-up (a quarter of the cycles, at most
20), half way through what is left and at the end, drop the caches and read

  - the live objects (active_objs x objsize in /proc/slabinfo) of the
    kmalloc caches and of kernfs_node_cache, where a leaked device, channel,
    LED class device, sysfs file or buffer descriptor would stay;
  - MemAvailable in /proc/meminfo plus the pages the per-CPU lists hold
    (the "count:" lines of /proc/zoneinfo's pagesets: free pages that
    MemAvailable does not count, and which swing it by +-16 KiB from one
    cycle to the next in a 2-CPU guest), where leaked DMA buffers (whole
    pages) would show.

The growth of the live objects per cycle over the second half must stay
under a bound well below what one leaked object set per cycle would cost
(caches that settle early do not count, a leak grows in both halves).
MemAvailable alone moved with the per-CPU lists (a make check run saw one
half of tests/vm/cases/85-rpmsg-stop-stress shrink it by 13 KiB/cycle and a
rerun by 2 KiB); with them counted it still moves with the kernel's own
caches, and a leak shrinks it in both halves, so the smaller of the two
halves' shrinks is what is bounded.  SUnreclaim (whole slab pages) and the caches
that grew most are reported, not bounded.

    meter = LeakMeter(cycles)
    for cycle in range(cycles):
        ...
        meter.after(cycle)
    meter.check(slab_per_cycle, avail_per_cycle, "what one cycle does")"""
import os
import time

from rpmsg import check, info


def counted(cache):
    """Where a leaked driver object lives.  (Not vmap_area: its objects are
    freed lazily, in batches, so it grows for hundreds of cycles without
    leaking; and not SUnreclaim, which counts whole slab pages.)"""
    return cache.startswith("kmalloc-") or cache == "kernfs_node_cache"


def shrink_slabs():
    """Flush SLUB's per-CPU slabs of the counted caches.  /proc/slabinfo
    counts every object of a slab a CPU holds (its current slab and its
    partial list) as active, free or not, so without this the live bytes
    move by whole slabs from one snapshot to the next: a 5.10 make check
    run saw kernfs_node_cache "grow" by 5 slabs (40 KiB) over 15 cycles in
    one half and 0 in another.  Writing 1 to /sys/kernel/slab/NAME/shrink
    (kmem_cache_shrink) hands them back to the node's lists, where the
    count sees their free objects."""
    for name in os.listdir("/sys/kernel/slab"):
        if counted(name):
            try:
                with open("/sys/kernel/slab/%s/shrink" % name, "w") as f:
                    f.write("1")
            except OSError:
                pass


def live_slab():
    """The counted caches' live bytes, now."""
    with open("/proc/slabinfo") as f:
        return sum(int(w[1]) * int(w[3]) for w in (line.split() for line in f.readlines()[2:])
                   if counted(w[0]))


def meminfo():
    """(live counted slab bytes, MemAvailable + per-CPU lists,
    {cache: live bytes}, SUnreclaim), caches dropped and the counted slab
    caches' per-CPU slabs flushed first - again, half a second apart, until
    the live bytes settle (at most 5 s): what a cycle frees late (TTM's
    delayed destruction, RCU, work items) counts once it is freed, however
    fast the cycles before the snapshot went."""
    prev = None
    for _ in range(10):
        with open("/proc/sys/vm/drop_caches", "w") as f:
            f.write("3")
        time.sleep(0.5)
        shrink_slabs()
        live = live_slab()
        if prev is not None and abs(live - prev) < 1024:
            break
        prev = live
    vals = {}
    with open("/proc/meminfo") as f:
        for line in f:
            k, v = line.split(":")
            vals[k] = int(v.split()[0]) * 1024
    caches = {}
    with open("/proc/slabinfo") as f:
        for line in f.readlines()[2:]:
            w = line.split()
            caches[w[0]] = int(w[1]) * int(w[3])     # active_objs * objsize
    live = sum(v for k, v in caches.items() if counted(k))
    pcp = 0
    with open("/proc/zoneinfo") as f:
        for line in f:
            w = line.split()
            if len(w) == 2 and w[0] == "count:":
                pcp += int(w[1])
    avail = vals["MemAvailable"] + pcp * os.sysconf("SC_PAGE_SIZE")
    return live, avail, caches, vals["SUnreclaim"]


def processes():
    """(pid, comm, state) of every process there is."""
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % pid) as f:
                stat = f.read()
        except OSError:
            continue
        yield int(pid), stat[stat.index("(") + 1:stat.rindex(")")], stat[stat.rindex(")") + 2]


def user_processes():
    """The comm of every userspace process (kernel threads have no
    cmdline), counted: memory a daemon left running (a udevd handling the
    cycles' uevents) shows in MemAvailable too."""
    seen = {}
    for pid, comm, _ in processes():
        try:
            with open("/proc/%d/cmdline" % pid, "rb") as f:
                if not f.read(1):
                    continue
        except OSError:
            continue
        seen[comm] = seen.get(comm, 0) + 1
    return ", ".join("%s x%d" % kv if kv[1] > 1 else kv[0] for kv in sorted(seen.items()))


class LeakMeter:
    """Snapshots after the warm-up, half way and at the end of CYCLES."""

    def __init__(self, cycles):
        self.cycles = cycles
        self.warmup = min(20, cycles // 4)
        self.mid = self.warmup + (cycles - self.warmup) // 2
        self.snaps = {}

    def after(self, cycle):
        """Call after cycle number CYCLE (from 0) has ended."""
        n = cycle + 1
        if n in (self.warmup, self.mid, self.cycles) and n not in self.snaps:
            self.snaps[n] = meminfo()

    def check(self, slab_per_cycle, avail_per_cycle, what):
        """Report both halves and check the bounds (bytes per cycle); a run
        cut short (fewer snapshots) fails."""
        w, m, e = self.warmup, self.mid, self.cycles
        if not check("leak measure over %d cycles of %s: all three snapshots taken" % (e, what),
                     e > m > w > 0 and all(k in self.snaps for k in (w, m, e)),
                     "cycles %d, snapshots after %s" % (e, sorted(self.snaps))):
            return
        base, mid, end = self.snaps[w], self.snaps[m], self.snaps[e]
        for name, a, b, n in (("first", base, mid, m - w), ("second", mid, end, e - m)):
            info("leak measure, %s half (%d cycles): live kmalloc+kernfs objects %+.0f B/cycle, "
                 "MemAvailable+pcp %+.0f B/cycle, SUnreclaim %+.0f B/cycle"
                 % (name, n, (b[0] - a[0]) / n, (b[1] - a[1]) / n, (b[3] - a[3]) / n))
        grew = sorted(((end[2].get(k, 0) - base[2].get(k, 0), k) for k in end[2]), reverse=True)
        info("live slab objects grown most since the warm-up: " +
             ", ".join("%s %+d B" % (k, d) for d, k in grew[:5]))
        info("userspace processes at the end: " + user_processes())
        slab = (end[0] - mid[0]) / (e - m)
        avail = min((base[1] - mid[1]) / (m - w), (mid[1] - end[1]) / (e - m))
        check("live kmalloc+kernfs objects grow less than %d B per cycle (%+.0f)"
              % (slab_per_cycle, slab), slab < slab_per_cycle)
        check("MemAvailable (+ per-CPU lists) shrinks less than %d B per cycle "
              "in one half at least (%+.0f)" % (avail_per_cycle, -avail),
              avail < avail_per_cycle)
