#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""The beaglelogic firmware in the prusim host tool, without a driver: the
control blocks are loaded with a START already posted (the storer's, PRU0,
and the sampler's, PRU1), R31 of PRU1 is the tests' stimulus (bl_stim.py),
and after the run the buffers in DDR and both control blocks are read back.

For 8- and 16-bit units at divisors 1 to 7, 50 and 10000, and a continuous
capture that wraps: the storer ends DONE with every buffer filled, the
sampler IDLE; sample k equals the stimulus at cycle t0 + 2 * divisor * k
for every k (t0 found from the first 64 samples: prusim's stimulus starts
at cycle 0, not at an IEP count the test could read); and t0 minus the
sampler's first_iep is the same in every run (the first sample is where
first_iep says, whatever the path; the VM test checks it absolutely).

usage: bl_sim.py [--bench] PRUSIM FIRMWARE_DIR WORK_DIR (--bench: the cycles
between two samples at each rate, measured; see bench())"""
import os
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "vm/lib"))
import bl_stim

MAGIC, VERSION, SIZE = 0x4c474c42, 3, 56 + 4 * 128 + 28
TRIG_BLOCK = 56 + 4 * 128 + 20
START = 1 | 1 << 16
ANSWER = 1 << 16 | 0x8000		# PRUKIT_CTRL_STATUS(1, BL_OK)
DDR = 0x80000000
failed = False


def check(name, cond, detail=""):
    global failed
    print(("PASS: " if cond else "FAIL: ") + name + ("" if cond or not detail else ": " + detail),
          flush=True)
    failed |= not cond
    return cond


def ctrl(unit, div, mode, nbufs, bufsize, trig=(0, 0, 0, 0, 0)):
    hdr = struct.pack("<IHHII", MAGIC, VERSION, SIZE, START, 0)
    body = struct.pack("<10I", unit, div, mode, nbufs, bufsize, 25, 0, 0, 0, 0)
    bufs = [DDR + i * bufsize for i in range(nbufs)] + [0] * (128 - nbufs)
    return hdr + body + struct.pack("<128I", *bufs) + struct.pack("<6I", *trig, 0)


def run(prusim, fw, work, unit, div, mode, nbufs, bufsize, periods, trig=(0, 0, 0, 0, 0),
        cycles=0, swap=False):
    """Run; return (storer ctrl fields, sampler ctrl fields, DDR bytes),
    the storer's with its trig_block last.  SWAP: the roles of
    PRUKIT-BEAGLELOGIC-POCKET-00A0, PRU0 samples its R31 and PRU1 stores,
    with the same two images."""
    with open(work + "/c0.bin", "wb") as f:
        f.write(ctrl(unit, div, mode, nbufs, bufsize, trig))
    with open(work + "/c1.bin", "wb") as f:
        f.write(ctrl(unit, div, mode, 0, 0))
    samples = periods * bufsize // (1 if unit else 2)
    total = nbufs * bufsize
    st, sa = ("pru1", "pru0") if swap else ("pru0", "pru1")
    cmd = [prusim, "--" + st, fw + "/beaglelogic-pru0.elf", "--" + sa, fw + "/beaglelogic-pru1.elf",
           "--r31-" + sa[-1], work + "/stim.txt", "--ddr", "0x%x" % max(total, 0x10000),
           "--load", "%s:0x8:%s/c0.bin" % (st, work), "--load", "%s:0x8:%s/c1.bin" % (sa, work),
           # the last block is published with the next block's first sample
           "--max-cycles", str(cycles or (samples + 2) * 2 * div + 5000),
           "--dump", "%s:0x8:%d:%s/d0.bin" % (st, SIZE, work),
           "--dump", "%s:0x8:56:%s/d1.bin" % (sa, work),
           "--dump", "0x%x:%d:%s/ddr.bin" % (DDR, total, work),
           # stores to DDR land as late as in the VM (scripts/vm.sh)
           "-C", "ocp_write_delay=" + os.environ.get("BL_OCP_WRITE_DELAY", "100")]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode:
        print(r.stderr)
        return None
    out = []
    for n in ("d0.bin", "d1.bin", "ddr.bin"):
        with open(work + "/" + n, "rb") as f:
            out.append(f.read())
    f0 = (struct.unpack("<IHHII10I", out[0][:56]) +
          struct.unpack("<I", out[0][TRIG_BLOCK:TRIG_BLOCK + 4]))
    f1 = struct.unpack("<IHHII10I", out[1])
    return f0, f1, out[2]


def main(prusim, fw, work):
    vals = bl_stim.values()
    with open(work + "/stim.txt", "w") as f:
        f.write(bl_stim.text(vals))
    offsets = set()
    # every delay: none (1), 2 or 4 cycles (2, 3), and 3 * rounds plus
    # each of the three paddings (4, 5, 6, 7, 50; 10000: 10 kHz)
    cases = [(1, 1, 0, 2, 4096, 2), (0, 1, 0, 2, 4096, 2), (1, 2, 0, 2, 2048, 2),
             (0, 2, 0, 2, 2048, 2), (1, 3, 0, 2, 1024, 2), (0, 3, 0, 2, 1024, 2),
             (1, 4, 0, 2, 1024, 2), (0, 5, 0, 2, 1024, 2), (1, 6, 0, 2, 512, 2),
             (0, 7, 0, 2, 1024, 2), (1, 50, 0, 2, 256, 2), (1, 10000, 0, 1, 64, 1),
             (0, 1, 1, 2, 2048, 3)]
    # and PocketBeagle's roles: the sampler on PRU0, the storer on PRU1
    cases += [(1, 1, 0, 2, 4096, 2, True), (1, 5, 0, 2, 1024, 2, True)]
    for unit, div, mode, nbufs, bufsize, periods, *swap in cases:
        name = "%s-bit, divisor %d, %s%s" % ("8" if unit else "16", div,
                                             "continuous" if mode else "one-shot",
                                             ", PRU0 samples, PRU1 stores" if swap else "")
        res = run(prusim, fw, work, unit, div, mode, nbufs, bufsize, periods, swap=bool(swap))
        if not check("%s: prusim ran" % name, res is not None):
            continue
        f0, f1, ddr = res
        # fields: magic version size command status unit divisor mode nbufs
        # bufsize event state error filled first_iep
        state0, filled, state1, first_iep = f0[11], f0[13], f1[11], f1[14]
        check("%s: both cores answered START with BL_OK" % name,
              f0[4] == f1[4] == ANSWER, "%#x %#x" % (f0[4], f1[4]))
        if mode:
            check("%s: the storer wrapped (filled %d >= 3), the sampler runs" % (name, filled),
                  state0 == 1 and filled >= 3 and state1 == 1, "states %d %d" % (state0, state1))
        else:
            check("%s: storer DONE, %d buffers filled, sampler IDLE" % (name, nbufs),
                  state0 == 2 and filled == nbufs and state1 == 0,
                  "state %d filled %d sampler %d" % (state0, filled, state1))
        mask = 0xff if unit else 0xffff
        got = list(ddr) if unit else [ddr[i] | ddr[i + 1] << 8 for i in range(0, len(ddr), 2)]
        per_buf = bufsize // (1 if unit else 2)
        # in the continuous run buffer 0 holds the last of the buffers
        # filled whose number is a multiple of nbufs
        first = (filled - 1) // nbufs * nbufs * per_buf if mode else 0
        if mode:
            got = got[:per_buf]
        step = 2 * div
        t0s = [t for t in range(0, 4000)
               if all(vals[(t + step * (first + k)) % len(vals)] & mask == got[k]
                      for k in range(min(64, len(got))))]
        if not check("%s: the samples are the stimulus every %d cycles" % (name, step),
                     len(t0s) == 1, "candidates %s" % t0s[:3]):
            continue
        want = bl_stim.expected(vals, t0s[0] + step * first, step, len(got), mask)
        bad = [k for k in range(len(got)) if got[k] != want[k]]
        check("%s: all %d samples, across buffers, with no gap or duplicate" % (name, len(got)),
              not bad, "%d differ from sample %s" % (len(bad), bad[:1]))
        if not mode:
            offsets.add(t0s[0] - first_iep)
    check("the first sample is first_iep's cycle on every path (one offset: %s)" % sorted(offsets),
          len(offsets) == 1)
    triggers(prusim, fw, work)


def lanes(x, unit):
    """X in each sample of a 32-bit word (unit 1: 8-bit samples)."""
    return x * 0x01010101 if unit else x | x << 16


def refine(got, kind, block, spb, chan, mask, value):
    """The trigger's sample in block BLOCK (from 1) of the samples GOT, as
    the driver finds it: the first edge, or the start of the matching run."""
    bit = [(g >> chan) & 1 for g in got] if chan is not None else None
    for k in range((block - 1) * spb, block * spb):
        if k == 0:
            continue
        if kind == "rising" and bit[k - 1] == 0 and bit[k] == 1 or \
           kind == "falling" and bit[k - 1] == 1 and bit[k] == 0 or \
           kind == "edge" and bit[k - 1] != bit[k]:
            return k
        if kind == "pattern" and got[k] & mask == value & mask:
            while k > 0 and got[k - 1] & mask == value & mask:
                k -= 1
            return k
    return None


def triggers(prusim, fw, work):
    """The storer's triggers: the ring runs until a block holds the trigger
    (the stimulus of bl_stim.trigger_values(): channels 6, 7, 12, 13 rise
    at TRIG_AT and fall TRIG_LEN cycles later, in every period), keeps
    @trig_post more blocks and ends DONE.  trig_block must be the block of
    the event's sample (pattern16_half: of the first sample it looks at in
    the run), the driver's search (refine()) must find the event's sample
    exactly, and the ring, read from block trig_block - pre, must be the
    stimulus sample for sample."""
    vals = bl_stim.trigger_values()
    with open(work + "/stim.txt", "w") as f:
        f.write(bl_stim.text(vals))
    at, length = bl_stim.TRIG_AT, bl_stim.TRIG_LEN
    cases = [  # kind, unit, div, channel, mask, value, event cycle
        ("rising", 0, 1, 13, 0, 0, at), ("falling", 0, 1, 12, 0, 0, at + length),
        ("edge", 1, 1, 7, 0, 0, at), ("falling", 1, 3, 6, 0, 0, at + length),
        ("pattern", 0, 1, None, 0x3000, 0x3000, at), ("pattern", 0, 2, None, 0x3001, 0x3000, at),
        ("pattern", 1, 1, None, 0xc0, 0xc0, at), ("rising", 0, 7, 13, 0, 0, at)]
    nbufs, bufsize, pre_samples = 2, 4096, 1000
    errors = []
    for kind, unit, div, chan, mask, value, event in cases:
        spb = 32 if unit else 16
        ring_blocks = nbufs * bufsize // 32
        pre = -(-pre_samples // spb)
        post = ring_blocks - pre - 1
        if kind == "pattern":
            mode = 4 if unit else 6 if div == 1 else 5
            tl, tb = lanes(mask, unit), lanes(value & mask, unit)
        else:
            mode = {"rising": 1, "falling": 2, "edge": 3}[kind]
            tl, tb = lanes(1 << chan, unit), chan + (24 if unit else 16)
        name = "trigger %s%s, %s-bit, divisor %d" % (
            kind, " on channel %d" % chan if chan is not None else
            " %#x/%#x" % (value, mask) + (" (every sample)" if mode != 6 else
                                         " (samples 0, 1, 4, 5, ... of a block)"),
            "8" if unit else "16", div)
        cycles = event + 2 * div * spb * (post + 4) + 5000
        res = run(prusim, fw, work, unit, div, 1, nbufs, bufsize, 0, (mode, tl, tb, pre, post),
                  cycles)
        if not check("%s: prusim ran" % name, res is not None):
            continue
        f0, f1, ddr = res
        state0, tblock = f0[11], f0[15]
        check("%s: both cores answered START with BL_OK" % name,
              f0[4] == f1[4] == ANSWER, "%#x %#x" % (f0[4], f1[4]))
        if not check("%s: the storer fired (block %d) and ended DONE %d blocks later" %
                     (name, tblock, post), state0 == 2 and tblock > pre,
                     "state %d, trig_block %d" % (state0, tblock)):
            continue
        # the ring from block tblock - pre on: the driver's read() order
        rot = (tblock - pre - 1) * 32 % len(ddr)
        stream = ddr[rot:] + ddr[:rot]
        got = list(stream) if unit else [stream[i] | stream[i + 1] << 8
                                         for i in range(0, len(stream), 2)]
        first = (tblock - pre - 1) * spb		# its first sample's number
        step = 2 * div
        t0s = [t for t in range(0, 4000)
               if all(vals[(t + step * (first + k)) % len(vals)] & (0xff if unit else 0xffff)
                      == got[k] for k in range(64))]
        if not check("%s: the ring from block trig_block - %d is the stimulus" % (name, pre),
                     len(t0s) == 1 and all(
                         vals[(t0s[0] + step * (first + k)) % len(vals)] &
                         (0xff if unit else 0xffff) == got[k] for k in range(len(got))),
                     "t0 candidates %s" % t0s[:3]):
            continue
        # the event's sample: the first taken at or after the event's cycle
        # (a pattern: the first there that matches: bit 0 is the LFSR's)
        e = next(k for k in range(len(got)) if t0s[0] + step * (first + k) >= event and
                 (kind != "pattern" or got[k] & mask == value & mask))
        want_block = (first + e) // spb + 1
        if mode == 6:
            k = next(k for k in range(e, len(got)) if (first + k) % 16 % 4 < 2)
            want_block = (first + k) // spb + 1
        found = refine(got, kind, want_block - (tblock - pre) + 1, spb, chan, mask, value) \
            if tblock == want_block else None
        check("%s: the block holds the event (sample %d of the ring, block %d); the driver's "
              "search finds that sample" % (name, e, want_block),
              tblock == want_block and found == e,
              "trig_block %d, found %s" % (tblock, found))
        errors.append(None if found is None else found - e)
    return errors


def bench(prusim, fw, work):
    """make bench: PRU cycles per sample at each rate, measured, not assumed:
    R31 is a cycle counter (its value in cycle t is t mod 65536), so each
    16-bit sample says when it was taken, and the difference of two in a
    row is the cycles between them."""
    with open(work + "/stim.txt", "w") as f:
        f.write("".join("%d %d\n" % (t, t) for t in range(65536)) + "repeat 65536\n")
    figures, counts = [], []
    for div, bufsize in ((1, 4096), (2, 4096), (3, 4096), (4, 2048), (10, 2048), (100, 1024),
                         (1000, 256), (10000, 64)):
        res = run(prusim, fw, work, 0, div, 0, 2, bufsize, 2)
        if not check("divisor %d: prusim ran" % div, res is not None):
            continue
        ddr = res[2]
        got = [ddr[i] | ddr[i + 1] << 8 for i in range(0, len(ddr), 2)]
        gaps = {(b - a) % 65536 for a, b in zip(got, got[1:])}
        counts.append(len(got))
        check("divisor %d: %d samples, every one %d cycles after the one before" %
              (div, len(got), 2 * div), gaps == {2 * div}, str(sorted(gaps)[:4]))
        rate = 100e6 / div
        figures.append("%s: %s" % ("%g MHz" % (rate / 1e6) if rate >= 1e6 else
                                   "%g kHz" % (rate / 1e3),
                                   "/".join(str(g) for g in sorted(gaps))))
    print("BENCH: beaglelogic: PRU cycles between two samples, every pair of %d to %d 16-bit "
          "samples measured in prusim: %s" % (max(counts, default=0), min(counts, default=0),
                                              "; ".join(figures)))
    errors = triggers(prusim, fw, work)
    print("BENCH: beaglelogic: trigger position error (the sample found - the stimulus "
          "event's), edges and patterns at 100, 50, 33 and 14 Msps in prusim: %s samples"
          % ", ".join("missed" if e is None else "%d" % e for e in errors))


if sys.argv[1] == "--bench":
    bench(*sys.argv[2:5])
else:
    main(*sys.argv[1:4])
sys.exit(1 if failed else 0)
