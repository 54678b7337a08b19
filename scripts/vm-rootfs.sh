#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Print the path of the VM guest's userland: a cpio of Debian bookworm
# armhf with the packages listed in tests/vm/packages, unpacked by
# mmdebstrap --variant=extract (no emulation of foreign binaries needed).
# Cached in $PRUKIT_CACHE/vm, keyed by the package list.  Not compressed:
# every boot would inflate it under emulation (about 5 s of each boot).
set -euo pipefail
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/papt.sh"

need_pkgs mmdebstrap cpio
list=$PRUKIT_TOP/tests/vm/packages
pkgs=$(grep -v '^#' "$list" | paste -sd, -)
key=$( (echo "$pkgs"; cat "$0") | sha256sum | cut -c1-12)
img=$PRUKIT_CACHE/vm/rootfs-$key.cpio

if [ ! -e "$img" ]; then
	msg "building the VM userland (bookworm armhf: $pkgs)"
	mkdir -p "$PRUKIT_CACHE/vm"
	tmp=$(mktemp -d "$PRUKIT_CACHE/vm/rootfs.XXXXXX")
	run_logged "$tmp.log" mmdebstrap --variant=extract --architectures=armhf \
		--include="$pkgs" bookworm "$tmp/root" "$(debian_mirror)"
	# The extract variant leaves no /bin/sh and no usr-merge links; busybox
	# provides the shell and, at boot, every applet a package does not.
	ln -sf busybox "$tmp/root/bin/sh"
	mkdir -p "$tmp/root"/{proc,sys,dev,run,tmp,in,out,mnt}
	# and none of what no test reads: docs, and udev's hardware database
	# sources (only a compiled hwdb.bin is ever looked up; there is none)
	rm -rf "$tmp/root"/usr/share/{doc,man,locale,info} "$tmp/root"/lib/udev/hwdb.d
	(cd "$tmp/root" && find . -print0 | cpio --null -o -H newc --quiet) >"$img.tmp"
	mv "$img.tmp" "$img"
	rm -rf "$tmp" "$tmp.log"
fi
echo "$img"
