#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/beaglelogic/tests/bench.sh - the beaglelogic driver's make bench
# figures:
#  - PRU cycles between two samples at each rate, measured in prusim on
#    the real firmware with a cycle-counter stimulus, and the trigger
#    position error (the storer's block and the driver's search, as
#    bl_sim.py's refine() does it, against the stimulus' edge) of 8 kinds
#    of trigger (bl_sim.py --bench; exact);
#  - the largest one-shot capture at 100 Msps, 16-bit, that completes
#    with zero loss in the VM (Debian 6.1 under QEMU, 1 GiB;
#    tests/vm/bench-capture).
# Prints BENCH: lines; exits non-zero if something failed (a FAIL: line
# says what).
set -euo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP"

work=$(mktemp -d "${TMPDIR:-/tmp}/prukit-beaglelogic-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
prusim_and_images "$work" beaglelogic-pru0.elf beaglelogic-pru1.elf || exit 1
mkdir -p "$work/run"
python3 drivers/beaglelogic/tests/bl_sim.py --bench "$PRUKIT_TOP/out/tools/prusim" \
	"$work/fw" "$work/run" >"$work/sim.log" || { cat "$work/sim.log"; exit 1; }
grep '^BENCH:' "$work/sim.log"

# (the log beside the VM's OUT directory, which vm.sh empties)
out=$PRUKIT_TOP/out/bench/beaglelogic
log=$PRUKIT_TOP/out/bench/beaglelogic-vm.log
mkdir -p "$out"
"$PRUKIT_TOP/scripts/vm.sh" run 6.1 "$PRUKIT_TOP/drivers/beaglelogic/tests/vm/bench-capture" \
	"" "$out" >"$log" 2>&1 || { tail -n 20 "$log"; exit 1; }
grep -E '^(BENCH|INFO|FAIL):' "$log"
grep -q '^BENCH:' "$log" && ! grep -q '^FAIL:' "$log"
