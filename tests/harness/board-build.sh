#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# What a board's build does without the development machine's caches:
# - on an ARM machine without pru-gcc, scripts/pru-toolchain.sh and make
#   firmware stop at once with what to install instead of building GCC for
#   hours; a pru-gcc on PATH (BeagleBoard's gcc-pru) is used as it is.  The
#   machine is faked with PRUKIT_HOST_MACHINE (uname -m's stand-in), and
#   PATH holds no pru-gcc unless the check puts a stub there;
# - make overlays with an empty cache builds every overlay from what the
#   checkout holds (prukit's dt-bindings headers): no linux-source fetched.
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
n=$(find overlays -maxdepth 1 -name '*.dtso' | wc -l)
mkdir -p "$tmp/cache"
if PRUKIT_CACHE=$tmp/cache timeout 120 make -s -C "$top" overlays >"$tmp/out" 2>&1 &&
	[ "$(find out/overlays -maxdepth 1 -name '*.dtbo' | wc -l)" -eq "$n" ] &&
	[ -z "$(ls -A "$tmp/cache")" ]; then
	pass "make overlays with an empty cache: all $n overlays built, nothing fetched or cached"
else
	sed -n 1,20p "$tmp/out"
	ls -A "$tmp/cache"
	fail "make overlays with an empty cache: all $n overlays built, nothing fetched or cached"
fi

printf '/dts-v1/;\n/plugin/;\n#include <dt-bindings/pinctrl/am33xx.h>\n/ { x = <AM335X_PIN_NO_SUCH_PAD>; };\n' \
	>"$tmp/bad.dtso"
if PRUKIT_CACHE=$tmp/cache scripts/dtso-build.sh "$tmp/bad.dtso" "$tmp/bad.dtbo" \
	>"$tmp/out" 2>&1; then
	fail "an overlay using a pad macro prukit's headers lack does not build"
elif [ ! -e "$tmp/bad.dtbo" ] && grep -q "bad.dtso:4" "$tmp/out"; then
	pass "an overlay using a pad macro prukit's headers lack fails, naming its line"
else
	cat "$tmp/out"
	fail "an overlay using a pad macro prukit's headers lack fails, naming its line"
fi
exit $failed
