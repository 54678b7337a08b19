#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# qemu-build.sh [--source] - build qemu-system-arm with prukit's AM335x
# PRU-ICSS and print the binary's path (with --source: only fetch and
# unpack the patched source, and print its path).
#
# The VM's board path (scripts/vm.sh) boots Debian's kernels on QEMU's
# vexpress-a15 with "-M vexpress-a15,pruss=on": the PRU-ICSS, the GPIO banks
# and the pad registers at their AM335x addresses (qemu/am335x_pruss.c,
# Documentation/qemu-pruss.rst), run by prukit's simulator (sim/, compiled
# in unchanged).  Without pruss=on the machine is QEMU's own.
#
# Source: Debian bookworm's qemu source package, 7.2 (the newest 1:7.2
# version in bookworm), fetched with deb-src through prukit's private apt
# setup (scripts/papt.sh).  7.2 because it is the QEMU of the distribution
# this project builds on: its build dependencies are bookworm's own (later
# QEMUs need a newer meson than bookworm has), and it is the release of
# bookworm's own qemu-system-arm, which the VM used before.  The VM boots
# this binary.
#
# Two patches: qemu/vexpress-pruss.patch hooks the device into vexpress-a15;
# qemu/arm-dacr.patch changes QEMU's ARM emulation itself, so that a DACR
# write (twice per system call and per copy to or from user space in the
# guest's kernels) flushes only what it can make wrong instead of the whole
# TLB and jump cache (tests/qemu/dacr checks that every access still faults
# or not as the architecture says).
#
# Only the arm system emulator, with only the vexpress boards, no tools,
# no docs (configure as below); about 10 CPU minutes cold.  The binary is
# cached in $PRUKIT_CACHE/qemu/<source version>-<hash>/, the hash taken over
# qemu/, sim/ and this script: a change to the device, the simulator or the
# build rebuilds it, nothing else does; the configured tree beside it makes
# that rebuild incremental.
set -euo pipefail
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/papt.sh"

source_only=0
if [ "${1:-}" = --source ]; then
	# only the patched source tree: print its path (QEMU's checkpatch.pl
	# for qemu/, scripts/checkpatch.sh)
	source_only=1
fi

need_pkgs dpkg-dev gcc make pkg-config python3 meson ninja-build libglib2.0-dev \
	libpixman-1-dev libfdt-dev zlib1g-dev

papt_init
version=$(pcache showsrc qemu 2>/dev/null | sed -n 's/^Version: //p' | grep '^1:7\.2' |
	sort -V | tail -n 1)
[ -n "$version" ] || die "no qemu 7.2 source package in bookworm (deb-src)"
upstream=${version#*:}

hash=$(cd "$PRUKIT_TOP" &&
	cat qemu/* sim/*.c sim/*.h sim/am335x-pins.tsv scripts/qemu-build.sh scripts/pins-header.sh |
	sha256sum | cut -c1-16)
dest=$PRUKIT_CACHE/qemu/$upstream-$hash
bin=$dest/qemu-system-arm
if [ -x "$bin" ] && [ $source_only -eq 0 ]; then
	echo "$bin"
	exit 0
fi

# The configured source tree is kept (keyed on the source version and the
# patch), so that a change to the device or the simulator rebuilds only
# what it touches (about 20 s).
tree=$PRUKIT_CACHE/qemu/src-$upstream-$( (cat "$PRUKIT_TOP"/qemu/*.patch; sed -n '/^# configure:/,/^# end configure/p' "$0") |
	sha256sum | cut -c1-16)
src=$tree/src
if [ ! -e "$tree/.unpacked" ]; then
	rm -rf "$tree"
	mkdir -p "$tree"
	msg "fetching the qemu source package $version (bookworm)"
	(cd "$tree" && run_logged "$tree/source.log" papt source --download-only "qemu=$version")
	dsc=$(ls "$tree"/qemu_*.dsc)
	msg "unpacking $dsc (with Debian's patches)"
	run_logged "$tree/unpack.log" dpkg-source -x "$dsc" "$src"
	rm -f "$tree"/qemu_*
	for p in vexpress-pruss arm-dacr; do
		(cd "$src" && run_logged "$tree/patch-$p.log" patch -p1 -i "$PRUKIT_TOP/qemu/$p.patch")
	done
	mkdir -p "$src/hw/misc/prusim"
	# configure: only the vexpress boards (and what 7.2's Kconfig asks for
	# with them), only the arm system emulator, no tools, no docs
	cat >"$src/configs/devices/arm-softmmu/prukit.mak" <<'EOT'
CONFIG_VEXPRESS=y
CONFIG_ARM_VIRT=y
CONFIG_SEMIHOSTING=y
CONFIG_ARM_COMPATIBLE_SEMIHOSTING=y
EOT
	touch "$tree/.unpacked"
fi
if [ $source_only -eq 1 ]; then
	echo "$src"
	exit 0
fi

# prukit's device and the simulator it wraps; files that did not change
# keep their time stamps (ninja rebuilds only what changed)
put() {
	cmp -s "$1" "$2" || cp "$1" "$2"
}
for f in "$PRUKIT_TOP"/qemu/am335x_pruss*.c "$PRUKIT_TOP"/qemu/am335x_pruss_internal.h; do
	put "$f" "$src/hw/misc/${f##*/}"
done
put "$PRUKIT_TOP/qemu/am335x_pruss.h" "$src/include/hw/misc/am335x_pruss.h"
for f in "$PRUKIT_TOP"/sim/*.c "$PRUKIT_TOP"/sim/*.h; do
	put "$f" "$src/hw/misc/prusim/${f##*/}"
done
"$PRUKIT_TOP/scripts/pins-header.sh" >"$tree/am335x_pins.h"
put "$tree/am335x_pins.h" "$src/hw/misc/prusim/am335x_pins.h"

if [ ! -e "$tree/.configured" ]; then
	mkdir -p "$src/build"
	(cd "$src/build" && run_logged "$tree/configure.log" ../configure \
		--target-list=arm-softmmu --without-default-features --with-devices-arm=prukit \
		--enable-fdt=system --disable-docs --disable-werror --disable-user --disable-tools \
		--disable-guest-agent --disable-debug-info)
	# end configure
	touch "$tree/.configured"
fi

msg "building qemu-system-arm $upstream with the AM335x PRU-ICSS (cold: about 10 CPU minutes)"
start=$(date +%s)
run_logged "$tree/build.log" ninja -C "$src/build" -j"$(ncpus)" qemu-system-arm
# The device, the simulator and the files arm-dacr.patch changes must
# compile without a warning (the build does not use -Werror): a warning in
# the compile step of one of them, wherever gcc places it (a header inlined
# into it included).
ours='(am335x_pruss|prusim_|target_arm_(helper|ptw|tlb_helper)\.c|accel_tcg_cputlb\.c)'
warned=$(ours=$ours awk '
	/^\[[0-9]+\/[0-9]+\] / { step = $0; mine = (step ~ ENVIRON["ours"]) }
	mine && /warning:/ { print step; print }' "$tree/build.log")
if [ -n "$warned" ]; then
	printf '%s\n' "$warned" >&2
	die "the PRU-ICSS device, the simulator or a file prukit patches compiled with warnings (see $tree/build.log)"
fi
"$src/build/qemu-system-arm" -M vexpress-a15,help 2>&1 | grep -q '^ *pruss=' ||
	die "the built qemu-system-arm has no vexpress-a15 option pruss"
mkdir -p "$dest"
install -m 0755 "$src/build/qemu-system-arm" "$bin.tmp"
mv "$bin.tmp" "$bin"
echo "$version" >"$dest/source-version"
msg "qemu-system-arm built in $(( $(date +%s) - start )) s: $bin"
# older builds of the same source, and the source trees of older patches
# (about 400 MB each)
find "$PRUKIT_CACHE/qemu" -maxdepth 1 \( -name "$upstream-*" ! -name "$upstream-$hash" -o \
	-name "src-$upstream-*" ! -name "${tree##*/}" \) -exec rm -rf {} +
echo "$bin"
