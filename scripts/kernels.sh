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
#    Debian's linux-source by scripts/pru-kit.sh (out/kernels/<tag>-pru-kit/)
#    and prukit compiled with CONFIG_PRU_REMOTEPROC, CONFIG_TI_PRUSS and
#    CONFIG_TI_PRUSS_INTC as modules, against their Module.symvers.  There the
#    PRU-consumer layer takes its cores with pru_rproc_get() where the
#    kernel has it (6.12; include/compat.h) and with its fallback where not
#    (5.10, 6.1), as on a board with that kernel - checked with nm.  This is
#    what the VM's board path loads (scripts/vm.sh).
# The kernels boards run (scripts/lib.sh kernel_flavour) are built once, as
# the board has them: 5.10-ti (BeagleBoard's, with its own PRU drivers and
# rpmsg_pru; out/kernels/<release>-board/) and 6.12-ti (Debian's 6.12 with
# TI's 6.x PRU drivers built by pru-kit.sh; out/kernels/<release>-tipru-board/).
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

# kernel_vermagic IMAGE KVER - the vermagic of the kernel's own modules
# (its image's first module): what a module built for it must carry.
kernel_vermagic() {
	local ko
	ko=$(find "$1/lib/modules/$2/kernel" -name '*.ko*' -print -quit)
	[ -n "$ko" ] && modinfo -F vermagic "$ko"
}

# build_variant SERIES KVER KDIR VARIANT IMAGE
build_variant() {
	local series=$1 kver=$2 kdir=$3 variant=$4 image=$5 tag label out log slog kit pkit ko ours vm bad kvm
	local kcflags=-Werror extra=(CONFIG_PRUKIT_TEST_MODULES=m) symvers=()
	tag=$(kernel_tag "$series" "$kver")
	# what the results name: the release, and a board's kernel by name
	label=$kver
	[ "$(kernel_flavour "$series")" = debian ] || label="$kver, $series"
	out=$PRUKIT_TOP/out/kernels/$tag
	[ "$variant" = board ] && out=$out-board
	copy_sources "$out"
	log=$out/build.log
	# A kernel without rpmsg (Debian's 5.10 armmp; TI's 5.10 has it) gets
	# the kernel's own rpmsg modules built beside it, so that rpmsg users
	# are still compiled and linked against the real interface.
	if ! grep -q '^CONFIG_RPMSG=[ym]' "$kdir/.config"; then
		kit=$("$PRUKIT_TOP/scripts/rpmsg-kit.sh" "${series%-ti}" "$kdir" \
			"$PRUKIT_TOP/out/kernels/$tag-rpmsg-kit")
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
		kit=$("$PRUKIT_TOP/scripts/counter-kit.sh" "${series%-ti}" "$kdir" \
			"$PRUKIT_TOP/out/kernels/$tag-counter-kit")
		if [ -n "$kit" ]; then
			kcflags="$kcflags -DCONFIG_COUNTER_MODULE=1"
			extra+=(CONFIG_COUNTER=m)
			symvers+=("$kit/Module.symvers")
			echo "  ($kver has no CONFIG_COUNTER: counter built from linux-source-$series)"
		fi
	fi
	if [ "$variant" = board ] && grep -q '^CONFIG_PRU_REMOTEPROC=[ym]' "$kdir/.config"; then
		# a board's kernel (5.10-ti): its own PRU drivers, its symbols
		pkit=$kdir
	elif [ "$variant" = board ]; then
		pkit=$("$PRUKIT_TOP/scripts/pru-kit.sh" "$series" "$kdir" \
			"$PRUKIT_TOP/out/kernels/$tag-pru-kit") || {
			fail "the kernel's PRU drivers for $label (scripts/pru-kit.sh)"
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
		pass "build $label ($variant; W=1, -Werror)"
	else
		grep -iE 'warning|error' "$log" | head -n 30
		fail "build $label ($variant), see $log"
		return
	fi
	# The VM's stand-in for TI's rpmsg_pru (tests/kmod/ti): prukit's module
	# name, so a build of its own; not where the kernel has TI's own (5.10-ti).
	if [ "$variant" = board ] && ! grep -q '^CONFIG_RPMSG_PRU=[ym]' "$kdir/.config"; then
		rm -rf "$out-ti"
		mkdir -p "$out-ti"
		cp "$PRUKIT_TOP"/tests/kmod/ti/* "$out-ti/"
		if make -C "$kdir" M="$out-ti" ARCH=arm CROSS_COMPILE=$cross CC=${cross}gcc W=1 \
			CONFIG_PRUKIT_TEST_MODULES=m -j"$(ncpus)" modules >"$out-ti/build.log" 2>&1 &&
			[ -e "$out-ti/rpmsg_pru.ko" ] && ! grep -qi 'warning' "$out-ti/build.log"; then
			pass "build $label (TI's rpmsg_pru's stand-in for the VM; W=1, -Werror)"
		else
			grep -iE 'warning|error' "$out-ti/build.log" | head -n 10
			fail "build $label (TI's rpmsg_pru's stand-in), see $out-ti/build.log"
		fi
	fi

	[ $build_only -eq 1 ] && return

	# Sparse over our sources: C=2 checks every file whether rebuilt or not.
	slog=$out/sparse.log
	"${kmake[@]}" C=2 CHECK="sparse" modules >"$slog" 2>&1 || true
	ours=$(grep -E ': (warning|error):' "$slog" | grep -F "$out/" || true)
	if [ -z "$ours" ] && grep -q ' CHECK ' "$slog"; then
		pass "sparse $label ($variant; $(grep -c ' CHECK ' "$slog") files)"
	else
		printf '%s\n' "$ours" | head -n 30
		fail "sparse $label ($variant), see $slog"
	fi

	# How the consumer layer takes its cores: pru_rproc_get() only where
	# the kernel has its PRU remoteproc driver and the function (6.12's
	# <linux/remoteproc/pruss.h>), the fallback everywhere else.
	ko=$out/drivers/prukit_pru/prukit_pru.ko
	if ${cross}nm -u "$ko" | grep -qw pru_rproc_get; then
		if [ "$variant" = board ] && grep -qw pru_rproc_get "$pkit/Module.symvers"; then
			pass "prukit_pru takes cores with pru_rproc_get() on $label ($variant)"
		else
			fail "prukit_pru calls pru_rproc_get(), which $label ($variant) lacks"
		fi
	elif [ "$variant" = board ] && grep -qw pru_rproc_get "$pkit/Module.symvers"; then
		fail "prukit_pru does not call pru_rproc_get(), which $label ($variant) has"
	else
		pass "prukit_pru takes cores with rproc_get_by_phandle() on $label ($variant: no pru_rproc_get())"
	fi

	# What DKMS on a board checks when the module loads: its vermagic is
	# the kernel's ("<release> SMP preempt mod_unload ..." on 5.10-ti).
	bad=0
	kvm=$(kernel_vermagic "$image" "$kver") || kvm="(none: no module in $image)"
	while IFS= read -r -d '' ko; do
		vm=$(modinfo -F vermagic "$ko")
		printf '  %-28s %s\n' "$(basename "$ko")" "$vm"
		[ "$vm" = "$kvm" ] || bad=1
	done < <(find "$out" -name '*.ko' -print0 | sort -z)
	if [ $bad -eq 0 ]; then
		pass "vermagic of every module built for $label ($variant) is the kernel's: $kvm"
	else
		fail "vermagic of the modules built for $label ($variant) is not the kernel's: $kvm"
	fi
}

while read -r series kver kdir _root image; do
	v=$variants
	# a board's kernel is built once, as the board has it
	[ "$(kernel_flavour "$series")" = debian ] || v=board
	for variant in $v; do
		build_variant "$series" "$kver" "$kdir" "$variant" "$image"
	done
done < <("$PRUKIT_TOP/scripts/fetch-kernels.sh" --image "$@")

exit $failed
