#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-only
"""The prukit command on the host: enable/disable against BeagleBoard's
default /boot/uEnv.txt, the prukit-overlays postrm's clean-up of the same
file, and status over a fake sysfs and device tree (pins held by cape
universal's helpers).  The overlays are the built ones (out/overlays);
the firmware directory is a temporary one.  PASS:/FAIL: lines; make
check's "tool" step.  The same command runs in the VM against the real
drivers (tests/vm/cases/90-prukit-status)."""
import os
import shutil
import subprocess
import sys
import tempfile

TOP = os.path.realpath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOOL = os.path.join(TOP, "tools", "prukit", "prukit")
FIXTURE = os.path.join(TOP, "tests", "tool", "uEnv-beagleboard.txt")
POSTRM = os.path.join(TOP, "packaging", "debian", "prukit-overlays.postrm")
failed = 0


def check(ok, what, detail=""):
    global failed
    print("%s: tool: %s" % ("PASS" if ok else "FAIL", what))
    if not ok:
        failed = 1
        for line in str(detail).splitlines()[:15]:
            print("    " + line)


def run(*args, env=None):
    e = dict(os.environ, **BASE_ENV)
    e.update(env or {})
    p = subprocess.run([TOOL] + list(args), capture_output=True, text=True, env=e)
    return p.returncode, p.stdout, p.stderr


def text(path):
    with open(path) as f:
        return f.read()


# the overlays as make overlays builds them (no kernel source needed)
subprocess.run(["make", "-s", "-C", TOP, "overlays"], check=True, stdout=subprocess.DEVNULL,
               stderr=subprocess.DEVNULL)
tmp = tempfile.mkdtemp()
fw = os.path.join(tmp, "firmware")
os.makedirs(os.path.join(fw, "prukit"))
for f in os.listdir(os.path.join(TOP, "out", "overlays")):
    if f.endswith(".dtbo"):
        shutil.copy(os.path.join(TOP, "out", "overlays", f), fw)
for f in ("ws281x-pru0.elf", "ws281x-pru1.elf", "hub75-pru0.elf", "hub75-pru1.elf",
          "rpmsg-neopixel-pru0.elf", "rpmsg-echo-pru1.elf", "beaglelogic-pru0.elf",
          "beaglelogic-pru1.elf"):
    open(os.path.join(fw, "prukit", f), "w").close()
dtdir = os.path.join(tmp, "dt")
os.makedirs(dtdir)
with open(os.path.join(dtdir, "model"), "w") as f:
    f.write("TI AM335x BeagleBone Black\0")
uenv = os.path.join(tmp, "uEnv.txt")
shutil.copy(FIXTURE, uenv)
orig = text(FIXTURE)
BASE_ENV = {"PRUKIT_FIRMWARE_DIR": fw, "PRUKIT_DT": dtdir, "PRUKIT_UENV": uenv,
            "PRUKIT_SYSFS": os.path.join(tmp, "sys")}

# ---- enable, refused until the pins are freed
rc, out, err = run("enable", "ws281x")
check(rc == 1 and "hdmi-audio" in err and "disable_uboot_overlay_audio=1" in err and
      "cape-universal" in err and "--free-pins" in err and text(uenv) == orig,
      "enable ws281x on a Black with HDMI audio and cape universal on: refused, names "
      "disable_uboot_overlay_audio=1 and --free-pins, file unchanged", err)

rc, out, err = run("enable", "ws281x", "--free-pins")
u = text(uenv).splitlines()
check(rc == 0 and "uboot_overlay_addr4=%s/PRUKIT-WS281X-00A0.dtbo" % fw in u and
      u[u.index("uboot_overlay_addr4=%s/PRUKIT-WS281X-00A0.dtbo" % fw) - 1] ==
      "#prukit: PRUKIT-WS281X-00A0" and
      "disable_uboot_overlay_audio=1" in u and
      "#prukit-off: pins: enable_uboot_cape_universal=1" in u and
      "enable_uboot_cape_universal=1" not in u,
      "enable ws281x --free-pins: addr4 marked with its name, HDMI audio off, cape "
      "universal turned off (marked)", out + err + "\n".join(u))
check(text(uenv + ".prukit-bak") == orig, "enable keeps the file before as uEnv.txt.prukit-bak")
check(all(len(line) == len(line.rstrip()) and "#" not in line.split("=", 1)[-1]
          for line in u if "=" in line and not line.startswith("#")),
      "no value prukit wrote carries a comment (U-Boot would take it as part of the value)")

rc, out, err = run("enable", "PRUKIT-WS281X-00A0")
check(rc == 0 and "already enabled" in out, "enable of an enabled overlay: says so, exit 0", err)

before = text(uenv)
rc, out, err = run("enable", "rpmsg-neopixel", "--free-pins")
check(rc == 1 and "PRUKIT-WS281X-00A0" in err and "PRU0" in err and "P9_29" in err and
      "prukit disable PRUKIT-WS281X-00A0" in err and text(uenv) == before,
      "enable rpmsg-neopixel beside ws281x: refused (both use PRU0, both mux P9_29), "
      "file unchanged", err)

rc, out, err = run("enable", "HUB75-00A0")
check(rc == 1 and "hdmi-video" in err and "emmc" in err and text(uenv) == before,
      "enable hub75 with HDMI video and eMMC on: refused, names both", err)
rc, out, err = run("enable", "HUB75-00A0", "--free-pins")
u = text(uenv).splitlines()
check(rc == 0 and "uboot_overlay_addr5=%s/PRUKIT-HUB75-00A0.dtbo" % fw in u and
      "disable_uboot_overlay_video=1" in u and "disable_uboot_overlay_emmc=1" in u,
      "enable hub75 --free-pins beside ws281x (PRU1, other pins): addr5, video and eMMC off",
      out + err)

rc, out, err = run("enable", "PRUKIT-BEAGLELOGIC-POCKET")
check(rc == 1 and "PocketBeagle" in err and "PRUKIT-BEAGLELOGIC-00A0" in err,
      "enable of a PocketBeagle overlay on a Black: refused, names the Black's", err)
rc, out, err = run("enable", "nosuch")
check(rc == 1 and "no overlay nosuch" in err and "PRUKIT-WS281X-00A0" in err and
      "prukit-overlays" in err, "enable of an unknown overlay: lists the installed ones", err)
rc, out, err = run("enable", "ws281x")
check(rc == 0 and "already" in out, "ws281x resolves to PRUKIT-WS281X-00A0, not -48", out + err)

# the Octoscroller cape: 8 HUB75 outputs, every line a GPIO, PRU0
before = text(uenv)
rc, out, err = run("enable", "hub75-octoscroller", "--free-pins")
check(rc == 1 and "PRUKIT-WS281X-00A0: both use PRU0; both mux P9_29" in err and
      "PRUKIT-HUB75-00A0: both mux P8_" in err and text(uenv) == before,
      "enable hub75-octoscroller beside ws281x and hub75: refused (PRU0 and P9_29, the LCD "
      "pads), file unchanged", err)
octo = os.path.join(tmp, "uEnv-octo.txt")
shutil.copy(FIXTURE, octo)
rc, out, err = run("enable", "hub75-octo", env={"PRUKIT_UENV": octo})
check(rc == 1 and "PRUKIT-HUB75-OCTOSCROLLER-00A0 needs pins" in err and
      "hdmi-video" in err and "disable_uboot_overlay_video=1" in err and
      "hdmi-audio" in err and "disable_uboot_overlay_audio=1" in err and
      "emmc" not in err and "cape-universal" in err and text(octo) == orig,
      "enable hub75-octo (a unique prefix) with HDMI and cape universal on: refused, names "
      "HDMI video and audio, not the eMMC, file unchanged", err)
rc, out, err = run("enable", "hub75-octoscroller", "--free-pins", env={"PRUKIT_UENV": octo})
u = text(octo).splitlines()
line = "uboot_overlay_addr4=%s/PRUKIT-HUB75-OCTOSCROLLER-00A0.dtbo" % fw
check(rc == 0 and line in u and u[u.index(line) - 1] == "#prukit: PRUKIT-HUB75-OCTOSCROLLER-00A0"
      and "disable_uboot_overlay_video=1" in u and "disable_uboot_overlay_audio=1" in u and
      "disable_uboot_overlay_emmc=1" not in u and "enable_uboot_cape_universal=1" not in u,
      "enable hub75-octoscroller --free-pins: addr4, HDMI video and audio off, cape universal "
      "turned off, the eMMC kept", out + err + "\n".join(u))
rc, out, err = run("overlays", env={"PRUKIT_UENV": octo})
mine = [ln for ln in out.splitlines() if "PRUKIT-HUB75-OCTOSCROLLER-00A0" in ln]
check(rc == 0 and len(mine) == 1 and mine[0].startswith("*") and "PRU0, pins " in mine[0] and
      "and 53 more" in mine[0] and "(for the" not in mine[0],
      "overlays: hub75-octoscroller enabled, on PRU0, 57 pads", out + err)
rc, out, err = run("disable", "hub75-octoscroller", env={"PRUKIT_UENV": octo})
check(rc == 0 and text(octo) == orig,
      "disable hub75-octoscroller: the file is byte for byte BeagleBoard's again", out + err)

with open(os.path.join(dtdir, "model"), "w") as f:
    f.write("TI AM335x PocketBeagle\0")
pocket = os.path.join(tmp, "uEnv-pocket.txt")
shutil.copy(FIXTURE, pocket)
rc, out, err = run("enable", "ws281x", "--free-pins", env={"PRUKIT_UENV": pocket})
u = text(pocket).splitlines()
check(rc == 0 and "uboot_overlay_addr4=%s/PRUKIT-WS281X-00A0.dtbo" % fw in u and
      "disable_uboot_overlay_audio=1" not in u,
      "enable ws281x on a PocketBeagle (P1.33, no HDMI audio there): no audio line", out + err)
rc, out, err = run("enable", "hub75", env={"PRUKIT_UENV": pocket})
check(rc == 1 and "use PRUKIT-HUB75-POCKETSCROLLER-00A0 instead" in err,
      "enable of the Black's hub75 on a PocketBeagle: refused, names the PocketScroller's", err)
rc, out, err = run("enable", "hub75-octoscroller", env={"PRUKIT_UENV": pocket})
check(rc == 1 and "PRUKIT-HUB75-OCTOSCROLLER-00A0 is made for the BeagleBone Black" in err and
      "use PRUKIT-HUB75-POCKETSCROLLER-00A0 instead" in err,
      "enable of the Octoscroller's overlay on a PocketBeagle: refused, names the "
      "PocketScroller's", err)
with open(os.path.join(dtdir, "model"), "w") as f:
    f.write("TI AM335x BeagleBone Black\0")

os.unlink(os.path.join(fw, "prukit", "beaglelogic-pru1.elf"))
rc, out, err = run("enable", "beaglelogic")
check(rc == 1 and "prukit/beaglelogic-pru1.elf" in err and "prukit-firmware" in err,
      "enable with a firmware file missing: refused, names it and prukit-firmware", err)

# ---- the package's postrm on this state gives the original back
pr = os.path.join(tmp, "uEnv-postrm.txt")
shutil.copy(uenv, pr)
with open(pr, "a") as f:
    f.write("uboot_overlay_addr7=/lib/firmware/PRUKIT-RPMSG-00A0.dtbo\n")
p = subprocess.run(["sh", POSTRM, "remove"], env=dict(os.environ, PRUKIT_UENV=pr),
                   capture_output=True, text=True)
check(p.returncode == 0 and text(pr) == orig +
      "#uboot_overlay_addr7=/lib/firmware/PRUKIT-RPMSG-00A0.dtbo\n",
      "prukit-overlays postrm remove: prukit's lines gone, what it turned off back, a "
      "user's PRUKIT line commented out", p.stderr + text(pr))
shutil.copy(FIXTURE, pr)
os.unlink(pr + ".prukit-bak")
p = subprocess.run(["sh", POSTRM, "purge"], env=dict(os.environ, PRUKIT_UENV=pr),
                   capture_output=True, text=True)
check(p.returncode == 0 and text(pr) == orig and not os.path.exists(pr + ".prukit-bak"),
      "prukit-overlays postrm on a file prukit never changed: untouched, no backup")

# ---- status over a fake system
sysd = os.path.join(tmp, "sys")
pru0 = os.path.join(sysd, "devices", "platform", "4a334000.pru")
ws = os.path.join(sysd, "devices", "platform", "ws281x")
os.makedirs(os.path.join(pru0, "of_node"))
os.makedirs(os.path.join(ws, "of_node"))
os.makedirs(os.path.join(sysd, "bus", "platform", "drivers", "pru-rproc"))
os.makedirs(os.path.join(sysd, "bus", "platform", "drivers", "ws281x"))
os.symlink(os.path.join(sysd, "bus", "platform", "drivers", "pru-rproc"), os.path.join(pru0, "driver"))
os.symlink(os.path.join(sysd, "bus", "platform", "drivers", "ws281x"), os.path.join(ws, "driver"))
with open(os.path.join(pru0, "of_node", "phandle"), "wb") as f:
    f.write((0x42).to_bytes(4, "big"))
with open(os.path.join(ws, "of_node", "compatible"), "wb") as f:
    f.write(b"prukit,ws281x\0")
with open(os.path.join(ws, "of_node", "ti,prus"), "wb") as f:
    f.write((0x42).to_bytes(4, "big"))
rp = os.path.join(sysd, "class", "remoteproc", "remoteproc1")
os.makedirs(rp)
os.symlink(pru0, os.path.join(rp, "device"))
for k, v in (("name", "4a334000.pru"), ("state", "running"), ("firmware", "prukit/ws281x-pru0.elf")):
    with open(os.path.join(rp, k), "w") as f:
        f.write(v + "\n")
os.makedirs(os.path.join(sysd, "bus", "platform", "devices"))
os.symlink(ws, os.path.join(sysd, "bus", "platform", "devices", "ws281x"))
pm = os.path.join(sysd, "kernel", "debug", "pinctrl", "44e10800.pinmux-pinctrl-single")
os.makedirs(pm)
with open(os.path.join(pm, "pinmux-pins"), "w") as f:
    f.write("Pinmux settings per pin\nFormat: pin (name): mux_owner gpio_owner hog?\n")
    f.write("pin 101 (PIN101): ocp:P9_29_pinmux (GPIO UNCLAIMED) function "
            "pinmux_P9_29_default_pin group pinmux_P9_29_default_pin\n")
    f.write("pin 100 (PIN100): UNCLAIMED\n")
rc, out, err = run("status")
check(rc == 0 and "PRU0  4a334000.pru     running  firmware prukit/ws281x-pru0.elf, driver "
      "pru-rproc, held by ws281x (prukit,ws281x)" in out,
      "status: PRU0's state, firmware, driver and the prukit device holding it", out + err)
check("P9_29 (mcasp0_fsx) for PRUKIT-WS281X-00A0: held by ocp:P9_29_pinmux" in out and
      "enable_uboot_cape_universal=0" in out,
      "status: P9_29 held by cape universal's helper, with the line that frees it", out)
check("uboot_overlay_addr4=%s/PRUKIT-WS281X-00A0.dtbo (prukit enable)" % fw in out,
      "status: the enabled overlays of uEnv.txt", out)
check("rpmsg_pru is the kernel's" not in out, "status: nothing of rpmsg_pru when none is loaded",
      out)
shutil.rmtree(os.path.join(sysd, "kernel"))
rc, out, err = run("status")
check(rc == 0 and "needs root and debugfs: sudo prukit status" in out,
      "status without pinctrl's debugfs: says the pin check needs root", out + err)
# TI's own rpmsg_pru loaded (it has no parameters), then prukit's
os.makedirs(os.path.join(sysd, "module", "rpmsg_pru"))
rc, out, err = run("status")
check(rc == 0 and "the loaded rpmsg_pru is the kernel's (TI's), not prukit's" in out and
      "sudo rmmod rpmsg_pru && sudo modprobe rpmsg_pru" in out,
      "status: TI's rpmsg_pru loaded: says so, and how to load prukit's", out + err)
os.makedirs(os.path.join(sysd, "module", "rpmsg_pru", "parameters"))
with open(os.path.join(sysd, "module", "rpmsg_pru", "parameters", "rx_queue_len"), "w") as f:
    f.write("64\n")
rc, out, err = run("status")
check(rc == 0 and "rpmsg_pru is the kernel's" not in out,
      "status: prukit's rpmsg_pru loaded: nothing to say", out + err)

# ---- disable
rc, out, err = run("disable", "ws281x")
u = text(uenv).splitlines()
check(rc == 0 and not any("PRUKIT-WS281X" in line for line in u) and
      "disable_uboot_overlay_audio=1" in u and "#prukit: pins" in u,
      "disable ws281x: its lines gone; the pins lines stay while hub75 is enabled", out + err)
rc, out, err = run("disable", "ws281x")
check(rc == 1 and "not enabled" in err and "PRUKIT-HUB75-00A0" in err,
      "disable of an overlay not enabled: says so, names the enabled ones", err)
rc, out, err = run("disable", "hub75")
check(rc == 0 and text(uenv) == orig,
      "disable of the last prukit overlay: the file is byte for byte BeagleBoard's again",
      out + err)

rc, out, err = run("enable", "ws281x", "--free-pins")
rc2, out2, err2 = run("disable", "--all")
check(rc == 0 and rc2 == 0 and text(uenv) == orig, "disable --all undoes every change", err2)

os.unlink(uenv)
rc, out, err = run("enable", "ws281x")
check(rc == 1 and "does not exist" in err and "Traceback" not in err,
      "enable without a uEnv.txt: a clear error", err)

rc, out, err = run("enable")
check(rc == 2 and "the following arguments are required: overlay" in err,
      "enable without a name: usage error", err)

# ---- prukit servo over a fake PWM chip of pru_pwm (the VM's 83-pru-pwm runs
# it on the real one)
chipd = os.path.join(sysd, "class", "pwm", "pwmchip3")
pwmdev = os.path.join(sysd, "devices", "platform", "pwm")
os.makedirs(os.path.join(sysd, "bus", "platform", "drivers", "pru_pwm"))
os.makedirs(pwmdev)
os.symlink(os.path.join(sysd, "bus", "platform", "drivers", "pru_pwm"),
           os.path.join(pwmdev, "driver"))
os.makedirs(chipd)
os.symlink(pwmdev, os.path.join(chipd, "device"))
for k, v in (("npwm", "8"), ("export", ""), ("unexport", "")):
    with open(os.path.join(chipd, k), "w") as f:
        f.write(v)
for n in range(8):
    os.makedirs(os.path.join(chipd, "pwm%d" % n))
    for k, v in (("period", "0"), ("duty_cycle", "0"), ("enable", "0"), ("polarity", "normal")):
        with open(os.path.join(chipd, "pwm%d" % n, k), "w") as f:
            f.write(v)


def pwm(n, k):
    return text(os.path.join(chipd, "pwm%d" % n, k)).strip()


rc, out, err = run("servo", "-c", "1", "-p", "0.5")
check(rc == 0 and (pwm(0, "period"), pwm(0, "duty_cycle"), pwm(0, "enable")) ==
      ("20000000", "1800000", "1") and pwm(1, "enable") == "0" and "pwmchip3" in out,
      "servo -c 1 -p 0.5: channel 1 (pwm0) 1800 us every 20 ms (the Library's position)",
      out + err)
rc, out, err = run("servo", "-p", "-1.5")
check(rc == 0 and all((pwm(n, "period"), pwm(n, "duty_cycle"), pwm(n, "enable")) ==
                      ("20000000", "600000", "1") for n in range(8)),
      "servo -p -1.5: all eight channels 600 us", out + err)
rc, out, err = run("servo", "-c", "8", "-w", "1234.567", "-f", "100")
check(rc == 0 and (pwm(7, "period"), pwm(7, "duty_cycle")) == ("10000000", "1234565"),
      "servo -c 8 -w 1234.567 -f 100: 10 ms, the width rounded down to 5 ns", out + err)
rc, out, err = run("servo", "-c", "2", "--off")
check(rc == 0 and pwm(1, "enable") == "0" and pwm(0, "enable") == "1",
      "servo -c 2 --off: only channel 2 stops", out + err)
before = [pwm(n, "duty_cycle") for n in range(8)]
rc, out, err = run("servo", "-c", "1", "-w", "25000")
check(rc == 1 and "does not fit" in err and before == [pwm(n, "duty_cycle") for n in range(8)],
      "servo -w 25000 at 50 Hz: refused, nothing changed", err)
rc, out, err = run("servo", "-c", "9")
check(rc == 2 and "channels are 1 to 8" in err, "servo -c 9: usage error", err)
rc, out, err = run("servo", "-p", "2")
check(rc == 2 and "positions are -1.5 to 1.5" in err, "servo -p 2: usage error", err)
rc, out, err = run("servo", "-p", "0", env={"PRUKIT_SYSFS": os.path.join(tmp, "nosys")})
check(rc == 1 and "no PWM chip of prukit's pru_pwm driver" in err and "prukit enable pwm" in err,
      "servo without a pru_pwm chip: says which overlay and module", err)

# ---- the wiring pictures in Documentation/wiring are what the overlays give
wd = os.path.join(tmp, "wiring")
p = subprocess.run([os.path.join(TOP, "tools", "wiring.py"), "-o", wd] +
                   sorted(os.path.join(TOP, "out", "overlays", f)
                          for f in os.listdir(os.path.join(TOP, "out", "overlays"))
                          if f.endswith(".dtbo")), capture_output=True, text=True)
doc = os.path.join(TOP, "Documentation", "wiring")
made = sorted(os.listdir(wd)) if p.returncode == 0 else []
have = sorted(f for f in os.listdir(doc) if f.endswith(".svg")) if os.path.isdir(doc) else []
stale = [f for f in made if f not in have or text(os.path.join(wd, f)) != text(os.path.join(doc, f))]
check(p.returncode == 0 and made and made == have and not stale,
      "Documentation/wiring/*.svg (%d) are what tools/wiring.py draws from the overlays and "
      "the pin table (regenerate: tools/wiring.py out/overlays/*.dtbo -o Documentation/wiring)"
      % len(made), p.stderr + " ".join(stale or sorted(set(made) ^ set(have))))

shutil.rmtree(tmp)
sys.exit(failed)
