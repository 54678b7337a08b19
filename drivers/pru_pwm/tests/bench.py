#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""pru_pwm's PWM figures for make bench (tests/bench.sh), from the
firmware's gaps (pru_pwm_proto.h) and checked on the firmware in prusim:
a single channel at the duty range's ends (PRU_PWM_MIN_GAP and period -
PRU_PWM_END_GAP) at the highest frequency with 8 bits of duty, and eight
channels at 100 kHz, every edge in its cycle and none late.  Prints BENCH:
lines, FAIL: lines for what did not hold.

usage: bench.py PRUSIM FW_DIR PWM_TABLE WORK_DIR"""
import math
import sys

import pwm_sim as P


def main():
    prusim, fw, tool, work = sys.argv[1:5]
    gap, end = P.MIN_GAP, P.END_GAP
    ok = True

    def steps(period):
        """Duties settable exactly, in 5 ns steps: 0, MIN_GAP..period-END_GAP, period."""
        return period - end - gap + 1 + 2

    def f_for(bits):
        p = (2 ** bits) - 2 + end + gap - 1
        return p, 200e6 / p

    for bits in (8, 10):
        period, _ = f_for(bits)
        for duty in (gap, period - end):
            t = P.build(tool, work, [(8, period, duty, 1, 0)], "b")
            s = P.Sim(prusim, fw, work, "b", t[0], t[0], 20 * period)
            good = P.matches(s, [(t[1], t[3])], [None]) == [None] and s.late == 0 and \
                t[2] == [duty]
            ok = ok and good
            if not good:
                print("FAIL: prusim: one channel, period %d, duty %d: not exact" % (period, duty))
    a = [(b, 2000, 100 + 237 * k, 1, 0) for k, b in enumerate(P.BITS)]
    t = P.build(tool, work, a, "k")
    s = P.Sim(prusim, fw, work, "k", t[0], t[0], 40000)
    if not (P.matches(s, [(t[1], t[3])], [None]) == [None] and s.late == 0):
        print("FAIL: prusim: eight channels at 100 kHz: not exact")
        ok = False
    p8, f8 = f_for(8)
    p10, f10 = f_for(10)
    print("BENCH: pru_pwm: %d channels on one PRU, period and duty in steps of 5 ns "
          "(1 PRU cycle), one period shared by the enabled channels; periods %d cycles "
          "(%.2f us, %.0f kHz) to 2^31-1 (10.7 s)" % (
              len(P.BITS), P.MIN_PERIOD, P.MIN_PERIOD / 200, 200000 / P.MIN_PERIOD))
    print("BENCH: pru_pwm duty range settable exactly: 0, %d cycles (%d ns) .. period - %d "
          "(%d ns), 100%%: 8 bits up to %.0f kHz (period %d), 10 bits up to %.0f kHz "
          "(period %d); at 100 kHz %d steps (%.1f bits); servos at 50 Hz: every 5 ns from "
          "115 ns to 19999.6 us%s" % (
              gap, 5 * gap, end, 5 * end, f8 / 1000, p8, f10 / 1000, p10, steps(2000),
              math.log2(steps(2000)), "" if ok else " (prusim check FAILED)"))
    print("BENCH: pru_pwm edges: within a period %d cycles apart at least (%d ns), ends of "
          "pulses in the same cycle written at once; the firmware in prusim at these limits "
          "and 8 channels at 100 kHz: every edge in its cycle, none late: %s" % (
              gap, 5 * gap, "yes" if ok else "NO"))
    print("BENCH: beside it, the Robotics Control Library on the PRU (PRU Cookbook): 8 servo "
          "channels, positions -1.5..1.5 = 600..2400 us at 50 Hz by default, as root through "
          "/dev/mem; prukit servo takes the same options through the kernel's PWM chip")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
