#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make check: every step CI runs, in order.  Each step prints PASS:/FAIL:
# lines; a step that fails without saying what failed counts as one failure.
# Everything it needs is installed or built on the way (and cached under
# $PRUKIT_CACHE); nothing is skipped because a cache is missing.  The last
# line is "N passed, N failed"; the exit status is non-zero on any failure.
set -uo pipefail
. "$(dirname "$0")/lib.sh"

cd "$PRUKIT_TOP"
mkdir -p out
log=out/check.log
: >"$log"
passed=0
failed=0
t0=$(date +%s)

step() {
	local name=$1 rc p f out
	shift
	msg "== $name: $*"
	local s=$(date +%s)
	out=$(mktemp)
	"$@" 2>&1 | tee -a "$log" | tee "$out" | grep -E '^(PASS|FAIL):|^  \S+\.ko ' || true
	rc=${PIPESTATUS[0]}
	p=$(grep -c '^PASS:' "$out")
	f=$(grep -c '^FAIL:' "$out")
	if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
		tail -n 20 "$out"
		echo "FAIL: $name exited with status $rc" | tee -a "$log"
		f=1
	fi
	rm -f "$out"
	passed=$((passed + p))
	failed=$((failed + f))
	msg "== $name: $p passed, $f failed ($(( $(date +%s) - s )) s)"
}

firmware_check() {
	local bin
	bin=$(scripts/pru-toolchain.sh) || return 1
	CROSS_COMPILE=$bin/pru- O="$PRUKIT_TOP/out/firmware" firmware/check.sh
}

prusim_check() {
	make -s -C tools/prusim && tests/prusim/run.sh
}

step checkpatch scripts/checkpatch.sh
step kernels scripts/kernels.sh 5.10 6.1 6.12
step firmware firmware_check
step overlays scripts/overlays.sh
step dkms scripts/dkms-test.sh
step prusim prusim_check
step rpmsg-fw tests/rpmsg-fw/run.sh
step kunit scripts/kunit.sh
step vmtest scripts/vm.sh test "5.10 6.1 6.12"

msg "make check took $(( $(date +%s) - t0 )) s; log in $log"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
