#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""Generate the data of the prusim KUnit suite (prusim_kunit.c).

Every validation program of tests/prusim (asm/*.S, c/*.c) is built for its
cores exactly as tests/prusim/runner.py builds it, and its directives
("cores:", "args:", "exit:", "expect:", "edges:", "gaps:", "period:"; parsed
by runner.py's own parser) become C data in the format of prusim_kunit.h:
the ELF images, the stimulus files, the run parameters and the checks.  The
header also defines one KUnit test function per program (named after it:
asm_alu, c_uart, ...; each calls prusim_kunit_run_case(), which the
including file provides) and PRUSIM_KUNIT_CASE_LIST, the list of their
KUNIT_CASE() entries.

usage: gen.py --tools BIN --build DIR --out FILE [SOURCE...]

The output is written only if its contents change (the kernel build then
recompiles the suite only when needed).  Anything the suite could not check
exactly as runner.py does (an unknown option or expectation key) is an
error, not a silently dropped check.
"""

import argparse
import os
import re
import shlex
import sys

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
sys.path.insert(0, os.path.join(TOP, "tests", "prusim"))
import runner  # noqa: E402  (tests/prusim/runner.py)

NUM_CORES = 2
NUM_PORTS = 6                   # PRUSIM_NUM_PORTS: R31 of 2 cores, 4 GPIO banks
NUM_LAT = 12
STATES = ["disabled", "running", "sleeping", "halted", "stopped"]
LAT_NAMES = ["dram", "shared", "intc", "ctrl", "cfg", "iep", "gpio0", "gpio", "ocmc", "ddr",
             "prcm", "ocp"]
CFG_NAMES = ["read_word_cycles", "write_cycles", "write_word_cycles", "gpio_write_latency",
             "gpio_write_interval", "r31_sync_delay", "event_latency", "ocp_write_delay",
             "ddr_jitter", "jitter_seed"]
CORE_FIELDS = {"pc": "PK_PC", "instructions": "PK_INSNS", "stalls": "PK_STALLS",
               "cycle_counter": "PK_CYCLE_CNT", "stall_counter": "PK_STALL_CNT"}
TOP_FIELDS = {"cycles": "PK_CYCLES", "pin_changes": "PK_PIN_CHANGES",
              "intc.raw": "PK_INTC_RAW", "intc.enabled": "PK_INTC_ENABLED",
              "intc.pending": "PK_INTC_PENDING"}
DEFAULT_MAX_CYCLES = 1000000000


class GenError(Exception):
    pass


def pin_names():
    """Signal name -> pin id, from the tables the prusim tool names pins with."""
    path = os.path.join(TOP, "tools", "prusim", "pinlog.c")
    with open(path) as f:
        text = f.read()
    names = {}
    for core in range(NUM_CORES):
        m = re.search(r"pru%d_r30_pins\[32\]\s*=\s*\{(.*?)\};" % core, text, re.S)
        if not m:
            raise GenError(f"{path}: no pru{core}_r30_pins table")
        bit = 0
        for item in re.findall(r'(?:\[(\d+)\]\s*=\s*)?"([A-Za-z0-9_]+)"', m.group(1)):
            if item[0]:
                bit = int(item[0])
            names[item[1]] = core * 32 + bit
            bit += 1
    if len(names) < 20:
        raise GenError(f"{path}: only {len(names)} header pin names found")
    return names


def pin_id(name, header):
    if name in header:
        return header[name]
    m = re.fullmatch(r"pru([01])_r30_(\d+)", name)
    if m and int(m.group(2)) < 32:
        return int(m.group(1)) * 32 + int(m.group(2))
    m = re.fullmatch(r"gpio([0-3])_(\d+)", name)
    if m and int(m.group(2)) < 32:
        return 64 + int(m.group(1)) * 32 + int(m.group(2))
    raise GenError(f"unknown signal {name!r}")


def parse_size(text):
    """As the prusim tool's parse_size(): a number with an optional K or M."""
    m = re.fullmatch(r"(0[xX][0-9a-fA-F]+|\d+)([KkMm]?)", text)
    if not m:
        raise GenError(f"bad size {text!r}")
    v = int(m.group(1), 0)
    return v << {"": 0, "k": 10, "m": 20}[m.group(2).lower()]


def c_string(data):
    """A C string literal (split in lines) for bytes @data."""
    out, line = [], ""
    for b in data:
        ch = chr(b)
        if ch == "\\" or ch == '"':
            line += "\\" + ch
        elif ch == "\n":
            line += "\\n"
            out.append(line)
            line = ""
            continue
        elif 0x20 <= b < 0x7f:
            line += ch
        else:
            line += "\\%03o" % b
    if line or not out:
        out.append(line)
    return "\n\t".join(f'"{x}"' for x in out)


def c_bytes(data):
    lines = []
    for i in range(0, len(data), 12):
        lines.append("\t" + " ".join(f"0x{b:02x}," for b in data[i:i + 12]))
    return "\n".join(lines)


def parse_args(args):
    """The prusim options a validation program may use."""
    run = {"stim": {}, "max_cycles": DEFAULT_MAX_CYCLES, "ddr": 0, "until_halt": False,
           "kicks": [], "cfg": []}
    i = 0

    def value():
        nonlocal i
        if i + 1 >= len(args):
            raise GenError(f"{args[i]} needs a value")
        i += 1
        return args[i]

    while i < len(args):
        a = args[i]
        if a in ("--r31-0", "--r31-1"):
            run["stim"][int(a[-1])] = value()
        elif a == "--gpio-in":
            v = value()
            m = re.fullmatch(r"([0-3]):(.+)", v)
            if not m:
                raise GenError(f"bad --gpio-in {v!r}")
            run["stim"][2 + int(m.group(1))] = m.group(2)
        elif a == "--max-cycles":
            run["max_cycles"] = parse_size(value())
        elif a == "--ddr":
            run["ddr"] = parse_size(value())
            if not 0 < run["ddr"] <= 0x40000000:
                raise GenError(f"bad --ddr {args[i]!r}")
        elif a == "--until-halt":
            run["until_halt"] = True
        elif a == "--event":
            v = value()
            m = re.fullmatch(r"(\d+):(\d+)", v)
            if not m or int(m.group(2)) >= 64:
                raise GenError(f"bad --event {v!r}")
            run["kicks"].append((int(m.group(1)), int(m.group(2))))
        elif a == "-C":
            name, _, v = value().partition("=")
            if name in LAT_NAMES:
                param = str(LAT_NAMES.index(name))
            elif name in CFG_NAMES:
                param = "PK_CFG_" + name.upper()
            else:
                raise GenError(f"unknown -C parameter {name!r}")
            if parse_size(v) > 0xffff:
                raise GenError(f"-C {name}: value too large")
            run["cfg"].append((param, parse_size(v)))
        else:
            raise GenError(f"prusim option {a!r} is not supported by the KUnit suite")
        i += 1
    run["kicks"].sort(key=lambda k: k[0])
    return run


def parse_expect(exp):
    """One "expect:" line -> C initializer of struct prusim_kunit_expect."""
    line = c_string(exp.encode())
    if "~" in exp and ("=" not in exp or exp.index("~") < exp.index("=")):
        key, text = exp.split("~", 1)
        contains = True
    else:
        key, _, text = exp.partition("=")
        contains = False
    m = re.fullmatch(r"pru([01])\.(\w+)", key)
    if m:
        core, field = int(m.group(1)), m.group(2)
        if field == "reason":
            kind = "PK_REASON_HAS" if contains else "PK_REASON_IS"
            return (f"{{ .field = {kind}, .core = {core}, .text = {c_string(text.encode())},"
                    f" .line = {line} }}")
        if contains:
            raise GenError(f"{exp!r}: '~' only works on reason")
        if field == "state":
            if text not in STATES:
                raise GenError(f"{exp!r}: unknown state")
            return (f"{{ .field = PK_STATE, .core = {core}, .value = {STATES.index(text)},"
                    f" .line = {line} }}")
        rm = re.fullmatch(r"r(\d+)", field)
        if rm and int(rm.group(1)) < 32:
            return (f"{{ .field = PK_REG, .core = {core}, .reg = {int(rm.group(1))},"
                    f" .value = {int(text, 0)}ull, .line = {line} }}")
        if field in CORE_FIELDS:
            return (f"{{ .field = {CORE_FIELDS[field]}, .core = {core},"
                    f" .value = {int(text, 0)}ull, .line = {line} }}")
        raise GenError(f"{exp!r}: unknown key")
    if key in TOP_FIELDS and not contains:
        return f"{{ .field = {TOP_FIELDS[key]}, .value = {int(text, 0)}ull, .line = {line} }}"
    raise GenError(f"{exp!r}: unknown key")


def ident(name):
    return re.sub(r"[^A-Za-z0-9]", "_", os.path.splitext(name)[0])


def gen_case(src, opts, header_pins, out):
    """C data of one validation program; returns (function name, initializer)."""
    name = os.path.relpath(src, os.path.join(TOP, "tests", "prusim"))
    d = runner.parse_directives(src)
    cid = ident(name)
    try:
        elves = {c: runner.build(src, c, opts.build, opts.tools, []) for c in d["cores"]}
    except runner.subprocess.CalledProcessError as e:
        raise GenError(f"build failed: {(e.stderr or e.stdout).strip()}")
    run = parse_args(d["args"])
    if d["exit"] not in (0, 2, 3):
        raise GenError(f"exit status {d['exit']} cannot be checked in the kernel")
    fw, fw_size = ["NULL"] * NUM_CORES, ["0"] * NUM_CORES
    for core, elf in sorted(elves.items()):
        with open(elf, "rb") as f:
            data = f.read()
        out.append(f"static const u8 pk_{cid}_fw{core}[] = {{\n{c_bytes(data)}\n}};\n")
        fw[core], fw_size[core] = f"pk_{cid}_fw{core}", str(len(data))
    stim, stim_len = ["NULL"] * NUM_PORTS, ["0"] * NUM_PORTS
    for port, path in sorted(run["stim"].items()):
        with open(path, "rb") as f:
            data = f.read()
        out.append(f"static const char pk_{cid}_stim{port}[] =\n\t{c_string(data)};\n")
        stim[port], stim_len[port] = f"pk_{cid}_stim{port}", str(len(data))
    fields = [f".name = {c_string(name.encode())}",
              f".fw = {{ {', '.join(fw)} }}", f".fw_size = {{ {', '.join(fw_size)} }}",
              f".stim = {{ {', '.join(stim)} }}",
              f".stim_len = {{ {', '.join(stim_len)} }}",
              f".max_cycles = {run['max_cycles']}ull", f".ddr_size = {run['ddr']}",
              f".until_halt = {'true' if run['until_halt'] else 'false'}",
              f".exit = {d['exit']}"]
    if run["kicks"]:
        items = ", ".join(f"{{ {c}ull, {e} }}" for c, e in run["kicks"])
        out.append(f"static const struct prusim_kunit_kick pk_{cid}_kicks[] = {{ {items} }};\n")
        fields += [f".kicks = pk_{cid}_kicks", f".nkicks = {len(run['kicks'])}"]
    if run["cfg"]:
        items = ", ".join(f"{{ {p}, {v} }}" for p, v in run["cfg"])
        out.append(f"static const struct prusim_kunit_cfg pk_{cid}_cfg[] = {{ {items} }};\n")
        fields += [f".cfg = pk_{cid}_cfg", f".ncfg = {len(run['cfg'])}"]
    expects = []
    for exp in d["expect"]:
        if exp.startswith("host_irq="):
            want = exp.split("=", 1)[1]
            irqs = [tuple(int(x, 0) for x in e.split(":")) for e in want.split(",") if e]
            if any(len(i) != 3 for i in irqs):
                raise GenError(f"{exp!r}: entries are CYCLE:HOST:LEVEL")
            if irqs:
                items = ", ".join(f"{{ {c}ull, {h}, {lv} }}" for c, h, lv in irqs)
                out.append(f"static const struct prusim_kunit_irq pk_{cid}_irq[] = "
                           f"{{ {items} }};\n")
                fields.append(f".host_irq = pk_{cid}_irq")
            fields += [".check_host_irq = true", f".nhost_irq = {len(irqs)}"]
        else:
            expects.append(parse_expect(exp))
    if expects:
        out.append(f"static const struct prusim_kunit_expect pk_{cid}_expect[] = {{\n\t" +
                   ",\n\t".join(expects) + "\n};\n")
        fields += [f".expect = pk_{cid}_expect", f".nexpect = {len(expects)}"]
    signals = []
    for kind, key in (("PK_EDGES", "edges"), ("PK_GAPS", "gaps"), ("PK_PERIOD", "period")):
        for spec in d[key]:
            sig, _, want = spec.partition("=")
            values = [int(x) for x in want.split(",") if x]
            if kind == "PK_PERIOD" and len(values) != 2:
                raise GenError(f"period: {spec!r} needs PERIOD,HIGH")
            arr = "NULL"
            if values:
                arr = f"pk_{cid}_sig{len(signals)}"
                out.append(f"static const u64 {arr}[] = {{ " +
                           ", ".join(f"{v}ull" for v in values) + " };\n")
            signals.append(f"{{ {kind}, {pin_id(sig, header_pins)}, {arr}, {len(values)}, "
                           f"{c_string(f'{key}: {spec}'.encode())} }}")
    if signals:
        out.append(f"static const struct prusim_kunit_signal pk_{cid}_signals[] = {{\n\t" +
                   ",\n\t".join(signals) + "\n};\n")
        fields += [f".signals = pk_{cid}_signals", f".nsignals = {len(signals)}"]
    return cid, "\t{\n\t\t" + ",\n\t\t".join(fields) + ",\n\t}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tools", required=True, help="directory with pru-as, pru-ld, pru-gcc")
    ap.add_argument("--build", required=True, help="directory for the ELF files")
    ap.add_argument("--out", required=True, help="the header to write")
    ap.add_argument("sources", nargs="*")
    opts = ap.parse_args()
    sources = opts.sources or sorted(
        [os.path.join(TOP, "tests", "prusim", "asm", f)
         for f in os.listdir(os.path.join(TOP, "tests", "prusim", "asm")) if f.endswith(".S")]
        + [os.path.join(TOP, "tests", "prusim", "c", f)
           for f in os.listdir(os.path.join(TOP, "tests", "prusim", "c")) if f.endswith(".c")])
    os.makedirs(opts.build, exist_ok=True)
    header_pins = pin_names()
    out = ["/* SPDX-License-Identifier: GPL-2.0-only */\n"
           "/*\n * Generated by tests/kunit/prusim/gen.py from tests/prusim; do not edit.\n"
           " * " + shlex.join(["gen.py"] + [os.path.relpath(s, TOP) for s in sources]) + "\n"
           " */\n"]
    cases = []
    for src in sources:
        try:
            cases.append(gen_case(src, opts, header_pins, out))
        except (GenError, ValueError, OSError) as e:
            print(f"gen.py: {os.path.relpath(src, TOP)}: {e}", file=sys.stderr)
            return 1
    if len({c for c, _ in cases}) != len(cases):
        print("gen.py: two sources give the same test name", file=sys.stderr)
        return 1
    out.append("static const struct prusim_kunit_case prusim_kunit_cases[] = {\n" +
               ",\n".join(init for _, init in cases) + ",\n};\n")
    for i, (cid, _) in enumerate(cases):
        out.append(f"static void {cid}(struct kunit *test)\n{{\n"
                   f"\tprusim_kunit_run_case(test, &prusim_kunit_cases[{i}]);\n}}\n")
    out.append("#define PRUSIM_KUNIT_CASE_LIST \\\n" +
               " \\\n".join(f"\tKUNIT_CASE({cid})," for cid, _ in cases) + "\n")
    text = "\n".join(out)
    try:
        with open(opts.out) as f:
            if f.read() == text:
                return 0
    except OSError:
        pass
    tmp = opts.out + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, opts.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
