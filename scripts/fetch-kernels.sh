#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# fetch-kernels.sh [--image] SERIES...
#
# Fetch Debian's armhf "armmp" kernel headers (and with --image the kernel
# image and its modules) for each SERIES (5.10, 6.1, 6.12) into
# $PRUKIT_CACHE/kernels/<release>/ and print one line per series:
#   SERIES RELEASE KDIR ROOT
# KDIR is a usable external-module build tree, ROOT the extracted packages.
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

need_pkgs apt dpkg debian-archive-keyring

# The Debian archive URI from the machine's apt sources (deb822 or one-line).
mirror=${PRUKIT_DEBIAN_MIRROR:-}
if [ -z "$mirror" ]; then
	mirror=$(awk '
		/^URIs:/ && $2 ~ /\/debian\/?$/ { print $2; exit }
		/^deb / { for (i = 2; i <= NF; i++) if ($i ~ /^[a-z]+:\/\// && $i ~ /\/debian\/?$/) { print $i; exit } }
	' /etc/apt/sources.list.d/*.sources /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
		head -n 1)
fi
[ -n "$mirror" ] || die "no Debian archive found in the apt sources; set PRUKIT_DEBIAN_MIRROR"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg

aptdir=$PRUKIT_CACHE/apt
mkdir -p "$aptdir"/{lists/partial,cache/archives/partial,etc/preferences.d,etc/sources.list.d}
: >"$aptdir/status"
cat >"$aptdir/etc/sources.list" <<EOF
deb [arch=amd64,armhf signed-by=$keyring] $mirror bullseye main
deb [arch=amd64,armhf signed-by=$keyring] $mirror bookworm main
deb [arch=amd64,armhf signed-by=$keyring] $mirror bookworm-backports main
EOF
apt_opts=(
	-o "Dir::Etc::SourceList=$aptdir/etc/sources.list"
	-o "Dir::Etc::SourceParts=$aptdir/etc/sources.list.d"
	-o "Dir::Etc::PreferencesParts=$aptdir/etc/preferences.d"
	-o "Dir::State=$aptdir"
	-o "Dir::State::Lists=$aptdir/lists"
	-o "Dir::State::status=$aptdir/status"
	-o "Dir::Cache=$aptdir/cache"
	-o "APT::Architecture=amd64"
	-o "APT::Architectures::=amd64"
	-o "APT::Architectures::=armhf"
	-o "Debug::NoLocking=1"
	-o "Acquire::Languages=none"
)
papt() { apt-get "${apt_opts[@]}" "$@"; }
pcache() { apt-cache "${apt_opts[@]}" "$@"; }

# Refresh the private package lists at most once a day.
if [ -z "$(find "$aptdir/lists" -maxdepth 1 -name '*Packages*' -mmin -1440 2>/dev/null | head -n 1)" ]; then
	msg "updating the private apt lists (bullseye, bookworm, bookworm-backports; amd64+armhf)"
	run_logged "$aptdir/update.log" papt update
fi

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
	want=headers
	[ $image -eq 1 ] && want=image
	if [ ! -e "$dest/.complete-$want" ]; then
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
		if [ $image -eq 1 ]; then
			img=$(pcache pkgnames "linux-image-$kver" | grep -E "^linux-image-$kver(-unsigned)?$" |
				sort | head -n 1)
			[ -n "$img" ] || die "no linux-image package for $kver"
			pkgs+=("$img:armhf")
		fi
		msg "fetching kernel $kver: ${pkgs[*]}"
		mkdir -p "$dest/debs"
		(cd "$dest/debs" && run_logged "$dest/download.log" papt download "${pkgs[@]}")
		rm -rf "$root"
		mkdir -p "$root"
		for deb in "$dest"/debs/*.deb; do
			dpkg-deb -x "$deb" "$root"
		done
		rm -rf "$dest/debs"
		kdir=$root/usr/src/linux-headers-$kver
		# The armmp Makefile includes the -common tree by absolute path;
		# point it into the extracted copy.
		sed -i "s|^include /usr/src/|include $root/usr/src/|" "$kdir/Makefile"
		touch "$dest/.complete-headers"
		[ $image -eq 1 ] && touch "$dest/.complete-image"
	fi
	echo "$series $kver $root/usr/src/linux-headers-$kver $root"
done
