#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# linux-source.sh SERIES [full|dt|rpmsg]
#
# Print the path of an extracted Debian linux-source-SERIES tree (5.10, 6.1,
# 6.12), fetching the package through the private apt configuration
# (scripts/papt.sh) and extracting it into $PRUKIT_CACHE first if needed.
#   full   everything (KUnit, checkpatch) - the default
#   dt     what device-tree work needs: dts, dt-bindings, scripts/dtc, bindings
#   rpmsg  drivers/rpmsg only (the rpmsg modules for kernels built without them)
set -euo pipefail
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/papt.sh"

series=${1:?usage: linux-source.sh SERIES [full|dt|rpmsg]}
what=${2:-full}
case $what in
full) paths=() ;;
dt) paths=(arch/arm/boot/dts include/dt-bindings scripts/dtc Documentation/devicetree/bindings) ;;
rpmsg) paths=(drivers/rpmsg) ;;
*) die "unknown part '$what'" ;;
esac

papt_init
pkg=linux-source-$series
pkgver=$(pcache show --no-all-versions "$pkg" 2>/dev/null | sed -n 's/^Version: //p' | head -n 1)
[ -n "$pkgver" ] || die "no package $pkg in bullseye, bookworm or bookworm-backports"
dest=$PRUKIT_CACHE/linux-source-$pkgver-$what
top=$dest/linux-source-$series

if [ ! -e "$dest/.complete" ]; then
	msg "extracting $pkg ($pkgver, $what) into $dest"
	rm -rf "$dest"
	papt_fetch "$dest/deb" "$pkg"
	tarball=$(ls "$dest"/deb/usr/src/linux-source-"$series".tar.*)
	tar -C "$dest" -xf "$tarball" "${paths[@]/#/linux-source-$series/}"
	rm -rf "$dest/deb"
	touch "$dest/.complete"
fi
echo "$top"
