#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# pru-rproc-build.sh - prove that prukit's pru_rproc_get() path compiles.
#
# None of Debian's armmp kernels has the kernel's own PRU remoteproc driver,
# so the path of drivers/prukit_pru that takes cores with pru_rproc_get()
# (include/compat.h: PRUKIT_HAVE_PRU_RPROC_GET) is never built by
# kernels.sh.  This configures Debian's 6.12 source with Debian's armmp
# configuration plus CONFIG_TI_PRUSS=m and CONFIG_PRU_REMOTEPROC=m (as TI's
# and BeagleBoard's kernels have them), prepares it for external modules
# (kept in $PRUKIT_CACHE), builds prukit's modules against it with W=1
# -Werror, and checks that prukit_pru.ko calls pru_rproc_get() and
# pru_rproc_put().  It proves compilation only: no kernel here runs that
# driver, so the path is untested at run time.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs gcc-arm-linux-gnueabihf make bc bison flex libssl-dev libelf-dev kmod
cross=arm-linux-gnueabihf-
series=6.12

read -r _ kver kdir _ < <("$PRUKIT_TOP/scripts/fetch-kernels.sh" "$series")
src=$("$PRUKIT_TOP/scripts/linux-source.sh" "$series" full)
obj=$PRUKIT_CACHE/pru-rproc-$kver
kmake=(make -C "$src" O="$obj" ARCH=arm CROSS_COMPILE=$cross CC=${cross}gcc -j"$(ncpus)")

if [ ! -e "$obj/.prukit-prepared" ]; then
	msg "preparing linux-source-$series with CONFIG_PRU_REMOTEPROC=m in $obj"
	rm -rf "$obj"
	mkdir -p "$obj"
	cp "$kdir/.config" "$obj/.config"
	"$src/scripts/config" --file "$obj/.config" \
		--enable SOC_TI --module TI_PRUSS --module TI_PRUSS_INTC --module PRU_REMOTEPROC \
		--disable DEBUG_INFO_BTF --disable GCC_PLUGINS \
		--set-str MODULE_SIG_KEY "" --set-str SYSTEM_TRUSTED_KEYS "" \
		--set-str SYSTEM_REVOCATION_KEYS ""
	run_logged "$obj/olddefconfig.log" "${kmake[@]}" olddefconfig
	grep -q '^CONFIG_PRU_REMOTEPROC=m' "$obj/.config" ||
		die "CONFIG_PRU_REMOTEPROC did not stay enabled (see $obj/.config)"
	run_logged "$obj/modules_prepare.log" "${kmake[@]}" modules_prepare
	touch "$obj/.prukit-prepared"
fi

out=$PRUKIT_TOP/out/kernels/$kver-pru-rproc
rm -rf "$out"
mkdir -p "$out"
(cd "$PRUKIT_TOP" &&
	find Kbuild include drivers sim tests/kmod -type f \( -name Kbuild -o -name '*.c' -o -name '*.h' \) \
		-print0 | xargs -0 cp --parents -t "$out")
log=$out/build.log
# No vmlinux symbol list in a prepared tree: modpost only warns (about
# every kernel symbol); the compiler must not warn at all.
if ! make -C "$obj" M="$out" ARCH=arm CROSS_COMPILE=$cross CC=${cross}gcc W=1 \
	KCFLAGS=-Werror KBUILD_MODPOST_WARN=1 CONFIG_PRUKIT_TEST_MODULES=m \
	-j"$(ncpus)" modules >"$log" 2>&1 || grep -qE ': (warning|error):' "$log"; then
	grep -E ': (warning|error):|Error' "$log" | head -n 20
	echo "FAIL: build against $kver with CONFIG_PRU_REMOTEPROC=m, see $log"
	exit 1
fi
echo "PASS: build against $kver with CONFIG_PRU_REMOTEPROC=m (W=1, -Werror)"
ko=$out/drivers/prukit_pru/prukit_pru.ko
if ${cross}nm -u "$ko" | grep -qw pru_rproc_get && ${cross}nm -u "$ko" | grep -qw pru_rproc_put; then
	echo "PASS: prukit_pru takes cores with pru_rproc_get()/pru_rproc_put() there"
else
	echo "FAIL: prukit_pru.ko does not call pru_rproc_get()/pru_rproc_put() with CONFIG_PRU_REMOTEPROC=m"
	exit 1
fi
if ${cross}nm -u "$out/../$kver/drivers/prukit_pru/prukit_pru.ko" 2>/dev/null | grep -qw pru_rproc_get; then
	echo "FAIL: the armmp build of prukit_pru calls pru_rproc_get(), which that kernel lacks"
	exit 1
fi
