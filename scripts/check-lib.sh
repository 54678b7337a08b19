# shellcheck shell=bash
# SPDX-License-Identifier: GPL-2.0-only
# make check's step(), sourced by scripts/check.sh and by the harness's own
# self-test (tests/harness/selftest.sh).  The caller sets log (a file the
# steps' output is appended to), passed and failed (the running totals), and
# runs without "set -e": a step's failure is counted, it does not end make
# check.  If the caller sets fails (a file), each FAIL: line is appended
# there too, after its step's name, so that make check can repeat them at
# its end, where the tail of a CI log shows them.

. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

# step NAME MIN CMD... - run CMD, show its PASS:/FAIL: lines and add them to
# passed and failed.  The step fails (at least one failure counted, with a
# FAIL: line saying why) if it printed a FAIL: line, if it exited non-zero
# whatever it printed, or if fewer than MIN checks ran.
step() {
	local name=$1 min=$2 rc n p f out s
	local -a st
	shift 2
	msg "== $name: $* (at least $min checks)"
	s=$(date +%s)
	out=$(mktemp)
	# shellcheck disable=SC2154 # log is the caller's
	"$@" 2>&1 | tee -a "$log" | tee "$out" | grep -E '^(PASS|FAIL):|^  \S+\.ko '
	# Nothing may run between the pipeline and this line: any command,
	# even "|| true", replaces PIPESTATUS with its own.
	st=("${PIPESTATUS[@]}")
	rc=${st[0]}
	p=$(grep -c '^PASS:' "$out")
	f=$(grep -c '^FAIL:' "$out")
	n=$((p + f))
	if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
		tail -n 20 "$out"
		echo "FAIL: $name exited with status $rc" | tee -a "$log" "$out"
		f=1
	fi
	if [ "$n" -lt "$min" ]; then
		echo "FAIL: $name: $n checks ran, at least $min expected" |
			tee -a "$log" "$out"
		f=$((f + 1))
	fi
	if [ -n "${fails:-}" ]; then
		grep '^FAIL:' "$out" | sed "s/^/[$name] /" >>"$fails"
	fi
	rm -f "$out"
	passed=$((passed + p))
	failed=$((failed + f))
	msg "== $name: $p passed, $f failed ($(( $(date +%s) - s )) s)"
}
