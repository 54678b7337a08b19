# SPDX-License-Identifier: GPL-2.0-only
"""prukit servo: servos on the PWM chip of prukit's pru_pwm driver, as the
Robotics Control Library's rc_test_servos drives them (the PRU Cookbook's
first case study), through the kernel's PWM sysfs interface
(/sys/class/pwm/pwmchipN): no root, no /dev/mem.

Channels are numbered 1-8 as the Library's servo channels (the chip's
channels 0-7).  A position is the Library's normalized one: 0 is the
centre, 1500 us; each 1.0 is 600 us, so -1.5 .. 1.5 is 600 .. 2400 us.
The pulses go on after the command ends (the PWM chip keeps them); --off
stops them.
"""
import errno
import glob
import os
import signal
import time

from . import Error, number_arg, read, sysfs

OVERLAY = "PRUKIT-PWM-00A0"
GROUP = "gpio"			# drivers/pru_pwm/udev/60-pru_pwm.rules
CENTRE_US = 1500		# the Library's SERVO_MID_US
US_PER_UNIT = 600		# the Library's normalized range: 1.0 = 600 us
NS_PER_CYCLE = 5		# the chip's step
SWEEP_STEP = 0.02		# units per period of a sweep
UDEV_WAIT = 5.0			# seconds for udev to hand an exported channel over

_channel = number_arg(int, lambda n: 0 <= n <= 8, "%r is not a channel number",
                      "%r: channels are 1 to 8 (0: all)")
_position = number_arg(float, lambda p: -1.5 <= p <= 1.5, "%r is not a position",
                       "%r: positions are -1.5 to 1.5")
_limit = number_arg(float, lambda p: 0 < p <= 1.5, "%r is not a position",
                    "%r: a sweep's limit is above 0 and at most 1.5")
_hz = number_arg(float, lambda f: 1 <= f <= 1000, "%r is not a frequency",
                 "%r: 1 to 1000 Hz")
_width = number_arg(float, lambda w: 0 < w <= 1000000, "%r is not a pulse width",
                    "%r: above 0, at most 1000000 us")
_seconds = number_arg(float, lambda s: 0 < s <= 86400, "%r is not a number of seconds",
                      "%r: above 0, at most 86400")


def chips():
    """The PWM chips of pru_pwm: [(/sys/class/pwm/pwmchipN, npwm)]."""
    out = []
    for path in sorted(glob.glob(sysfs("class", "pwm", "pwmchip*"))):
        drv = os.path.join(path, "device", "driver")
        if os.path.basename(os.path.realpath(drv)) == "pru_pwm":
            out.append((path, int(read(os.path.join(path, "npwm"), "0"))))
    return out


def pick_chip(name):
    have = chips()
    if not have:
        raise Error("no PWM chip of prukit's pru_pwm driver in %s" % sysfs("class", "pwm"),
                    "enable its overlay and reboot: sudo prukit enable pwm --free-pins && "
                    "sudo reboot\n(the module: sudo modprobe pru_pwm; prukit status says more)")
    if name is None:
        return have[0]
    for path, n in have:
        if os.path.basename(path) in (name, "pwmchip" + name):
            return path, n
    raise Error("%s is not a pru_pwm chip" % name,
                "pru_pwm's chips: " + ", ".join(os.path.basename(p) for p, _ in have))


def _write(path, value):
    try:
        with open(path, "w") as f:
            f.write(str(value))
    except OSError as e:
        if e.errno == errno.EACCES:
            raise Error("no permission to write %s" % path,
                        "users in group %s may (sudo usermod -aG %s $USER, then log in "
                        "again), or use sudo" % (GROUP, GROUP))
        raise


def export(chip, hw):
    """/sys/class/pwm/pwmchipN/pwmM, exported if it was not, once udev made
    it ours (its rules give group gpio the files a moment after the export)."""
    ch = os.path.join(chip, "pwm%d" % hw)
    if not os.path.isdir(ch):
        try:
            _write(os.path.join(chip, "export"), hw)
        except OSError as e:
            if e.errno != errno.EBUSY:
                raise Error("cannot export channel %d of %s: %s"
                            % (hw + 1, os.path.basename(chip), os.strerror(e.errno)))
    end = time.monotonic() + UDEV_WAIT
    while not (os.path.isdir(ch) and os.access(os.path.join(ch, "enable"), os.W_OK)):
        if time.monotonic() > end:
            if not os.path.isdir(ch):
                raise Error("%s did not appear after the export" % ch)
            raise Error("no permission to write %s" % os.path.join(ch, "enable"),
                        "udev gives group %s an exported channel's files (is udev running? "
                        "is your user in group %s?), or use sudo" % (GROUP, GROUP))
        time.sleep(0.05)
    return ch


def set_pulses(chip, chans, period_ns, width_ns):
    """Every channel of chans (chip's numbers) at width_ns every period_ns.
    The chip has one period for its enabled channels: channels whose period
    changes are all disabled first."""
    paths = [export(chip, hw) for hw in chans]
    if any(read(os.path.join(p, "period")) != str(period_ns) for p in paths):
        for p in paths:
            _write(os.path.join(p, "enable"), 0)
    for p in paths:
        try:
            if int(read(os.path.join(p, "duty_cycle"), "0")) > period_ns:
                _write(os.path.join(p, "duty_cycle"), 0)
            _write(os.path.join(p, "period"), period_ns)
            _write(os.path.join(p, "duty_cycle"), width_ns)
            _write(os.path.join(p, "enable"), 1)
        except OSError as e:
            if e.errno == errno.EBUSY:
                raise Error("another channel of %s runs with another period"
                            % os.path.basename(chip),
                            "the chip's enabled channels share one period: use the same "
                            "-f, or stop the others (prukit servo --off)")
            raise Error("%s: %s" % (p, os.strerror(e.errno)))


def to_ns(us):
    """Microseconds as the chip's nanoseconds: whole 5 ns steps, rounded down."""
    return int(round(us * 1000)) // NS_PER_CYCLE * NS_PER_CYCLE


def cmd_servo(args):
    chip, npwm = pick_chip(args.chip)
    if args.channel > npwm:
        raise Error("%s has channels 1 to %d" % (os.path.basename(chip), npwm))
    chans = [args.channel - 1] if args.channel else list(range(npwm))
    names = ", ".join(str(c + 1) for c in chans)
    if args.off:
        for hw in chans:
            ch = os.path.join(chip, "pwm%d" % hw)
            if os.path.isdir(ch):
                _write(os.path.join(ch, "enable"), 0)
        print("servo %s of %s: off" % (names, os.path.basename(chip)))
        return 0
    period_ns = to_ns(1e6 / args.frequency)
    if args.width is not None:
        width_us = args.width
    else:
        width_us = CENTRE_US + US_PER_UNIT * (args.position or 0.0)
    if to_ns(width_us) >= period_ns:
        raise Error("a %g us pulse does not fit in a period of %g us (%g Hz)"
                    % (width_us, period_ns / 1000, args.frequency))
    if args.sweep is None:
        set_pulses(chip, chans, period_ns, to_ns(width_us))
        print("servo %s of %s: %g us every %g us (%g Hz)%s" % (
            names, os.path.basename(chip), to_ns(width_us) / 1000, period_ns / 1000,
            args.frequency, "" if args.width is not None else
            ", position %g" % (args.position or 0.0)))
        return 0
    # sweep between -limit and +limit, one step per period, until Ctrl-C or --seconds
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    pos, step = 0.0, SWEEP_STEP
    end = time.monotonic() + args.seconds if args.seconds else None
    print("servo %s of %s: sweeping between %g and %g, Ctrl-C stops" % (
        names, os.path.basename(chip), -args.sweep, args.sweep))
    try:
        while end is None or time.monotonic() < end:
            set_pulses(chip, chans, period_ns, to_ns(CENTRE_US + US_PER_UNIT * pos))
            time.sleep(period_ns / 1e9)
            pos += step
            if abs(pos) > args.sweep:
                step = -step
                pos = max(-args.sweep, min(args.sweep, pos))
    except KeyboardInterrupt:
        pass
    set_pulses(chip, chans, period_ns, to_ns(CENTRE_US))
    print("servo %s: back to the centre (%d us)" % (names, CENTRE_US))
    return 0


def register(sub):
    p = sub.add_parser(
        "servo", help="drive servos on the PRU's PWM channels, as rc_test_servos",
        description="Send servo pulses on the PWM chip of prukit's pru_pwm driver, with "
        "the Robotics Control Library's rc_test_servos options: channels 1-8, positions "
        "-1.5 to 1.5 (0: centre, 1500 us; 1.0 = 600 us, so 600 to 2400 us), 50 Hz.  The "
        "pulses go on after the command ends; --off stops them.",
        epilog="The chip comes from the overlay %s (PRUKIT-PWM-POCKET-00A0 on a "
        "PocketBeagle: channels 1-4) and the module pru_pwm; users in group %s may use "
        "it.  Example: prukit servo -c 1 -p 0.5 (channel 1, 1800 us).  "
        "Documentation/pru_pwm.rst." % (OVERLAY, GROUP))
    p.add_argument("-c", "--channel", type=_channel, default=0, metavar="CH",
                   help="the channel, 1-8 (default: all channels, driven equally)")
    p.add_argument("-f", "--frequency", type=_hz, default=50.0, metavar="HZ",
                   help="pulses per second (default 50)")
    what = p.add_mutually_exclusive_group()
    what.add_argument("-p", "--position", type=_position, metavar="POS",
                      help="position, -1.5 to 1.5 (default 0, the centre)")
    what.add_argument("-w", "--width", type=_width, metavar="US",
                      help="pulse width in microseconds instead of a position")
    what.add_argument("-s", "--sweep", type=_limit, metavar="LIMIT",
                      help="sweep back and forth between -LIMIT and LIMIT (up to 1.5) "
                      "until Ctrl-C (or --seconds), then centre")
    what.add_argument("--off", action="store_true", help="stop the pulses")
    p.add_argument("--seconds", type=_seconds, metavar="S",
                   help="with --sweep: stop after S seconds")
    p.add_argument("--chip", metavar="CHIP",
                   help="pwmchipN or N (default: the first pru_pwm chip)")
    p.set_defaults(func=cmd_servo)
