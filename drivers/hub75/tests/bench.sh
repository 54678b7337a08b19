#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/hub75/tests/bench.sh - the hub75 driver's make bench figures.
# Both are exact counts, not timings:
#  - the PRU's refresh: the real firmware (hub75-pru0.elf, hub75-pru1.elf)
#    in prusim on the all-R30 map (one 64x32 panel, two and eight chained),
#    on the PocketScroller's (data through GPIO bank 1), on outdoor panels,
#    at 12 bit planes, and on the Octoscroller's wall (24 64x32 panels on
#    8 outputs, every line on GPIO, 12 planes; against Falcon Player's
#    published figure and the physical limit of prusim's L4 path): refresh
#    length in PRU cycles and Hz, pixel clock, the share of time rows are
#    lit; every pixel of every layout decoded and checked on the way
#    (hub75_sim.py --bench);
#  - the ARM's work per damaged frame: instructions per pixel of
#    hub75_convert() (drivers/hub75/hub75_conv.c, built unchanged for the
#    host by tests/conv/Makefile) converting a whole 64x32 XRGB8888 frame
#    into 8 bit planes, and a whole frame of the Octoscroller wall into
#    GPIO bank words at 12 planes, counted by callgrind.
# Prints BENCH: lines; exits non-zero if something failed (a FAIL: line
# says what).  Works in out/tests/hub75-bench.
set -euo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP"

command -v python3 >/dev/null || need_pkgs python3

out=$PRUKIT_TOP/out/tests/hub75-bench
mkdir -p "$out"

# 1. The conversion, on the host, under callgrind
make -s -C drivers/hub75/tests/conv O="$out" "$out/conv_test" >"$out/conv-build.log" 2>&1 || {
	cat "$out/conv-build.log"
	echo "FAIL: building drivers/hub75/tests/conv/conv_test"
	exit 1
}
frames=10
ir=$(callgrind_ir hub75_convert "$out/conv_bench" "$out/conv_test" bench "$frames") || {
	echo "$ir"
	exit 1
}
cc=$(${CC:-cc} --version | head -n 1)
awk -v n="$ir" -v f="$frames" -v arch="$(uname -m)" -v cc="$cc" 'BEGIN {
	printf "BENCH: hub75 conversion of a damaged frame into bit planes: %.1f instructions " \
	       "per pixel (64x32 XRGB8888, 8 planes, CIE 1931; callgrind, host build of " \
	       "drivers/hub75/hub75_conv.c: %s, %s -O2; %d instructions for %d frames)\n",
	       n / (f * 64 * 32), arch, cc, n, f
}'

# ... and a whole frame of the Octoscroller wall (every line on GPIO banks)
frames=2
ir=$(callgrind_ir hub75_convert "$out/conv_bench_banks" "$out/conv_test" bench-banks "$frames") || {
	echo "$ir"
	exit 1
}
awk -v n="$ir" -v f="$frames" -v arch="$(uname -m)" -v cc="$cc" 'BEGIN {
	printf "BENCH: hub75 conversion of a whole frame of the Octoscroller wall (24 64x32 " \
	       "panels, 8 outputs x 3, 192x256 XRGB8888, 12 planes, CIE 1931) into GPIO bank " \
	       "words: %.1f instructions per pixel (callgrind, host build of " \
	       "drivers/hub75/hub75_conv.c: %s, %s -O2; %d instructions for %d frames)\n",
	       n / (f * 192 * 256), arch, cc, n, f
}'

# 2. The refresh, from the real firmware in prusim
prusim_and_images "$out" hub75-pru0.elf hub75-pru1.elf || exit 1
mkdir -p "$out/run"
rc=0
python3 drivers/hub75/tests/hub75_sim.py "$PRUKIT_TOP/out/tools/prusim" "$out/fw" "$out/run" \
	--bench >"$out/hub75_sim.log" 2>&1 || rc=$?
grep -E '^(BENCH|FAIL):' "$out/hub75_sim.log"
echo "INFO: hub75 for comparison (not measured here): Falcon Player's PRU code clocks" \
	"HUB75 panels at about 2-6 MHz (about 507 ns a clock through OCP GPIO), and refreshes" \
	"24 64x32 panels at 12 bits at 40-101 Hz; the PRU Cookbook's C loop (rgb1.c) at 2.9 MHz"
rm -rf "$out/run"
exit "$rc"
