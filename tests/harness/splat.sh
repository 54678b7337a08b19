#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# The VM harness's splat check (scripts/vm.sh kernel_log_clean, through
# "vm.sh log-check") reads what the kernel wrote, not what a test printed:
# a console on which a test says "PASS: dmesg: no Oops/BUG/WARNING" is
# clean (a clean kernel once failed make vmrun on that line), a kernel
# WARNING, BUG or Oops is not - on a line of its own, after a test's output
# on the same console line, or in the dmesg the guest saved - and neither is
# a line the PRU-ICSS model logged, unless a test said it makes that line on
# purpose, and how often (model-log-expected).  One PASS:/FAIL: line per
# case.
set -uo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0

clean_boot='[    0.000000] Booting Linux on physical CPU 0x0
prukit-vm: 6.1.0-50-armmp, 2 CPUs, mode test
[    5.340634] prukit_pru: pru-rproc 4a334000.pru: remoteproc1: rpmsg kick and vring interrupt by prukit
PASS: 70-rpmsg-echo: no Oops/BUG/WARNING in dmesg
INFO: a test quoting "Kernel panic" and "BUG: KASAN" in its own words
PRUKIT-VM-EXIT 0'

# expect NAME WANT(0 clean, 1 not) CONSOLE DMESG [QEMU-LOG [MODEL-LOG-EXPECTED]]
# (the last: a test's out/<test>/model-log-expected, "COUNT TEXT" lines)
expect() {
	local what=$1 want=$2 d=$tmp/$RANDOM got
	mkdir -p "$d/out"
	printf '%s\n' "$3" >"$d/console.log"
	printf '%s\n' "$4" >"$d/out/dmesg.txt"
	printf '%s\n' "${5:-}" >"$d/qemu.log"
	if [ -n "${6:-}" ]; then
		mkdir -p "$d/out/15-board"
		printf '%s\n' "$6" >"$d/out/15-board/model-log-expected"
	fi
	"$top/scripts/vm.sh" log-check "$d" "$d/out" >"$d/result" 2>&1
	got=$?
	[ "$got" -eq 0 ] || got=1
	if [ "$got" -eq "$want" ]; then
		echo "PASS: splat check: $what"
	else
		echo "FAIL: splat check: $what: exit $got, want $want"
		sed 's/^/    /' "$d/result"
		bad=1
	fi
}

expect "a clean boot whose tests print the words the check looks for is clean" 0 \
	"$clean_boot" "[    1.000000] pruss 4a300000.pruss: creating PRU cores"
expect "a kernel WARNING on the console is a splat" 1 \
	"$clean_boot
[   12.345678] WARNING: CPU: 1 PID: 80 at kernel/irq/manage.c:1893 free_irq+0x2f8/0x330" ""
expect "a kernel BUG after a test's output on the same console line is a splat" 1 \
	"$clean_boot
PASS: 80-rpmsg-robust: read returns[   20.000001] BUG: KASAN: use-after-free in pru_kick_vring_thread" ""
expect "an Oops in the guest's dmesg is a splat" 1 \
	"$clean_boot" "[    3.000000] Internal error: Oops: 817 [#1] SMP ARM"
expect "a hung task in the guest's dmesg is a splat" 1 \
	"$clean_boot" "[  250.000000] INFO: task modprobe:312 blocked for more than 122 seconds."
expect "a line the PRU-ICSS model logged fails the check" 1 \
	"$clean_boot" "" "am335x-pruss: PRU0 stopped by the simulator: illegal opcode at 0x0040"
expect "an access to the unmodelled rest of L4 (an unimplemented device) fails the check" 1 \
	"$clean_boot" "" "am335x.l4_per: unimplemented device read  (size 4, offset 0x04c13c)"
expect "... a line of vexpress's own devices does not" 0 \
	"$clean_boot" "" "arm_sysctl_read: Bad register offset 0xa8"
gated='am335x-pruss: PRU0 stopped at pc 0x60: OCP read of GPIO bank 1 at 0x4804c134 while its clocks are gated'
expect "the model's lines a test expects, as many times as it says, are clean" 0 \
	"$clean_boot" "" "$gated
$gated" "2 OCP read of GPIO bank 1 at 0x4804c134 while its clocks are gated"
expect "... once more or once less than the test says fails the check" 1 \
	"$clean_boot" "" "$gated" "2 OCP read of GPIO bank 1 at 0x4804c134 while its clocks are gated"
expect "... and so does a line the test did not expect beside them" 1 \
	"$clean_boot" "" "$gated
am335x-pruss: GPIO1 read at 0x000 while PRCM gates its clocks" \
	"1 OCP read of GPIO bank 1 at 0x4804c134 while its clocks are gated"
exit $bad
