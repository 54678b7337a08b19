#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# pru-kit.sh SERIES KDIR OUT
#
# Debian's armmp kernels are built without the kernel's PRU drivers
# (CONFIG_SOC_TI unset, so no TI_PRUSS, TI_PRUSS_INTC or PRU_REMOTEPROC),
# while the kernels BeagleBone users run have all three.  So that prukit's
# VM tests run on the drivers a board runs, this builds them, from Debian's
# linux-source of the same series, as external modules against the armmp
# headers in KDIR (the third field of scripts/fetch-kernels.sh SERIES):
#   pruss.ko           drivers/soc/ti/pruss.c (and 6.12's drivers/soc/ti/pruss.h)
#   irq-pruss-intc.ko  drivers/irqchip/irq-pruss-intc.c
#   pru_rproc.ko       drivers/remoteproc/pru_rproc.c and pru_rproc.h, with
#                      drivers/remoteproc/remoteproc_internal.h and
#                      remoteproc_elf_helpers.h
# all from linux-source-SERIES (SERIES 5.10, 6.1 or 6.12), and compiled with
# KDIR's include/linux/pruss_driver.h and (6.12) include/linux/remoteproc/pruss.h,
# which must be linux-source-SERIES's: checked after the build against the
# headers kbuild's dependency lists name.
#
# Except on 5.10, which has no pru_rproc.c (it arrived in 5.11): there
# pru_rproc.c and pru_rproc.h come from linux-source-6.1 (still compiled with
# 5.10's remoteproc_internal.h and remoteproc_elf_helpers.h), with one line
# changed, in the copy in OUT:
#   static void *pru_rproc_da_to_va(struct rproc *rproc, u64 da, size_t len, bool *is_iomem)
# loses ", bool *is_iomem": 5.10's struct rproc_ops.da_to_va has no such
# argument (mainline added it in 5.13) and the function never uses it.  The
# script stops if that line is not there exactly as above.  Nothing else is
# needed: the rest of 6.1's pru_rproc.c compiles against 5.10's headers
# unchanged (a changed kernel interface would not: the kernel builds with
# -Werror=incompatible-pointer-types, and this script fails on any warning),
# and what it shares with pruss.ko, include/linux/pruss_driver.h (struct
# pruss and its memory regions), is identical in 5.10 and 6.1 (checked too).
#
# SERIES 6.12-ti: TI's 6.x pru_rproc.c and irq-pruss-intc.c (test material
# in shared/ti-kernel/ti-6.x-pru-drivers, scripts/lib.sh ti_material: TI's
# kick and "vring" interrupt, its INTC that clears every event at init and
# enables an ARM-bound event only on unmask) instead of linux-source-6.12's,
# with linux-source-6.12's pruss.c, pruss.h, pru_rproc.h and remoteproc
# headers: what a board's TI 6.x kernel runs, on Debian's 6.12.  They
# compile unchanged (checked: no warning, as for the others); their
# sha256 must be the ones ti-6.x-pru-drivers/README.md records.
#
# OUT is emptied and gets the three .ko files, OUT/Module.symvers (for
# prukit's build as KBUILD_EXTRA_SYMBOLS: 6.12's drivers export pruss_get(),
# pru_rproc_get() and the like, 5.10's and 6.1's nothing, so theirs is empty)
# and the build's log OUT/build.log; OUT is printed on success.  The build
# fails on any compiler or modpost warning.  This is test scaffolding for
# the VM only, not part of prukit: the kernels users run have these drivers
# already.
set -euo pipefail
# shellcheck source=SCRIPTDIR/lib.sh
. "$(dirname "$0")/lib.sh"

series=${1:?usage: pru-kit.sh SERIES KDIR OUT}
kdir=${2:?usage: pru-kit.sh SERIES KDIR OUT}
out=${3:?usage: pru-kit.sh SERIES KDIR OUT}
case $series in
5.10 | 6.1 | 6.12 | 6.12-ti) ;;
*) die "pru-kit.sh: unsupported series '$series' (5.10, 6.1, 6.12 or 6.12-ti)" ;;
esac
# TI's drivers for 6.12-ti, the rest from Debian's 6.12
ti=
if [ "$series" = 6.12-ti ]; then
	series=6.12
	ti=$(ti_material)/ti-6.x-pru-drivers
	for f in pru_rproc.c irq-pruss-intc.c; do
		[ -f "$ti/$f" ] || die "pru-kit.sh: no $ti/$f (shared/ beside the checkout; PRUKIT_SHARED=DIR names another)"
		sum=$(sha256sum "$ti/$f" | cut -d' ' -f1)
		grep -q "^| \`$f\` .*\`$sum\` |\$" "$ti/README.md" ||
			die "pru-kit.sh: $ti/$f is not the file its README.md records (sha256 $sum)"
	done
fi
[ -f "$kdir/Module.symvers" ] || die "pru-kit.sh: $kdir is not a kernel headers build tree"

src=$("$PRUKIT_TOP/scripts/linux-source.sh" "$series" pru)
# Where pru_rproc.c and pru_rproc.h come from.
rsrc=$src
[ "$series" = 5.10 ] && rsrc=$("$PRUKIT_TOP/scripts/linux-source.sh" 6.1 pru)

rm -rf "$out"
mkdir -p "$out"
out=$(realpath "$out")
cp "$src"/drivers/soc/ti/pruss.c "$src"/drivers/irqchip/irq-pruss-intc.c \
	"$src"/drivers/remoteproc/remoteproc_internal.h \
	"$src"/drivers/remoteproc/remoteproc_elf_helpers.h \
	"$rsrc"/drivers/remoteproc/pru_rproc.c "$rsrc"/drivers/remoteproc/pru_rproc.h "$out/"
[ -z "$ti" ] || cp "$ti/pru_rproc.c" "$ti/irq-pruss-intc.c" "$out/"
# 6.12's pruss.c has a local header of its own.
[ ! -e "$src"/drivers/soc/ti/pruss.h ] || cp "$src"/drivers/soc/ti/pruss.h "$out/"

if [ "$series" = 5.10 ]; then
	cmp -s "$src"/include/linux/pruss_driver.h "$rsrc"/include/linux/pruss_driver.h ||
		die "pru-kit.sh: include/linux/pruss_driver.h differs between 5.10 and 6.1: 6.1's pru_rproc.c needs porting"
	# The one change: 6.1's
	#   static void *pru_rproc_da_to_va(struct rproc *rproc, u64 da, size_t len, bool *is_iomem)
	# becomes 5.10's da_to_va signature.  The line must be there exactly
	# once, and is_iomem nowhere else.
	old='static void *pru_rproc_da_to_va(struct rproc *rproc, u64 da, size_t len, bool *is_iomem)'
	new='static void *pru_rproc_da_to_va(struct rproc *rproc, u64 da, size_t len)'
	if [ "$(grep -cxF "$old" "$out/pru_rproc.c")" != 1 ] || [ "$(grep -c is_iomem "$out/pru_rproc.c")" != 1 ]; then
		die "pru-kit.sh: 6.1's pru_rproc.c does not have the expected da_to_va line: the 5.10 change needs redoing"
	fi
	sed -i 's/^\(static void \*pru_rproc_da_to_va(struct rproc \*rproc, u64 da, size_t len\), bool \*is_iomem)$/\1)/' \
		"$out/pru_rproc.c"
	if [ "$(grep -cxF "$new" "$out/pru_rproc.c")" != 1 ] || grep -q is_iomem "$out/pru_rproc.c"; then
		die "pru-kit.sh: the 5.10 da_to_va change did not apply"
	fi
fi

from=linux-source-$series
[ "$series" = 5.10 ] && from="$from (pru_rproc.[ch]: linux-source-6.1, da_to_va without is_iomem)"
[ -z "$ti" ] || from="$from (pru_rproc.c, irq-pruss-intc.c: TI's, $ti)"
# prukit's own declaration of rproc_vq_interrupt() (include/compat.h: the
# kernel declares it only in remoteproc_internal.h, which an external module
# cannot include) compiled after this kernel's: a difference is an error.
decl=$(grep -x 'irqreturn_t rproc_vq_interrupt(.*);' "$PRUKIT_TOP/include/compat.h" || true)
[ "$(printf '%s\n' "$decl" | grep -c .)" = 1 ] ||
	die "pru-kit.sh: include/compat.h does not declare rproc_vq_interrupt() on one line"
cat >"$out/prukit_decls.c" <<EOT
// SPDX-License-Identifier: GPL-2.0-only
/* Generated by prukit's scripts/pru-kit.sh: include/compat.h's declaration
 * against this kernel's drivers/remoteproc/remoteproc_internal.h. */
#include <linux/remoteproc.h>
#include "remoteproc_internal.h"
$decl
EOT
cat >"$out/Kbuild" <<EOT
# Generated by prukit's scripts/pru-kit.sh from $from.
ccflags-y += -DCONFIG_TI_PRUSS_MODULE=1 -DCONFIG_TI_PRUSS_INTC_MODULE=1 -DCONFIG_PRU_REMOTEPROC_MODULE=1
obj-m += pruss.o irq-pruss-intc.o pru_rproc.o
always-y += prukit_decls.o
EOT
run_logged "$out/build.log" make -C "$kdir" M="$out" ARCH=arm \
	CROSS_COMPILE=arm-linux-gnueabihf- CC=arm-linux-gnueabihf-gcc -j"$(ncpus)" modules
if grep -i 'warning' "$out/build.log" >&2; then
	die "pru-kit.sh: the build warned, see $out/build.log"
fi
for m in pruss irq-pruss-intc pru_rproc; do
	[ -f "$out/$m.ko" ] || die "pru-kit.sh: $m.ko was not built, see $out/build.log"
done
[ -f "$out/prukit_decls.o" ] ||
	die "pru-kit.sh: include/compat.h's rproc_vq_interrupt() against the kernel's: not compiled, see $out/build.log"
# (5.10's and 6.1's drivers export nothing: their Module.symvers is empty.)
[ -f "$out/Module.symvers" ] || die "pru-kit.sh: no Module.symvers, see $out/build.log"

# The PRU headers the compiler read (from the dependency lists kbuild keeps)
# must be this release's: for pru_rproc.o on 5.10, 6.1's (the same, above).
for o in pruss irq-pruss-intc pru_rproc; do
	for h in include/linux/pruss_driver.h include/linux/remoteproc/pruss.h; do
		grep -qF "#include <${h#include/}>" "$out/$o.c" || continue
		used=$(grep -o "[^ ]*/$h" "$out/.$o.o.cmd" | sort -u || true)
		[ -n "$used" ] || die "pru-kit.sh: cannot tell which $h $o.o was compiled with"
		for f in $used; do
			cmp -s "$f" "$src/$h" ||
				die "pru-kit.sh: $o.o was compiled with $f, not linux-source-$series's $h"
		done
	done
done
echo "$out"
