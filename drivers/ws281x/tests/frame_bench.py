#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""PRU cycles of one 48-string x 600-LED frame, from the real firmware.

Each core drives 24 of the 48 strings, all at once: first each core alone,
then both at once in step, as the driver runs them (both drive GPIO pins).  Runs ws281x-pruN.elf in prusim with a control block and a
24-string x 600-RGB-LED frame (14400 bit slots) preloaded in DDR, default
reset (WS281X_RESET_DEFAULT), and measures, exactly: the cycle slot 0
starts (the first R30 rise), the cycle the frame-done event is strobed (a
bisection on --max-cycles, as ws281x_sim.py does), every edge against the
schedule (worst error per pin kind), and the bits sent.  Prints BENCH:
lines, and FAIL: lines if an edge or a bit is wrong.

usage: frame_bench.py PRUSIM FW_DIR WORK_DIR [CORE...]   (default: 0)"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ws281x_sim as sim  # noqa: E402

LEDS = 600
PRU_HZ = 200e6


def strings_for(core):
    """8 R30 strings and 16 GPIO strings (4 per bank), 600 RGB LEDs each."""
    rng = random.Random(600 + core)
    r30 = [0, 1, 2, 3, 4, 5, 14, 15] if core == 0 else [0, 1, 2, 3, 4, 5, 6, 7]
    gpio = [(b, bit) for b in range(4) for bit in ((2, 9, 17, 30), (3, 10, 19, 28))[core]]
    return [(kind, bit, sim.random_bytes(rng, 3 * LEDS))
            for kind, bit in [("r30", bit) for bit in r30] + gpio]


def main():
    sim.PRUSIM, fwdir, work = sys.argv[1:4]
    cores = [int(c) for c in sys.argv[4:]] or [0]
    fw = os.path.join(fwdir, "ws281x-pru%d.elf")
    reset = sim.D["WS281X_RESET_DEFAULT"]
    ok = True
    for core in cores:
        frame = sim.Frame(core, strings_for(core))
        slots = frame.slots
        budget = slots * sim.SLOT + reset + 100000
        params = {"reset": reset}
        run = sim.Run(work, fw, frame, budget, params, "bench%d" % core)
        start, worst, _ = sim.check_frame("pru%d 24x%d" % (core, LEDS), run, frame)
        if sim.failed:
            ok = False
        # the strobe: not yet at the end of the reset, then bisected
        lo = start + slots * sim.SLOT + reset
        hi = lo + 256
        if sim.Run(work, fw, frame, lo, params, "early%d" % core).event_raised(17) or \
                not sim.Run(work, fw, frame, hi, params, "late%d" % core).event_raised(17):
            print("FAIL: pru%d: the event is not strobed within 256 cycles after the reset"
                  % core)
            return 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if sim.Run(work, fw, frame, mid, params, "bisect%d" % core).event_raised(17):
                hi = mid
            else:
                lo = mid
        cycles = lo - start       # strobed in the run of lo + 1 cycles
        ideal = slots * sim.SLOT + reset
        r30 = worst.get("r30", "-")
        gpio = max(v for k, v in worst.items() if k != "r30")
        print("BENCH: ws281x frame, pru%d alone: %d PRU cycles for its 24x%d (8 R30 + 16 "
              "GPIO strings, %d slots, reset %d) = %.2f fps; worst edge error R30 %s, GPIO %s "
              "cycles" % (core, cycles, LEDS, slots, reset, PRU_HZ / cycles, r30, gpio))
        print("BENCH: ws281x frame: pru%d: %d cycles over %d slots x %d + reset %d (%.3f%% of "
              "the 1250 ns slots' %.2f fps); slot 0 started %d cycles after the core did "
              "(boot, SHOW taken, the first frame's low hold, setup, slot 0 read)"
              % (core, cycles - ideal, slots, sim.SLOT, reset, 100.0 * ideal / cycles,
                 PRU_HZ / ideal, start))
    if cores == [0, 1]:
        ok = pair(fw, work, reset) and ok
    return 0 if ok else 1


def pair(fw, work, reset):
    """The 48-string map as the driver runs it: both cores at once, in
    step (both drive GPIO pins): every edge of both checked, and the cycles
    from PRU0's slot 0 to PRU1's event (the frame's end), bisected."""
    frames = [sim.Frame(core, strings_for(core)) for core in (0, 1)]
    slots = frames[0].slots
    params = [{"reset": reset, "sync": sim.D["WS281X_SYNC_LEADER"]},
              {"reset": reset, "sync": sim.D["WS281X_SYNC_FOLLOWER"]}]
    budget = slots * sim.SLOT + reset + 100000
    run = sim.PairRun(work, fw, frames, budget, params, "pair")
    starts, worst = [], {}
    for frame in frames:
        start, w, _ = sim.check_frame("in step, pru%d 24x%d" % (frame.core, LEDS), run, frame)
        starts.append(start)
        for k, v in w.items():
            worst[k == "r30"] = max(worst.get(k == "r30", 0), v)
    if sim.failed or None in starts:
        return False
    lo = starts[1] + slots * sim.SLOT + reset
    hi = lo + 256
    if sim.PairRun(work, fw, frames, lo, params, "pair-early").event_raised(18) or \
            not sim.PairRun(work, fw, frames, hi, params, "pair-late").event_raised(18):
        print("FAIL: in step: PRU1's event is not strobed within 256 cycles after its reset")
        return False
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if sim.PairRun(work, fw, frames, mid, params, "pair-bisect").event_raised(18):
            hi = mid
        else:
            lo = mid
    cycles = lo - starts[0]
    ideal = slots * sim.SLOT + reset
    print("BENCH: ws281x frame, 48 strings in step: %d PRU cycles for 48x%d (both cores at "
          "once, 8 R30 + 16 GPIO strings each, PRU1 %d cycles after PRU0) = %.2f fps, %.3f%% of "
          "the 1250 ns slots' %.2f fps; worst edge error R30 %d, GPIO %d cycles; PRU0's slot 0 "
          "%d cycles after both SHOWs were there (boot, first frame's low hold, handshake, lead %d)"
          % (cycles, LEDS, starts[1] - starts[0], PRU_HZ / cycles, 100.0 * ideal / cycles,
             PRU_HZ / ideal, worst.get(True, 0), worst.get(False, 0), starts[0],
             sim.D["WS281X_SYNC_LEAD"]))
    return True


if __name__ == "__main__":
    sys.exit(main())
