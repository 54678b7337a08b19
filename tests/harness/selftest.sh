#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make check's own check, its first step: scripts/check-lib.sh's step()
# counts a step that exits non-zero as failed whatever it printed (only
# PASS: lines, or nothing at all), a step that runs fewer checks than its
# minimum as failed, and a good step as passed.  Each case runs step() on a
# small fake step, with its output kept aside (so that the fake steps'
# PASS:/FAIL: lines are not counted as this test's); this test prints one
# PASS:/FAIL: line per case and exits non-zero if any failed.  Takes well
# under a second.
# shellcheck disable=SC2317 # the fake steps run through step()
set -uo pipefail
. "$(dirname "$0")/../../scripts/check-lib.sh"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
log=$tmp/check.log
fails=$tmp/fails
bad=0

# Fake steps.
good() { echo "PASS: one"; echo "PASS: two"; echo "PASS: three"; }
pass_then_exit() { echo "PASS: one"; echo "PASS: two"; return "$1"; }
silent_exit() { return 1; }
says_fail() { echo "PASS: one"; echo "FAIL: two"; }
few() { echo "PASS: one"; echo "PASS: two"; }

# expect NAME PASSED FAILED LINE STEP-ARGS... - run step STEP-ARGS from zero
# totals; passed must be PASSED and failed FAILED, and the step's output must
# hold the line LINE (none if empty) and no FAIL: line if FAILED is 0.
expect() {
	local what=$1 want_p=$2 want_f=$3 line=$4 got
	shift 4
	passed=0
	failed=0
	step "$@" >"$tmp/out" 2>&1
	got="$passed passed, $failed failed"
	if [ "$got" != "$want_p passed, $want_f failed" ]; then
		echo "FAIL: harness: $what: $got, want $want_p passed, $want_f failed"
	elif [ -n "$line" ] && ! grep -qxF -- "$line" "$tmp/out"; then
		echo "FAIL: harness: $what: no line \"$line\" in its output"
	elif [ "$want_f" -eq 0 ] && grep -q '^FAIL:' "$tmp/out"; then
		echo "FAIL: harness: $what: a FAIL: line although it passed"
	else
		echo "PASS: harness: $what ($got)"
		return 0
	fi
	sed 's/^/    /' "$tmp/out"
	bad=1
}

expect "a good step passes" 3 0 "" \
	good 3 good
expect "a step with more checks than its minimum passes" 3 0 "" \
	more 1 good
expect "a step that prints only PASS: lines and exits 3 fails" 2 1 \
	"FAIL: crash exited with status 3" crash 2 pass_then_exit 3
expect "a step that prints nothing and exits 1 fails" 0 1 \
	"FAIL: silent exited with status 1" silent 0 silent_exit
expect "a command that is not found fails" 0 1 \
	"FAIL: missing exited with status 127" missing 0 "$tmp/no-such-command"
expect "a step killed by a signal after PASS: lines fails" 1 1 \
	"FAIL: killed exited with status 137" killed 1 sh -c 'echo "PASS: one"; kill -9 $$'
expect "a step that prints a FAIL: line and exits 0 fails" 1 1 "FAIL: two" \
	fails 2 says_fail
expect "a step that runs 2 checks where at least 5 are expected fails" 2 1 \
	"FAIL: few: 2 checks ran, at least 5 expected" few 5 few
expect "a silent step that exits 0 with a minimum of 1 fails" 0 1 \
	"FAIL: nothing: 0 checks ran, at least 1 expected" nothing 1 true
expect "a step that exits 1 having run too few checks counts both failures" 2 2 \
	"FAIL: both: 2 checks ran, at least 5 expected" both 5 pass_then_exit 1
expect "step() appends the step's output to the log" 0 0 "" \
	logged 0 echo "log line"
if grep -qxF "log line" "$log"; then
	echo "PASS: harness: the log holds the step's output"
else
	echo "FAIL: harness: the log does not hold the step's output"
	bad=1
fi
# Every FAIL: line above, the step's own and step()'s, is in fails once,
# after its step's name (make check repeats them at its end).
want_fails="[crash] FAIL: crash exited with status 3
[silent] FAIL: silent exited with status 1
[missing] FAIL: missing exited with status 127
[killed] FAIL: killed exited with status 137
[fails] FAIL: two
[few] FAIL: few: 2 checks ran, at least 5 expected
[nothing] FAIL: nothing: 0 checks ran, at least 1 expected
[both] FAIL: both exited with status 1
[both] FAIL: both: 2 checks ran, at least 5 expected"
if [ "$(cat "$fails")" = "$want_fails" ]; then
	echo "PASS: harness: the failures file lists every failure once, by step"
else
	echo "FAIL: harness: the failures file is not the failures:"
	sed 's/^/    /' "$fails"
	bad=1
fi
exit "$bad"
