#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/ws281x/tests/bench.sh - the ws281x driver's make bench figures,
# for 48 strings x 600 RGB LEDs (two cores, 24 strings each: 8 on R30, 16
# on GPIO pins).  Both are exact counts, not timings:
#  - the ARM's work per frame: instructions per LED of ws281x_convert()
#    (drivers/ws281x/ws281x_conv.c, built unchanged for the host by
#    tests/conv/Makefile) converting both cores' slots, counted by
#    callgrind; and those of the conversion it replaced (tests/conv/legacy.c);
#  - the PRU's time per frame: the real firmware (ws281x-pruN.elf) in
#    prusim, from slot 0's start to the frame's event, and frames per
#    second at 200 MHz, with the worst edge error per pin kind
#    (frame_bench.py).
# Prints BENCH: lines; exits non-zero if something failed (a FAIL: line
# says what).  Works in out/tests/ws281x-bench.
set -euo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP"

command -v python3 >/dev/null || need_pkgs python3

out=$PRUKIT_TOP/out/tests/ws281x-bench
mkdir -p "$out"

# 1. The conversion, on the host, under callgrind
make -s -C drivers/ws281x/tests/conv O="$out" "$out/conv_bench" >"$out/conv-build.log" 2>&1 || {
	cat "$out/conv-build.log"
	echo "FAIL: building drivers/ws281x/tests/conv/conv_bench"
	exit 1
}
declare -A ir
for which in new legacy; do
	fn=ws281x_convert
	[ "$which" = legacy ] && fn=ws281x_legacy_convert
	ir[$which]=$(callgrind_ir "$fn" "$out/conv_bench.$which" "$out/conv_bench" "$which") || {
		echo "${ir[$which]}"
		exit 1
	}
done
leds=$(sed -n 's/.* \([0-9]*\) LEDs, checksum.*/\1/p' "$out/conv_bench.new.log")
cc=$(${CC:-cc} --version | head -n 1)
awk -v n="${ir[new]}" -v o="${ir[legacy]}" -v leds="$leds" -v arch="$(uname -m)" -v cc="$cc" \
	'BEGIN {
		printf "BENCH: ws281x conversion: %.1f instructions per LED (48 strings x 600 LEDs, " \
		       "callgrind, host build of drivers/ws281x/ws281x_conv.c: %s, %s -O2; " \
		       "%d instructions for %d LEDs)\n", n / leds, arch, cc, n, leds
		printf "BENCH: ws281x conversion it replaced (set bit by set bit after a memset, " \
		       "tests/conv/legacy.c): %.1f instructions per LED (%.1fx)\n",
		       o / leds, o / n
	}'

# 2. The frame, from the real firmware in prusim
prusim_and_images "$out" ws281x-pru0.elf ws281x-pru1.elf || exit 1
fw=$out/fw
mkdir -p "$out/run"
rc=0
# shellcheck disable=SC2086 # the cores are words
python3 drivers/ws281x/tests/frame_bench.py "$PRUKIT_TOP/out/tools/prusim" "$fw" "$out/run" \
	${WS281X_BENCH_CORES:-0 1} >"$out/frame_bench.log" 2>&1 || rc=$?
grep -E '^(BENCH|FAIL):' "$out/frame_bench.log"
rm -rf "$out/run"
exit "$rc"
