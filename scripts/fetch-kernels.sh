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

for series in "$@"; do
	rel=$(newest_release "$series")
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
	"$PRUKIT_TOP/scripts/fix-modpost.sh" "$series" "$kdir" \
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
