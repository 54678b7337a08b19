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
