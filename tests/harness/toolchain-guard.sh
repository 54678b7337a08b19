#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# On an ARM machine (a board) without pru-gcc, scripts/pru-toolchain.sh and
# make firmware stop at once with what to install instead of building GCC
# for hours; a pru-gcc on PATH (BeagleBoard's gcc-pru) is used as it is.
# The machine is faked with PRUKIT_HOST_MACHINE (uname -m's stand-in), and
# PATH holds no pru-gcc unless the check puts a stub there.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 1
top=$PWD
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; failed=1; }

for m in armv7l aarch64; do
	if PRUKIT_HOST_MACHINE=$m PATH=/usr/sbin:/usr/bin:/sbin:/bin \
		timeout 60 scripts/pru-toolchain.sh >"$tmp/out" 2>"$tmp/err"; then
		fail "$m without pru-gcc: pru-toolchain.sh refuses (it printed $(cat "$tmp/out"))"
	elif grep -q "sudo apt install gcc-pru" "$tmp/err" && grep -q "make deb" "$tmp/err" &&
	     ! grep -qE "installing Debian packages|pru toolchain:" "$tmp/err"; then
		pass "$m without pru-gcc: pru-toolchain.sh refuses at once and names gcc-pru and the prebuilt firmware"
	else
		cat "$tmp/err"
		fail "$m without pru-gcc: pru-toolchain.sh refuses at once and names gcc-pru and the prebuilt firmware"
	fi
done

if PRUKIT_HOST_MACHINE=armv7l PATH=/usr/sbin:/usr/bin:/sbin:/bin \
	timeout 60 make -s -C "$top" firmware >"$tmp/out" 2>"$tmp/err"; then
	fail "armv7l without pru-gcc: make firmware fails"
elif grep -q "sudo apt install gcc-pru" "$tmp/err" && ! grep -q "pru-gcc" "$tmp/out"; then
	pass "armv7l without pru-gcc: make firmware fails with that message, compiling nothing"
else
	cat "$tmp/out" "$tmp/err"
	fail "armv7l without pru-gcc: make firmware fails with that message, compiling nothing"
fi

mkdir -p "$tmp/bin"
printf '#!/bin/sh\nexit 0\n' >"$tmp/bin/pru-gcc"
chmod +x "$tmp/bin/pru-gcc"
if out=$(PRUKIT_HOST_MACHINE=armv7l PATH=$tmp/bin:/usr/sbin:/usr/bin:/sbin:/bin \
	timeout 60 scripts/pru-toolchain.sh 2>/dev/null) && [ "$out" = "$tmp/bin" ]; then
	pass "armv7l with a pru-gcc on PATH (gcc-pru): pru-toolchain.sh uses it"
else
	fail "armv7l with a pru-gcc on PATH (gcc-pru): pru-toolchain.sh uses it (printed '${out:-}')"
fi
exit $failed
