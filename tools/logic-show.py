#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""Draw a sigrok session (.sr, as sigrok-cli -o or PulseView save it) as a
waveform picture, with the bytes sigrok's protocol decoders find in it.

    logic-show.py SESSION.sr --png OUT.png [--from SAMPLE] [--samples N]
        [--channel NAME[=LABEL]]... [--decode DECODER:OPTIONS@ANNOTATION[@LABEL]]...
        [--width PIXELS]

--channel picks and orders the channels drawn (default: all of the
session's).  --decode runs sigrok-cli -P DECODER:OPTIONS -A DECODER=ANNOTATION
on the session (e.g. uart:rx=P8_45:baudrate=1000000@rx-data@UART) and
draws each annotation as a box under the waveforms; the decoded bytes are
printed too, one row per --decode.  The picture needs Debian's python3-pil
(run with /usr/bin/python3); sigrok-cli and its decoders come from Debian's
sigrok-cli package.  read_session() and decode() are for other tools too
(drivers/beaglelogic/tests/bl_decode.py): they raise SessionError."""
import argparse
import re
import subprocess
import sys
import zipfile

ROW, PAD, LABEL_W = 26, 6, 110


class SessionError(Exception):
    """A session that cannot be read, or a decoder that failed on it."""


def read_session(path):
    """(samplerate Hz, unit size, [channel names by bit], samples bytes)."""
    try:
        z = zipfile.ZipFile(path)
        meta = z.read("metadata").decode()
    except (OSError, zipfile.BadZipFile, KeyError) as e:
        raise SessionError("%s: not a sigrok session (%s)" % (path, e)) from e
    unit = int(re.search(r"^unitsize=(\d+)", meta, re.M).group(1))
    m = re.search(r"^samplerate=([\d.]+) *([kMG]?)Hz", meta, re.M)
    rate = float(m.group(1)) * {"": 1, "k": 1e3, "M": 1e6, "G": 1e9}[m.group(2)]
    names = {}
    for num, name in re.findall(r"^probe(\d+)=(.*)$", meta, re.M):
        names[int(num) - 1] = name.strip()
    chunks = sorted((n for n in z.namelist() if re.fullmatch(r"logic-1-\d+", n)),
                    key=lambda n: int(n.rsplit("-", 1)[1]))
    return rate, unit, names, b"".join(z.read(n) for n in chunks)


def decode(path, spec):
    """(label, [(first sample, last sample, text)]) of one --decode SPEC:
    DECODER:OPTIONS@ANNOTATION[@LABEL]."""
    parts = spec.split("@")
    if len(parts) not in (2, 3):
        raise SessionError("--decode %s: want DECODER:OPTIONS@ANNOTATION[@LABEL]" % spec)
    decoder, ann = parts[0], parts[1]
    name = decoder.split(":")[0]
    r = subprocess.run(["sigrok-cli", "-i", path, "-P", decoder, "-A", name + "=" + ann,
                        "--protocol-decoder-samplenum"], capture_output=True, text=True)
    if r.returncode:
        raise SessionError("sigrok-cli -P %s on %s: %s" % (decoder, path, r.stderr.strip()))
    out = []
    for ln in r.stdout.splitlines():
        m = re.match(r"(\d+)-(\d+) \S+: (.*)$", ln)
        if m:
            out.append((int(m.group(1)), int(m.group(2)), m.group(3)))
    return parts[2] if len(parts) == 3 else "%s %s" % (name, ann), out


def text_of(vals):
    """Hex bytes as text where they are printable."""
    try:
        b = bytes(int(v, 16) for v in vals)
    except ValueError:
        return " ".join(vals)
    if all(32 <= c < 127 or c in (10, 13) for c in b):
        return repr(b.decode())
    return " ".join(vals)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("session")
    p.add_argument("--png", required=True)
    p.add_argument("--from", dest="start", type=int, default=0)
    p.add_argument("--samples", type=int, default=0, help="default: to the end")
    p.add_argument("--channel", action="append", default=[])
    p.add_argument("--decode", action="append", default=[])
    p.add_argument("--width", type=int, default=1600)
    a = p.parse_args()
    try:
        rate, unit, names, data = read_session(a.session)
        decoded = [decode(a.session, spec) for spec in a.decode]
    except SessionError as e:
        sys.exit("logic-show: %s" % e)
    total = len(data) // unit
    start = max(0, min(a.start, total - 1))
    count = min(a.samples or total - start, total - start)
    by_name = {n: bit for bit, n in names.items()}
    rows = []
    for spec in a.channel or [names[b] for b in sorted(names)]:
        name, _, label = spec.partition("=")
        if name not in by_name:
            sys.exit("logic-show: no channel %s in %s (it has %s)" %
                     (name, a.session, ", ".join(names[b] for b in sorted(names))))
        rows.append((by_name[name], label or name))
    for label, anns in decoded:
        print("%s: %s" % (label, text_of([t for _, _, t in anns])))

    from PIL import Image, ImageDraw
    plot_w = a.width - LABEL_W - PAD
    height = PAD + (len(rows) + len(decoded)) * (ROW + PAD) + ROW
    img = Image.new("RGB", (a.width, height), "white")
    d = ImageDraw.Draw(img)

    def x_of(sample):
        return LABEL_W + (sample - start) * plot_w / count

    y = PAD
    for bit, label in rows:
        d.text((4, y + ROW // 3), label, fill="black")
        prev, px = None, x_of(start)
        pts = []
        for k in range(start, start + count):
            v = data[k * unit + bit // 8] >> (bit % 8) & 1
            if v != prev:
                x = x_of(k)
                if prev is not None:
                    pts.append((x, y + (ROW - 4 if prev == 0 else 4)))
                pts.append((x, y + (ROW - 4 if v == 0 else 4)))
                prev = v
        pts.append((x_of(start + count), pts[-1][1]))
        d.line(pts, fill=(0, 110, 0), width=2)
        y += ROW + PAD
    for label, anns in decoded:
        d.text((4, y + ROW // 3), label, fill="black")
        for first, last, text in anns:
            if last < start or first >= start + count:
                continue
            x0, x1 = x_of(max(first, start)), x_of(min(last, start + count))
            d.rectangle((x0, y + 2, x1, y + ROW - 2), outline=(40, 60, 160), fill=(220, 228, 255))
            try:
                code = int(text, 16)
                shown = chr(code) if 33 <= code < 127 else text
            except ValueError:
                shown = text
            if x1 - x0 > 6 * len(shown):
                d.text((x0 + 2, y + ROW // 3), shown, fill=(20, 20, 90))
        y += ROW + PAD
    d.text((LABEL_W, y), "%d samples from sample %d at %g MHz (%g us)" %
           (count, start, rate / 1e6, count / rate * 1e6), fill="gray")
    img.save(a.png)


if __name__ == "__main__":
    main()
