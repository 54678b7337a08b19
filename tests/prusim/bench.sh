#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Simulated cycles per second of prusim on one host core for a busy
# two-core firmware (bench.S: ALU loop, DRAM store and load, R30 toggle on
# both cores).  Prints the figure; there is no pass/fail on speed.
#
# usage: tests/prusim/bench.sh [CYCLES]   (default 500000000)
set -euo pipefail
. "$(dirname "$0")/../../scripts/lib.sh"

cycles=${1:-500000000}
out=$PRUKIT_TOP/out/tests/prusim/bench
mkdir -p "$out"
bin=$("$PRUKIT_TOP/scripts/pru-toolchain.sh")
make -s -C "$PRUKIT_TOP/tools/prusim" >/dev/null
prusim=$PRUKIT_TOP/out/tools/prusim

for core in 0 1; do
	"$bin/pru-as" --defsym PRU="$core" -o "$out/bench$core.o" "$PRUKIT_TOP/tests/prusim/bench.S"
	"$bin/pru-ld" -o "$out/bench$core.elf" "$out/bench$core.o"
done

# CPU time of the simulator process (the machine may be shared), and wall time
python3 - "$prusim" "$out" "$cycles" <<'PY'
import json, resource, subprocess, sys, time
prusim, out, cycles = sys.argv[1:]
cmd = ["taskset", "-c", "0", prusim, "--pru0", f"{out}/bench0.elf", "--pru1", f"{out}/bench1.elf",
       "--max-cycles", cycles, "--json"]
t0 = time.monotonic()
res = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
wall = time.monotonic() - t0
ru = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = ru.ru_utime + ru.ru_stime
insns = sum(p["instructions"] for p in res["pru"])
print(f"prusim bench: {res['cycles']} cycles, {insns} instructions, {res['pin_changes']} pin changes")
print(f"prusim bench: {cpu:.2f} s CPU, {wall:.2f} s wall on one host core")
print(f"prusim bench: {res['cycles'] / cpu / 1e6:.1f} M simulated cycles/s (CPU time), "
      f"{res['cycles'] / wall / 1e6:.1f} M (wall time)")
PY
