#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# linux-source.sh SERIES [full|dt]
#
# Print the path of an extracted Debian linux-source-SERIES tree (6.1, 6.12),
# installing the package and extracting its tarball into $PRUKIT_CACHE first
# if needed.  "full" (the default) extracts everything (KUnit, checkpatch);
# "dt" only what device-tree work needs (dts, dt-bindings, scripts/dtc,
# binding documents), which is much quicker.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

series=${1:?usage: linux-source.sh SERIES [full|dt]}
what=${2:-full}

need_pkgs "linux-source-$series" xz-utils
tarball=$(ls /usr/src/linux-source-"$series".tar.xz 2>/dev/null) ||
	die "linux-source-$series did not install /usr/src/linux-source-$series.tar.xz"
pkgver=$(dpkg-query -W -f='${Version}' "linux-source-$series")
dest=$PRUKIT_CACHE/linux-source-$pkgver-$what
top=$dest/linux-source-$series

if [ ! -e "$dest/.complete" ]; then
	msg "extracting linux-source-$series ($pkgver, $what) into $dest"
	rm -rf "$dest"
	mkdir -p "$dest"
	if [ "$what" = dt ]; then
		tar -C "$dest" -xJf "$tarball" --wildcards \
			"linux-source-$series/arch/arm/boot/dts/*" \
			"linux-source-$series/include/dt-bindings/*" \
			"linux-source-$series/scripts/dtc/*" \
			"linux-source-$series/Documentation/devicetree/bindings/*"
	else
		tar -C "$dest" -xJf "$tarball"
	fi
	touch "$dest/.complete"
fi
echo "$top"
