#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/pru_encoder/tests/bench.sh - the pru_encoder driver's make bench
# figures, all PRU cycle counts the simulator measured on the real firmware
# (drivers/pru_encoder/tests/check.sh and enc_sim.py, whose PASS lines
# carry them): the sample gap with no change and per decoding path, the
# highest edge rate counted without a miss (in any direction, and one
# way), and the event latency (an input edge to the R31 strobe of the
# PRU -> ARM event).  Prints BENCH: lines; exits non-zero if the checks
# failed.
set -euo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP"

out=$PRUKIT_TOP/out/tests/pru_encoder-bench
mkdir -p "$out"
drivers/pru_encoder/tests/check.sh >"$out/check.log" 2>&1 || {
	grep '^FAIL' "$out/check.log" || tail -n 20 "$out/check.log"
	exit 1
}
python3 - "$out/check.log" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
idle = int(re.search(r"sample gap without a change: (\d+) cycles", log).group(1))
worst = int(re.search(r"worst path \(reversal, underflow, index, strobe\): gap \[(\d+)\]", log).group(1))
paths = [int(x) for x in re.search(r"sample gaps per path \(irq not armed\): \[([0-9, ]+)\]",
                                    log).group(1).split(",")]
fwd = int(re.search(r"(\d+) steps forward, (\d+) cycles apart: count", log).group(2))
bwd = int(re.search(r"(\d+) steps backward from \d+, (\d+) cycles apart: count", log).group(2))
one_way = max(fwd, bwd)
print("BENCH: pru_encoder decoding, PRU cycles per sample (prusim, the real firmware): %d with "
      "no change, %d-%d by decoding path (a step forward %d, backward %d), %d for the worst "
      "change (reversal, underflow, index and the event)"
      % (idle, min(paths), max(paths), fwd, bwd, worst))
print("BENCH: pru_encoder highest edge rate without a miss: %.2f M edges/s in any direction "
      "(changes %d cycles apart: A and B at %.2f MHz, x4), %.1f M edges/s turning one way "
      "(%d cycles apart); beyond, two changes between samples are a skipped state (counted, "
      "reported), three or more may alias to a wrong step no decoder can tell"
      % (200 / worst, worst, 200 / worst / 4, 200 / one_way, one_way))
print("BENCH: pru_encoder event latency: at most %d PRU cycles (%d ns) from an input edge to the "
      "event's R31 strobe (a sample gap and the worst path); the ARM's share is the "
      "interrupt's, in the VM the test port's irq_latency (not a board figure)"
      % (idle + worst, 5 * (idle + worst)))
PY
