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
# What a release tarball (or a dkms-managed /usr/src/prukit-VER) holds.
mkdir -p "$src"
(cd "$PRUKIT_TOP" && git ls-files --cached --others --exclude-standard -- \
	Kbuild Makefile dkms.conf include drivers | xargs cp --parents -t "$src")

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
names=$(sed -n 's/^BUILT_MODULE_NAME\[[0-9]*\]="\(.*\)"/\1/p' "$src/dkms.conf")
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
exit $failed
