# SPDX-License-Identifier: GPL-2.0-only
"""What a hub75 panel should show: the driver's documented arithmetic
(Documentation/hub75.rst, "Levels"), written again from the formulas, not
from hub75_conv.c, for the tests to compare with decoded pins."""
import struct


def plane_order(planes):
    """The order the planes are shown: longest, shortest, second longest ..."""
    lo, hi, out = 0, planes, []
    for k in range(planes):
        if k % 2:
            out.append(lo)
            lo += 1
        else:
            hi -= 1
            out.append(hi)
    return out


def level(v, planes, correction):
    """The level (0 .. 2^planes - 1) of 8-bit component value V: the exact
    rational value rounded half up."""
    m = (1 << planes) - 1
    if correction == "linear":
        num, den = v * m, 255
    elif v <= 20:
        # CIE 1931: L* = 100 v / 255 <= 8: Y = L* / 903.3
        num, den = v * 1000 * m, 255 * 9033
    else:
        # Y = ((L* + 16) / 116)^3 = (100 v + 4080)^3 / 29580^3
        num, den = (100 * v + 4080) ** 3 * m, 29580 ** 3
    return (2 * num + den) // (2 * den)


def pixels(data, fmt, width, height):
    """8-bit (r, g, b) rows of an XRGB8888 or RGB565 little-endian image."""
    rows = []
    for y in range(height):
        row = []
        for x in range(width):
            if fmt == "RGB565":
                p = struct.unpack_from("<H", data, 2 * (y * width + x))[0]
                r5, g6, b5 = p >> 11, p >> 5 & 0x3f, p & 0x1f
                row.append((r5 << 3 | r5 >> 2, g6 << 2 | g6 >> 4, b5 << 3 | b5 >> 2))
            else:
                p = struct.unpack_from("<I", data, 4 * (y * width + x))[0]
                row.append((p >> 16 & 255, p >> 8 & 255, p & 255))
        rows.append(row)
    return rows


def expected(data, fmt, width, height, planes, correction):
    lut = [level(v, planes, correction) for v in range(256)]
    return [[tuple(lut[c] for c in px) for px in row]
            for row in pixels(data, fmt, width, height)]


def frame_buffer(line_bits, entry_bytes, img, rows, planes):
    """hub75_proto.h's frame buffer of an image of levels: blocks in the
    order shown, block k * rows + r = address row r of plane order[k]; its
    entry x: bit line_bits[c] = bit p of line c's level (R1 G1 B1 from row
    r, R2 G2 B2 from row r + rows)."""
    width = len(img[0])
    out = bytearray()
    for p in plane_order(planes):
        for r in range(rows):
            for x in range(width):
                lv = tuple(img[r][x]) + tuple(img[r + rows][x])
                e = 0
                for c in range(6):
                    e |= ((lv[c] >> p) & 1) << line_bits[c]
                out += struct.pack("<H" if entry_bytes == 2 else "<B", e)
    return bytes(out)


# Outdoor panels (hub75.rst, "Outdoor panels"): the LED at (x, y) of a
# w x h panel is pixel (mx, my) of the panel as driven, 2w x h/2.  Written
# from the rules of hzeller's rpi-rgb-led-matrix's documentation of its
# --led-multiplexing mappers, in their own form (not hub75_conv.c's).
def _stripe_y(y, h):
    return (y // (h // 2)) * (h // 4) + y % (h // 4)


def _is_top(y, h):
    return (y % (h // 2)) < h // 4


def _zstripe(x, y, even_off, odd_off):
    odd = (y // 4) % 2
    mx = x + ((x + (0 if odd else even_off)) // 8) * 8 + (odd_off if odd else 0)
    return mx, (y % 4) + 4 * (y // 8)


def mux_map(name, w, h, x, y):
    """(mx, my) of LED (x, y) of a w x h panel wired as NAME."""
    top = _is_top(y, h)
    sy = _stripe_y(y, h)
    odd = (y // 4) % 2
    even = 1 - odd
    ty = (y % 4) + 4 * (y // 8)
    if name == "direct":
        return x, y
    if name == "stripe":
        return (x + w if top else x), sy
    if name == "flipped-stripe":
        return (x if top else x + w), sy
    if name == "checkered":
        if top:
            return (x + w // 2 if x < w // 2 else x + w), sy
        return (x if x < w // 2 else x + w // 2), sy
    if name == "spiral":
        q = w // 4
        quarter, off = x // q, x % q
        return 2 * quarter * q + (q - 1 - off if top else q + off), sy
    if name == "p3-outdoor-64x64":
        return 2 * x + (1 if top else 0), sy
    if name == "zstripe":
        return _zstripe(x, y, 0, 8)
    if name == "zn-mirror-zstripe":
        return _zstripe(x, y, 4, 4)
    if name == "zstripe-uneven":
        return _zstripe(x, y, 8, 0)
    if name == "inversed-zstripe":
        if odd:
            return x + (x // 8) * 8, ty
        return (x // 8) * 16 + 8 + (7 - x % 8), ty
    if name == "p10-outdoor-1r1g1-1":
        return 8 * (1 + even + 2 * (x // 8)) - (x % 8) - 1, ty
    if name == "p10-outdoor-1r1g1-2":
        if even:
            return 8 * (1 + 2 * (x // 8)) - (x % 8) - 1, ty
        return x + (x // 8) * 8 + 8, ty
    if name == "p10-outdoor-1r1g1-3":
        if odd:
            return 8 * (2 + 2 * (x // 8)) - (x % 8) - 1, ty
        return x + (x // 8) * 8, ty
    raise ValueError("unknown multiplexing %r" % name)


MUXES = ("stripe", "checkered", "spiral", "zstripe", "zn-mirror-zstripe", "zstripe-uneven",
         "inversed-zstripe", "p10-outdoor-1r1g1-1", "p10-outdoor-1r1g1-2",
         "p10-outdoor-1r1g1-3", "flipped-stripe", "p3-outdoor-64x64")


def driven(img, name, panel_w):
    """The picture as driven: IMG (rows of a chain of panel_w-wide panels)
    rearranged into the chain of panels as their outputs are wired."""
    h, width = len(img), len(img[0])
    s = 1 if name == "direct" else 2
    out = [[None] * (width * s) for _ in range(h // s)]
    for y in range(h):
        for vx in range(width):
            c, x = divmod(vx, panel_w)
            mx, my = mux_map(name, panel_w, h, x, y)
            out[my][c * panel_w * s + mx] = img[y][vx]
    return out


def seen(decoded, name, panel_w, width, h):
    """The picture a viewer sees (width x h) from DECODED, the levels of
    the panels as driven (hub75-decode.py's chain image)."""
    s = 1 if name == "direct" else 2
    out = []
    for y in range(h):
        row = []
        for vx in range(width):
            c, x = divmod(vx, panel_w)
            mx, my = mux_map(name, panel_w, h, x, y)
            row.append(tuple(decoded[my][c * panel_w * s + mx]))
        out.append(row)
    return out


# The Octoscroller cape (PRUKIT-HUB75-OCTOSCROLLER-00A0): (bank, bit) of
# R1 G1 B1 R2 G2 B2 of outputs 1..8 and of the control lines, all GPIO
# (LEDscape's Octoscroller schematic, cross-checked with the BeagleBone's
# pin table)
OCTO_DATA = [
    [(2, 2), (2, 3), (2, 5), (0, 23), (2, 4), (0, 26)],
    [(0, 27), (2, 1), (0, 22), (2, 22), (2, 23), (2, 24)],
    [(0, 30), (1, 18), (0, 31), (1, 16), (0, 3), (0, 5)],
    [(0, 2), (0, 15), (1, 17), (3, 21), (3, 19), (0, 4)],
    [(2, 25), (0, 11), (0, 10), (0, 9), (0, 8), (2, 17)],
    [(2, 16), (2, 15), (2, 14), (2, 13), (2, 10), (2, 12)],
    [(2, 11), (2, 9), (2, 8), (2, 6), (0, 7), (2, 7)],
    [(3, 17), (3, 16), (3, 15), (3, 14), (0, 14), (0, 20)],
]
OCTO_CTRL = dict(bank=1, clk=19, lat=28, oe=29, addr=[12, 13, 14, 15])


def bank_slots(data, ctrl_bank):
    """hub75_proto.h's slots: the data banks but the control bank, in
    order, at the end of slots 0..2; the control bank in slot 3; None for
    a slot not used."""
    banks = sorted({b for lines in data for b, _ in lines} - {ctrl_bank})
    return [None] * (3 - len(banks)) + banks + [ctrl_bank]


def banks_frame(data, slots, imgs, rows, planes):
    """The frame buffer of HUB75_DATA_BANKS: per plane shown, row, clock:
    four 32-bit words, the data bits set in each slot's bank.  DATA[o] the
    (bank, bit) of output o's six lines, IMGS[o] its picture of levels as
    driven (2 * rows high)."""
    out = bytearray()
    width = len(imgs[0][0])
    for p in plane_order(planes):
        for r in range(rows):
            for x in range(width):
                words = [0, 0, 0, 0]
                for o, lines in enumerate(data):
                    lv = tuple(imgs[o][r][x]) + tuple(imgs[o][r + rows][x])
                    for c, (bank, bit) in enumerate(lines):
                        if lv[c] >> p & 1:
                            words[slots.index(bank)] |= 1 << bit
                out += struct.pack("<4I", *words)
    return bytes(out)


def arrange(x, y, width, height, band, serpentine, rotation):
    """Where pixel (x, y) of the outputs' chains, one under the other
    (WIDTH x HEIGHT, bands BAND high), is on the display: with SERPENTINE
    the bands of outputs 2, 4, ... mirrored both ways, then the picture
    turned ROTATION degrees clockwise (hub75.rst, "Parallel outputs")."""
    if serpentine and (y // band) % 2 == 1:
        x, y = width - 1 - x, (y // band) * band + (band - 1 - y % band)
    if rotation == 90:
        return height - 1 - y, x
    if rotation == 180:
        return width - 1 - x, height - 1 - y
    if rotation == 270:
        return y, width - 1 - x
    return x, y
