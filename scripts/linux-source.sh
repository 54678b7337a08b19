#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# linux-source.sh SERIES [full|dt|rpmsg|counter|pru|modpost]
#
# Print the path of an extracted Debian linux-source-SERIES tree (5.10, 6.1,
# 6.12), fetching the package through the private apt configuration
# (scripts/papt.sh) into $PRUKIT_CACHE once and extracting what is asked:
#   full     everything (KUnit, checkpatch) - the default
#   dt       dts, dt-bindings, scripts/dtc and the binding documents
#   rpmsg    drivers/rpmsg (rpmsg modules for kernels built without them)
#   counter  drivers/counter (the counter core for kernels built without it)
#   pru      the kernel's PRU drivers for kernels built without them
#            (scripts/pru-kit.sh): drivers/soc/ti/pruss*,
#            drivers/irqchip/irq-pruss-intc.c, drivers/remoteproc/pru_rproc.[ch],
#            remoteproc_internal.h and remoteproc_elf_helpers.h,
#            include/linux/pruss_driver.h and include/linux/remoteproc/pruss.h;
#            what a release lacks (5.10 has no pru_rproc) is left out
#   modpost  what modpost is built from (for cross builds)
set -euo pipefail
# shellcheck source=SCRIPTDIR/lib.sh
. "$(dirname "$0")/lib.sh"
# shellcheck source=SCRIPTDIR/papt.sh
. "$(dirname "$0")/papt.sh"

series=${1:?usage: linux-source.sh SERIES [full|dt|rpmsg|counter|pru|modpost]}
what=${2:-full}
wildcards=()
case $what in
full) paths=() ;;
dt) paths=(arch/arm/boot/dts include/dt-bindings scripts/dtc Documentation/devicetree/bindings) ;;
rpmsg) paths=(drivers/rpmsg) ;;
counter) paths=(drivers/counter) ;;
pru)
	paths=('drivers/soc/ti/pruss*' drivers/irqchip/irq-pruss-intc.c 'drivers/remoteproc/pru_rproc.[ch]'
	       drivers/remoteproc/remoteproc_internal.h drivers/remoteproc/remoteproc_elf_helpers.h
	       include/linux/pruss_driver.h include/linux/remoteproc/pruss.h)
	wildcards=(--wildcards)
	;;
modpost) paths=(scripts/mod scripts/include include/linux/license.h include/linux/mod_devicetable.h include/linux/module_symbol.h) ;;
*) die "unknown part '$what'" ;;
esac

papt_init
pkg=linux-source-$series
pkgver=$(pcache show --no-all-versions "$pkg" 2>/dev/null | sed -n 's/^Version: //p' | head -n 1)
[ -n "$pkgver" ] || die "no package $pkg in bullseye, bookworm or bookworm-backports"
dest=$PRUKIT_CACHE/linux-source-$pkgver-$what
top=$dest/linux-source-$series

if [ ! -e "$dest/.complete" ]; then
	tarball=$PRUKIT_CACHE/linux-source-$pkgver.tar.xz
	if [ ! -e "$tarball" ]; then
		msg "fetching $pkg ($pkgver)"
		tmp=$(mktemp -d "$PRUKIT_CACHE/linux-source.XXXXXX")
		papt_fetch "$tmp" "$pkg"
		mv "$tmp"/usr/src/linux-source-"$series".tar.xz "$tarball"
		rm -rf "$tmp"
	fi
	msg "extracting $pkg ($pkgver, $what) into $dest"
	rm -rf "$dest"
	mkdir -p "$dest"
	# A part some releases lack (scripts/include before 6.x, pru_rproc
	# before 5.11) is not an error.
	tar -C "$dest" -xf "$tarball" "${wildcards[@]}" "${paths[@]/#/linux-source-$series/}" 2>/dev/null || true
	[ -d "$top" ] || die "cannot extract $pkg"
	touch "$dest/.complete"
fi
echo "$top"
