# SPDX-License-Identifier: GPL-2.0-only
"""The beaglelogic tests' R31 stimulus, for the guest (which writes it to
the test port's input/r31-1) and the host (which computes every sample expected).

A new 16-bit value in every PRU cycle: the states of a maximal 16-bit
Galois LFSR (taps 0xb400), PERIOD cycles long and repeated.  PERIOD is a
prime, so samples taken every 2 * divisor cycles visit every phase, and the
values never repeat within a period: a sample taken one cycle early or late,
or a sample lost or doubled, differs from what is expected."""

PERIOD = 65521
SEED = 0xace1


def values(period=PERIOD, seed=SEED):
    """The stimulus' value in each cycle of one period."""
    out = []
    s = seed
    for _ in range(period):
        out.append(s)
        s = (s >> 1) ^ (0xb400 if s & 1 else 0)
    return out


def text(vals):
    """The stimulus in the simulator's input format."""
    lines = ["%d %d" % (i, v) for i, v in enumerate(vals)]
    lines.append("repeat %d" % len(vals))
    return "\n".join(lines) + "\n"


def expected(vals, t0, step, count, mask):
    """The COUNT samples taken STEP cycles apart from stimulus cycle T0."""
    n = len(vals)
    return [vals[(t0 + k * step) % n] & mask for k in range(count)]


# --- a serial stimulus: a UART line and an SPI bus ------------------------------------
# Channels (BeagleLogic's names, libsigrok's too): bit 0 P8_45 UART TX (8N1,
# idle high), bit 1 P8_46 SPI SCLK, bit 2 P8_43 SPI MOSI, bit 3 P8_44 SPI
# CS# (active low), bit 4 P8_41 SPI MISO; mode 0 (data changes on the
# falling edge, sampled on the rising), MSB first.  Every SERIAL_PERIOD
# cycles (400 us): 50 us idle, the UART message, and two SPI transfers,
# 10 us apart.  (Short: a simulated millisecond takes about a second in
# the VM.)
CYCLES_PER_S = 200000000
UART_BIT, SCLK_BIT, MOSI_BIT, CS_BIT, MISO_BIT = 0, 1, 2, 3, 4
UART_BAUD = 1000000
UART_MSG = b"prukit: hello from PRU1\r\n"
SPI_HZ = 2000000
SPI_XFERS = ((b"\x9f\x00\x00\x00", b"\xff\xc2\x20\x18"),
             (b"BeagleLg", b"\x00\x01\x7f\x80\xfe\xa5\x5aZ"))
SERIAL_PERIOD = 80000


def serial_events():
    """(frames, changes): frames is a list of (protocol, first cycle, last
    cycle, byte[s]) sent in one period; changes the (cycle, value) of each
    change of the lines, sorted, the first at cycle 0."""
    lines = {}			# cycle -> {bit: level}

    def put(cycle, bit, level):
        lines.setdefault(int(cycle), {})[bit] = level

    put(0, UART_BIT, 1)
    put(0, CS_BIT, 1)
    put(0, SCLK_BIT, 0)
    frames = []
    bit_t = CYCLES_PER_S / UART_BAUD
    t = 10000			# 50 us idle
    for byte in UART_MSG:
        bits = [0] + [(byte >> i) & 1 for i in range(8)] + [1]
        start = t
        for k, b in enumerate(bits):
            put(round(t + k * bit_t), UART_BIT, b)
        t += 10 * bit_t
        frames.append(("uart", round(start), round(t) - 1, byte))
    half = CYCLES_PER_S // SPI_HZ // 2
    t = round(t) + 2000
    for mosi, miso in SPI_XFERS:
        put(t, CS_BIT, 0)
        begin = t
        t += half
        for a, b in zip(mosi, miso):
            for i in range(7, -1, -1):
                put(t, MOSI_BIT, (a >> i) & 1)
                put(t, MISO_BIT, (b >> i) & 1)
                put(t + half, SCLK_BIT, 1)
                put(t + 2 * half, SCLK_BIT, 0)
                t += 2 * half
        t += half
        put(t, CS_BIT, 1)
        frames.append(("spi", begin, t, (mosi, miso)))
        t += 2000
    assert t < SERIAL_PERIOD
    changes, value = [], 0
    for cycle in sorted(lines):
        for bit, level in lines[cycle].items():
            value = (value & ~(1 << bit)) | (level << bit)
        changes.append((cycle, value))
    return frames, changes


def serial_text():
    """The serial stimulus in the simulator's input format."""
    _, changes = serial_events()
    return "".join("%d %d\n" % c for c in changes) + "repeat %d\n" % SERIAL_PERIOD


def serial_expected(t0, step, count):
    """The COUNT samples taken STEP cycles apart from stimulus cycle T0."""
    import bisect
    _, changes = serial_events()
    cycles = [c for c, _ in changes]
    out = []
    for k in range(count):
        c = (t0 + k * step) % SERIAL_PERIOD
        out.append(changes[bisect.bisect_right(cycles, c) - 1][1])
    return out


# --- a stimulus for the triggers -----------------------------------------------------
# The LFSR of values(), but bits 6, 7, 12 and 13 (channels P8_40, P8_39,
# P8_21, P8_20) low, except from cycle TRIG_AT for TRIG_LEN cycles of each
# period, where they are all high: one rising edge (TRIG_AT), one falling
# edge (TRIG_AT + TRIG_LEN) and one run of the pattern per period.
TRIG_BITS = 0x30c0
TRIG_AT = 40000
TRIG_LEN = 40


def trigger_values():
    """The trigger stimulus' value in each cycle of one period."""
    return [(v & ~TRIG_BITS) | (TRIG_BITS if TRIG_AT <= i < TRIG_AT + TRIG_LEN else 0)
            for i, v in enumerate(values())]
