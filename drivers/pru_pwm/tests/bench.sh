#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/pru_pwm/tests/bench.sh - the pru_pwm driver's make bench
# figures.  Counts, not timings:
#  - the PWM chip: channels, resolution, the shortest period, the duty
#    range settable in 5 ns steps and the highest frequency with 8 and with
#    10 bits of it, from the firmware's gaps (pru_pwm_proto.h), with the
#    firmware itself in prusim at that range's ends and at 100 kHz
#    (bench.py: edges exact, none late);
#  - the ARM's work per duty update: instructions of pru_pwm_table_build()
#    (drivers/pru_pwm/pru_pwm_table.c, built unchanged for the host) per
#    update of one of eight servo channels, counted by callgrind, and the
#    MMIO words the driver writes per update;
#  - beside them, the Robotics Control Library's servo figures as the PRU
#    Cookbook gives them.
# Prints BENCH: lines; exits non-zero if something failed (a FAIL: line
# says what).  Works in out/tests/pru_pwm-bench.
set -euo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP"

command -v python3 >/dev/null || need_pkgs python3

out=$PRUKIT_TOP/out/tests/pru_pwm-bench
mkdir -p "$out"

make -s -C drivers/pru_pwm/tests/table O="$out" all >"$out/build.log" 2>&1 || {
	cat "$out/build.log"
	echo "FAIL: building drivers/pru_pwm/tests/table (pru_pwm_table.c on the host)"
	exit 1
}
n=10000
ir=$(callgrind_ir pru_pwm_table_build "$out/pwm_bench" "$out/pwm_bench" "$n") || {
	echo "$ir"
	exit 1
}
words=$(python3 -c 'import sys
sys.path.insert(0, "drivers/pru_pwm/tests")
import pwm_sim
print(pwm_sim.TABLE_BYTES // 4)')
awk -v ir="$ir" -v n="$n" -v words="$words" -v cc="$(${CC:-cc} --version | head -n 1)" \
	'BEGIN {
		printf "BENCH: pru_pwm duty update, ARM: %.0f instructions to build the table " \
		       "(pru_pwm_table_build(), 8 servo channels enabled, one duty changed; " \
		       "callgrind, host build: %s -O2; %d instructions for %d updates), then %d " \
		       "32-bit MMIO writes of the table and 2 of the command, and a wait of at " \
		       "most one period for the switch\n", ir / n, cc, ir, n, words
	}'

prusim_and_images "$out" pru_pwm-pru1.elf pwm-poke-pru0.elf || exit 1
make -s -C drivers/pru_pwm/tests/table O="$out" "$out/pwm_table" >/dev/null
mkdir -p "$out/run"
python3 drivers/pru_pwm/tests/bench.py "$PRUKIT_TOP/out/tools/prusim" "$out/fw" \
	"$out/pwm_table" "$out/run"
