# SPDX-License-Identifier: GPL-2.0-only
# Helpers for VM tests (sourced in the guest).

vmtest_failed=0

# check NAME CMD... - run CMD, print PASS/FAIL NAME
check() {
	name=$1
	shift
	if "$@" >/tmp/check.out 2>&1; then
		echo "PASS: $name"
	else
		echo "FAIL: $name"
		sed 's/^/    /' /tmp/check.out | head -n 20
		vmtest_failed=1
	fi
}

done_testing() {
	exit $vmtest_failed
}
