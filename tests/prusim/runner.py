#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""Run prusim assembly/C firmware tests and check their expectations.

Directives in a test source, one per line, in a comment ("#" in .S files,
"//" in .c files):

  cores: 0 1            cores to build the source for (default 0); the
                        source sees PRU=<core> (.S: --defsym, .c: -DPRU=)
  args: ARGS...         extra prusim arguments; {dir} is the test directory
  exit: N               expected prusim exit status (default 0)
  expect: KEY=VALUE     a value of the JSON result, e.g. cycles=12,
                        pru0.r5=0x10, pru1.state=halted, intc.pending=2,
                        host_irq=CYCLE:HOST:LEVEL,...
  expect: KEY~TEXT      the JSON string value contains TEXT
  edges: SIGNAL=C1,C2   the cycles at which VCD signal SIGNAL changed
  gaps: SIGNAL=D1,D2    the distances in cycles between its changes
  period: SIGNAL=P,H    every full period of SIGNAL lasts P cycles and is
                        high for H cycles

Every test is run twice, with and without idle skipping; the JSON result and
the VCD trace must be identical ("skip-exact").
"""

import argparse
import json
import os
import re
import shlex
import subprocess
import sys

DIRECTIVE = re.compile(
    r"^\s*(?:#|//|\*)\s*(cores|args|exit|expect|edges|gaps|period):\s*(.*?)\s*$")


def parse_directives(path):
    d = {"cores": [0], "args": [], "exit": 0, "expect": [], "edges": [], "gaps": [],
         "period": []}
    with open(path) as f:
        for line in f:
            m = DIRECTIVE.match(line)
            if not m:
                continue
            key, val = m.groups()
            if key == "cores":
                d["cores"] = [int(x) for x in val.split()]
            elif key == "args":
                d["args"] += shlex.split(val.replace("{dir}", os.path.dirname(path)))
            elif key == "exit":
                d["exit"] = int(val)
            else:
                d[key].append(val)
    return d


def build(src, core, out, tools, linker_args):
    base = os.path.join(out, f"{os.path.splitext(os.path.basename(src))[0]}.pru{core}")
    elf = base + ".elf"
    if src.endswith(".S"):
        cmd = [os.path.join(tools, "pru-as"), "--defsym", f"PRU={core}", "-o", base + ".o", src]
        subprocess.run(cmd, check=True, capture_output=True, text=True)
        cmd = [os.path.join(tools, "pru-ld"), "-o", elf, base + ".o"] + linker_args
    else:
        cmd = [os.path.join(tools, "pru-gcc"), "-O2", "-Wall", "-Werror", f"-DPRU={core}",
               "-o", elf, src]
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    return elf


def vcd_signals(path):
    """Map signal name -> list of (cycle, level) changes after time 0."""
    ids, sig, t = {}, {}, 0
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.startswith("$var"):
                parts = line.split()
                ids[parts[3]] = parts[4]
                sig[parts[4]] = []
            elif line.startswith("#"):
                t = int(line[1:])
            elif line and line[0] in "01" and t > 0:
                sig[ids[line[1:]]].append((t, int(line[0])))
    return sig


def lookup(result, key):
    node = result
    for part in key.split("."):
        m = re.fullmatch(r"(pru)(\d)", part)
        if m:
            node = node["pru"][int(m.group(2))]
        elif re.fullmatch(r"r\d+", part):
            node = node["regs"][int(part[1:])]
        else:
            node = node[part]
    return node


def check_expect(result, exp):
    if "~" in exp and ("=" not in exp or exp.index("~") < exp.index("=")):
        key, text = exp.split("~", 1)
        val = str(lookup(result, key))
        return None if text in val else f"{key}={val!r} does not contain {text!r}"
    key, want = exp.split("=", 1)
    if key == "host_irq":
        got = ",".join(f"{e['cycle']}:{e['host']}:{e['level']}" for e in result["host_irq"])
        return None if got == want else f"host_irq={got}, expected {want}"
    val = lookup(result, key)
    if isinstance(val, int):
        ok = val == int(want, 0)
        shown = f"{val} (0x{val:x})"
    else:
        ok = str(val) == want
        shown = repr(val)
    return None if ok else f"{key}={shown}, expected {want}"


def check_edges(signals, spec):
    name, want = spec.split("=", 1)
    got = ",".join(str(t) for t, _ in signals.get(name, []))
    return None if got == want else f"edges of {name} at {got}, expected {want}"


def check_gaps(signals, spec):
    name, want = spec.split("=", 1)
    times = [t for t, _ in signals.get(name, [])]
    got = ",".join(str(b - a) for a, b in zip(times, times[1:]))
    return None if got == want else f"gaps between edges of {name}: {got}, expected {want}"


def check_period(signals, spec):
    name, want = spec.split("=", 1)
    period, high = (int(x) for x in want.split(","))
    rises = [t for t, v in signals.get(name, []) if v]
    falls = [t for t, v in signals.get(name, []) if not v]
    if len(rises) < 3:
        return f"{name} has only {len(rises)} rising edges"
    for a, b in zip(rises, rises[1:]):
        if b - a != period:
            return f"{name} period {b - a} at cycle {a}, expected {period}"
    for r in rises:
        f = next((x for x in falls if x > r), None)
        if f is not None and f - r != high:
            return f"{name} high for {f - r} cycles at {r}, expected {high}"
    return None


def run_prusim(prusim, elves, args, vcd, skip):
    cmd = [prusim, "--json", "--vcd", vcd] + args
    for core, elf in elves.items():
        cmd += [f"--pru{core}", elf]
    if not skip:
        cmd.append("--no-skip")
    p = subprocess.run(cmd, capture_output=True, text=True)
    lines = [x for x in p.stdout.splitlines() if x.startswith("{")]
    return p.returncode, (json.loads(lines[-1]) if lines else None), p.stderr


def run_test(src, opts):
    name = os.path.relpath(src, opts.testdir)
    d = parse_directives(src)
    try:
        elves = {c: build(src, c, opts.out, opts.tools, opts.ld) for c in d["cores"]}
    except subprocess.CalledProcessError as e:
        return [f"FAIL: {name}: build failed: {(e.stderr or e.stdout).strip()}"]
    base = os.path.join(opts.out, os.path.splitext(os.path.basename(src))[0])
    rc, res, err = run_prusim(opts.prusim, elves, d["args"], base + ".vcd", True)
    rc2, res2, _ = run_prusim(opts.prusim, elves, d["args"], base + ".noskip.vcd", False)
    problems = []
    if rc != d["exit"]:
        problems.append(f"exit status {rc}, expected {d['exit']} ({err.strip()})")
    if res is None:
        problems.append("no JSON output")
    else:
        for exp in d["expect"]:
            try:
                p = check_expect(res, exp)
            except (KeyError, IndexError, ValueError) as e:
                p = f"bad expectation {exp!r}: {e}"
            if p:
                problems.append(p)
        signals = vcd_signals(base + ".vcd")
        problems += [p for p in (check_edges(signals, e) for e in d["edges"]) if p]
        problems += [p for p in (check_gaps(signals, e) for e in d["gaps"]) if p]
        problems += [p for p in (check_period(signals, e) for e in d["period"]) if p]
    lines = [f"FAIL: {name}: " + "; ".join(problems) if problems else f"PASS: {name}"]
    with open(base + ".vcd") as a, open(base + ".noskip.vcd") as b:
        same_vcd = a.read() == b.read()
    if res == res2 and rc == rc2 and same_vcd:
        lines.append(f"PASS: skip-exact {name}")
    else:
        lines.append(f"FAIL: skip-exact {name}: results differ with --no-skip")
    return lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--prusim", required=True)
    ap.add_argument("--tools", required=True, help="directory with pru-as, pru-ld, pru-gcc")
    ap.add_argument("--out", required=True)
    ap.add_argument("--testdir", required=True)
    ap.add_argument("--ld", action="append", default=[], help="extra pru-ld argument")
    ap.add_argument("tests", nargs="+")
    opts = ap.parse_args()
    os.makedirs(opts.out, exist_ok=True)
    failed = 0
    for src in opts.tests:
        for line in run_test(src, opts):
            print(line, flush=True)
            failed += line.startswith("FAIL")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
