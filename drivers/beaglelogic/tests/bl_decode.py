# SPDX-License-Identifier: GPL-2.0-only
"""The beaglelogic tests' sigrok sessions, on the host: read a session
(.sr), and check what sigrok's own uart and spi decoders find in a capture
of bl_stim's serial stimulus (tools/logic-show.py reads the session and
runs the decoders).  Used by tests/vm/host/82-beaglelogic and by
make demo:

    bl_decode.py SESSION T0 STEP

checks every sample of SESSION (taken STEP cycles apart, the first T0
cycles after the stimulus' origin) and the decoders' bytes; prints PASS:
and FAIL: lines, exits 1 on a failure."""
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.join(HERE, "vm/lib"))
import bl_stim  # noqa: E402

# tools/logic-show.py reads sessions and runs sigrok's decoders on them
_spec = importlib.util.spec_from_file_location("logic_show",
                                               os.path.join(HERE, "../../../tools/logic-show.py"))
logic_show = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(logic_show)


def read_sr(path):
    """(unit size, samples) of a sigrok session file."""
    _, unit, _, data = logic_show.read_session(path)
    return unit, data


def decode(path, decoder, ann):
    """sigrok's DECODER on the session PATH: [(first sample, byte)] of its
    annotation ANN ([] and a line saying why if sigrok-cli failed)."""
    try:
        _, anns = logic_show.decode(path, "%s@%s" % (decoder, ann))
    except logic_show.SessionError as e:
        print(e, flush=True)
        return []
    return [(first, int(text, 16)) for first, _, text in anns]


def check_decoded(check, name, path, t0, step, count):
    """sigrok's uart and spi decoders print exactly the bytes the stimulus
    sent, each where it was sent (within a sample: the decoders place a
    byte at its first data bit, a UART start bit or an SPI clock half
    period after the byte began), in the part of the capture after the
    first start of a period (idle lines: no decoder can be mid-frame there)
    and before the last frame the capture may cut."""
    frames, _ = bl_stim.serial_events()
    period = bl_stim.SERIAL_PERIOD
    sync = -(-(-t0 % period) // step)	# the first period start's sample
    uart_bit = bl_stim.CYCLES_PER_S / bl_stim.UART_BAUD
    spi_half = bl_stim.CYCLES_PER_S // bl_stim.SPI_HZ // 2
    byte_cycles = 16 * spi_half
    uart_len = int(10 * uart_bit) // step + 2
    spi_len = byte_cycles // step + 2
    want = {"uart": [], "mosi": [], "miso": []}
    for r in range(t0 // period, (t0 + count * step) // period + 2):
        for proto, first, last, data in frames:
            base = r * period + first - t0
            if proto == "uart":
                want["uart"].append((-(-base // step) + uart_bit / step, data))
                continue
            for k, (a, b) in enumerate(zip(*data)):
                at = -(-(base + k * byte_cycles) // step) + 2 * spi_half / step
                want["mosi"].append((at, a))
                want["miso"].append((at, b))
    got = {"uart": decode(path, "uart:rx=P8_45:baudrate=%d" % bl_stim.UART_BAUD, "rx-data"),
           "mosi": decode(path, "spi:clk=P8_46:mosi=P8_43:miso=P8_41:cs=P8_44", "mosi-data"),
           "miso": decode(path, "spi:clk=P8_46:mosi=P8_43:miso=P8_41:cs=P8_44", "miso-data")}
    for what, length in (("uart", uart_len), ("mosi", spi_len), ("miso", spi_len)):
        inside = [(at, v) for at, v in want[what] if sync <= at < count - length]
        dec = [(at, v) for at, v in got[what] if sync <= at < count - length]
        where = [abs(a[0] - b[0]) <= 1 for a, b in zip(dec, inside)]
        check("%s: sigrok's %s decoder prints exactly the %d bytes sent, where they were sent "
              "(samples %d to %d)" % (name, "uart" if what == "uart" else "spi (%s)" % what,
                                      len(inside), sync, count - length),
              len(inside) >= (20 if what == "uart" else 8) and
              [v for _, v in dec] == [v for _, v in inside] and all(where),
              "decoded %s, sent %s, %d misplaced" %
              (bytes(v for _, v in dec)[:40], bytes(v for _, v in inside)[:40],
               where.count(False)))


def main(path, t0, step):
    failed = []

    def check(name, cond, detail=""):
        print(("PASS: " if cond else "FAIL: ") + name +
              ("" if cond or not detail else ": " + detail), flush=True)
        if not cond:
            failed.append(name)

    unit, data = read_sr(path)
    got = list(data) if unit == 1 else [data[i] | data[i + 1] << 8
                                        for i in range(0, len(data) - 1, 2)]
    want = bl_stim.serial_expected(t0, step, len(got))
    mask = (1 << 8 * unit) - 1
    bad = [k for k in range(len(got)) if got[k] & mask != want[k] & mask]
    check("%s: %d samples, %d cycles apart: each equals the stimulus" %
          (os.path.basename(path), len(got), step), got and not bad,
          "%d differ" % len(bad))
    check_decoded(check, os.path.basename(path), path, t0, step, len(got))
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit("usage: bl_decode.py SESSION T0 STEP")
    sys.exit(main(sys.argv[1], int(sys.argv[2]), int(sys.argv[3])))
