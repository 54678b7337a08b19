#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""make demo's matrix part, host side (scripts/demo.sh).

    hub75_demo.py frames DIR
        the frames the guest draws (tests/vm/demo/matrix): DIR/picture.raw,
        a 64x32 XRGB8888 picture, DIR/scroll-NN.raw, text scrolling
        across the panel (drawn with python3-pil's built-in font), and
        DIR/wall/wall.raw, a 256x192 picture for the Octoscroller's 24
        panels (8 outputs x 3 64x32, snaking, turned 90 degrees)
    hub75_demo.py show ARTIFACTS OUTDIR
        every picture the guest recorded (hub75.json, NAME.trace) decoded
        from the simulated pins by tools/hub75-decode.py and compared with
        what was drawn, pixel by pixel (drivers/hub75/tests/hub75_pictures.py);
        then drawn as the panel would look: OUTDIR/matrix-picture.png,
        matrix-scroll.gif and matrix-scroll.png (a frame per row),
        matrix-wall.png (the 24 panels, each output's chains put where the
        wall shows them), and the picture in the terminal.  Exits 1 unless
        every pixel of every frame is exact.

Decoded levels are linear light (the driver applies CIE 1931 lightness
correction); the pictures show them as the eye sees them: each level back
through CIE 1931 lightness to an 8-bit value."""
import json
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hub75_model import arrange  # noqa: E402
from hub75_pictures import check_picture  # noqa: E402

W, H = 64, 32
TEXT = "HUB75 on a BeagleBone PRU"
STEP = 6			# pixels the text moves per frame
SCALE = 8			# pixels per LED in the pictures
WALL_W, WALL_H = 256, 192	# the wall as shown: 8 outputs x 3 64x32, turned 90
WALL_SCALE = 4


def xrgb(img):
    """XRGB8888 little-endian bytes of a PIL RGB image."""
    return b"".join(struct.pack("<I", r << 16 | g << 8 | b) for r, g, b in img.getdata())


def frames(outdir):
    from PIL import Image, ImageDraw, ImageFont
    os.makedirs(outdir, exist_ok=True)
    font = ImageFont.load_default()
    # the picture: a sunset over hills, a sun, the board's name
    pic = Image.new("RGB", (W, H))
    d = ImageDraw.Draw(pic)
    for y in range(H):
        d.line([(0, y), (W - 1, y)], fill=(40 + 6 * y, 20 + 3 * y, 120 - 3 * y))
    d.ellipse([40, 4, 56, 20], fill=(255, 200, 40))
    d.polygon([(0, 31), (0, 22), (14, 16), (30, 24), (46, 19), (63, 25), (63, 31)],
              fill=(20, 110, 40))
    d.text((2, 1), "PRU", font=font, fill=(255, 255, 255))
    with open(os.path.join(outdir, "picture.raw"), "wb") as f:
        f.write(xrgb(pic))
    # the text, scrolling from the right edge until it has left on the left
    tw = font.getbbox(TEXT)[2]
    n = 0
    for x in range(W, -tw - 1, -STEP):
        fr = Image.new("RGB", (W, H), (0, 0, 40))
        d = ImageDraw.Draw(fr)
        d.rectangle([0, 0, W - 1, 3], fill=(255, 0, 0))
        d.rectangle([0, 28, W - 1, 31], fill=(0, 0, 255))
        for i, ch in enumerate(TEXT):
            hue = [(255, 255, 0), (0, 255, 255), (255, 128, 255), (255, 255, 255)][i % 4]
            d.text((x + font.getlength(TEXT[:i]), 10), ch, font=font, fill=hue)
        with open(os.path.join(outdir, "scroll-%02d.raw" % n), "wb") as f:
            f.write(xrgb(fr))
        n += 1
    # the wall: a sky in bands 8 LEDs high (the chains run down the wall:
    # few data changes a clock, so 2.6 refreshes fit the simulator's
    # trace), a sun, hills and big text
    wall = Image.new("RGB", (WALL_W, WALL_H))
    d = ImageDraw.Draw(wall)
    for y in range(0, WALL_H, 8):
        d.rectangle([(0, y), (WALL_W - 1, y + 7)], fill=(30 + y, 10 + y // 2, 140 - y * 2 // 3))
    d.ellipse([170, 20, 230, 80], fill=(255, 210, 60))
    d.polygon([(0, 191), (0, 140), (60, 110), (120, 150), (180, 120), (255, 145), (255, 191)],
              fill=(20, 110, 40))
    small = Image.new("L", (WALL_W // 4, WALL_H // 4))
    ImageDraw.Draw(small).text((3, 2), "24 panels", font=font, fill=255)
    ImageDraw.Draw(small).text((3, 14), "8 outputs", font=font, fill=255)
    wall.paste((255, 255, 255), (0, 0), small.resize((WALL_W, WALL_H), Image.NEAREST))
    os.makedirs(os.path.join(outdir, "wall"), exist_ok=True)
    with open(os.path.join(outdir, "wall", "wall.raw"), "wb") as f:
        f.write(xrgb(wall))
    print("hub75_demo: a picture, %d frames of scrolling text and the wall's picture in %s"
          % (n, outdir))


def perceived(level, planes):
    """The 8-bit value whose CIE 1931 luminance is LEVEL (of 2^planes - 1)."""
    y = level / ((1 << planes) - 1)
    lstar = 116 * y ** (1 / 3) - 16 if y > 0.008856 else 903.3 * y
    return max(0, min(255, int(round(lstar * 255 / 100))))


def panel(levels, planes):
    """A picture of the panel: each LED a round dot on black."""
    from PIL import Image, ImageDraw
    img = Image.new("RGB", (len(levels[0]) * SCALE, len(levels) * SCALE), (8, 8, 8))
    d = ImageDraw.Draw(img)
    for y, row in enumerate(levels):
        for x, px in enumerate(row):
            col = tuple(perceived(v, planes) for v in px)
            d.ellipse([x * SCALE + 1, y * SCALE + 1, x * SCALE + SCALE - 2,
                       y * SCALE + SCALE - 2], fill=col)
    return img


def wall_picture(m, levels):
    """The wall as it looks: LEVELS are the outputs' chains one under the
    other (check_picture()); each LED put where the display shows it, a
    dark seam between panels."""
    from PIL import Image, ImageDraw
    s = WALL_SCALE
    img = Image.new("RGB", (m["width"] * s, m["height"] * s), (8, 8, 8))
    d = ImageDraw.Draw(img)
    cw, full, band = len(levels[0]), len(levels), len(levels) // m["outputs"]
    for y, row in enumerate(levels):
        for x, px in enumerate(row):
            dx, dy = arrange(x, y, cw, full, band, m.get("serpentine", False),
                             m.get("rotation", 0))
            col = tuple(perceived(v, m["planes"]) for v in px)
            d.rectangle([dx * s, dy * s, dx * s + s - 2, dy * s + s - 2], fill=col)
    pw, ph = cw // m["chain"], band		# a panel, as driven
    if m.get("rotation", 0) in (90, 270):
        pw, ph = ph, pw
    for x in range(pw, m["width"], pw):
        d.line([(x * s - 1, 0), (x * s - 1, m["height"] * s)], fill=(0, 0, 0), width=2)
    for y in range(ph, m["height"], ph):
        d.line([(0, y * s - 1), (m["width"] * s, y * s - 1)], fill=(0, 0, 0), width=2)
    return img


def terminal(levels, planes):
    """The picture in a terminal: two LEDs per character (24-bit colour)."""
    for y in range(0, len(levels), 2):
        line = ""
        for x in range(len(levels[0])):
            top = [perceived(v, planes) for v in levels[y][x]]
            bot = [perceived(v, planes) for v in levels[y + 1][x]]
            line += "\033[38;2;%d;%d;%dm\033[48;2;%d;%d;%dm\u2580" % tuple(top + bot)
        print(line + "\033[0m")


def decode_pictures(art, who="hub75_demo"):
    """Every picture of ART/hub75.json decoded from its trace and checked
    (check_picture): [(its entry, its levels or None, its checks failed)];
    each failed check printed."""
    with open(os.path.join(art, "hub75.json")) as f:
        pics = json.load(f)
    fails = []

    def check(name, cond, detail=""):
        if not cond:
            fails.append(name)
            print("%s: FAIL: %s: %s" % (who, name, detail))
        return cond

    out = []
    for m in pics:
        before = len(fails)
        levels = check_picture(art, m, check)
        check("%s decoded" % m["name"], levels is not None)
        out.append((m, levels, len(fails) - before))
    return out


def show(art, outdir):
    from PIL import Image
    res = decode_pictures(art)
    pics = [m for m, _, _ in res]
    fails = sum(n for _, _, n in res)
    decoded = {m["name"]: (levels, m["planes"]) for m, levels, _ in res if levels is not None}
    exact = sum(not n for _, _, n in res)
    if "picture" in decoded:
        terminal(*decoded["picture"])
        panel(*decoded["picture"]).save(os.path.join(outdir, "matrix-picture.png"))
    wall = [(m, decoded[m["name"]][0]) for m in pics if m["name"] == "wall" and
            m["name"] in decoded]
    if wall:
        wall_picture(*wall[0]).save(os.path.join(outdir, "matrix-wall.png"))
    scroll = [panel(*decoded[m["name"]]) for m in pics
              if m["name"].startswith("scroll-") and m["name"] in decoded]
    if scroll:
        scroll[0].save(os.path.join(outdir, "matrix-scroll.gif"), save_all=True,
                       append_images=scroll[1:], duration=120, loop=0)
        w, h = scroll[0].size
        strip = Image.new("RGB", (w, h * len(scroll)))
        for i, fr in enumerate(scroll):
            strip.paste(fr, (0, i * h))
        strip.save(os.path.join(outdir, "matrix-scroll.png"))
    print("hub75_demo: %d pictures decoded from the pins, %d of them exact to every pixel's "
          "level" % (len(pics), exact))
    if fails or len(pics) < 2:
        print("hub75_demo: the panel did not show what was drawn")
        return 1
    return 0


def main(argv):
    if len(argv) == 3 and argv[1] == "frames":
        frames(argv[2])
        return 0
    if len(argv) == 4 and argv[1] == "show":
        return show(argv[2], argv[3])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
