#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""make demo's pixeld part, host side (scripts/demo.sh): the panel frames
prukit-pixeld wrote from E1.31 in the guest (tests/vm/demo/pixels), each
decoded from the simulated pins by tools/hub75-decode.py and compared with
what was sent, pixel by pixel (drivers/hub75/tests/hub75_pictures.py),
then drawn as the panel would look: OUTDIR/pixeld-panel.gif and
pixeld-panel.png (the frames side by side), and the first in the terminal.
Exits 1 unless every pixel of every frame is exact.

usage: pixeld_demo.py ARTIFACTS OUTDIR   (ARTIFACTS: the guest's /out/pixeld)"""
import os
import sys

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../../drivers/hub75/tests"))
from hub75_demo import decode_pictures, panel, terminal  # noqa: E402


def main(art, outdir):
    from PIL import Image
    res = decode_pictures(art, "pixeld_demo")
    fails = sum(n for _, _, n in res)
    shown = []
    for m, levels, _ in res:
        if levels is not None:
            shown.append(panel(levels, m["planes"]))
            if len(shown) == 1:
                terminal(levels, m["planes"])
    if shown:
        shown[0].save(os.path.join(outdir, "pixeld-panel.gif"), save_all=True,
                      append_images=shown[1:], duration=150, loop=0)
        w, h = shown[0].size
        cols = 4
        rows = (len(shown) + cols - 1) // cols
        sheet = Image.new("RGB", (cols * w + (cols - 1) * 8, rows * h + (rows - 1) * 8))
        for i, img in enumerate(shown):
            sheet.paste(img, ((i % cols) * (w + 8), (i // cols) * (h + 8)))
        sheet.save(os.path.join(outdir, "pixeld-panel.png"))
    print("pixeld_demo: %d panel frames sent over E1.31 decoded from the pins, %s" % (
        len(res), "every pixel exact" if not fails and len(shown) == len(res) else
        "%d checks failed" % fails))
    return 1 if fails or not res or len(shown) != len(res) else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
