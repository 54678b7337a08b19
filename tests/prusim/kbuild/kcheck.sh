#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# kcheck.sh [SERIES...] - cross-build the prusim core as kernel code for
# Debian's armmp kernels (default 5.10 6.1 6.12) with W=1 -Werror and run
# sparse over it.  Prints PASS:/FAIL: lines; exits non-zero on a failure.
set -euo pipefail
. "$(dirname "$0")/../../../scripts/lib.sh"

[ $# -gt 0 ] || set -- 5.10 6.1 6.12
need_pkgs gcc-arm-linux-gnueabihf sparse make bc bison flex libssl-dev libelf-dev
cross=arm-linux-gnueabihf-
failed=0

while read -r _series kver kdir _root; do
	out=$PRUKIT_TOP/out/tests/prusim/kbuild/$kver
	rm -rf "$out"
	mkdir -p "$out"
	cp "$PRUKIT_TOP"/sim/*.[ch] "$PRUKIT_TOP"/tests/prusim/kbuild/{Kbuild,kcheck.c} "$out"
	kmake=(make -C "$kdir" M="$out" ARCH=arm CROSS_COMPILE=$cross CC=${cross}gcc
	       W=1 KCFLAGS=-Werror -j"$(ncpus)")
	if "${kmake[@]}" modules >"$out/build.log" 2>&1 && ! grep -qi warning "$out/build.log"; then
		echo "PASS: prusim kernel build $kver (W=1, -Werror)"
	else
		grep -iE 'warning|error' "$out/build.log" | head -n 20
		echo "FAIL: prusim kernel build $kver, see $out/build.log"
		failed=1
		continue
	fi
	"${kmake[@]}" C=2 CHECK=sparse modules >"$out/sparse.log" 2>&1 || true
	ours=$(grep -E ': (warning|error):' "$out/sparse.log" | grep -F "$out/" || true)
	if [ -z "$ours" ] && grep -q ' CHECK ' "$out/sparse.log"; then
		echo "PASS: prusim sparse $kver"
	else
		printf '%s\n' "$ours" | head -n 20
		echo "FAIL: prusim sparse $kver, see $out/sparse.log"
		failed=1
	fi
done < <("$PRUKIT_TOP/scripts/fetch-kernels.sh" "$@")
exit $failed
