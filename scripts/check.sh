#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make check: every step CI runs, in order.  Each step prints PASS:/FAIL:
# lines; a step that exits non-zero counts as failed whatever it printed
# (one failure if it said nothing failed), and so does a step that runs
# fewer checks than the minimum next to it below (scripts/check-lib.sh).
# Everything it needs is installed or built on the way (and cached under
# $PRUKIT_CACHE); nothing is skipped because a cache is missing.  The last
# line is "N passed, N failed"; the exit status is non-zero on any failure.
set -uo pipefail
. "$(dirname "$0")/check-lib.sh"

cd "$PRUKIT_TOP" || exit 1
mkdir -p out
log=out/check.log
: >"$log"
fails=out/check-failures.log
: >"$fails"
passed=0
failed=0
t0=$(date +%s)

firmware_check() {
	local bin
	bin=$(scripts/pru-toolchain.sh) || return 1
	CROSS_COMPILE=$bin/pru- O="$PRUKIT_TOP/out/firmware" firmware/check.sh
}

# The harness checks itself: step() (selftest.sh), that a driver's
# folder is found by the builds, make install and the harnesses
# (discovery.sh), that a board without pru-gcc is not sent into a GCC
# bootstrap, nor overlays a kernel source (board-build.sh), and that the VM
# splat check reads the kernel's lines, not the tests' (splat.sh).
harness_check() {
	local rc=0
	tests/harness/selftest.sh || rc=1
	tests/harness/discovery.sh || rc=1
	tests/harness/board-build.sh || rc=1
	tests/harness/splat.sh || rc=1
	return $rc
}

prusim_check() {
	make -s -C tools/prusim && tests/prusim/run.sh
}

# The QEMU of the VM's board path: Debian's 7.2 with prukit's PRU-ICSS
# (scripts/qemu-build.sh; about 10 CPU minutes cold, then cached), and
# with qemu/arm-dacr.patch: a bare-metal program checks that loads, stores
# and fetches still fault exactly as DACR says (tests/qemu/dacr); and the
# AM335x blocks as QEMU's monitor sees them (one device per block, at its
# address, out of reset) and as its qtest protocol drives them (PRCM's
# lines to the PRU-ICSS and the GPIO banks): tests/qemu/blocks.
qemu_check() {
	local bin rc=0
	bin=$(scripts/qemu-build.sh) || { echo "FAIL: scripts/qemu-build.sh"; return 1; }
	if "$bin" -M vexpress-a15,help 2>&1 | grep -q '^ *pruss='; then
		echo "PASS: qemu-system-arm with the AM335x PRU-ICSS (-M vexpress-a15,pruss=on): $bin"
	else
		echo "FAIL: $bin has no vexpress-a15 option pruss"
		rc=1
	fi
	need_pkgs gcc-arm-linux-gnueabihf
	tests/qemu/dacr/run.sh "$bin" out/tests/qemu-dacr || rc=1
	tests/qemu/blocks/run.sh "$bin" out/tests/qemu-blocks || rc=1
	return $rc
}

# step NAME MIN COMMAND: MIN is the fewest checks (PASS: and FAIL: lines) the
# step must run, a little below what a clean clone gives (in brackets; they
# only grow as tests are added).  The harness checks itself first.
step harness 60 harness_check				# [67]
step checkpatch 125 scripts/checkpatch.sh		# [131], one per C file
# Debian's three kernels as shipped and as a board's (with the kernel's
# own PRU drivers), BeagleBoard's 5.10-ti and Debian's 6.12 with TI's PRU
# drivers (Documentation/kernels.rst)
step kernels 31 scripts/kernels.sh 5.10 6.1 6.12 5.10-ti 6.12-ti	# [33]
step qemu 95 qemu_check					# [101]
step firmware 185 firmware_check				# [193], grows with the images
step overlays 950 scripts/overlays.sh --check		# [978]
step dkms 32 scripts/dkms-test.sh			# [35]: 5.10 (no rpmsg_pru: no CONFIG_RPMSG), 6.1, 6.12, 5.10-ti
step deb 63 scripts/deb.sh --check			# [67]: 4 packages, lintian
step tool 33 tests/tool/test-prukit.py			# [35]: the prukit command on the host
step pixeld 150 tools/pixeld/tests/check.sh		# [163]: prukit-pixeld on the host, fuzzed, abused
step prusim 145 prusim_check				# [151]
step rpmsg-fw 75 tests/rpmsg-fw/run.sh			# [81]
# Each driver's own checks, drivers/<driver>/tests/check.sh, with the
# minimum its line "# prukit-check-min: N" declares (driver_checks,
# scripts/lib.sh).  Read on fd 3: a step may read its standard input.
while read -r name min path <&3; do
	if [ "$min" = none ]; then
		step "driver-$name" 1 echo "FAIL: $path declares no \"# prukit-check-min: N\" line"
	else
		step "driver-$name" "$min" "$path"
	fi
done 3< <(driver_checks)
step kunit 14 scripts/kunit.sh				# [15]
# The VM tests on the kernels boards run and on mainline's drivers: BeagleBoard's
# 5.10-ti, Debian's 6.1 and 6.12, and 6.12 with TI's PRU drivers (Debian's
# 5.10 is left to "make vmtest KVERS=5.10": a board on 5.10 runs TI's), each
# with the PRUs in lockstep with the guest's clock (one CPU a boot, the
# longest first); and a few tests on 6.1 with the PRUs on their own thread,
# the clock make bench and make vmdeb use.
step vmtest 5600 scripts/vm.sh test "6.12-ti 6.12 6.1 5.10-ti 6.1@thread"	# [~7600], 4 kernels, one boot each (and a second for 71)
# The Debian packages on a Debian root in the VM (6.1): installed with apt,
# upgraded, used, removed, purged (cold: debootstrap's second stage first,
# once: here under qemu-user, about 2.5 minutes, or in the VM, about 7).
step vmdeb 24 scripts/vm.sh deb 6.1			# [26]
# The harness again: make vmrun, vmtest and bench from a copy with no out/
# (after the VM tests, so that a cold run has its QEMU and kernels cached).
step fresh-clone 5 tests/harness/fresh-clone.sh		# [5]

# The failures again, at the end, where the tail of a CI log shows them.
if [ -s "$fails" ]; then
	echo "The failed checks ($failed; out/check-failures.log):"
	head -n 40 "$fails"
	# the VM's boots, to replay a failure under the same jitter
	grep -h "jitter seed" "$log" | sort -u | head -n 12
fi
msg "make check took $(( $(date +%s) - t0 )) s; log in $log"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
