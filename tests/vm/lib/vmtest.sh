# SPDX-License-Identifier: GPL-2.0-only
# Helpers for VM tests (sourced in the guest).

vmtest_failed=0

# check NAME CMD... - run CMD, print PASS/FAIL NAME
check() {
	local check_name=$1
	shift
	if "$@" >/tmp/check.out 2>&1; then
		echo "PASS: $check_name"
	else
		echo "FAIL: $check_name"
		sed 's/^/    /' /tmp/check.out | head -n 20
		vmtest_failed=1
	fi
}

fail() {
	echo "FAIL: $*"
	vmtest_failed=1
}

pass() {
	echo "PASS: $*"
}

done_testing() {
	exit $vmtest_failed
}

# The simulated PRU-ICSS's debugfs directory: the QEMU device's test port
# (tests/kmod/prusim_port.c).
sim_dir() {
	[ -e /sys/kernel/debug/prusim/stats ] && echo /sys/kernel/debug/prusim
}

# board_path - true if both PRU cores are bound to the kernel's own
# pru-rproc driver (the board path).
board_path() {
	local c
	for c in 4a334000.pru 4a338000.pru; do
		[ "$(basename "$(readlink -f "/sys/bus/platform/devices/$c/driver")")" = pru-rproc ] ||
			return 1
	done
}

# ti_pru_drivers - true on a kernel with TI's PRU drivers (5.10-ti: BeagleBoard's
# whole kernel; 6.12-ti: TI's pru_rproc and pruss_intc on Debian's 6.12),
# whose kick, vring interrupt and INTC differ from mainline's
# (Documentation/kernels.rst).
ti_pru_drivers() {
	case ${PRUKIT_SERIES:-} in *-ti) return 0 ;; esac
	return 1
}

# deny_sysfs_ops - true on a remoteproc core that refuses sysfs stores at
# each write while a driver holds the core (5.10-ti's deny_sysfs_ops);
# elsewhere (sysfs_read_only) the files are read-only, and a descriptor
# opened before still writes.
deny_sysfs_ops() {
	[ "${PRUKIT_SERIES:-}" = 5.10-ti ]
}

# check_board_path - the check every board-path test makes first
check_board_path() {
	check "PRU0 and PRU1 are bound to the kernel's pru-rproc" board_path
}

# pru_rproc N - the remoteproc sysfs directory of PRU N (its device is
# 4a334000.pru / 4a338000.pru).
pru_rproc() {
	local iram r
	case $1 in 0) iram=34000 ;; 1) iram=38000 ;; *) return 1 ;; esac
	for r in /sys/class/remoteproc/remoteproc*; do
		case $(readlink -f "$r/device") in
		*pru@$iram | */4a3$iram.pru) echo "$r"; return 0 ;;
		esac
	done
	return 1
}

# pad_mux OFFSET VALUE - set a pad of the simulated board (what config-pin
# does on BeagleBoard's images): e.g. "pad_mux 0x9a4 0x05" puts P9_27 in
# mode 5, PRU0 R30 bit 5.  Fails for a pad a pinctrl state holds.
pad_mux() {
	echo "$1 $2" >"$(sim_dir)/pads"
}

# pru_state N - state of PRU N in the simulator (disabled/running/halted...)
pru_state() {
	sed -n "s/^pru$1 state \([a-z]*\) .*/\1/p" "$(sim_dir)/stats"
}

# pru_state_unreset N - the state PRU N was left in by its drivers: its
# state, or while PRCM holds the PRU-ICSS in reset (ti-sysc asserts it once
# pruss is unbound, and the reset stops every core), its state as the reset
# came (the model's "icss ... cores_at_last_reset S0 S1")
pru_state_unreset() {
	local icss
	icss=$(sed -n "s/^icss //p" "$(sim_dir)/stats")
	case $icss in
	reset\ *) echo "$icss" | cut -d' ' -f$((7 + $1)) ;;
	*) pru_state "$1" ;;
	esac
}

# wait_pru_state N STATE [SECONDS] - until the simulator reports STATE
wait_pru_state() {
	local i=0
	while [ "$(pru_state "$1")" != "$2" ]; do
		i=$((i + 1))
		[ $i -gt $((${3:-60} * 10)) ] && return 1
		sleep 0.1
	done
}

# rproc_run N FIRMWARE - stop PRU N if it runs, then start FIRMWARE
# (a path relative to /lib/firmware) through remoteproc sysfs.
rproc_run() {
	local r
	r=$(pru_rproc "$1") || return 1
	[ "$(cat "$r/state")" = running ] && echo stop >"$r/state"
	echo "$2" >"$r/firmware" && echo start >"$r/state"
}

rproc_stop() {
	local r
	r=$(pru_rproc "$1") || return 1
	[ "$(cat "$r/state")" = running ] && echo stop >"$r/state"
	return 0
}

# rproc_crash N - report a crash of PRU N as remoteproc's debugfs "crash"
# file does (pru_rproc itself detects none); wait until remoteproc says
# "crashed" (pru_rproc disables recovery).  The PRU itself runs on.
rproc_crash() {
	local r i=0
	r=$(pru_rproc "$1") || return 1
	echo 2 >"/sys/kernel/debug/remoteproc/$(basename "$r")/crash" || return 1
	while [ "$(cat "$r/state")" != crashed ]; do
		i=$((i + 1))
		[ $i -gt 100 ] && return 1
		sleep 0.1
	done
}

# The test consumer's device directory in sysfs.
consumer_dir() {
	local d
	for d in /sys/bus/platform/drivers/pru_test_consumer/*/; do
		[ -e "$d/irq_count" ] && { echo "${d%/}"; return 0; }
	done
	return 1
}

# consumer_load - load the test consumer (tests/kmod/pru_test_consumer.c),
# which takes PRU0 as a prukit driver does: while it is bound, PRU0's
# remoteproc sysfs files that change the core are read-only.  So it is not
# loaded at boot; the tests that use it load it and consumer_unload it.
consumer_load() {
	local i=0
	modprobe pru_test_consumer || return 1
	while ! consumer_dir >/dev/null; do
		i=$((i + 1))
		[ $i -gt 50 ] && return 1
		sleep 0.1
	done
}

consumer_unload() {
	! grep -qw pru_test_consumer /proc/modules || rmmod pru_test_consumer
}
