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

usage: bl_sim.py PRUSIM FIRMWARE_DIR WORK_DIR"""
import os
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "vm/lib"))
import bl_stim

MAGIC, VERSION, SIZE = 0x4c474c42, 1, 56 + 4 * 128
START = 1 | 1 << 16
DDR = 0x80000000
failed = False


def check(name, cond, detail=""):
    global failed
    print(("PASS: " if cond else "FAIL: ") + name + ("" if cond or not detail else ": " + detail),
          flush=True)
    failed |= not cond
    return cond


def ctrl(unit, div, mode, nbufs, bufsize):
    hdr = struct.pack("<IHHII", MAGIC, VERSION, SIZE, START, 0)
    body = struct.pack("<10I", unit, div, mode, nbufs, bufsize, 25, 0, 0, 0, 0)
    bufs = [DDR + i * bufsize for i in range(nbufs)] + [0] * (128 - nbufs)
    return hdr + body + struct.pack("<128I", *bufs)


def run(prusim, fw, work, unit, div, mode, nbufs, bufsize, periods):
    """Run; return (storer ctrl fields, sampler ctrl fields, DDR bytes)."""
    with open(work + "/c0.bin", "wb") as f:
        f.write(ctrl(unit, div, mode, nbufs, bufsize))
    with open(work + "/c1.bin", "wb") as f:
        f.write(ctrl(unit, div, mode, 0, 0))
    samples = periods * bufsize // (1 if unit else 2)
    total = nbufs * bufsize
    cmd = [prusim, "--pru0", fw + "/beaglelogic-pru0.elf", "--pru1", fw + "/beaglelogic-pru1.elf",
           "--r31-1", work + "/stim.txt", "--ddr", "0x%x" % max(total, 0x10000),
           "--load", "pru0:0x8:%s/c0.bin" % work, "--load", "pru1:0x8:%s/c1.bin" % work,
           # the last block is published with the next block's first sample
           "--max-cycles", str((samples + 2) * 2 * div + 5000),
           "--dump", "pru0:0x8:56:%s/d0.bin" % work, "--dump", "pru1:0x8:56:%s/d1.bin" % work,
           "--dump", "0x%x:%d:%s/ddr.bin" % (DDR, total, work)]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode:
        print(r.stderr)
        return None
    out = []
    for n in ("d0.bin", "d1.bin", "ddr.bin"):
        with open(work + "/" + n, "rb") as f:
            out.append(f.read())
    f0 = struct.unpack("<IHHII10I", out[0])
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
    for unit, div, mode, nbufs, bufsize, periods in cases:
        name = "%s-bit, divisor %d, %s" % ("8" if unit else "16", div,
                                           "continuous" if mode else "one-shot")
        res = run(prusim, fw, work, unit, div, mode, nbufs, bufsize, periods)
        if not check("%s: prusim ran" % name, res is not None):
            continue
        f0, f1, ddr = res
        # fields: magic version size command status unit divisor mode nbufs
        # bufsize event state error filled first_iep
        state0, filled, state1, first_iep = f0[11], f0[13], f1[11], f1[14]
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


main(*sys.argv[1:4])
sys.exit(1 if failed else 0)
