#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Prove dkms.conf: `dkms add` and `dkms build` prukit, as a user's machine
# would, against Debian's armmp 5.10, 6.1 and 6.12 headers and the headers
# of BeagleBoard's 5.10.168-ti-r71 (5.10-ti: scripts/fetch-kernels.sh) with
# the ARM cross compiler (the package test, vm.sh deb, builds it with DKMS
# in the guest, natively, for 6.1).
# dkms runs with private trees under out/dkms, so the machine's own
# /var/lib/dkms and /lib/modules are not touched.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs dkms gcc-arm-linux-gnueabihf
SERIES=${PRUKIT_DKMS_SERIES:-5.10 6.1 6.12 5.10-ti}
declare -A KVER KDIR
while read -r series kver kdir _root; do
	KVER[$series]=$kver
	KDIR[$series]=$kdir
done < <(# shellcheck disable=SC2086
	"$PRUKIT_TOP/scripts/fetch-kernels.sh" $SERIES)
ver=$(make -s -C "$PRUKIT_TOP" version)

work=$PRUKIT_TOP/out/dkms
rm -rf "$work"
mkdir -p "$work"/{source,tree,install}
src=$work/source/prukit-$ver
# What the prukit-dkms package (make deb) and a release hold.
dkms_source "$src"

dkms=(dkms --dkmstree "$work/tree" --sourcetree "$work/source" --installtree "$work/install")
export ARCH=arm CROSS_COMPILE=arm-linux-gnueabihf-
# A kernel's headers call its own compiler (5.10's Makefile: gcc-10); this
# machine's ARM cross compiler is another version (bookworm: 12), which
# scripts/kernels.sh passes as CC=.  DKMS runs dkms.conf's make line as it
# is, so the version a header tree asks for is linked to the cross gcc.
mkdir -p "$work/bin"
for series in $SERIES; do
	v=$(sed -n 's/^CONFIG_CC_VERSION_TEXT="gcc-\([0-9]*\) .*/\1/p' "${KDIR[$series]}/.config")
	[ -z "$v" ] || command -v "${CROSS_COMPILE}gcc-$v" >/dev/null ||
		ln -sf "$(command -v "${CROSS_COMPILE}gcc")" "$work/bin/${CROSS_COMPILE}gcc-$v"
done
export PATH=$work/bin:$PATH

failed=0
if "${dkms[@]}" add -m prukit -v "$ver" >"$work/add.log" 2>&1; then
	echo "PASS: dkms add prukit/$ver"
else
	cat "$work/add.log"
	echo "FAIL: dkms add prukit/$ver"
	exit 1
fi

for series in $SERIES; do
	kver=${KVER[$series]}
	kdir=${KDIR[$series]}
	if "${dkms[@]}" build -m prukit -v "$ver" -k "$kver" -a armv7l --kernelsourcedir "$kdir" \
		>"$work/build-$series.log" 2>&1; then
		echo "PASS: dkms build prukit/$ver for $kver"
	else
		cat "$work/build-$series.log"
		find "$work/tree" -name make.log -exec tail -n 30 {} \;
		echo "FAIL: dkms build prukit/$ver for $kver"
		failed=1
		continue
	fi

	# Every module dkms.conf names was built, for the right kernel.
	names=$(kernel_source_dir=$kdir; . "$src/dkms.conf" >/dev/null; echo "${BUILT_MODULE_NAME[*]}")
	[ -n "$names" ] || { echo "FAIL: dkms.conf names no module for $kver"; failed=1; continue; }
	for name in $names; do
		ko=$(find "$work/tree/prukit/$ver/$kver" -name "$name.ko*" | head -n 1)
		vm=$([ -n "$ko" ] && modinfo -F vermagic "$ko" || true)
		if [ -n "$ko" ] && [ "${vm%% *}" = "$kver" ]; then
			echo "PASS: dkms built $name.ko ($vm)"
		else
			echo "FAIL: dkms built $name.ko for $kver (found '${ko:-nothing}', vermagic '$vm')"
			failed=1
		fi
	done
done
kver=${KVER[6.1]:-}
kdir=${KDIR[6.1]:-}
[ -n "$kver" ] || { echo "FAIL: make install is checked against 6.1, not in PRUKIT_DKMS_SERIES"; exit 1; }

# make install into a staging directory, as a package build would do it.
stage=$work/install-root
rm -rf "$stage"
make -s -C "$PRUKIT_TOP" firmware >/dev/null
ls "$PRUKIT_TOP"/out/overlays/*.dtbo >/dev/null 2>&1 || "$PRUKIT_TOP/scripts/overlays.sh" >/dev/null
if make -s -C "$PRUKIT_TOP" modules KDIR="$kdir" >"$work/install.log" 2>&1 &&
   make -s -C "$PRUKIT_TOP" install KDIR="$kdir" DESTDIR="$stage" >>"$work/install.log" 2>&1; then
	for f in "lib/modules/$kver/updates/drivers/rpmsg_pru/rpmsg_pru.ko" \
		 "lib/firmware/prukit/rpmsg-echo-pru0.elf" "lib/firmware/PRUKIT-RPMSG-00A0.dtbo" \
		 "etc/udev/rules.d/60-prukit.rules"; do
		if [ -n "$(find "$stage" -path "$stage/${f%.ko}*" -print -quit)" ]; then
			echo "PASS: make install puts /$f"
		else
			echo "FAIL: make install puts /$f"
			failed=1
		fi
	done
	# Test firmware (fw-test := y) is built but not installed.
	for f in consumer-test-pru0.elf irq-test-pru0.elf; do
		if [ -e "$PRUKIT_TOP/out/firmware/$f" ] && [ ! -e "$stage/lib/firmware/prukit/$f" ]; then
			echo "PASS: make install leaves out the test firmware $f"
		else
			echo "FAIL: make install leaves out the test firmware $f"
			failed=1
		fi
	done
else
	tail -n 20 "$work/install.log"
	echo "FAIL: make install DESTDIR=... (see $work/install.log)"
	failed=1
fi
make -s -C "$kdir" M="$PRUKIT_TOP" clean >/dev/null 2>&1 || true
exit $failed
