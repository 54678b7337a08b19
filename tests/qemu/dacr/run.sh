#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# What a guest sees after it writes DACR, the ARMv7 Domain Access Control
# Register (cp15 c3).  QEMU's ARM TCG does not keep a translation's domain
# in its TLB, so QEMU 7.2 flushes the whole TLB, and with it the jump cache
# of translated code, on every DACR write.  A QEMU that flushes less (only
# on a reduction, only when a translation from that domain may be cached)
# must still give the guest exactly the architectural behaviour: every
# load, store and instruction fetch that the new DACR forbids faults, every
# one it allows works, however hot the translation or the code was.
#
# A bare-metal Cortex-A15 program (start.S, dacr.c) maps 1 MB sections and
# 4 KB pages in domains 1 and 2 and, over many rounds, changes DACR between
# loads, stores and calls (a thousand calls at a time, so that the called
# code is hot in the jump cache); its abort handlers record DFSR/DFAR and
# IFSR/IFAR and resume.  It also runs code in user mode (PL0), in domain 3,
# as Linux does: entered by an exception return (or a CPS), back to PL1 by
# an SVC, with DACR changed at PL1 in between; a QEMU that keeps PL0 code
# in its jump cache, or flushes its TLB only for some MMU indexes, across
# such a write must still fault every access the new value forbids.
# 18 checks:
#   load-domain           client and manager loads work, noaccess loads take
#                         a section domain fault at the address
#   store-manager-client  manager stores work on PL1 read-only data, client
#                         ones take a permission fault (a reduction)
#   fetch-manager-client  a hot function in an XN section runs as manager
#                         (which ignores XN) and as client takes a prefetch
#                         abort, also after a domain-2 reduction between
#   same-value            rewriting the DACR value it holds changes nothing
#   fetch-hot             a hot function in domain 1: client calls return
#                         42, noaccess calls take a prefetch abort
#   data-then-fetch       code first read as data still runs; noaccess stops it
#   other-domain          reducing data-only domain 2 leaves domain-1 code
#                         running and faults domain-2 loads; a later domain-1
#                         reduction still stops the code
#   page-domain           the same for 4 KB pages (second-level table)
#   user-fetch-revoke     a hot user function whose domain PL1 revokes
#                         takes a prefetch abort on the return to user mode
#   user-fetch-restore    revoked, then granted again before the return: it
#                         runs (what Linux does on every kernel entry)
#   user-fetch-revoke-again  revoked, granted, revoked again: it aborts
#   user-fetch-cps        the same when user mode is entered by CPS and a
#                         branch instead of an exception return
#   user-fetch-other-domain  domain 1 reduced too, in the same DACR write or
#                         another: the user function aborts exactly when its
#                         own domain ends revoked
#   user-manager-client   manager to client on a PL1-only (by AP) section:
#                         hot user fetches and loads take permission faults
#   user-data-revoke      data hot at PL1 and PL0: after a revoke a PL1 load,
#                         an LDRT and a PL0 load each take a domain fault
#   user-data-pl0-only    data hot at PL0 only: after a revoke an LDRT at PL1
#                         (no PL1 load between) takes a domain fault
#   user-data-pl1-only    data hot at PL1 only: after a revoke a PL0 load
#                         and an LDRT take a domain fault
#   readback              DACR reads back as written
#
# The program runs twice, on two vexpress-a15 CPUs:
#   no-el2-el3  secure=off,virtualization=off: a CPU with one DACR and no
#               stage 2, where a QEMU may flush less on a DACR write;
#   el2-el3     the board's default (EL3 and EL2, as prukit's VM boots it;
#               a non-Linux ELF starts in Secure SVC mode).
# Each prints one PASS:/FAIL: line per check, and one that it reached its
# end marker.  A check without a result line (the program crashed, hung or
# never ran) is a FAIL; so are a failed build, a QEMU exit status other
# than 0 and a timeout (60 s).
#
# usage: run.sh QEMU_BINARY [OUT_DIR]   (or O=OUT_DIR; by default a
# temporary directory, removed at the end).  CROSS_COMPILE defaults to
# arm-linux-gnueabihf-.  The exit status is 0 only if every line is PASS.
set -euo pipefail
trap 'echo "FAIL: dacr: run.sh stopped at line $LINENO"' ERR

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
	echo "usage: $0 QEMU_BINARY [OUT_DIR]" >&2
	exit 2
fi
qemu=$1
out=${2:-${O:-}}
here=$(cd "$(dirname "$0")" && pwd)
cc=${CROSS_COMPILE:-arm-linux-gnueabihf-}gcc
checks=(load-domain store-manager-client fetch-manager-client same-value
	fetch-hot data-then-fetch other-domain page-domain
	user-fetch-revoke user-fetch-restore user-fetch-revoke-again
	user-fetch-cps user-fetch-other-domain user-manager-client
	user-data-revoke user-data-pl0-only user-data-pl1-only readback)
configs=("no-el2-el3 vexpress-a15,secure=off,virtualization=off"
	"el2-el3 vexpress-a15")

if [ -z "$out" ]; then
	out=$(mktemp -d)
	trap 'rm -rf "$out"' EXIT
fi
mkdir -p "$out"

failed=0
pass() { echo "PASS: dacr: $*"; }
fail() { echo "FAIL: dacr: $*"; failed=$((failed + 1)); }

cflags=(-O2 -g -Wall -Wextra -Werror -ffreestanding -nostdlib -static
	-marm -march=armv7-a -mfloat-abi=soft -mno-unaligned-access
	-fno-pie -no-pie -fno-stack-protector -fno-asynchronous-unwind-tables
	-T "$here/dacr.ld")
if ! "$cc" "${cflags[@]}" -o "$out/dacr.elf" "$here/start.S" \
	"$here/dacr.c" >"$out/build.log" 2>&1; then
	cat "$out/build.log"
	fail "build of the test program with $cc failed"
	for config in "${configs[@]}"; do
		for c in "${checks[@]}"; do
			fail "${config%% *}: $c: not run"
		done
	done
	exit 1
fi

export QEMU_AUDIO_DRV=none
for config in "${configs[@]}"; do
	name=${config%% *}
	machine=${config#* }
	log=$out/$name.log
	echo "--- $name: -M $machine"
	rc=0
	timeout -k 10 60 "$qemu" -M "$machine" -cpu cortex-a15 -m 256 -nographic \
		-semihosting -no-reboot -kernel "$out/dacr.elf" \
		</dev/null >"$log.raw" 2>&1 || rc=$?
	tr -d '\r' <"$log.raw" >"$log"
	cat "$log"

	for c in "${checks[@]}"; do
		line=$(grep -m1 "^dacr: result $c " "$log" || true)
		case $line in
		"dacr: result $c pass "*)
			pass "$name: $c: ${line#"dacr: result $c pass "}"
			;;
		"dacr: result $c fail "*)
			fail "$name: $c: ${line#"dacr: result $c fail "}"
			;;
		*)
			fail "$name: $c: no result (the program stopped before it)"
			;;
		esac
	done
	if [ "$rc" -eq 124 ]; then
		fail "$name: QEMU timed out after 60 s"
	elif [ "$rc" -ne 0 ]; then
		fail "$name: QEMU ($qemu) exited with status $rc"
	fi
	if grep -qx 'dacr: end' "$log"; then
		pass "$name: program reached its end marker"
	else
		fail "$name: program did not reach its end marker ('dacr: end')"
	fi
done

exit $((failed > 0))
