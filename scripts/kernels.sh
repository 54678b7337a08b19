#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# kernels.sh [--build-only] [SERIES...]
#
# Cross-build every prukit module for ARM against Debian's armmp kernels
# (default: 5.10 6.1 6.12) with W=1 and warnings as errors, then run sparse
# (C=2) over our sources and fail on any sparse warning in them.  Each build
# happens in out/kernels/<release>/ so the source tree stays clean.  Prints
# the vermagic of every module built, and "PASS:/FAIL:" lines.  With
# --build-only: just the builds (for the VM harness).
set -euo pipefail
. "$(dirname "$0")/lib.sh"

build_only=0
if [ "${1:-}" = --build-only ]; then
	build_only=1
	shift
fi
[ $# -gt 0 ] || set -- 5.10 6.1 6.12
need_pkgs gcc-arm-linux-gnueabihf sparse kmod make bc bison flex libssl-dev libelf-dev

cross=arm-linux-gnueabihf-
failed=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; failed=1; }

# Copy what kbuild needs (and nothing it built before) into a build tree.
copy_sources() {
	local dest=$1
	rm -rf "$dest"
	mkdir -p "$dest"
	(cd "$PRUKIT_TOP" &&
		find Kbuild include drivers sim tests/kmod -type f \( -name Kbuild -o -name '*.c' -o -name '*.h' \) \
			-print0 | xargs -0 cp --parents -t "$dest")
}

while read -r series kver kdir _root; do
	out=$PRUKIT_TOP/out/kernels/$kver
	copy_sources "$out"
	log=$out/build.log
	kcflags=-Werror
	extra=(CONFIG_PRUKIT_TEST_MODULES=m)
	# A kernel without rpmsg (Debian's 5.10 armmp; TI's 5.10 has it) gets
	# the kernel's own rpmsg modules built beside it, so that rpmsg users
	# are still compiled and linked against the real interface.
	if ! grep -q '^CONFIG_RPMSG=[ym]' "$kdir/.config"; then
		kit=$("$PRUKIT_TOP/scripts/rpmsg-kit.sh" "$series" "$kdir" "$out-rpmsg-kit")
		kcflags="$kcflags -DCONFIG_RPMSG_MODULE=1"
		extra+=(CONFIG_RPMSG=m KBUILD_EXTRA_SYMBOLS="$kit/Module.symvers")
		echo "  ($kver has no CONFIG_RPMSG: rpmsg_core built from linux-source-$series)"
	fi
	kmake=(make -C "$kdir" M="$out" ARCH=arm CROSS_COMPILE=$cross CC=${cross}gcc
	       W=1 KCFLAGS="$kcflags" "${extra[@]}" -j"$(ncpus)")
	if "${kmake[@]}" modules >"$log" 2>&1 && ! grep -qi 'warning' "$log"; then
		pass "build $kver (W=1, -Werror)"
	else
		grep -iE 'warning|error' "$log" | head -n 30
		fail "build $kver, see $log"
		continue
	fi

	[ $build_only -eq 1 ] && continue

	# Sparse over our sources: C=2 checks every file whether rebuilt or not.
	slog=$out/sparse.log
	"${kmake[@]}" C=2 CHECK="sparse" modules >"$slog" 2>&1 || true
	ours=$(grep -E ': (warning|error):' "$slog" | grep -F "$out/" || true)
	if [ -z "$ours" ] && grep -q ' CHECK ' "$slog"; then
		pass "sparse $kver ($(grep -c ' CHECK ' "$slog") files)"
	else
		printf '%s\n' "$ours" | head -n 30
		fail "sparse $kver, see $slog"
	fi

	while IFS= read -r -d '' ko; do
		printf '  %-28s %s\n' "$(basename "$ko")" "$(modinfo -F vermagic "$ko")"
	done < <(find "$out" -name '*.ko' -print0 | sort -z)
done < <("$PRUKIT_TOP/scripts/fetch-kernels.sh" "$@")

exit $failed
