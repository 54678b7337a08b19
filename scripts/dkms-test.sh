#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Prove dkms.conf: `dkms add` and `dkms build` prukit, as a user's machine
# would, against Debian's armmp 6.1 headers with the ARM cross compiler.
# dkms runs with private trees under out/dkms, so the machine's own
# /var/lib/dkms and /lib/modules are not touched.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs dkms gcc-arm-linux-gnueabihf
read -r _series kver kdir _root < <("$PRUKIT_TOP/scripts/fetch-kernels.sh" 6.1)
ver=$(make -s -C "$PRUKIT_TOP" version)

work=$PRUKIT_TOP/out/dkms
rm -rf "$work"
mkdir -p "$work"/{source,tree,install}
src=$work/source/prukit-$ver
# What the prukit-dkms package (make deb) and a release hold.
dkms_source "$src"

dkms=(dkms --dkmstree "$work/tree" --sourcetree "$work/source" --installtree "$work/install")
export ARCH=arm CROSS_COMPILE=arm-linux-gnueabihf-

failed=0
if "${dkms[@]}" add -m prukit -v "$ver" >"$work/add.log" 2>&1; then
	echo "PASS: dkms add prukit/$ver"
else
	cat "$work/add.log"
	echo "FAIL: dkms add prukit/$ver"
	exit 1
fi

if "${dkms[@]}" build -m prukit -v "$ver" -k "$kver" -a armv7l --kernelsourcedir "$kdir" \
	>"$work/build.log" 2>&1; then
	echo "PASS: dkms build prukit/$ver for $kver"
else
	cat "$work/build.log"
	find "$work/tree" -name make.log -exec tail -n 30 {} \;
	echo "FAIL: dkms build prukit/$ver for $kver"
	exit 1
fi

# Every module dkms.conf names was built, for the right kernel.
names=$(kernel_source_dir=$kdir; . "$src/dkms.conf" >/dev/null; echo "${BUILT_MODULE_NAME[*]}")
[ -n "$names" ] || { echo "FAIL: dkms.conf names no module"; exit 1; }
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
