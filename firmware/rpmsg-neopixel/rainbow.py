#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""A rainbow running along the rpmsg NeoPixel firmware's 24 LEDs.

Start the firmware on PRU0 (as root, or in group remoteproc):

    echo prukit/rpmsg-neopixel-pru0.elf > /sys/class/remoteproc/remoteproc1/firmware
    echo start > /sys/class/remoteproc/remoteproc1/state
    ./rainbow.py

It speaks the PRU Cookbook's protocol: a line "index red green blue" sets
one pixel, "-1" sends the whole string to the LEDs.  A frame is the 24
pixel lines and "-1" in one write() (split at line ends if it would not fit
in one 496-byte message).  With --frames N it stops after N frames and
leaves the last one lit; Ctrl-C turns the LEDs off before it exits.
--print writes each frame's colours to stdout as "#rrggbb" words, one line
per frame (what prukit's tests compare with the decoded pin).
"""
import argparse
import errno
import os
import sys
import time

COUNT = 24		# LEDs on the string (firmware/rpmsg-neopixel/neopixel.h)
MAX_MSG = 496		# bytes in one rpmsg message


def wheel(pos):
    """A colour wheel: 0..255 goes red -> green -> blue -> red."""
    pos &= 255
    if pos < 85:
        return (255 - pos * 3, pos * 3, 0)
    if pos < 170:
        pos -= 85
        return (0, 255 - pos * 3, pos * 3)
    pos -= 170
    return (pos * 3, 0, 255 - pos * 3)


def frame(n, step=8, brightness=255, count=COUNT):
    """The colours (r, g, b) of the count LEDs in frame n."""
    return [tuple(c * brightness // 255 for c in wheel(i * 256 // count + n * step))
            for i in range(count)]


def messages(pixels):
    """The writes that show pixels: its lines and "-1", at most MAX_MSG each."""
    lines = ["%d %d %d %d\n" % (i, r, g, b) for i, (r, g, b) in enumerate(pixels)]
    lines.append("-1\n")
    msgs, cur = [], ""
    for line in lines:
        if len(cur) + len(line) > MAX_MSG:
            msgs.append(cur.encode())
            cur = ""
        cur += line
    msgs.append(cur.encode())
    return msgs


def show(fd, pixels):
    for m in messages(pixels):
        os.write(fd, m)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-d", "--device", default="/dev/rpmsg_pru30",
                    help="the firmware's rpmsg device (default %(default)s)")
    ap.add_argument("-n", "--frames", type=int, default=0,
                    help="frames to send, 0 for ever (default)")
    ap.add_argument("-s", "--step", type=int, default=8,
                    help="how far the wheel turns per frame, 0..255 (default %(default)s)")
    ap.add_argument("-b", "--brightness", type=int, default=64,
                    help="0..255 (default %(default)s: full white draws 60 mA per LED)")
    ap.add_argument("-t", "--delay", type=float, default=0.04,
                    help="seconds between frames (default %(default)s)")
    ap.add_argument("-p", "--print", action="store_true",
                    help="print each frame's colours to stdout")
    args = ap.parse_args()
    if args.frames < 0 or not 0 <= args.brightness <= 255 or args.delay < 0:
        ap.error("--frames and --delay must not be negative, --brightness is 0..255")

    try:
        fd = os.open(args.device, os.O_WRONLY)
    except OSError as e:
        hint = ""
        if e.errno == errno.ENOENT:
            hint = " (is prukit/rpmsg-neopixel-pru0.elf running on PRU0?)"
        elif e.errno == errno.EACCES:
            hint = " (run as root or join group remoteproc)"
        sys.exit("%s: %s: %s%s" % (ap.prog, args.device, e.strerror, hint))

    n = 0
    try:
        while args.frames == 0 or n < args.frames:
            pixels = frame(n, args.step, args.brightness)
            show(fd, pixels)
            if args.print:
                print(" ".join("#%02x%02x%02x" % p for p in pixels), flush=True)
            n += 1
            if args.delay:
                time.sleep(args.delay)
    except KeyboardInterrupt:
        show(fd, [(0, 0, 0)] * COUNT)
    except OSError as e:
        # EPIPE: the PRU was stopped under us
        sys.exit("%s: %s: %s" % (ap.prog, args.device, e.strerror))
    finally:
        os.close(fd)


if __name__ == "__main__":
    main()
