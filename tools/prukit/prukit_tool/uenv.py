# SPDX-License-Identifier: GPL-2.0-only
"""BeagleBoard's /boot/uEnv.txt, as prukit enable and disable edit it.

U-Boot imports the file as NAME=VALUE lines ("env import -t"); a line
starting with '#' is a comment, and everything after '=' is the value, a
'#' included, so nothing may follow a value on its line.  prukit marks
what it changes with comment lines of its own, which also lets the
prukit-overlays package undo them when it is removed (its postrm, with
sed, in case this command is gone by then):

  #prukit: TAG                  the next line was added by prukit for TAG
  #prukit-off: TAG: LINE        LINE was in effect; prukit turned it off

TAG is an overlay's name (PRUKIT-WS281X-00A0) for its
uboot_overlay_addrN line, or "pins" for what frees pins for prukit's
overlays (disable_uboot_overlay_video=1, cape universal off), kept while
any prukit overlay is enabled.
"""
import os
import re

from . import Error

DEFAULT = "/boot/uEnv.txt"
MARK = "#prukit: "
OFF = "#prukit-off: "
# The slots BeagleBoard's uEnv.txt leaves for "additional custom capes"
# first, then the rest.
SLOTS = (4, 5, 6, 7, 0, 1, 2, 3)
SLOT_RE = re.compile(r"^uboot_overlay_addr([0-7])=(.*)$")


def path():
    return os.environ.get("PRUKIT_UENV", DEFAULT)


class UEnv:
    def __init__(self, file=None):
        self.file = file or path()
        try:
            with open(self.file) as f:
                self.lines = f.read().splitlines()
        except FileNotFoundError:
            raise Error("%s does not exist" % self.file,
                        "prukit enable edits BeagleBoard's U-Boot settings in /boot/uEnv.txt; "
                        "images without it (another bootloader setup)\n"
                        "load overlays their own way: see Documentation/overlays.rst")
        except OSError as e:
            raise Error("cannot read %s: %s" % (self.file, e.strerror))

    def require_writable(self):
        """Error, before any other check, if this user cannot change the file."""
        d = os.path.dirname(os.path.abspath(self.file))
        if not (os.access(self.file, os.W_OK) and os.access(d, os.W_OK)):
            raise Error("no permission to change %s" % self.file,
                        "run it as root: sudo prukit ...")

    # ---- reading

    def value(self, name):
        """The value of NAME where a line sets it, else None."""
        for line in self.lines:
            if line.startswith(name + "="):
                return line[len(name) + 1:]
        return None

    def overlays(self):
        """[(slot, path, tag or None)] of the uboot_overlay_addrN lines in effect;
        tag: the prukit marker's, for lines prukit added."""
        out = []
        for i, line in enumerate(self.lines):
            m = SLOT_RE.match(line)
            if m:
                tag = None
                if i > 0 and self.lines[i - 1].startswith(MARK):
                    tag = self.lines[i - 1][len(MARK):].strip()
                out.append((int(m.group(1)), m.group(2).strip(), tag))
        return out

    def enabled_names(self):
        """Names (file name without .dtbo) of the overlays in effect."""
        return [os.path.basename(p)[:-5] if p.endswith(".dtbo") else os.path.basename(p)
                for _, p, _ in self.overlays()]

    # ---- changing

    def add_overlay(self, name, dtbo):
        """A uboot_overlay_addrN line for DTBO, marked with NAME; the slot."""
        used = {slot for slot, _, _ in self.overlays()}
        free = [s for s in SLOTS if s not in used]
        if not free:
            raise Error("all eight uboot_overlay_addr0-7 slots of %s are in use" % self.file,
                        "disable an overlay first (prukit disable NAME, or comment out its line)")
        slot = free[0]
        self._append(name, "uboot_overlay_addr%d=%s" % (slot, dtbo))
        return slot

    def _append(self, tag, line):
        # after the last uboot_overlay line (in effect or commented), else at the end
        at = len(self.lines)
        for i, cur in enumerate(self.lines):
            if re.match(r"^#?\s*uboot_overlay_addr[0-7]=", cur) or cur.startswith(MARK):
                at = i + 1
        if at < len(self.lines) and self.lines[at - 1].startswith(MARK):
            at += 1
        self.lines[at:at] = [MARK + tag, line]

    def set_line(self, tag, name, value):
        """NAME=VALUE in effect, marked TAG; a line setting NAME otherwise
        is turned off (marked, so that it comes back).  True if changed."""
        want = "%s=%s" % (name, value)
        if want in self.lines:
            return False
        for i, line in enumerate(self.lines):
            if line.startswith(name + "="):
                self.lines[i] = "%s%s: %s" % (OFF, tag, line)
        self._append(tag, want)
        return True

    def turn_off(self, tag, name):
        """Every line setting NAME turned off, marked TAG.  True if changed."""
        changed = False
        for i, line in enumerate(self.lines):
            if line.startswith(name + "="):
                self.lines[i] = "%s%s: %s" % (OFF, tag, line)
                changed = True
        return changed

    def remove(self, tag):
        """Undo what prukit did for TAG: its lines go, the lines it turned
        off come back.  The number of lines changed."""
        out, n, i = [], 0, 0
        while i < len(self.lines):
            line = self.lines[i]
            if line == MARK + tag:
                i += 2
                n += 1
                continue
            if line.startswith("%s%s: " % (OFF, tag)):
                out.append(line[len(OFF) + len(tag) + 2:])
                n += 1
            else:
                out.append(line)
            i += 1
        self.lines = out
        return n

    def tags(self):
        return sorted({line[len(MARK):].strip() for line in self.lines if line.startswith(MARK)} |
                      {line[len(OFF):].split(":", 1)[0] for line in self.lines
                       if line.startswith(OFF)})

    def comment_out(self, index):
        self.lines[index] = "#" + self.lines[index]

    def save(self):
        """Write the file through a temporary one, the old one kept as
        FILE.prukit-bak.  Errors say what to do."""
        text = "\n".join(self.lines) + "\n"
        tmp = self.file + ".prukit-tmp"
        try:
            with open(self.file, "rb") as f:
                old = f.read()
            with open(self.file + ".prukit-bak", "wb") as f:
                f.write(old)
            with open(tmp, "w") as f:
                f.write(text)
                f.flush()
                os.fsync(f.fileno())
            os.chmod(tmp, os.stat(self.file).st_mode & 0o7777)
            os.replace(tmp, self.file)
        except PermissionError:
            raise Error("no permission to change %s" % self.file,
                        "run it as root: sudo prukit ...")
        except OSError as e:
            try:
                os.unlink(tmp)
            except OSError:
                pass
            raise Error("cannot write %s: %s (it is unchanged)" % (self.file, e.strerror))
