#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# fetch-kernels.sh [--image] SERIES...
#
# Fetch Debian's armhf "armmp" kernel headers (and with --image the kernel
# image and its modules) for each SERIES (5.10, 6.1, 6.12) into
# $PRUKIT_CACHE/kernels/<release>/ and print one line per series:
#   SERIES RELEASE KDIR ROOT [IMAGE]
# KDIR is a usable external-module build tree, ROOT the extracted header
# packages, IMAGE (with --image) the extracted kernel image package.
#
# The kernels boards run, by name beside Debian's (kernel_flavour in
# scripts/lib.sh):
#   5.10-ti  BeagleBoard's 5.10.168-ti-r71, built for the VM's machine: test
#            material in shared/ti-kernel beside the checkout (PRUKIT_SHARED
#            names another place), unpacked into the cache as Debian's
#            packages are: its headers tree as KDIR, and IMAGE laid out as
#            Debian's image package is (boot/vmlinuz-<release>,
#            lib/modules/<release>, usr/lib/linux-image-<release>/<dtb>).
#   6.12-ti  Debian's 6.12 (the same lines as 6.12): TI's PRU drivers are
#            built beside it by scripts/pru-kit.sh.
#
# Packages come from the Debian archive the machine's own apt sources name,
# through a private apt configuration under $PRUKIT_CACHE/apt: the machine's
# apt sources, lists and dpkg state are never touched.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

image=0
if [ "${1:-}" = --image ]; then
	image=1
	shift
fi
[ $# -gt 0 ] || set -- 5.10 6.1 6.12

. "$(dirname "$0")/papt.sh"
papt_init

# newest_release SERIES - the newest linux-headers-<release> (armhf, armmp) of a series
newest_release() {
	local series=$1 pat
	case $series in
	6.12) pat="^linux-headers-6\.12\.[0-9]+\+(bpo|deb12)-armmp$" ;;
	*) pat="^linux-headers-${series//./\\.}\.0-[0-9]+-armmp$" ;;
	esac
	pcache pkgnames linux-headers- | grep -E "$pat" |
		sed -e 's/^linux-headers-//' -e 's/-armmp$//' | sort -V | tail -n 1
}

# ti_kernel SERIES - the line of a whole TI kernel from shared/ti-kernel,
# unpacked into the cache under a key of its files' contents.
ti_kernel() {
	local series=$1 kver src key dest
	case $series in
	5.10-ti) kver=5.10.168-ti-r71 ;;
	*) die "no TI kernel for $series" ;;
	esac
	src=$(ti_material)/$kver
	[ -f "$src/zImage" ] && [ -f "$src/headers.tar.xz" ] ||
		die "$series: BeagleBoard's kernel is not in $src (shared/ beside the checkout; PRUKIT_SHARED=DIR names another)"
	key=$(cat "$src"/zImage "$src"/vexpress-v2p-ca15-tc1.dtb "$src"/modules.tar.xz \
		"$src"/headers.tar.xz | sha256sum | cut -c1-12)
	dest=$PRUKIT_CACHE/kernels/$kver-$key
	if [ ! -e "$dest/.complete" ]; then
		msg "unpacking $kver from $src"
		rm -rf "$dest"
		mkdir -p "$dest/root/usr/src" "$dest/image/boot" "$dest/image/usr/lib/linux-image-$kver"
		tar -xJf "$src/headers.tar.xz" -C "$dest/root/usr/src"
		tar -xJf "$src/modules.tar.xz" -C "$dest/image"
		cp "$src/zImage" "$dest/image/boot/vmlinuz-$kver"
		cp "$src/vexpress-v2p-ca15-tc1.dtb" "$dest/image/usr/lib/linux-image-$kver/"
		[ -f "$dest/root/usr/src/linux-headers-$kver/Module.symvers" ] ||
			die "$src/headers.tar.xz has no linux-headers-$kver/Module.symvers"
		touch "$dest/.complete"
	fi
	line="$series $kver $dest/root/usr/src/linux-headers-$kver $dest/root"
	[ $image -eq 0 ] || line="$line $dest/image"
	echo "$line"
}

for series in "$@"; do
	flavour=$(kernel_flavour "$series")
	if [ "$flavour" = ti-kernel ]; then
		ti_kernel "$series"
		continue
	fi
	rel=$(newest_release "${series%-ti}")
	[ -n "$rel" ] || die "no armmp headers found for kernel $series"
	kver=$rel-armmp
	dest=$PRUKIT_CACHE/kernels/$kver
	root=$dest/root
	if [ ! -e "$dest/.complete-headers" ]; then
		# The headers package depends on its -common package and the
		# matching host kbuild tools; fetch exactly those.
		pkgs=("linux-headers-$kver:armhf")
		deps=$(pcache show --no-all-versions "linux-headers-$kver:armhf" |
			sed -n 's/^Depends: //p' | tr ',' '\n' |
			sed -n 's/^ *\(linux-\(headers\|kbuild\)-[^ ]*\).*/\1/p')
		for d in $deps; do
			case $d in
			linux-kbuild-*) pkgs+=("$d:amd64") ;;
			*) pkgs+=("$d") ;;
			esac
		done
		msg "fetching kernel headers $kver: ${pkgs[*]}"
		rm -rf "$root"
		papt_fetch "$root" "${pkgs[@]}"
		# The armmp Makefile includes the -common tree by absolute path;
		# point it into the extracted copy.
		sed -i "s|^include /usr/src/|include $root/usr/src/|" \
			"$root/usr/src/linux-headers-$kver/Makefile"
		touch "$dest/.complete-headers"
	fi
	kdir=$root/usr/src/linux-headers-$kver
	# Debian's modpost cannot check ARM device tables: rebuild it once.
	"$PRUKIT_TOP/scripts/fix-modpost.sh" "${series%-ti}" "$kdir" \
		"$(dirname "$(readlink -f "$kdir/scripts")")" >&2
	line="$series $kver $kdir $root"
	if [ $image -eq 1 ]; then
		if [ ! -e "$dest/.complete-image" ]; then
			img=$(pcache pkgnames "linux-image-$kver" |
				grep -Fx -e "linux-image-$kver" -e "linux-image-$kver-unsigned" |
				sort | head -n 1)
			[ -n "$img" ] || die "no linux-image package for $kver"
			msg "fetching kernel image $kver: $img"
			rm -rf "$dest/image"
			papt_fetch "$dest/image" "$img:armhf"
			touch "$dest/.complete-image"
		fi
		line="$line $dest/image"
	fi
	echo "$line"
done
