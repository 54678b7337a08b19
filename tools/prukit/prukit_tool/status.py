# SPDX-License-Identifier: GPL-2.0-only
"""prukit status: the PRU cores, prukit's devices, the overlays, and the
pins prukit's overlays need that something else holds."""
import glob
import grp
import os
import re
import stat

from . import Error, dt, firmware_dir, pins, read, sysfs, uenv
from . import overlays as ovl

# The driver module of each prukit compatible, for the hints.
MODULE = {"prukit,ws281x": "ws281x", "prukit,beaglelogic": "beaglelogic",
          "prukit,hub75": "hub75"}
# remoteproc device names end in the core's offset in the PRU-ICSS.
CORE = {"34000.pru": "pru0", "38000.pru": "pru1"}


def core_name(devname):
    for suffix, core in CORE.items():
        if devname.endswith(suffix):
            return core
    return None


def phandle_of(path):
    v = _raw(os.path.join(path, "of_node", "phandle"))
    return int.from_bytes(v[:4], "big") if v and len(v) >= 4 else None


def _raw(path):
    try:
        with open(path, "rb") as f:
            return f.read()
    except OSError:
        return None


def prukit_devices():
    """[(platform device name, sysfs path, compatible)] of prukit's nodes."""
    out = []
    for d in sorted(glob.glob(sysfs("bus", "platform", "devices", "*"))):
        comp = _raw(os.path.join(d, "of_node", "compatible"))
        if comp and comp.startswith(b"prukit,"):
            out.append((os.path.basename(d), d, comp.split(b"\0")[0].decode()))
    return out


def driver_of(path):
    link = os.path.join(path, "driver")
    return os.path.basename(os.path.realpath(link)) if os.path.islink(link) else None


def nodes_of(path):
    """The /dev nodes whose sysfs device is PATH (ws281x, drm, graphics)."""
    real = os.path.realpath(path)
    out = []
    for cls in ("ws281x", "drm", "graphics", "misc"):
        for d in sorted(glob.glob(sysfs("class", cls, "*"))):
            dev = os.path.join(d, "device")
            if os.path.exists(dev) and os.path.realpath(dev) == real:
                name = os.path.basename(d)
                out.append("/dev/dri/" + name if cls == "drm" else "/dev/" + name)
    return [n for n in out if not re.match(r"/dev/dri/card\d+-", n)]


def access_note(node):
    """'' when the user can open NODE read-write, else why not."""
    try:
        st = os.stat(node)
    except OSError:
        return " (no %s: is udev running?)" % node
    if os.access(node, os.R_OK | os.W_OK):
        return ""
    try:
        group = grp.getgrgid(st.st_gid).gr_name
    except KeyError:
        group = str(st.st_gid)
    if st.st_mode & stat.S_IRWXG and group != "root":
        return " (not yours: sudo adduser $USER %s, then log in again)" % group
    return " (root only: are prukit's udev rules installed? prukit-tools)"


def pinmux_owners():
    """{pad offset: owner} from pinctrl's debugfs, or None if unreadable
    (root and a mounted debugfs are needed)."""
    files = glob.glob(sysfs("kernel", "debug", "pinctrl", "*pinmux*", "pinmux-pins"))
    if not files:
        return None
    owners = {}
    try:
        with open(files[0]) as f:
            for line in f:
                m = re.match(r"pin (\d+) \([^)]*\): (\S+)(?: (\S+))?", line)
                if not m:
                    continue
                # "pin 101 (PIN101): 4a334000.pru (GPIO UNCLAIMED) function ..."
                # or, on a strict controller, "pin 101 (PIN101): device 4a334000.pru"
                owner = m.group(3) if m.group(2) == "device" else m.group(2)
                if owner in (None, "UNCLAIMED", "(MUX"):
                    continue
                owners[0x800 + 4 * int(m.group(1))] = owner
    except OSError:
        return None
    return owners


def section(title):
    print("\n" + title)


def cmd_status(args):
    board, model = pins.running_board()
    print("prukit status on %s, Linux %s" % (model or "an unknown board", os.uname().release))
    if not board:
        print("  (not a BeagleBone or PocketBeagle model: pins are named for both)")

    # ---- PRU cores
    section("PRU cores:")
    holders = {}
    devs = prukit_devices()
    for name, path, comp in devs:
        # a bound driver holds the cores its node names (the others failed
        # to bind: a core is taken by one consumer at a time)
        if not driver_of(path):
            continue
        for ph in _cells(os.path.join(path, "of_node", "ti,prus")):
            holders.setdefault(ph, []).append("%s (%s)" % (name, comp))
    cores = 0
    by_phandle = {}
    for r in sorted(glob.glob(sysfs("class", "remoteproc", "remoteproc*"))):
        devname = read(os.path.join(r, "name"), "?")
        core = core_name(devname)
        if core is None:
            continue
        cores += 1
        dev = os.path.join(r, "device")
        held = ", ".join(holders.get(phandle_of(dev), []))
        by_phandle[phandle_of(dev)] = (core, r, held)
        fw = read(os.path.join(r, "firmware"), "?")
        state = read(os.path.join(r, "state"), "?")
        print("  %s  %-16s %-8s firmware %s, driver %s%s" %
              (core.upper(), devname, state, fw, driver_of(dev) or "none",
               (", held by " + held) if held else ""))
        if not os.path.exists(os.path.join(firmware_dir(), fw)) and state != "running":
            print("        %s is not in %s: install prukit-firmware" % (fw, firmware_dir()))
    if not cores:
        print("  none: the PRU-ICSS is not enabled, or the kernel has no PRU remoteproc "
              "driver (pru_rproc).")
        print("  Debian's own armmp kernels have none: use BeagleBoard's kernel "
              "(see README.md); else enable an overlay (prukit enable ...) and reboot.")

    # ---- devices
    section("prukit devices:")
    if not devs:
        print("  none in the device tree (no prukit overlay with a driver node applied)")
    for name, path, comp in devs:
        drv = driver_of(path)
        if not drv:
            mod = MODULE.get(comp)
            why = ""
            if mod and not os.path.isdir(sysfs("module", mod)):
                why = ": module %s not loaded: sudo modprobe %s" % (mod, mod)
            elif mod:
                why = ": %s is loaded but did not bind (dmesg | grep %s)" % (mod, mod)
                for ph in _cells(os.path.join(path, "of_node", "ti,prus")):
                    core, r, held = by_phandle.get(ph, (None, None, ""))
                    if core and not held and read(os.path.join(r, "state")) != "offline":
                        why += ("; %s runs %s for someone else: stop it (echo stop | sudo tee "
                                "%s/state) and bind again (sudo modprobe -r %s; sudo modprobe "
                                "%s)" % (core.upper(), read(os.path.join(r, "firmware"), "?"),
                                         r.replace(sysfs(), "/sys", 1), mod, mod))
                    elif core and held:
                        why += "; %s is held by %s" % (core.upper(), held)
            print("  %-14s %s: no driver bound%s" % (comp, name, why))
            continue
        nodes = nodes_of(path)
        if comp == "prukit,beaglelogic" and os.path.exists("/dev/beaglelogic"):
            nodes.append("/dev/beaglelogic")
        print("  %-14s %s, driver %s: %s" %
              (comp, name, drv, ", ".join(n + access_note(n) for n in nodes) or
               "no device node (dmesg)"))
    rp = sorted(glob.glob(sysfs("class", "rpmsg_pru", "rpmsg_pru*")))
    for d in rp:
        n = "/dev/" + os.path.basename(d)
        print("  %-14s %s%s" % ("rpmsg_pru", n, access_note(n)))
    # TI's kernels have an rpmsg_pru of their own, of the same name: if it
    # loaded before prukit's was installed (or depmod ran), it stays
    if os.path.isdir(sysfs("module", "rpmsg_pru")) and \
       not os.path.exists(sysfs("module", "rpmsg_pru", "parameters", "rx_queue_len")):
        print("  %-14s the loaded rpmsg_pru is the kernel's (TI's), not prukit's: one opener "
              "at a time, no counters.  Use prukit's: sudo rmmod rpmsg_pru && sudo modprobe "
              "rpmsg_pru (if modinfo -n rpmsg_pru is not under updates/, sudo depmod -a "
              "first)" % "rpmsg_pru")

    # ---- overlays
    section("Overlays:")
    env = None
    try:
        env = uenv.UEnv()
    except Error as e:
        print("  %s" % e)
    if env:
        ours = [(s, p, t) for s, p, t in env.overlays()]
        if not ours:
            print("  none enabled in %s (prukit overlays lists them; prukit enable NAME)" %
                  env.file)
        for slot, p, tag in ours:
            note = "" if os.path.exists(p) else "  MISSING: U-Boot cannot load it"
            print("  uboot_overlay_addr%d=%s%s%s" % (slot, p, " (prukit enable)" if tag else "",
                                                    note))
        if env.value("enable_uboot_cape_universal") == "1":
            print("  enable_uboot_cape_universal=1: cape universal's pinmux helpers claim "
                  "the header pins prukit's overlays need (prukit enable --free-pins turns "
                  "it off)")
    applied = sorted(os.listdir(dt("chosen", "overlays"))) \
        if os.path.isdir(dt("chosen", "overlays")) else []
    applied = [a for a in applied if a != "name"]
    if applied:
        print("  applied by U-Boot at this boot: " + ", ".join(applied))

    # ---- pins
    section("Pins prukit's enabled overlays need:")
    table = pins.PinTable()
    want = {}
    for name in (env.enabled_names() if env else []):
        path = os.path.join(firmware_dir(), name + ".dtbo")
        if name.startswith(ovl.PREFIX) and os.path.exists(path):
            for off in ovl.info(name, path).pads:
                want.setdefault(off, []).append(name)
    if not want:
        print("  none (no prukit overlay with pins enabled)")
        return 0
    owners = pinmux_owners()
    if owners is None:
        print("  who holds them needs root and debugfs: sudo prukit status")
        return 0
    bad = 0
    for off in sorted(want):
        owner = owners.get(off)
        if owner is None or re.search(r"(^|\.)pru|pruss", owner):
            continue
        bad += 1
        pad = table.pads.get(off)
        func = pad.conflict.get(board or "black") if pad else None
        line = table.functions.get(func, (None, ""))[0] if func else None
        if owner.endswith("_pinmux"):
            fix = "cape universal: set enable_uboot_cape_universal=0 (prukit enable --free-pins)"
        elif line:
            fix = "%s: %s in %s" % (func, line, uenv.path())
        else:
            fix = "find what %s is in dmesg and the device tree" % owner
        print("  %s for %s: held by %s; free it: %s" %
              (table.describe(off, board), ", ".join(want[off]), owner, fix))
    if not bad:
        print("  all %d are free or the PRUs' own" % len(want))
    return 0


def _cells(path):
    v = _raw(path)
    return [int.from_bytes(v[i:i + 4], "big") for i in range(0, len(v) - 3, 4)] if v else []


def register(sub):
    p = sub.add_parser("status", help="PRU cores, prukit devices, overlays, pins",
                       description="What runs on the PRUs, which prukit devices exist and "
                       "who may use them, which overlays are enabled, and pins they need "
                       "that another owner holds (that part needs root).")
    p.set_defaults(func=cmd_status)
