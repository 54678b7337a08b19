# SPDX-License-Identifier: GPL-2.0-only
"""Helpers for the VM tests (guest side, python3 of the guest): results,
sysfs attributes, the PRUs' remoteproc devices, rpmsg character devices."""
import errno
import glob
import os
import select
import sys
import time

failed = False


def check(name, cond, detail=""):
    """Print PASS/FAIL name (and detail when failing); remember failures."""
    global failed
    if cond:
        print("PASS: " + name, flush=True)
    else:
        print("FAIL: " + name + (": " + str(detail) if detail else ""), flush=True)
        failed = True
    return cond


def info(text):
    print("INFO: " + text, flush=True)


def done():
    sys.exit(1 if failed else 0)


def write_attr(path, value):
    """errno of writing value to a sysfs file, 0 if it worked."""
    try:
        with open(path, "w") as f:
            f.write(value)
        return 0
    except OSError as e:
        return e.errno


def read_attr(path):
    """A sysfs file's value, without the newline."""
    with open(path) as f:
        return f.read().strip()


def pru_rproc(core):
    iram = {0: "34000", 1: "38000"}[core]
    for r in glob.glob("/sys/class/remoteproc/remoteproc*"):
        if os.path.realpath(r + "/device").endswith("pru@" + iram):
            return r
    raise RuntimeError("no remoteproc for PRU%d" % core)


def rproc_state(core):
    with open(pru_rproc(core) + "/state") as f:
        return f.read().strip()


def rproc_stop(core):
    r = pru_rproc(core)
    if rproc_state(core) == "running":
        with open(r + "/state", "w") as f:
            f.write("stop")


def rproc_start(core, firmware):
    r = pru_rproc(core)
    rproc_stop(core)
    with open(r + "/firmware", "w") as f:
        f.write(firmware)
    with open(r + "/state", "w") as f:
        f.write("start")


def wait_for(path, present=True, timeout=120):
    """Wait until path exists (or is gone); True if it happened in time."""
    end = time.monotonic() + timeout
    while os.path.exists(path) != present:
        if time.monotonic() > end:
            return False
        time.sleep(0.05)
    return True


def read_msg(fd, timeout=60, size=512):
    """One message, waiting at most timeout seconds (None on timeout)."""
    r, _, _ = select.select([fd], [], [], timeout)
    if not r:
        return None
    return os.read(fd, size)


def write_err(fd, data):
    """errno of a write, 0 if it succeeded."""
    try:
        os.write(fd, data)
        return 0
    except OSError as e:
        return e.errno


def errname(code):
    return errno.errorcode.get(code, str(code))
