#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# kernels.sh [--build-only [--board]] [SERIES...]
#
# Cross-build every prukit module for ARM against Debian's armmp kernels
# (default: 5.10 6.1 6.12) with W=1 and warnings as errors, then run sparse
# (C=2) over our sources and fail on any sparse warning in them.  Each
# kernel is built twice:
#  - as Debian ships it (out/kernels/<release>/): no PRU drivers of its own;
#  - as a BeagleBone kernel has it ("board", out/kernels/<release>-board/):
#    with the kernel's own pruss, pruss_intc and pru_rproc, built from
#    Debian's linux-source by scripts/pru-kit.sh (out/kernels/<release>-pru-kit/)
#    and prukit compiled with CONFIG_PRU_REMOTEPROC, CONFIG_TI_PRUSS and
#    CONFIG_TI_PRUSS_INTC as modules, against their Module.symvers.  There the
#    PRU-consumer layer takes its cores with pru_rproc_get() where the
#    kernel has it (6.12; include/compat.h) and with its fallback where not
#    (5.10, 6.1), as on a board with that kernel - checked with nm.  This is
#    what the VM's board path loads (scripts/vm.sh).
# The source tree stays clean.  Prints the vermagic of every module built,
# and "PASS:/FAIL:" lines.  With --build-only: just the builds, the first
# variant, or with --board the second (for the VM harness).
set -euo pipefail
. "$(dirname "$0")/lib.sh"

build_only=0
variants="armmp board"
if [ "${1:-}" = --build-only ]; then
	build_only=1
	variants=armmp
	shift
	if [ "${1:-}" = --board ]; then
		variants=board
		shift
	fi
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
		find Kbuild include drivers sim tests/kmod -type f \( -name Kbuild -o -name '*.c' -o -name '*.h' \
			-o -path drivers/registry -o -path drivers/registry.mk -o -path drivers/gate.mk \) \
			-print0 | xargs -0 cp --parents -t "$dest")
}

# build_variant SERIES KVER KDIR VARIANT
build_variant() {
	local series=$1 kver=$2 kdir=$3 variant=$4 out log slog kit pkit ko ours
	local kcflags=-Werror extra=(CONFIG_PRUKIT_TEST_MODULES=m) symvers=()
	out=$PRUKIT_TOP/out/kernels/$kver
	[ "$variant" = board ] && out=$out-board
	copy_sources "$out"
	log=$out/build.log
	# A kernel without rpmsg (Debian's 5.10 armmp; TI's 5.10 has it) gets
	# the kernel's own rpmsg modules built beside it, so that rpmsg users
	# are still compiled and linked against the real interface.
	if ! grep -q '^CONFIG_RPMSG=[ym]' "$kdir/.config"; then
		kit=$("$PRUKIT_TOP/scripts/rpmsg-kit.sh" "$series" "$kdir" \
			"$PRUKIT_TOP/out/kernels/$kver-rpmsg-kit")
		kcflags="$kcflags -DCONFIG_RPMSG_MODULE=1"
		extra+=(CONFIG_RPMSG=m)
		symvers+=("$kit/Module.symvers")
		echo "  ($kver has no CONFIG_RPMSG: rpmsg_core built from linux-source-$series)"
	fi
	# Nor has it the counter subsystem (Debian's armmp; a BeagleBone's
	# kernel has it, for eQEP): the kernel's own counter core built beside
	# it, where its interface is the one prukit's counter drivers are
	# written for (not 5.10: include/compat.h; pru_encoder is not built
	# there, as on any kernel without CONFIG_COUNTER).
	if ! grep -q '^CONFIG_COUNTER=[ym]' "$kdir/.config"; then
		kit=$("$PRUKIT_TOP/scripts/counter-kit.sh" "$series" "$kdir" \
			"$PRUKIT_TOP/out/kernels/$kver-counter-kit")
		if [ -n "$kit" ]; then
			kcflags="$kcflags -DCONFIG_COUNTER_MODULE=1"
			extra+=(CONFIG_COUNTER=m)
			symvers+=("$kit/Module.symvers")
			echo "  ($kver has no CONFIG_COUNTER: counter built from linux-source-$series)"
		fi
	fi
	if [ "$variant" = board ]; then
		pkit=$("$PRUKIT_TOP/scripts/pru-kit.sh" "$series" "$kdir" \
			"$PRUKIT_TOP/out/kernels/$kver-pru-kit") || {
			fail "the kernel's PRU drivers for $kver (scripts/pru-kit.sh)"
			return
		}
		kcflags="$kcflags -DCONFIG_PRU_REMOTEPROC_MODULE=1 -DCONFIG_TI_PRUSS_MODULE=1"
		kcflags="$kcflags -DCONFIG_TI_PRUSS_INTC_MODULE=1"
		symvers+=("$pkit/Module.symvers")
	fi
	[ ${#symvers[@]} -eq 0 ] || extra+=(KBUILD_EXTRA_SYMBOLS="${symvers[*]}")
	kmake=(make -C "$kdir" M="$out" ARCH=arm CROSS_COMPILE=$cross CC=${cross}gcc
	       W=1 KCFLAGS="$kcflags" "${extra[@]}" -j"$(ncpus)")
	if "${kmake[@]}" modules >"$log" 2>&1 && ! grep -qi 'warning' "$log"; then
		pass "build $kver ($variant; W=1, -Werror)"
	else
		grep -iE 'warning|error' "$log" | head -n 30
		fail "build $kver ($variant), see $log"
		return
	fi
	# The VM's stand-in for TI's rpmsg_pru (tests/kmod/ti): prukit's module
	# name, so a build of its own.
	if [ "$variant" = board ]; then
		rm -rf "$out-ti"
		mkdir -p "$out-ti"
		cp "$PRUKIT_TOP"/tests/kmod/ti/* "$out-ti/"
		if make -C "$kdir" M="$out-ti" ARCH=arm CROSS_COMPILE=$cross CC=${cross}gcc W=1 \
			CONFIG_PRUKIT_TEST_MODULES=m -j"$(ncpus)" modules >"$out-ti/build.log" 2>&1 &&
			[ -e "$out-ti/rpmsg_pru.ko" ] && ! grep -qi 'warning' "$out-ti/build.log"; then
			pass "build $kver (TI's rpmsg_pru's stand-in for the VM; W=1, -Werror)"
		else
			grep -iE 'warning|error' "$out-ti/build.log" | head -n 10
			fail "build $kver (TI's rpmsg_pru's stand-in), see $out-ti/build.log"
		fi
	fi

	[ $build_only -eq 1 ] && return

	# Sparse over our sources: C=2 checks every file whether rebuilt or not.
	slog=$out/sparse.log
	"${kmake[@]}" C=2 CHECK="sparse" modules >"$slog" 2>&1 || true
	ours=$(grep -E ': (warning|error):' "$slog" | grep -F "$out/" || true)
	if [ -z "$ours" ] && grep -q ' CHECK ' "$slog"; then
		pass "sparse $kver ($variant; $(grep -c ' CHECK ' "$slog") files)"
	else
		printf '%s\n' "$ours" | head -n 30
		fail "sparse $kver ($variant), see $slog"
	fi

	# How the consumer layer takes its cores: pru_rproc_get() only where
	# the kernel has its PRU remoteproc driver and the function (6.12's
	# <linux/remoteproc/pruss.h>), the fallback everywhere else.
	ko=$out/drivers/prukit_pru/prukit_pru.ko
	if ${cross}nm -u "$ko" | grep -qw pru_rproc_get; then
		if [ "$variant" = board ] && grep -qw pru_rproc_get "$pkit/Module.symvers"; then
			pass "prukit_pru takes cores with pru_rproc_get() on $kver ($variant)"
		else
			fail "prukit_pru calls pru_rproc_get(), which $kver ($variant) lacks"
		fi
	elif [ "$variant" = board ] && grep -qw pru_rproc_get "$pkit/Module.symvers"; then
		fail "prukit_pru does not call pru_rproc_get(), which $kver ($variant) has"
	else
		pass "prukit_pru takes cores with rproc_get_by_phandle() on $kver ($variant: no pru_rproc_get())"
	fi

	while IFS= read -r -d '' ko; do
		printf '  %-28s %s\n' "$(basename "$ko")" "$(modinfo -F vermagic "$ko")"
	done < <(find "$out" -name '*.ko' -print0 | sort -z)
}

while read -r series kver kdir _root; do
	for variant in $variants; do
		build_variant "$series" "$kver" "$kdir" "$variant"
	done
done < <("$PRUKIT_TOP/scripts/fetch-kernels.sh" "$@")

exit $failed
