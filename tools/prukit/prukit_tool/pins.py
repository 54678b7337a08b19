# SPDX-License-Identifier: GPL-2.0-only
"""prukit's AM335x pin table (sim/am335x-pins.tsv, installed in
/usr/share/prukit): which header pin each pad is on, and which board
function holds it, with the uEnv.txt line that frees it."""
from . import Error, data_file, dt, read

BOARDS = ("black", "pocket")


class Pad:
    def __init__(self, name, offset):
        self.name = name            # AM335X_PIN_MCASP0_FSX
        self.offset = offset        # 0x994
        self.header = {}            # board -> "P9_29" / "P1.33"
        self.conflict = {}          # board -> board function name
        self.signals = {}           # mode -> "pru0_r30_1"

    @property
    def short(self):
        return self.name.replace("AM335X_PIN_", "").lower()


class PinTable:
    def __init__(self, path=None):
        path = path or data_file("am335x-pins.tsv")
        self.pads = {}
        self.functions = {}         # name -> (uEnv line or None, description)
        try:
            f = open(path)
        except OSError as e:
            raise Error("cannot read prukit's pin table %s: %s" % (path, e.strerror),
                        "reinstall prukit-tools (sudo apt install --reinstall prukit-tools)")
        with f:
            for line in f:
                line = line.rstrip("\n")
                if line.startswith("# conflict: "):
                    name, uenv, desc = (line[len("# conflict: "):].split("\t") + ["", ""])[:3]
                    self.functions[name] = (None if uenv == "-" else uenv, desc)
                    continue
                if not line.strip() or line.startswith("#"):
                    continue
                f8 = line.split("\t")
                if len(f8) != 8:
                    continue
                off = int(f8[1], 16)
                pad = self.pads.setdefault(off, Pad(f8[0], off))
                for board, hdr, conf in (("black", f8[2], f8[6]), ("pocket", f8[3], f8[7])):
                    if hdr != "-":
                        pad.header[board] = hdr
                    if conf != "-":
                        pad.conflict[board] = conf
                pad.signals[int(f8[4])] = f8[5]

    def describe(self, offset, board):
        """'P9_29 (mcasp0_fsx)' for a pad, on one board or both."""
        pad = self.pads.get(offset)
        if pad is None:
            return "pad 0x%03x" % offset
        if board in pad.header:
            return "%s (%s)" % (pad.header[board], pad.short)
        hdrs = "/".join(pad.header[b] for b in BOARDS if b in pad.header)
        return "%s (%s)" % (hdrs or "no header pin", pad.short)


def board_of_model(model):
    """'black' or 'pocket' from /proc/device-tree/model's text, else None."""
    m = (model or "").lower()
    if "pocketbeagle" in m:
        return "pocket"
    if "beaglebone" in m or "am335x" in m:
        return "black"
    return None


def running_board():
    model = read(dt("model"), "")
    return board_of_model(model.rstrip("\0")), model.rstrip("\0")
