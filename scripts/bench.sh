#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make bench: speed figures, measured, never asserted (these machines are
# shared and noisy).  PRU time itself is exact and is not a benchmark.
#   - prusim on one host core, both PRU cores busy (tests/prusim/bench.sh)
#   - the simulator in the VM (Debian 6.1 under QEMU TCG, the QEMU
#     PRU-ICSS): simulated cycles per second with both cores running
#     blinky, beside the prusim tool on the host running the same firmware
#     in the same run (the ratio); the PRU-consumer layer's command round
#     trip in PRU cycles; rpmsg echo round trips and bytes per second each
#     way through /dev/rpmsg_pru30 on the kernel's pru_rproc with
#     prukit_pru's kick, and simulated PRU cycles per round trip
#   - PRU cycles the firmware spends per received and per sent rpmsg message
#     and from kick to kick (exact: counted by the simulator in
#     tests/rpmsg-fw, not timed)
#   - the PRU -> ARM event latency in PRU cycles (it reflects the emulation's
#     rule of holding simulated time while the ARM has an interrupt it has
#     not taken, not a board)
#   - ws281x, 48 strings x 600 LEDs: the ARM's instructions per LED to
#     convert a frame (callgrind, host build of drivers/ws281x/ws281x_conv.c)
#     and the PRU cycles and frames per second of the real firmware in
#     prusim (exact; drivers/ws281x/tests/bench.sh)
#   - beaglelogic: PRU cycles between two samples at each rate and the
#     trigger position error (exact, prusim), and the largest one-shot
#     100 Msps capture with zero loss in the VM
#     (drivers/beaglelogic/tests/bench.sh)
#   - hub75: the refresh of the real firmware in prusim (PRU cycles and Hz,
#     pixel clock; one, two and eight chained 64x32 panels on the all-R30
#     map, one on the PocketScroller's) and the ARM's instructions per pixel
#     to turn a damaged frame into bit planes (callgrind, host build of
#     drivers/hub75/hub75_conv.c; drivers/hub75/tests/bench.sh)
#   - pru_pwm: channels, resolution, periods, the duty range settable
#     exactly and the highest frequency with 8 and 10 bits of it (from the
#     firmware's gaps, checked in prusim), and the ARM's instructions per
#     duty update (callgrind, host build of drivers/pru_pwm/pru_pwm_table.c;
#     drivers/pru_pwm/tests/bench.sh)
#   - pru_encoder: PRU cycles per sample and decoding path, the highest
#     edge rate counted without a miss, the event latency (prusim, the real
#     firmware; drivers/pru_encoder/tests/bench.sh)
#   - prukit-pixeld: the parse + map instructions per pixel of an E1.31
#     universe, an OPC message and a DDP packet (callgrind, in-process: the
#     CPython interpreter's on the host, not a board's), the universes per
#     CPU-second the daemon handles on one host core over loopback and the
#     fraction of such a core 48 strings x 600 pixels at the wire rate need,
#     and the packet-to-write latency, median and 99th percentile, alone and
#     under abuse (tools/pixeld/tests/bench.sh)
#   - the 900-cycle stop/start stress under rpmsg I/O on 6.1 and 6.12
#     (leaks per cycle, page poisoning), too long for make check
#
# Usage: bench.sh [PART...] (make bench [PARTS="..."]): the parts named, in
# the order above, or all of them: prusim rpmsg-fw ws281x beaglelogic hub75 pwm
# encoder pixeld vm stress.  Whatever the parts, the host tools and the
# firmware are built first (a fresh clone needs nothing else).
set -euo pipefail
. "$(dirname "$0")/lib.sh"
# The VM parts boot with the PRUs on their own thread (vm.sh's threaded
# clock, not make vmtest's lockstep default): the model's speed is the
# simulation thread's, comparable with earlier figures, and the stress is
# timed for it.  PRUKIT_VM_CLOCK=lockstep make bench runs them in lockstep.
export PRUKIT_VM_CLOCK=${PRUKIT_VM_CLOCK:-thread}

ALL_PARTS="prusim rpmsg-fw ws281x beaglelogic hub75 pwm encoder pixeld vm stress"
for p in "$@"; do
	[[ " $ALL_PARTS " == *" $p "* ]] || die "bench: no part '$p' (parts: $ALL_PARTS)"
done
want() { [ "$PARTS_GIVEN" = 0 ] || [[ $PARTS == *" $1 "* ]]; }
PARTS=" $* "
PARTS_GIVEN=$#

make -s -C "$PRUKIT_TOP" tools firmware >/dev/null
out=$PRUKIT_TOP/out/bench
mkdir -p "$out"
if want prusim; then
	"$PRUKIT_TOP/tests/prusim/bench.sh"
fi
if want rpmsg-fw; then
	"$PRUKIT_TOP/tests/rpmsg-fw/run.sh" >"$PRUKIT_TOP/out/rpmsg-fw-bench.log" 2>&1 ||
		die "tests/rpmsg-fw failed; see out/rpmsg-fw-bench.log"
	sed -n 's/^PASS: \(echo-pru0: cycles per message\)/BENCH: rpmsg firmware \1 (exact)/p' \
		"$PRUKIT_TOP/out/rpmsg-fw-bench.log" | sed 's/; /\n       /g'
fi
# bench_part NAME SCRIPT SHOWN: a part's own bench script, its log in
# out/NAME-bench.log; its lines matching ^(SHOWN): are printed, and on a
# failure its FAIL: and INFO: lines before make bench stops.
bench_part() {
	local log=$PRUKIT_TOP/out/$1-bench.log
	"$PRUKIT_TOP/$2" >"$log" 2>&1 ||
		{ grep -E '^(FAIL|INFO):' "$log" || true
		  die "$2 failed; see out/$1-bench.log"; }
	grep -E "^($3):" "$log"
}
want ws281x && bench_part ws281x drivers/ws281x/tests/bench.sh BENCH
want beaglelogic && bench_part beaglelogic drivers/beaglelogic/tests/bench.sh 'BENCH|INFO'
want hub75 && bench_part hub75 drivers/hub75/tests/bench.sh 'BENCH|INFO'
want pwm && bench_part pru_pwm drivers/pru_pwm/tests/bench.sh BENCH
want encoder && bench_part pru_encoder drivers/pru_encoder/tests/bench.sh BENCH
want pixeld && bench_part pixeld tools/pixeld/tests/bench.sh BENCH
if want vm; then
	# The simulator's speed, side by side: the same firmware (blinky on both
	# cores) in the host tool, then in the VM.
	host_mcps=$(python3 - "$PRUKIT_TOP/out/tools/prusim" "$PRUKIT_TOP/out/firmware" <<'PY'
import json, resource, subprocess, sys
prusim, fw = sys.argv[1:]
cmd = [prusim, "--pru0", fw + "/blinky-pru0.elf", "--pru1", fw + "/blinky-pru1.elf",
       "--max-cycles", "400000000", "--json"]
res = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
ru = resource.getrusage(resource.RUSAGE_CHILDREN)
print("%.2f" % (res["cycles"] / (ru.ru_utime + ru.ru_stime) / 1e6))
PY
	)
	echo "BENCH: prusim host tool, blinky on both cores: $host_mcps M simulated cycles per CPU second"
	# the model's own speed: without the jitter knob's random pauses
	# (PRUKIT_VM_JITTER=SEED measures with them)
	PRUKIT_VM_JITTER=${PRUKIT_VM_JITTER:-0} \
		"$PRUKIT_TOP/scripts/vm.sh" run "${PRUKIT_VM_KVER:-6.1}" "$PRUKIT_TOP/tests/vm/bench/guest" "" "$out/guest" \
		>"$out/guest.log" 2>&1 || { tail -n 20 "$out/guest.log"; die "the bench guest failed"; }
	grep -E '^(BENCH|INFO):' "$out/guest.log" || true
	python3 - "$host_mcps" "$out/guest.log" <<'PY'
import re, sys
host = float(sys.argv[1])
def mcps(log):
    for line in open(log):
        m = re.search(r"blinky on both cores: ([0-9.]+) M simulated cycles per second of simulation", line)
        if m:
            return float(m.group(1))
    return None
board = mcps(sys.argv[2])
if board:
    print("BENCH: simulator speed, blinky on both cores, PRU cycles per second of simulation "
          "time: the QEMU PRU-ICSS %.1f M = %.0f%% of the host tool's %.1f M"
          % (board, 100 * board / host, host))
PY
fi
# The long stop/start stress (900 cycles under rpmsg I/O, page_poison=1),
# on the kernel's pru_rproc with prukit_pru's kick (Documentation/rpmsg-kick.rst):
# not a speed figure, but too long for make check.  Its checks count: a
# FAIL line, a splat or a run that does not finish fails make bench.
# About 0.4 s per cycle under TCG (900 cycles took 384 s on 6.12, 376 s on
# 6.1); the boot gets 80 minutes all the same: the host may be shared (up to
# 3x slower, measured), and a regression should fail here, not time out.
want stress || exit 0
rc=0
for k in ${BENCH_STRESS_KVERS:-${PRUKIT_VM_KVER:-6.1 6.12}}; do
	VM_TIMEOUT=${VM_TIMEOUT:-4800} \
		"$PRUKIT_TOP/scripts/vm.sh" run "$k" \
		"$PRUKIT_TOP/tests/vm/bench/stop-stress" "" "$out/stress-$k" \
		>"$out/stress-$k.log" 2>&1 || rc=$?
	grep -E '^(PASS|FAIL|INFO):' "$out/stress-$k.log" | sed "s/^/$k: /" || true
	if [ "$rc" -ne 0 ]; then
		tail -n 5 "$out/stress-$k.log"
		die "the $k stop/start stress failed (exit $rc); see $out/stress-$k.log"
	fi
done
