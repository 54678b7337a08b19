# SPDX-License-Identifier: GPL-2.0-only
"""prukit hub75: text or a picture on the HUB75 LED matrix, through the
fbdev emulation of prukit's hub75 DRM driver (/dev/fbN).

The framebuffer is found in sysfs: /sys/class/graphics/fbN whose name is
the driver's ("hub75drmfb") or whose device is bound to the hub75 driver.
Its geometry and pixel format come from the framebuffer itself
(FBIOGET_VSCREENINFO and FBIOGET_FSCREENINFO), frames go in with pwrite().
The text is drawn in prukit's own 5x7 font (FONT below).
"""
import argparse
import errno
import fcntl
import glob
import os
import struct
import sys
import time

from . import Error, number_arg, read, sysfs

OVERLAY = "PRUKIT-HUB75-00A0"
GROUP = "video"			# udev's own rules give /dev/fbN to it
DRIVER = "hub75"		# drivers/hub75/hub75_drv.c: the DRM and platform driver

FBIOGET_VSCREENINFO = 0x4600
FBIOGET_FSCREENINFO = 0x4602
VAR = struct.Struct("=40I")	# struct fb_var_screeninfo: 40 __u32
FIX = struct.Struct("@16sLIIIIHHHILIIHHH")  # struct fb_fix_screeninfo (unsigned long: L)

# prukit's 5x7 font, drawn for this tool: each line is the character, a
# space, then its 7 rows top to bottom, 5 columns each ('#' lit).
FONT_ROWS = r"""
  ..... ..... ..... ..... ..... ..... .....
! ..#.. ..#.. ..#.. ..#.. ..#.. ..... ..#..
" .#.#. .#.#. ..... ..... ..... ..... .....
# .#.#. .#.#. ##### .#.#. ##### .#.#. .#.#.
$ ..#.. .#### #.#.. .###. ..#.# ####. ..#..
% ##... ##..# ...#. ..#.. .#... #..## ...##
& .##.. #..#. #.#.. .#... #.#.# #..#. .##.#
' ..#.. ..#.. ..... ..... ..... ..... .....
( ...#. ..#.. .#... .#... .#... ..#.. ...#.
) .#... ..#.. ...#. ...#. ...#. ..#.. .#...
* ..... ..#.. #.#.# .###. #.#.# ..#.. .....
+ ..... ..#.. ..#.. ##### ..#.. ..#.. .....
, ..... ..... ..... ..... .##.. ..#.. .#...
- ..... ..... ..... ##### ..... ..... .....
. ..... ..... ..... ..... ..... .##.. .##..
/ ..... ....# ...#. ..#.. .#... #.... .....
0 .###. #...# #..## #.#.# ##..# #...# .###.
1 ..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###.
2 .###. #...# ....# ...#. ..#.. .#... #####
3 ##### ...#. ..#.. ...#. ....# #...# .###.
4 ...#. ..##. .#.#. #..#. ##### ...#. ...#.
5 ##### #.... ####. ....# ....# #...# .###.
6 ..##. .#... #.... ####. #...# #...# .###.
7 ##### ....# ...#. ..#.. .#... .#... .#...
8 .###. #...# #...# .###. #...# #...# .###.
9 .###. #...# #...# .#### ....# ...#. .##..
: ..... .##.. .##.. ..... .##.. .##.. .....
; ..... .##.. .##.. ..... .##.. ..#.. .#...
< ...#. ..#.. .#... #.... .#... ..#.. ...#.
= ..... ..... ##### ..... ##### ..... .....
> .#... ..#.. ...#. ....# ...#. ..#.. .#...
? .###. #...# ....# ...#. ..#.. ..... ..#..
@ .###. #...# ....# .##.# #.#.# #.#.# .###.
A .###. #...# #...# ##### #...# #...# #...#
B ####. #...# #...# ####. #...# #...# ####.
C .###. #...# #.... #.... #.... #...# .###.
D ###.. #..#. #...# #...# #...# #..#. ###..
E ##### #.... #.... ####. #.... #.... #####
F ##### #.... #.... ####. #.... #.... #....
G .###. #...# #.... #.### #...# #...# .####
H #...# #...# #...# ##### #...# #...# #...#
I .###. ..#.. ..#.. ..#.. ..#.. ..#.. .###.
J ..### ...#. ...#. ...#. ...#. #..#. .##..
K #...# #..#. #.#.. ##... #.#.. #..#. #...#
L #.... #.... #.... #.... #.... #.... #####
M #...# ##.## #.#.# #.#.# #...# #...# #...#
N #...# #...# ##..# #.#.# #..## #...# #...#
O .###. #...# #...# #...# #...# #...# .###.
P ####. #...# #...# ####. #.... #.... #....
Q .###. #...# #...# #...# #.#.# #..#. .##.#
R ####. #...# #...# ####. #.#.. #..#. #...#
S .#### #.... #.... .###. ....# ....# ####.
T ##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#..
U #...# #...# #...# #...# #...# #...# .###.
V #...# #...# #...# #...# #...# .#.#. ..#..
W #...# #...# #...# #.#.# #.#.# #.#.# .#.#.
X #...# #...# .#.#. ..#.. .#.#. #...# #...#
Y #...# #...# .#.#. ..#.. ..#.. ..#.. ..#..
Z ##### ....# ...#. ..#.. .#... #.... #####
[ .###. .#... .#... .#... .#... .#... .###.
\ ..... #.... .#... ..#.. ...#. ....# .....
] .###. ...#. ...#. ...#. ...#. ...#. .###.
^ ..#.. .#.#. #...# ..... ..... ..... .....
_ ..... ..... ..... ..... ..... ..... #####
` .#... ..#.. ..... ..... ..... ..... .....
a ..... ..... .###. ....# .#### #...# .####
b #.... #.... #.##. ##..# #...# #...# ####.
c ..... ..... .###. #.... #.... #...# .###.
d ....# ....# .##.# #..## #...# #...# .####
e ..... ..... .###. #...# ##### #.... .###.
f ..##. .#..# .#... ###.. .#... .#... .#...
g ..... .#### #...# #...# .#### ....# .###.
h #.... #.... #.##. ##..# #...# #...# #...#
i ..#.. ..... .##.. ..#.. ..#.. ..#.. .###.
j ...#. ..... ..##. ...#. ...#. #..#. .##..
k #.... #.... #..#. #.#.. ##... #.#.. #..#.
l .##.. ..#.. ..#.. ..#.. ..#.. ..#.. .###.
m ..... ..... ##.#. #.#.# #.#.# #...# #...#
n ..... ..... #.##. ##..# #...# #...# #...#
o ..... ..... .###. #...# #...# #...# .###.
p ..... ..... ####. #...# ####. #.... #....
q ..... ..... .##.# #..## .#### ....# ....#
r ..... ..... #.##. ##..# #.... #.... #....
s ..... ..... .###. #.... .###. ....# ####.
t .#... .#... ###.. .#... .#... .#..# ..##.
u ..... ..... #...# #...# #...# #..## .##.#
v ..... ..... #...# #...# #...# .#.#. ..#..
w ..... ..... #...# #...# #.#.# #.#.# .#.#.
x ..... ..... #...# .#.#. ..#.. .#.#. #...#
y ..... ..... #...# #...# .#### ....# .###.
z ..... ..... ##### ...#. ..#.. .#... #####
{ ...#. ..#.. ..#.. .#... ..#.. ..#.. ...#.
| ..#.. ..#.. ..#.. ..#.. ..#.. ..#.. ..#..
} .#... ..#.. ..#.. ...#. ..#.. ..#.. .#...
~ ..... ..... .#... #.#.# ...#. ..... .....
"""
GLYPH_W, GLYPH_H = 5, 7


def _font():
    """{character: 7 rows of 5 booleans}."""
    font = {}
    for line in FONT_ROWS.split("\n"):
        if len(line) < 3:
            continue
        rows = line[2:].split()
        assert len(rows) == GLYPH_H and all(len(r) == GLYPH_W for r in rows), line
        font[line[0]] = [[c == "#" for c in r] for r in rows]
    return font


FONT = _font()


def _colour(text):
    """argparse type: R,G,B with each 0..255."""
    parts = text.split(",")
    try:
        rgb = tuple(int(p, 0) for p in parts)
    except ValueError:
        rgb = ()
    if len(rgb) != 3 or not all(0 <= v <= 255 for v in rgb):
        raise argparse.ArgumentTypeError("%r is not a colour R,G,B (each 0-255)" % text)
    return rgb


_seconds = number_arg(float, lambda s: 0 < s <= 86400,
                      "%r is not a number of seconds", "%r is not in (0, 86400] seconds")


_positive = number_arg(lambda t: int(t, 0), lambda n: 1 <= n <= 64,
                       "%r is not a number", "%r is not in 1..64")


_speed = number_arg(float, lambda s: 0 < s <= 1000, "%r is not a number of pixels per second",
                    "%r is not in (0, 1000] pixels per second")


def register(sub):
    p = sub.add_parser(
        "hub75", help="text or a picture on the HUB75 LED matrix",
        description="Draw text (prukit's own 5x7 font) or a picture on the HUB75 matrix "
        "through its framebuffer /dev/fbN.  Pictures: binary PPM (P6, colour) or PGM "
        "(P5, grey), 8 or 16 bits per component, scaled down or up to fit the panel "
        "keeping their shape (nearest pixel), or cropped with --crop; other formats: "
        "convert them first, e.g. `convert photo.jpg photo.ppm` (ImageMagick) or "
        "`pngtopnm`.  The picture stays shown after the command ends (with "
        "--seconds, it is cleared after that time).",
        epilog="The matrix comes from the overlay %s (or "
        "PRUKIT-HUB75-POCKETSCROLLER-00A0, PRUKIT-HUB75-OCTOSCROLLER-00A0) and the "
        "module hub75; /dev/fbN is group %s's.  Documentation/hub75.rst."
        % (OVERLAY, GROUP))
    what = p.add_mutually_exclusive_group(required=True)
    what.add_argument("--text", metavar="TEXT", help="the text to draw (ASCII)")
    what.add_argument("--image", metavar="FILE",
                      help="a binary PPM (P6) or PGM (P5) picture")
    p.add_argument("--scroll", action="store_true",
                   help="scroll the text from right to left (one pass, or for --seconds)")
    p.add_argument("--speed", type=_speed, default=20.0, metavar="PX/S",
                   help="scrolling speed in pixels per second (default 20)")
    p.add_argument("--device", metavar="/dev/fbN",
                   help="the framebuffer (default: the one of the hub75 driver)")
    p.add_argument("--seconds", type=_seconds, metavar="S",
                   help="show it for S seconds, then clear the panel (scrolling: "
                   "scroll for S seconds)")
    p.add_argument("--color", type=_colour, default=(255, 255, 255), metavar="R,G,B",
                   help="the text's colour (default 255,255,255)")
    p.add_argument("--background", type=_colour, default=(0, 0, 0), metavar="R,G,B",
                   help="the background's colour (default 0,0,0)")
    p.add_argument("--scale", type=_positive, metavar="N",
                   help="text pixels per font pixel (default: the largest that fits "
                   "the panel's height, and its width unless scrolling)")
    p.add_argument("--crop", action="store_true",
                   help="show the picture's middle at its own size instead of scaling it")
    p.add_argument("--dump", metavar="FILE",
                   help="also write the last frame sent to FILE, as written to the "
                   "framebuffer (for tests)")
    p.set_defaults(func=run)


def _driver_of(path):
    """The driver bound to the device at PATH or one of its parents, or None."""
    d = os.path.realpath(path)
    while d and d != "/":
        drv = os.path.join(d, "driver")
        if os.path.islink(drv):
            name = os.path.basename(os.readlink(drv))
            if name == DRIVER:
                return name
        d = os.path.dirname(d)
    return None


def missing_hint():
    return ("The matrix comes from the overlay %s (or PRUKIT-HUB75-POCKETSCROLLER-00A0,\n"
            "PRUKIT-HUB75-OCTOSCROLLER-00A0):\n"
            "  sudo prukit enable %s\n"
            "then reboot.  If the overlay is enabled, the module may not be loaded:\n"
            "  sudo modprobe hub75\n"
            "and `dmesg | grep hub75` says why a display did not bind." % (OVERLAY, OVERLAY))


def find_fb(arg):
    """(/dev/fbN, its sysfs name) of --device, or of the hub75 display."""
    if arg:
        name = os.path.basename(arg)
        if name.isdigit():
            name = "fb" + name
        d = sysfs("class", "graphics", name)
        if not os.path.isdir(d):
            raise Error("no framebuffer %s" % arg, missing_hint())
        return "/dev/" + name, read(d + "/name", "")
    found = []
    for d in sorted(glob.glob(sysfs("class", "graphics", "fb*"))):
        fbname = read(d + "/name", "")
        if fbname.startswith(DRIVER) or _driver_of(d + "/device"):
            found.append(("/dev/" + os.path.basename(d), fbname))
    if not found:
        raise Error("no framebuffer of the hub75 driver in %s" % sysfs("class", "graphics"),
                    missing_hint())
    return found[0]


def os_error(e, dev, doing):
    """An Error for an OSError of DEV while DOING."""
    code = e.errno
    what = "%s: %s: %s" % (dev, doing, os.strerror(code) if code else e)
    if code in (errno.EACCES, errno.EPERM):
        return Error(what, "%s is group %s's (udev's rules for framebuffers):\n"
                     "  sudo adduser $USER %s\n"
                     "then log in again (or run prukit with sudo)." % (dev, GROUP, GROUP))
    if code in (errno.ENOENT, errno.ENXIO, errno.ENODEV):
        return Error(what, "The display went away (unbound or the module removed).\n"
                     + missing_hint())
    if code in (errno.EFBIG, errno.ENOSPC):
        return Error(what, "The frame is larger than the framebuffer: did the mode change?")
    if code == errno.EBUSY:
        return Error(what, "Another program holds the display (a DRM master, e.g. a "
                     "compositor): stop it first.")
    return Error(what)


class Fb:
    """An open framebuffer: geometry and the packing of a pixel."""

    def __init__(self, dev):
        self.dev = dev
        try:
            self.fd = os.open(dev, os.O_RDWR)
        except OSError as e:
            raise os_error(e, dev, "open")
        try:
            var = VAR.unpack(fcntl.ioctl(self.fd, FBIOGET_VSCREENINFO, bytes(VAR.size)))
            fix = FIX.unpack(fcntl.ioctl(self.fd, FBIOGET_FSCREENINFO, bytes(FIX.size)))
        except OSError as e:
            os.close(self.fd)
            raise os_error(e, dev, "FBIOGET_VSCREENINFO/FSCREENINFO")
        self.width, self.height = var[0], var[1]
        self.yoffset, self.bpp = var[5], var[6]
        # red, green, blue: (offset, length) of fb_bitfield
        self.fields = [(var[8 + 3 * i], var[9 + 3 * i]) for i in range(3)]
        self.stride = fix[9]
        self.id = fix[0].split(b"\0")[0].decode("ascii", "replace")
        if self.bpp not in (16, 24, 32) or not all(n for _, n in self.fields):
            os.close(self.fd)
            raise Error("%s: %d bits per pixel, not a true-colour format this command "
                        "draws" % (dev, self.bpp))
        if not self.stride:
            self.stride = self.width * self.bpp // 8

    def pixel(self, rgb):
        """The bytes of one pixel of colour RGB."""
        v = 0
        for c, (off, n) in zip(rgb, self.fields):
            v |= (c >> (8 - n) if n <= 8 else c << (n - 8)) << off
        return v.to_bytes(self.bpp // 8, "little")

    def frame(self, img):
        """The framebuffer's bytes for IMG (height rows of width colours)."""
        cache = {}
        out = bytearray()
        pad = bytes(self.stride - self.width * self.bpp // 8)
        for row in img:
            for c in row:
                px = cache.get(c)
                if px is None:
                    px = cache[c] = self.pixel(c)
                out += px
            out += pad
        return bytes(out)

    def show(self, data):
        try:
            n = os.pwrite(self.fd, data, self.yoffset * self.stride)
        except OSError as e:
            raise os_error(e, self.dev, "write")
        if n != len(data):
            raise Error("%s: wrote %d of %d bytes" % (self.dev, n, len(data)))

    def close(self):
        os.close(self.fd)


def text_bitmap(text):
    """The text in the font: rows of booleans, 1 column between glyphs."""
    rows = [[] for _ in range(GLYPH_H)]
    for i, ch in enumerate(text):
        g = FONT.get(ch, FONT["?"])
        for y in range(GLYPH_H):
            if i:
                rows[y].append(False)
            rows[y].extend(g[y])
    return rows


def render_text(bitmap, scale, width, height, x0, fg, bg):
    """A WIDTH x HEIGHT picture: BITMAP scaled by SCALE, its left edge at
    column X0, centred vertically."""
    bh = len(bitmap) * scale
    y0 = (height - bh) // 2
    bw = len(bitmap[0]) if bitmap else 0
    img = []
    for y in range(height):
        by = (y - y0) // scale if y >= y0 else -1
        row = []
        for x in range(width):
            bx = (x - x0) // scale if x >= x0 else -1
            lit = 0 <= by < len(bitmap) and 0 <= bx < bw and bitmap[by][bx]
            row.append(fg if lit else bg)
        img.append(row)
    return img


def read_pnm(path):
    """(width, height, rows of (r, g, b)) of a binary PPM (P6) or PGM (P5)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise Error("--image %s: %s" % (path, e.strerror))
    conv = ("Convert it first, e.g. `convert %s picture.ppm` (ImageMagick) or "
            "`pngtopnm`, `jpegtopnm` (netpbm)." % path)
    magic = data[:2]
    if magic not in (b"P5", b"P6"):
        raise Error("%s is not a binary PPM (P6) or PGM (P5) picture" % path, conv)
    tokens, pos = [], 2
    while len(tokens) < 3:
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while pos < len(data) and data[pos:pos + 1] not in (b"\n", b"\r"):
                pos += 1
            continue
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace() and data[pos:pos + 1] != b"#":
            pos += 1
        if start == pos:
            break
        tokens.append(data[start:pos])
    try:
        w, h, maxval = (int(t) for t in tokens)
    except ValueError:
        raise Error("%s: a broken %s header" % (path, magic.decode()), conv)
    if w < 1 or h < 1 or not 1 <= maxval <= 65535:
        raise Error("%s: a broken %s header (%dx%d, maxval %d)" % (
            path, magic.decode(), w, h, maxval), conv)
    pos += 1			# the one white space character after maxval
    comps = 3 if magic == b"P6" else 1
    size = 2 if maxval > 255 else 1
    need = w * h * comps * size
    body = data[pos:pos + need]
    if len(body) < need:
        raise Error("%s: %d bytes of pixels, the header says %d" % (path, len(body), need))
    if size == 2:
        vals = struct.unpack(">%dH" % (w * h * comps), body)
    else:
        vals = body
    if maxval != 255:
        vals = [(v * 255 + maxval // 2) // maxval for v in vals]
    rows = []
    for y in range(h):
        row = []
        for x in range(w):
            i = (y * w + x) * comps
            row.append(tuple(vals[i:i + 3]) if comps == 3 else (vals[i],) * 3)
        rows.append(row)
    return w, h, rows


def fit(w, h, rows, width, height, crop, bg):
    """The picture on a WIDTH x HEIGHT panel: scaled to fit keeping its
    shape and centred (nearest pixel), or its middle at its own size."""
    if crop:
        sw, sh = w, h
    elif w * height >= h * width:	# as wide or wider than the panel
        sw, sh = width, max(1, h * width // w)
    else:
        sw, sh = max(1, w * height // h), height
    x0, y0 = (width - sw) // 2, (height - sh) // 2
    img = []
    for y in range(height):
        row = []
        for x in range(width):
            px, py = x - x0, y - y0
            if 0 <= px < sw and 0 <= py < sh:
                row.append(rows[py * h // sh][px * w // sw])
            else:
                row.append(bg)
        img.append(row)
    return img


def console_note(fbdev):
    """A note when the kernel's framebuffer console may draw on the matrix."""
    for vt in glob.glob(sysfs("class", "vtconsole", "vtcon*")):
        if "frame buffer" in read(vt + "/name", "") and read(vt + "/bind") == "1":
            print("note: the framebuffer console (%s) may draw on %s: unbind it with\n"
                  "  echo 0 | sudo tee %s/bind\n"
                  "or keep it off with fbcon=map:... on the kernel command line"
                  % (os.path.basename(vt), fbdev, vt), file=sys.stderr)
            return


def run(args):
    if args.scroll and not args.text:
        raise Error("--scroll scrolls --text, not a picture")
    dev, name = find_fb(args.device)
    fb = Fb(dev)
    dump_data = None
    try:
        W, H = fb.width, fb.height
        print("%s: %s, %dx%d, %d bits per pixel" % (dev, name or fb.id, W, H, fb.bpp),
              flush=True)
        console_note(dev)
        blank = fb.frame([[args.background] * W for _ in range(H)])
        if args.image:
            w, h, rows = read_pnm(args.image)
            dump_data = fb.frame(fit(w, h, rows, W, H, args.crop, args.background))
            fb.show(dump_data)
            print("%s: %dx%d%s" % (args.image, w, h, "" if (w, h) == (W, H) else
                                   " cropped" if args.crop else " scaled"), flush=True)
            if args.seconds:
                time.sleep(args.seconds)
                fb.show(blank)
                dump_data = blank
            return 0
        bitmap = text_bitmap(args.text)
        bw = len(bitmap[0]) if args.text else 0
        scale = args.scale
        if scale is None:
            scale = max(1, H // GLYPH_H)
            if not args.scroll and bw:
                scale = max(1, min(scale, W // bw))
        if not args.scroll:
            x0 = (W - bw * scale) // 2 if bw * scale <= W else 0
            dump_data = fb.frame(render_text(bitmap, scale, W, H, x0, args.color,
                                             args.background))
            fb.show(dump_data)
            if bw * scale > W:
                print("the text is %d pixels wide, the panel %d: try --scroll"
                      % (bw * scale, W), file=sys.stderr)
            if args.seconds:
                time.sleep(args.seconds)
                fb.show(blank)
                dump_data = blank
            return 0
        # scrolling: from just off the right edge until it left on the left
        end = time.monotonic() + args.seconds if args.seconds else None
        step = 1.0 / args.speed
        t = time.monotonic()
        try:
            while True:
                for x0 in range(W, -bw * scale - 1, -1):
                    fb.show(fb.frame(render_text(bitmap, scale, W, H, x0, args.color,
                                                 args.background)))
                    t += step
                    now = time.monotonic()
                    if end is not None and now >= end:
                        break
                    if t > now:
                        time.sleep(t - now)
                if end is None or time.monotonic() >= end:
                    break
        except KeyboardInterrupt:
            fb.show(blank)
            raise
        fb.show(blank)
        dump_data = blank
        return 0
    finally:
        fb.close()
        if args.dump and dump_data is not None:
            try:
                with open(args.dump, "wb") as f:
                    f.write(dump_data)
            except OSError as e:
                print("prukit: --dump %s: %s" % (args.dump, e.strerror), file=sys.stderr)
