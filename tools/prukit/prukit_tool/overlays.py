# SPDX-License-Identifier: GPL-2.0-only
"""prukit overlays / enable / disable: prukit's device-tree overlays and
the uEnv.txt lines that make BeagleBoard's U-Boot apply them."""
import glob
import os

from . import Error, firmware_dir, fdt, pins, uenv

PREFIX = "PRUKIT-"
INSTALL_HINT = ("prukit's overlays come in the prukit-overlays package: "
                "sudo apt install ./prukit-overlays_*.deb\n"
                "(built on a PC with make deb, see README.md), or make overlays_install "
                "from a checkout")


def installed():
    """{name: path} of the PRUKIT-*.dtbo files in /lib/firmware."""
    return {os.path.basename(p)[:-5]: p
            for p in sorted(glob.glob(os.path.join(firmware_dir(), PREFIX + "*.dtbo")))}


def resolve(name):
    """An overlay's full name from NAME, PRUKIT-NAME or a unique prefix,
    any case; Error listing what there is otherwise."""
    have = installed()
    if not have:
        raise Error("no prukit overlays in %s" % firmware_dir(), INSTALL_HINT)
    want = name.upper()
    if want.endswith(".DTBO"):
        want = want[:-5]
    if not want.startswith(PREFIX):
        want = PREFIX + want
    if want in have:
        return want
    for cand in (want + "-00A0",):
        if cand in have:
            return cand
    hits = [n for n in have if n.startswith(want)]
    if len(hits) == 1:
        return hits[0]
    listing = "overlays here: " + ", ".join(have)
    if hits:
        raise Error("%s could be %s" % (name, " or ".join(hits)), listing)
    raise Error("no overlay %s in %s" % (name, firmware_dir()), listing + "\n" + INSTALL_HINT)


def info(name, path=None):
    path = path or os.path.join(firmware_dir(), name + ".dtbo")
    try:
        return fdt.OverlayInfo(name, fdt.load(path))
    except OSError as e:
        raise Error("cannot read %s: %s" % (path, e.strerror))
    except ValueError as e:
        raise Error("%s is not a usable overlay: %s" % (path, e),
                    "reinstall it: sudo apt install --reinstall prukit-overlays")


def boards_of(ov, table):
    """The boards an overlay can be used on: the PocketBeagle's (a POCKET in
    its name: made for it, or a cape of it), else each board that has a
    header pin for every pad it muxes."""
    if "POCKET" in ov.name:
        return ["pocket"]
    return [b for b in pins.BOARDS
            if all(b in getattr(table.pads.get(o), "header", {}) for o in ov.pads)]


def board_name(board):
    return "PocketBeagle" if board == "pocket" else "BeagleBone Black"


def missing_firmware(ov):
    return [f for f in ov.firmware if not os.path.exists(os.path.join(firmware_dir(), f))]


def needs_freeing(ov, env, table, board):
    """[(function, uEnv line, pads)] of board functions holding pads of OV
    whose uEnv.txt line is not in effect; cape universal included."""
    out = {}
    for off in ov.pads:
        pad = table.pads.get(off)
        if pad is None:
            continue
        for b in ([board] if board else pins.BOARDS):
            func = pad.conflict.get(b)
            if not func:
                continue
            line = table.functions.get(func, (None, ""))[0]
            if not line:
                continue
            key, val = line.split("=", 1)
            if env.value(key) != val:
                out.setdefault(func, (line, []))[1].append(table.describe(off, board))
    res = [(f, line, p) for f, (line, p) in sorted(out.items())]
    if env.value("enable_uboot_cape_universal") == "1" and ov.pads:
        res.append(("cape-universal", "enable_uboot_cape_universal=1 turned off",
                    ["every header pin"]))
    pru = env.value("uboot_overlay_pru") or ""
    if "UIO" in pru.upper():
        res.append(("pru-uio", "uboot_overlay_pru=%s turned off" % pru,
                    ["the PRU-ICSS (uio_pruss takes it from the kernel's PRU drivers)"]))
    return res


def conflicts(ov, others, table, board):
    """[(other name, why)] for enabled overlays sharing a PRU core or a pad."""
    out = []
    for other in others:
        why = []
        cores = sorted(set(ov.prus) & set(other.prus))
        if cores:
            why.append("both use " + " and ".join(c.upper() for c in cores))
        shared = sorted(set(ov.pads) & set(other.pads))
        if shared:
            why.append("both mux " + ", ".join(table.describe(o, board) for o in shared[:6]) +
                       (" and %d more" % (len(shared) - 6) if len(shared) > 6 else ""))
        if why:
            out.append((other.name, "; ".join(why)))
    return out


def cmd_list(args):
    have = installed()
    if not have:
        raise Error("no prukit overlays in %s" % firmware_dir(), INSTALL_HINT)
    try:
        enabled = set(uenv.UEnv().enabled_names())
    except Error:
        enabled = set()
    table = pins.PinTable()
    board, _ = pins.running_board()
    for name, path in have.items():
        ov = info(name, path)
        fits = boards_of(ov, table)
        b = board if board in fits else fits[0] if fits else None
        pads = ", ".join(table.describe(o, b) for o in sorted(ov.pads)[:4])
        if len(ov.pads) > 4:
            pads += " and %d more" % (len(ov.pads) - 4)
        print("%s %-36s %s, %s%s" % ("*" if name in enabled else " ", name,
                                     "+".join(p.upper() for p in ov.prus) or "no PRU",
                                     ("pins " + pads) if ov.pads else "no pins",
                                     "" if not board or board in fits else " (for the %s)" %
                                     " and ".join(board_name(f) for f in fits)))
    print("(* enabled in %s)" % uenv.path())
    return 0


def cmd_enable(args):
    uenv.UEnv(args.uenv).require_writable()
    name = resolve(args.overlay)
    ov = info(name)
    table = pins.PinTable()
    board, model = pins.running_board()
    fits = boards_of(ov, table)
    if board and board not in fits:
        alt = [n for n in installed() if n.split("-")[1] == name.split("-")[1] and
               board in boards_of(info(n), table)]
        raise Error("%s is made for the %s, and this is a %s" %
                    (name, " and ".join(board_name(f) for f in fits) or "no board", model),
                    ("use %s instead" % alt[0]) if alt else
                    "its pins are not on this board's headers")
    target = board or (fits[0] if fits else "black")
    lost = missing_firmware(ov)
    if lost:
        raise Error("%s loads %s, missing from %s" % (name, ", ".join(lost), firmware_dir()),
                    "install the PRU firmware: sudo apt install ./prukit-firmware_*.deb")
    env = uenv.UEnv(args.uenv)
    if name in env.enabled_names():
        print("%s is already enabled in %s" % (name, env.file))
        return 0
    others = []
    for other in env.enabled_names():
        path = os.path.join(firmware_dir(), other + ".dtbo")
        if os.path.exists(path):
            others.append(info(other, path))
    clash = conflicts(ov, others, table, board or target)
    if clash:
        raise Error("%s conflicts with %s enabled in %s" %
                    (name, ", ".join(o for o, _ in clash), env.file),
                    "\n".join("%s: %s" % c for c in clash) +
                    "\ndisable it first: sudo prukit disable " + clash[0][0])
    free = needs_freeing(ov, env, table, board or target)
    if free and not args.free_pins:
        raise Error("%s needs pins that %s hold%s" %
                    (name, ", ".join(f for f, _, _ in free), "" if len(free) > 1 else "s"),
                    "\n".join("%s: %s -> %s" % (f, ", ".join(p), line) for f, line, p in free) +
                    "\nrun it again with --free-pins to let prukit change those lines "
                    "too (prukit disable undoes it)")
    for func, line, _ in free:
        if func == "cape-universal":
            env.turn_off("pins", "enable_uboot_cape_universal")
        elif func == "pru-uio":
            env.turn_off("pins", "uboot_overlay_pru")
        else:
            key, val = line.split("=", 1)
            env.set_line("pins", key, val)
    slot = env.add_overlay(name, os.path.join(firmware_dir(), name + ".dtbo"))
    env.save()
    print("%s enabled: uboot_overlay_addr%d in %s (the old file is %s.prukit-bak)" %
          (name, slot, env.file, env.file))
    for func, line, _ in free:
        print("  and for its pins (%s): %s" % (func, line))
    print("Reboot to apply it: sudo reboot")
    return 0


def cmd_disable(args):
    env = uenv.UEnv(args.uenv)
    env.require_writable()
    changed = 0
    if args.all:
        for tag in env.tags():
            changed += env.remove(tag)
        names = [n for n in env.enabled_names() if n.startswith(PREFIX)]
    else:
        if not args.overlay:
            raise Error("name the overlay to disable, or --all")
        name = args.overlay.upper()
        name = name if name.startswith(PREFIX) else PREFIX + name
        cands = [n for n in env.enabled_names() if n == name or n.startswith(name)]
        if len(cands) != 1:
            enabled = [n for n in env.enabled_names() if n.startswith(PREFIX)]
            raise Error("%s is not enabled in %s" % (args.overlay, env.file),
                        "enabled there: " + (", ".join(enabled) or "no prukit overlay"))
        name = cands[0]
        changed += env.remove(name)
        names = [name]
    # lines a user wrote for prukit overlays: commented out, not deleted
    for i, line in enumerate(list(env.lines)):
        m = uenv.SLOT_RE.match(line)
        if m and os.path.basename(m.group(2).strip())[:-5] in names:
            env.comment_out(i)
            changed += 1
    if not [n for n in env.enabled_names() if n.startswith(PREFIX)]:
        changed += env.remove("pins")
    if not changed:
        print("nothing to change in %s" % env.file)
        return 0
    env.save()
    print("disabled %s in %s (the old file is %s.prukit-bak); reboot to apply it" %
          (", ".join(names) or "prukit's changes", env.file, env.file))
    return 0


def register(sub):
    p = sub.add_parser("overlays", help="list prukit's overlays and what each takes")
    p.set_defaults(func=cmd_list)
    p = sub.add_parser("enable", help="enable an overlay in /boot/uEnv.txt",
                       description="Add an uboot_overlay_addrN line for a prukit overlay to "
                       "/boot/uEnv.txt (a backup is kept), after checking that its firmware "
                       "is installed and that no enabled overlay uses its PRU cores or pins.")
    p.add_argument("overlay", help="PRUKIT-WS281X-00A0, or WS281X, ws281x ...")
    p.add_argument("--free-pins", action="store_true",
                   help="also turn off what holds its pins or the PRUs (HDMI video/audio, "
                   "eMMC, cape universal, the PRU UIO overlay), with marked lines "
                   "prukit disable undoes")
    p.add_argument("--uenv", metavar="FILE", help="the file to edit (default %s)" % uenv.DEFAULT)
    p.set_defaults(func=cmd_enable)
    p = sub.add_parser("disable", help="disable an overlay in /boot/uEnv.txt")
    p.add_argument("overlay", nargs="?")
    p.add_argument("--all", action="store_true",
                   help="undo every change prukit made to the file, and disable every "
                   "prukit overlay")
    p.add_argument("--uenv", metavar="FILE", help="the file to edit (default %s)" % uenv.DEFAULT)
    p.set_defaults(func=cmd_disable)
