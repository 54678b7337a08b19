# SPDX-License-Identifier: GPL-2.0-only
"""Who may use prukit's devices, in the guest: udevd with the rules `make
udev_install` installs, the groups BeagleBoard's images have, and calls
made as an unprivileged user in a child process (a user in a device's
group, and one in none)."""
import grp
import os
import subprocess
import time

from leak import processes
from rpmsg import info

RULES = "/etc/udev/rules.d/60-prukit.rules"
UDEVD = next((p for p in ("/lib/systemd/systemd-udevd", "/usr/lib/systemd/systemd-udevd")
              if os.path.exists(p)), None)
# prukit's modules: a udev process that does not exit must not be waiting in one
PRUKIT_MODULES = ("[ws281x]", "[beaglelogic]", "[hub75]", "[pru_pwm]", "[pru_encoder]", "[prukit_pru]", "[rpmsg_pru]",
                  "[pru_test_consumer]", "[prusim_port]")
# Users with no account: the kernel checks numbers, not names.
USER = 1000
OUTSIDER = 1001


def sh(cmd):
    r = subprocess.run(["sh", "-c", cmd], capture_output=True, text=True)
    if r.returncode:
        info("%s: %s" % (cmd, (r.stderr or r.stdout).strip()))
    return r.returncode == 0


def add_groups():
    """The groups the rules name, as BeagleBoard's images have them (the
    image is unpacked without maintainer scripts: /etc/group may lack them)."""
    with open("/etc/group", "a") as f:
        for name, gid in (("root", 0), ("video", 44), ("gpio", 997), ("remoteproc", 998)):
            try:
                grp.getgrnam(name)
            except KeyError:
                f.write("%s:x:%d:\n" % (name, gid))


def gid(name):
    return grp.getgrnam(name).gr_gid


def perms(path):
    """"uid:group mode" of a file, e.g. "0:gpio 0660"."""
    st = os.stat(path)
    try:
        group = grp.getgrgid(st.st_gid).gr_name
    except KeyError:
        group = str(st.st_gid)
    return "%d:%s %04o" % (st.st_uid, group, st.st_mode & 0o7777)


def udevd_start():
    """Start udevd; True once it answers (--daemon returns before it
    listens: a uevent sent before that is lost)."""
    if not UDEVD or not sh(UDEVD + " --daemon"):
        return False
    return sh("udevadm control --timeout=60 --ping")


def udev_add(*match):
    """udevadm trigger --action=add for the devices matching, then settle."""
    return sh("udevadm trigger --action=add %s && udevadm settle --timeout=60" % " ".join(match))


def udev_procs():
    """udevd and its workers still alive (not zombies): "pid comm state"
    and the wchan and kernel stack of each, for the log."""
    found = []
    for pid, comm, state in processes():
        if "udev" not in comm or state == "Z":
            continue
        desc = "%d %s %s" % (pid, comm, state)
        for extra in ("wchan", "stack"):
            try:
                with open("/proc/%d/%s" % (pid, extra)) as f:
                    desc += " " + extra + ": " + " | ".join(f.read().split("\n")[:8])
            except OSError:
                pass
        found.append(desc)
    return found


def udevd_stop():
    """Stop udevd, asking first (no other VM test expects it).  Returns how
    it went ("udevadm control --exit", "SIGTERM", "SIGKILL" or None if
    something survived) and the udev processes that did not exit when
    asked while waiting in a prukit module."""
    stuck = []
    for step, sig in (("udevadm control --exit", None), ("SIGTERM", 15), ("SIGKILL", 9)):
        if sig is None:
            sh("timeout 90 udevadm control --exit")
        else:
            for p in udev_procs():
                try:
                    os.kill(int(p.split()[0]), sig)
                except OSError:
                    pass
        end = time.monotonic() + 60
        while time.monotonic() < end and udev_procs():
            time.sleep(0.2)
        left = udev_procs()
        if not left:
            return step, stuck
        for p in left:
            info("after %s, still there: %s" % (step, p))
        stuck += [p for p in left if any(m in p for m in PRUKIT_MODULES)]
    return None, stuck


def as_user(uid, groups, fn):
    """Run fn() as uid with only the supplementary groups named; the errno
    of the OSError it raised, 0 if none, -1 if it failed otherwise."""
    gids = [gid(g) for g in groups]
    pid = os.fork()
    if pid == 0:
        code = 0
        try:
            os.setgroups(gids)
            os.setgid(gids[0] if gids else 65534)
            os.setuid(uid)
            fn()
        except OSError as e:
            code = e.errno or 255
        except BaseException:
            code = 255
        os._exit(code)
    _, status = os.waitpid(pid, 0)
    code = os.waitstatus_to_exitcode(status)
    return -1 if code == 255 or code < 0 else code


def write_as(uid, groups, path, value):
    """errno of writing value to path as uid (0: it worked)."""
    def write():
        with open(path, "w") as f:
            f.write(value)
    return as_user(uid, groups, write)


def open_as(uid, groups, path, flags=os.O_RDONLY):
    """errno of opening path as uid (0: it opened)."""
    return as_user(uid, groups, lambda: os.close(os.open(path, flags)))


def read_as(uid, groups, path):
    """errno of reading path as uid (0: it read)."""
    def read():
        with open(path) as f:
            f.read()
    return as_user(uid, groups, read)
