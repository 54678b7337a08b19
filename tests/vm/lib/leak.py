# SPDX-License-Identifier: GPL-2.0-only
"""How every VM test measures leaks, the same way everywhere: run N cycles
of what could leak, and at five points (below) drop the caches and read

  - the live objects (active objects times object size) of the kmalloc
    caches and of kernfs_node_cache, where a leaked device, channel, LED
    class device, sysfs file or buffer descriptor would stay;
  - the memory no /proc/meminfo counter accounts for: MemTotal less
    MemFree, the free pages the per-CPU lists hold (the "count:" lines of
    /proc/zoneinfo's pagesets, which swing MemFree by up to 2 MiB between
    two snapshots), and the pages the kernel knows the use of (ACCOUNTED:
    page cache, anonymous memory, slab, stacks, page tables).  Leaked
    pages, DMA buffers and vmalloc() areas stay there.

The snapshots are taken after the warm-up (a quarter of the cycles, at
most 20) and at each quarter of what is left.  The growth of the live
objects per cycle over the second half must stay under a bound well below
what one leaked object set per cycle would cost (caches that settle early
do not count, a leak grows all the time).

The unaccounted memory moves without a leak: the kernel allocates for
itself once in a while (a 6.12 run of tests/vm/cases/85-rpmsg-stop-stress
saw 420 KiB go in one quarter and not come back, 42 KiB per cycle of that
quarter).  MemAvailable, measured before, moved more still (the test's
own Python clients, the page cache, slab pages), and failed a make check
once with both halves of 85 shrinking it (-26 and -15 KiB/cycle).  The
quarters swing without a leak: on 6.12, 80-ws281x-cycles' by up to 60 KiB
per cycle either way (the per-CPU page lists move by hundreds of KiB
between snapshots); a make check saw +31, +28, -33, +12 KiB per cycle there
(+4 over the last three quarters together), another 84-hub75's on 6.1 at
-42, +26, -11, +10 (+9.7 over the last three: 4-5 cycles per quarter).  So
the check fails only when memory went both in three quarters of four and
over the last three together (the first follows the warm-up).  That is a
coarse bound: a driver that leaked an order-2 page (16 KiB) per display
bind failed three quarters on 5.10 and 6.1 in one session, and in another
moved 84's quarters on 6.1 by +2, +16, -5, +35 KiB per cycle (+16.7 over
the last three), which this check lets pass.  The
counters, caches and call sites that moved most are reported, not bounded.

The guest boots with slub_debug=U on the counted caches (scripts/vm.sh),
so the kernel keeps who allocated each live object: the growth is also
told by call site, and what the kernel itself keeps on every bind of any
device, whoever drives it (KERNEL_OWN), is reported but not counted.
(5.10 lists the call sites of a cache in one page of sysfs at most and
cuts kmalloc-128's short: there, pinctrl-single's kmalloc-128 objects
count, 384 B per bind.)

    meter = LeakMeter(cycles)
    for cycle in range(cycles):
        ...
        meter.after(cycle)
    meter.check(slab_per_cycle, unaccounted_per_cycle, "what one cycle does")"""
import os
import time

from rpmsg import check, info


def counted(cache):
    """Where a leaked driver object lives.  (Not vmap_area: its objects are
    freed lazily, in batches, so it grows for hundreds of cycles without
    leaking; and not SUnreclaim, which counts whole slab pages.)"""
    return cache.startswith("kmalloc-") or cache == "kernfs_node_cache"


# Call sites whose objects the kernel keeps for good on every probe of a
# device, or every framebuffer fbcon takes over, whatever the driver: no
# driver can free them.  Found by call site when a make check run saw 84's
# display bind/unbind cycles grow by 3371 B/cycle (about 770 of it every
# cycle, on all three kernels, from these).
KERNEL_OWN = {
    # pinctrl-single adds a pin function and group for a device's pinctrl
    # state each time the state is looked up (each probe) and frees them
    # only with the pin controller (drivers/pinctrl/pinctrl-single.c)
    "pcs_dt_node_to_map": "pinctrl-single",
    "pcs_add_function": "pinctrl-single",
    # the unicode map of the VT fbcon hands a new framebuffer
    # (drivers/tty/vt/consolemap.c), kept with the VT
    "con_insert_unipair": "the VT's unicode map",
}

# Where SLUB lists the live objects by call site (slub_debug=U): debugfs
# from 5.16 on ("alloc_traces"), sysfs before ("alloc_calls").
TRACES = ("/sys/kernel/debug/slab/%s/alloc_traces", "/sys/kernel/slab/%s/alloc_calls")


def object_size(cache):
    """The size a caller gets from CACHE (/proc/slabinfo's objsize is what
    an object takes, debug metadata included)."""
    try:
        with open("/sys/kernel/slab/%s/object_size" % cache) as f:
            return int(f.read())
    except OSError:
        return None


def sites(caches):
    """{(cache, function): live bytes} of the counted CACHES, by the call
    site SLUB keeps; empty where the kernel keeps none."""
    out = {}
    for cache in caches:
        if not counted(cache):
            continue
        for path in TRACES:
            try:
                with open(path % cache) as f:
                    lines = f.readlines()
            except OSError:
                continue
            size = object_size(cache) or 0
            for line in lines:
                w = line.split()
                if len(w) > 1 and w[0].isdigit():
                    key = (cache, w[1].split("+")[0].split(".")[0])
                    out[key] = out.get(key, 0) + int(w[0]) * size
            break
    return out


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


def slab_caches():
    """{cache: live bytes} of every cache in /proc/slabinfo (active objects
    times the size a caller gets)."""
    caches = {}
    with open("/proc/slabinfo") as f:
        for line in f.readlines()[2:]:
            w = line.split()
            size = (object_size(w[0]) if counted(w[0]) else None) or int(w[3])
            caches[w[0]] = int(w[1]) * size
    return caches


def live_slab():
    """The counted caches' live bytes, now."""
    return sum(v for k, v in slab_caches().items() if counted(k))


def meminfo():
    """(live counted slab bytes but KERNEL_OWN's, unaccounted bytes,
    {cache: live bytes}, SUnreclaim, {(cache, call site): live bytes},
    {meminfo counter: bytes}), caches dropped and the counted slab
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
    caches = slab_caches()
    by_site = sites(caches)
    own = sum(v for (_, fn), v in by_site.items() if fn in KERNEL_OWN)
    live = sum(v for k, v in caches.items() if counted(k)) - own
    pcp = 0
    with open("/proc/zoneinfo") as f:
        for line in f:
            w = line.split()
            if len(w) == 2 and w[0] == "count:":
                pcp += int(w[1])
    vals["pcp"] = pcp * os.sysconf("SC_PAGE_SIZE")
    unaccounted = (vals["MemTotal"] - vals["MemFree"] - vals["pcp"] -
                   sum(vals.get(k, 0) for k in ACCOUNTED))
    return live, unaccounted, caches, vals["SUnreclaim"], by_site, vals


# The meminfo counters of pages the kernel knows the use of: the LRU lists
# (page cache, shmem, anonymous memory), slab, kernel stacks, page tables and
# per-CPU areas.  A page allocated with alloc_pages(), a DMA buffer or a
# vmalloc() area is in none of them.
ACCOUNTED = ("Active", "Inactive", "Unevictable", "SReclaimable", "SUnreclaim",
             "KernelStack", "PageTables", "SecPageTables", "Percpu")


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
    """Snapshots after the warm-up and at each quarter of what is left of
    CYCLES."""

    def __init__(self, cycles):
        self.cycles = cycles
        self.warmup = min(20, cycles // 4)
        self.points = [self.warmup + (cycles - self.warmup) * q // 4 for q in range(5)]
        self.snaps = {}

    def after(self, cycle):
        """Call after cycle number CYCLE (from 0) has ended."""
        n = cycle + 1
        if n in self.points and n not in self.snaps:
            self.snaps[n] = meminfo()

    def check(self, slab_per_cycle, unaccounted_per_cycle, what):
        """Report each quarter and check the bounds (bytes per cycle); a run
        cut short (fewer snapshots) fails."""
        p = self.points
        if not check("leak measure over %d cycles of %s: all five snapshots taken"
                     % (self.cycles, what),
                     p[0] > 0 and all(a < b for a, b in zip(p, p[1:])) and
                     all(k in self.snaps for k in p),
                     "cycles %d, snapshots after %s" % (self.cycles, sorted(self.snaps))):
            return
        snap = [self.snaps[k] for k in p]
        growth = []
        for q in range(4):
            a, b, n = snap[q], snap[q + 1], p[q + 1] - p[q]
            growth.append((b[1] - a[1]) / n)
            info("leak measure, quarter %d (%d cycles): live kmalloc+kernfs objects %+.0f B/cycle, "
                 "unaccounted memory %+.0f B/cycle, SUnreclaim %+.0f B/cycle"
                 % (q + 1, n, (b[0] - a[0]) / n, growth[-1], (b[3] - a[3]) / n))
            moved = sorted(((v - a[5].get(k, 0), k) for k, v in b[5].items()),
                           key=lambda x: -abs(x[0]))
            info("  meminfo counters moved most: " +
                 ", ".join("%s %+d KiB" % (k, d // 1024) for d, k in moved[:8]))
        base, end = snap[0], snap[4]
        grew = sorted(((end[2].get(k, 0) - base[2].get(k, 0), k) for k in end[2]), reverse=True)
        info("live slab objects grown most since the warm-up: " +
             ", ".join("%s %+d B" % (k, d) for d, k in grew[:5]))
        if end[4]:
            moved = sorted(((end[4].get(k, 0) - base[4].get(k, 0), k)
                            for k in set(end[4]) | set(base[4])), reverse=True)
            info("call sites grown most since the warm-up: " +
                 (", ".join("%s %s %+d B" % (k[0], k[1], d) for d, k in moved[:6] if d > 0)
                  or "none"))
            info("the kernel's own, not counted: " +
                 (", ".join("%s %s (%s) %+d B" % (k[0], k[1], KERNEL_OWN[k[1]], d)
                            for d, k in moved if d and k[1] in KERNEL_OWN) or "none"))
        else:
            info("no call sites: the kernel keeps none (slub_debug=U not set)")
        info("userspace processes at the end: " + user_processes())
        slab = (end[0] - snap[2][0]) / (p[4] - p[2])
        check("live kmalloc+kernfs objects (the kernel's own left out) grow less than "
              "%d B per cycle over the second half (%+.0f)"
              % (slab_per_cycle, slab), slab < slab_per_cycle)
        late = (end[1] - snap[1][1]) / (p[4] - p[1])
        check("memory no meminfo counter accounts for grows less than %d B per cycle over "
              "the last three quarters together (%+.0f), or in fewer than three quarters (%s)"
              % (unaccounted_per_cycle, late, ", ".join("%+.0f" % x for x in growth)),
              late < unaccounted_per_cycle or sorted(growth)[1] < unaccounted_per_cycle)
