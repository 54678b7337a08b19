# SPDX-License-Identifier: GPL-2.0-only
"""Helpers for the VM tests (guest side, python3 of the guest): results,
sysfs attributes, the PRUs' remoteproc devices, rpmsg character devices."""
import errno
import glob
import os
import select
import subprocess
import sys
import threading
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
    """errno of writing value to a sysfs file, 0 if it worked: one write(2),
    as echo does (a buffered file would write again when it is closed after
    a failed write, and report that second write's errno)."""
    try:
        fd = os.open(path, os.O_WRONLY)
    except OSError as e:
        return e.errno
    try:
        os.write(fd, value.encode() if isinstance(value, str) else value)
        return 0
    except OSError as e:
        return e.errno
    finally:
        os.close(fd)


def read_attr(path):
    """A sysfs file's value, without the newline."""
    with open(path) as f:
        return f.read().strip()


def pru_rproc(core):
    """PRU core's remoteproc sysfs directory: its device is 4a334000.pru /
    4a338000.pru."""
    iram = {0: "34000", 1: "38000"}[core]
    for r in glob.glob("/sys/class/remoteproc/remoteproc*"):
        dev = os.path.realpath(r + "/device")
        if dev.endswith("/4a3" + iram + ".pru"):
            return r
    raise RuntimeError("no remoteproc for PRU%d" % core)


def sim_dir():
    """The simulated PRU-ICSS's debugfs directory: the QEMU device's test
    port (tests/kmod/prusim_port.c)."""
    d = "/sys/kernel/debug/prusim"
    if os.path.exists(d + "/stats"):
        return d
    raise RuntimeError("no simulated PRU-ICSS in debugfs")


def single_step(core, on):
    """Halt PRU core as a debugger does, behind remoteproc's back, or let it
    run again: pru_rproc's debugfs "single_step" (1: one instruction, then
    halted, as a firmware's HALT or a fault leaves a core; 0: on again).
    remoteproc still says "running"."""
    path = "/sys/kernel/debug/remoteproc/%s/single_step" % os.path.basename(pru_rproc(core))
    err = write_attr(path, "1" if on else "0")
    if err:
        raise OSError(err, "cannot write " + path)


def sim_pru_state(core):
    """What the simulated PRU-ICSS says of core: "running", "halted", ..."""
    with open(sim_dir() + "/stats") as f:
        for ln in f:
            w = ln.split()
            if w[:2] == ["pru%d" % core, "state"]:
                return w[2]
    return None


def halt_pru(core, timeout=10):
    """single_step(core, True), and the core's state in the simulator once
    it left "running" (the simulator takes the CONTROL write on its own
    thread), or "running" after timeout seconds."""
    single_step(core, True)
    end = time.monotonic() + timeout
    while sim_pru_state(core) == "running" and time.monotonic() < end:
        time.sleep(0.05)
    return sim_pru_state(core)


def pad_owners():
    """{pad offset: the device whose pinctrl state holds it} from the pin
    controller's debugfs: pinctrl-single's (its pin N is pad 0x800 + 4 * N)."""
    owners = {}
    for f in glob.glob("/sys/kernel/debug/pinctrl/*pinmux*/pinmux-pins"):
        with open(f) as fh:
            for line in fh:
                # "pin 101 (PIN101): 4a334000.pru (GPIO UNCLAIMED) function ..."
                # (a strict controller: "pin 101 (...): device 4a334000.pru")
                w = line.split()
                if len(w) < 4 or w[0] != "pin" or not w[1].isdigit():
                    continue
                dev = w[4] if w[3] == "device" and len(w) > 4 else w[3]
                if dev not in ("(MUX", "UNCLAIMED", "GPIO"):
                    owners[0x800 + 4 * int(w[1])] = dev
    return owners


def board_path():
    """Both PRU cores bound to the kernel's own pru-rproc driver: the board
    path."""
    for c in ("4a334000.pru", "4a338000.pru"):
        drv = "/sys/bus/platform/devices/%s/driver" % c
        if not os.path.exists(drv) or os.path.basename(os.path.realpath(drv)) != "pru-rproc":
            return False
    return True


def check_board_path():
    """The check every board-path test makes first."""
    return check("PRU0 and PRU1 are bound to the kernel's pru-rproc", board_path())


def rproc_state(core):
    with open(pru_rproc(core) + "/state") as f:
        return f.read().strip()


def rproc_stop(core):
    r = pru_rproc(core)
    if rproc_state(core) == "running":
        with open(r + "/state", "w") as f:
            f.write("stop")


def rproc_crash(core, timeout=10):
    """Report a crash of PRU core as remoteproc's debugfs "crash" file does
    (pru_rproc itself detects none); wait until remoteproc says "crashed"
    (pru_rproc disables recovery).  The PRU itself runs on.  True once it
    says so."""
    path = "/sys/kernel/debug/remoteproc/%s/crash" % os.path.basename(pru_rproc(core))
    err = write_attr(path, "2")
    if err:
        raise OSError(err, "cannot write " + path)
    end = time.monotonic() + timeout
    while rproc_state(core) != "crashed":
        if time.monotonic() > end:
            return False
        time.sleep(0.05)
    return True


def rproc_start(core, firmware):
    r = pru_rproc(core)
    rproc_stop(core)
    with open(r + "/firmware", "w") as f:
        f.write(firmware)
    with open(r + "/state", "w") as f:
        f.write("start")


def rproc_start_refused(core, firmware):
    """Start firmware on core, expecting a refusal: (errno of the start, 0 if
    it was not refused; the kernel log lines it wrote)."""
    mark = len(subprocess.run(["dmesg"], capture_output=True, text=True).stdout.splitlines())
    try:
        rproc_start(core, firmware)
        err = 0
    except OSError as e:
        err = e.errno
    log = subprocess.run(["dmesg"], capture_output=True, text=True).stdout.splitlines()[mark:]
    return err, log


# ARM EABI system call numbers (the kernel's arch/arm/tools/syscall.tbl):
# what a client blocked in read(2), write(2) or poll(2) sleeps in (glibc's
# poll() is poll, ppoll or ppoll_time64)
SYSCALLS = {"read": (3,), "write": (4,), "poll": (168, 336, 414)}


def _syscall_nr(tid):
    """The system call number /proc's syscall file gives for thread tid of
    this process, or None (it runs, or the file cannot be read)."""
    try:
        with open("/proc/self/task/%d/syscall" % tid) as f:
            nr = f.read().split()[0]
    except (OSError, IndexError):
        return None
    return int(nr) if nr.isdigit() else None


# Before 6.1 ARM records a task's system call number only when the call is
# traced (5.10's entry code), so the file names the call only where it
# names this read(2) of itself.
SYSCALL_NR_KNOWN = _syscall_nr(threading.get_native_id()) == SYSCALLS["read"][0]


def in_syscall(tid, name):
    """True while thread tid of this process sleeps in system call name
    (a key of SYSCALLS).  /proc's stat file says whether it sleeps, its
    syscall file in which call; where the kernel does not record that
    (SYSCALL_NR_KNOWN false), its wchan must at least not be a futex (a
    thread waiting for the interpreter's lock) or a sleep of its own."""
    try:
        with open("/proc/self/task/%d/stat" % tid) as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
        with open("/proc/self/task/%d/wchan" % tid) as f:
            wchan = f.read().strip()
    except (OSError, IndexError):
        return False
    nr = _syscall_nr(tid) if SYSCALL_NR_KNOWN else None
    LAST_SEEN[tid] = (state, wchan, nr)
    if state not in ("S", "D"):
        return False
    if SYSCALL_NR_KNOWN:
        return nr in SYSCALLS[name]
    return wchan not in ("", "0") and not any(w in wchan for w in ("futex", "nanosleep"))


# what in_syscall() last saw of each thread: (state, wchan, syscall number)
LAST_SEEN = {}


def start_blocked(target, name, timeout=60):
    """Run target() in a daemon thread and wait until it sleeps in system
    call name (read, write or poll): a client blocked in the driver, not one
    that has not got there yet.  Returns (thread, blocked): blocked is False
    if target returned first, or did not block within timeout seconds."""
    tid = []

    def run():
        tid.append(threading.get_native_id())
        target()

    t = threading.Thread(target=run, daemon=True)
    t.start()
    deadline = time.monotonic() + timeout
    looks = 0
    while t.is_alive() and time.monotonic() < deadline:
        if tid and in_syscall(tid[0], name):
            return t, True
        looks += 1
        if looks % 2:
            # one CPU (an AM335x, a lockstep boot): a client that polls its
            # firmware with short sleeps is runnable whenever this thread
            # runs, and woken with it; give it the CPU, then look again
            os.sched_yield()
        else:
            time.sleep(0.01)
    info("not seen asleep in %s (%s after %d looks): last seen state, wchan, call %s" %
         (name, "it returned" if not t.is_alive() else "timed out", looks,
          LAST_SEEN.get(tid[0]) if tid else "never started"))
    return t, False


def wait_until(cond, timeout=60, step=0.05):
    """Poll cond() until it is true or timeout seconds passed; its last value."""
    deadline = time.monotonic() + timeout
    while True:
        v = cond()
        if v or time.monotonic() >= deadline:
            return v
        time.sleep(step)


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
