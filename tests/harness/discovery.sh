#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Adding a driver touches two places, its folder and its line in
# drivers/registry: a copy of the tree (git ls-files) gets a fake driver
# folder, drivers/zz_example/ (module and Kbuild, firmware, udev rule, VM
# test with host half, make check step) plus its registry line, and this
# test asserts that the firmware build, make udev_install, the VM harness's
# test discovery, make check's driver steps, dkms.conf and the Kconfig
# entries find it by themselves, and that its gate builds it only where the
# kernel has the option its line needs (one kbuild run against Debian's
# 6.12 armmp headers with the option, one without).  A second fake folder,
# drivers/zz_unlisted/, the same but with no registry line, is found by
# none of them.  Part of make check's harness step; takes some 20 s.
set -uo pipefail
. "$(dirname "$0")/../../scripts/lib.sh"

need_pkgs gcc-arm-linux-gnueabihf make
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0
pass() { echo "PASS: discovery: $*"; }
fail() { echo "FAIL: discovery: $*"; bad=1; }
# check WHAT CMD... - one PASS:/FAIL: line for a condition.
check() {
	local what=$1
	shift
	if "$@"; then pass "$what"; else fail "$what"; fi
}

# --- the copy, and the fake driver ------------------------------------------

src=$tmp/src
copy_checkout "$src" || { fail "copying the tree"; exit 1; }

zz=$src/drivers/zz_example
mkdir -p "$zz"/firmware/zz-test "$zz"/udev "$zz"/tests/vm/cases "$zz"/tests/vm/host
cat >"$zz/Kbuild" <<'EOF'
# SPDX-License-Identifier: GPL-2.0-only
include $(prukit_top)/drivers/gate.mk
obj-$(CONFIG_PRUKIT_ZZ_EXAMPLE) += zz_example.o
EOF
cat >"$zz/zz_example.c" <<'EOF'
// SPDX-License-Identifier: GPL-2.0-only
#include <linux/module.h>
MODULE_DESCRIPTION("prukit discovery self-test");
MODULE_LICENSE("GPL");
EOF
# Two options: one every kernel has, one none has.
printf 'zz_example\tMODULES,PRUKIT_ZZ_EXAMPLE_DEP\tthe discovery self-test\n' >>"$src/drivers/registry"
# The driver's firmware (drivers/<driver>/firmware/fw.mk, named after the
# driver) and a test firmware in a subfolder (named after the folder).
printf 'fw-srcs := zz.c\nfw-cores := 0\n' >"$zz/firmware/fw.mk"
printf 'fw-srcs := zz.c\nfw-cores := 1\nfw-test := y\n' >"$zz/firmware/zz-test/fw.mk"
echo 'SUBSYSTEM=="zz_example", GROUP="remoteproc", MODE="0660"' >"$zz/udev/zz_example.rules"
printf '#!/bin/sh\necho "PASS: zz"\n' >"$zz/tests/vm/cases/50-zz-example"
printf '#!/bin/sh\necho "PASS: zz host"\n' >"$zz/tests/vm/host/50-zz-example"
printf '#!/bin/sh\n# prukit-check-min: 3\n' >"$zz/tests/check.sh"
chmod +x "$zz"/tests/vm/cases/50-zz-example "$zz"/tests/vm/host/50-zz-example "$zz"/tests/check.sh
# The same folder under another name, without a registry line.
un=$src/drivers/zz_unlisted
cp -r "$zz" "$un"
mv "$un/zz_example.c" "$un/zz_unlisted.c"
mv "$un/tests/vm/cases/50-zz-example" "$un/tests/vm/cases/51-zz-unlisted"
sed -i 's/ZZ_EXAMPLE/ZZ_UNLISTED/; s/zz_example/zz_unlisted/' "$un/Kbuild"
sed -i 's/zz_example/zz_unlisted/' "$un/udev/zz_example.rules"
mv "$un/firmware/zz-test" "$un/firmware/zz-unlisted-test"

# --- (a) the firmware build -------------------------------------------------

fwmake() { make -s --no-print-directory -C "$src/firmware" O="$tmp/fw" "$@"; }
list=$(fwmake list 2>&1) || fail "make -C firmware list: $list"
install_list=$(fwmake list-install 2>&1) || fail "make -C firmware list-install: $install_list"
check "firmware list has the driver's firmware/fw.mk as zz_example-pru0.elf" \
	grep -qw 'zz_example-pru0\.elf' <<<"$list"
check "firmware list has its firmware/zz-test/fw.mk as zz-test-pru1.elf" \
	grep -qw 'zz-test-pru1\.elf' <<<"$list"
check "firmware list still has firmware/rpmsg-echo" grep -qw 'rpmsg-echo-pru0\.elf' <<<"$list"
check "make install's firmware (list-install) has zz_example-pru0.elf" \
	grep -qF "$tmp/fw/zz_example-pru0.elf" <<<"$install_list"
check "make install's firmware leaves out the test firmware zz-test (fw-test := y)" \
	eval '! grep -qF zz-test <<<"$install_list"'
check "the driver's firmware is compiled with -I drivers/zz_example (its protocol header)" \
	eval 'fwmake print-cflags-zz_example-pru0 | grep -qF -- "-I$zz "'
check "firmware list has nothing of a folder without a registry line" \
	eval '! grep -q "zz_unlisted\|zz-unlisted" <<<"$list"'

# --- (b) make udev_install --------------------------------------------------

rules=$tmp/root/etc/udev/rules.d/60-prukit.rules
if make -s -C "$src" udev_install DESTDIR="$tmp/root" >"$tmp/udev.log" 2>&1; then
	check "make udev_install puts the driver's rule into 60-prukit.rules" \
		grep -qxF 'SUBSYSTEM=="zz_example", GROUP="remoteproc", MODE="0660"' "$rules"
	check "60-prukit.rules has nothing of a folder without a registry line" \
		eval '! grep -q zz_unlisted "$rules"'
	check "60-prukit.rules still has rpmsg_pru's rule" \
		grep -qxF 'SUBSYSTEM=="rpmsg_pru", GROUP="remoteproc", MODE="0660"' "$rules"
else
	sed 's/^/    /' "$tmp/udev.log"
	fail "make udev_install DESTDIR=..."
fi

# --- (c) the VM harness's test discovery (vm.sh test, make_initrd) ----------

cases=$(vm_cases "$src") || fail "vm_cases"
check "vm_cases lists the driver's VM test" \
	grep -qxF "50-zz-example $zz/tests/vm/cases/50-zz-example" <<<"$cases"
check "vm_cases leaves out the VM test of a folder without a registry line" \
	eval '! grep -q zz-unlisted <<<"$cases"'
check "vm_cases still lists tests/vm/cases/10-boot" \
	grep -qxF "10-boot $src/tests/vm/cases/10-boot" <<<"$cases"
check "vm_cases lists them in name order" \
	eval 'awk "{ print \$1 }" <<<"$cases" | LC_ALL=C sort -c'
check "vm_host_half finds the driver's host half" \
	test "$(vm_host_half "$zz/tests/vm/cases/50-zz-example")" = "$zz/tests/vm/host/50-zz-example"
cp "$zz/tests/vm/cases/50-zz-example" "$src/tests/vm/cases/"
check "vm_cases refuses two tests with one name" eval '! vm_cases "$src" >/dev/null 2>&1'
rm "$src/tests/vm/cases/50-zz-example"

# --- make check's per-driver steps -------------------------------------------

check "driver_checks finds the driver's tests/check.sh with its minimum 3" \
	grep -qxF "zz_example 3 $zz/tests/check.sh" <<<"$(driver_checks "$src")"
check "driver_checks leaves out the check step of a folder without a registry line" \
	eval '! driver_checks "$src" | grep -q zz_unlisted'

# --- the Kconfig entries (a kernel tree prukit is grafted into) -------------

kconfig=$("$src/scripts/registry.sh" kconfig) || fail "registry.sh kconfig"
check "registry.sh kconfig: the driver's tristate, depending on its line's options" \
	eval 'grep -A2 -x "config PRUKIT_ZZ_EXAMPLE" <<<"$kconfig" |
		grep -qx "$(printf "\tdepends on MODULES && PRUKIT_ZZ_EXAMPLE_DEP")"'
check "registry.sh kconfig: prukit_pru is CONFIG_PRUKIT_PRU, rpmsg_pru CONFIG_PRUKIT_RPMSG_PRU" \
	eval 'grep -qx "config PRUKIT_PRU" <<<"$kconfig" && grep -qx "config PRUKIT_RPMSG_PRU" <<<"$kconfig"'
check "registry.sh kconfig: one entry per registry line, nothing for a folder without one" \
	test "$(grep -c "^config " <<<"$kconfig")" = "$(prukit_drivers "$src" | wc -l)" -a \
	"$(grep -c ZZ_UNLISTED <<<"$kconfig")" = 0

# --- (d) the Kbuild gate, in a real kbuild run ------------------------------

read -r _ kver kdir _ < <("$PRUKIT_TOP/scripts/fetch-kernels.sh" 6.12) ||
	{ fail "no 6.12 kernel headers"; exit 1; }
# The real drivers are switched off on the command line (which overrides
# their gates' ?=): only the fake one is at stake, and the run is quick.
off=()
for f in "$PRUKIT_TOP"/drivers/*/Kbuild; do
	while read -r v; do off+=("$v="); done < <(sed -n 's/^obj-\$(\(CONFIG_[A-Z0-9_]*\)).*/\1/p' "$f")
done
kmake() {
	make -C "$kdir" M="$src" ARCH=arm CROSS_COMPILE=arm-linux-gnueabihf- \
		"${off[@]}" -j"$(ncpus)" "$@" modules
}
if kmake >"$tmp/kbuild1.log" 2>&1; then
	check "Kbuild gate: no zz_example.ko where the kernel lacks CONFIG_PRUKIT_ZZ_EXAMPLE_DEP ($kver)" \
		test ! -e "$zz/zz_example.ko"
else
	tail -n 20 "$tmp/kbuild1.log"
	fail "kbuild without CONFIG_PRUKIT_ZZ_EXAMPLE_DEP failed ($kver)"
fi
if kmake CONFIG_PRUKIT_ZZ_EXAMPLE_DEP=y >"$tmp/kbuild2.log" 2>&1; then
	check "Kbuild gate: zz_example.ko built where the kernel has it ($kver, through its registry line)" \
		test -e "$zz/zz_example.ko"
	check "Kbuild: nothing built of a folder without a registry line" \
		eval '! ls "$un"/*.o >/dev/null 2>&1' 
else
	tail -n 20 "$tmp/kbuild2.log"
	fail "kbuild with CONFIG_PRUKIT_ZZ_EXAMPLE_DEP=y failed ($kver)"
fi

# --- dkms.conf against the kernel's .config and the Kbuild gates -------------

# dkms_list CONFIG_LINES - source dkms.conf as dkms does (bash, with
# kernel_source_dir set) against a .config holding CONFIG_LINES; print
# "NAME LOCATION DEST" per listed module, in index order.
dkms_list() {
	mkdir -p "$tmp/k"
	printf '%s\n' "$@" >"$tmp/k/.config"
	(kernel_source_dir=$tmp/k
	 . "$PRUKIT_TOP/dkms.conf" >/dev/null
	 for ((i = 0; i < ${#BUILT_MODULE_NAME[@]}; i++)); do
		echo "${BUILT_MODULE_NAME[$i]} ${BUILT_MODULE_LOCATION[$i]} ${DEST_MODULE_LOCATION[$i]}"
	 done)
}
all_opts=(CONFIG_REMOTEPROC=y CONFIG_OF=y CONFIG_PINCTRL=y CONFIG_GPIOLIB=y CONFIG_RPMSG=m)
full=$(dkms_list "${all_opts[@]}")
no_rpmsg=$(dkms_list "${all_opts[@]:0:4}")
check "dkms.conf lists rpmsg_pru where the kernel has CONFIG_RPMSG" \
	grep -qx 'rpmsg_pru drivers/rpmsg_pru/ /updates/dkms' <<<"$full"
check "dkms.conf leaves rpmsg_pru out where the kernel lacks CONFIG_RPMSG, the rest listed" \
	test -n "$no_rpmsg" -a "$(grep -v '^rpmsg_pru ' <<<"$full")" = "$no_rpmsg"
check "dkms.conf's list has no gap or misaligned entry without CONFIG_RPMSG" \
	eval '! grep -qvE "^[a-z_]+ drivers/[a-z_]+/ /updates/dkms$" <<<"$no_rpmsg"'

# a driver's "prukit-kernel-api:" line (pru_encoder: the counter interface
# of v5.17): listed where the kernel's header declares the symbol, or cannot
# be read; left out where it does not (5.10's <linux/counter.h>)
api_opts=(CONFIG_REMOTEPROC=y CONFIG_OF=y CONFIG_COUNTER=m)
check "dkms.conf lists pru_encoder where the kernel's headers cannot be read" \
	grep -qx 'pru_encoder drivers/pru_encoder/ /updates/dkms' <<<"$(dkms_list "${api_opts[@]}")"
mkdir -p "$tmp/k/include/linux"
echo 'int counter_register(struct counter_device *const counter);' >"$tmp/k/include/linux/counter.h"
check "dkms.conf leaves pru_encoder out where <linux/counter.h> lacks devm_counter_alloc (5.10)" \
	eval '! grep -q "^pru_encoder " <<<"$(dkms_list "${api_opts[@]}")"'
echo 'struct counter_device *devm_counter_alloc(struct device *dev, size_t sizeof_priv);' \
	>"$tmp/k/include/linux/counter.h"
check "dkms.conf lists pru_encoder where <linux/counter.h> has devm_counter_alloc" \
	grep -qx 'pru_encoder drivers/pru_encoder/ /updates/dkms' <<<"$(dkms_list "${api_opts[@]}")"
rm -rf "$tmp/k/include"

# dkms.conf lists every driver of the registry, and no other; the options
# it drops a module for are the module's registry line's (the zz_example
# copy: listed with the option, dropped without).
every_opt=($(awk '/^[a-z0-9_]+[ \t]/ { print $2 }' "$PRUKIT_TOP/drivers/registry" |
	tr , '\n' | sort -u | sed 's/.*/CONFIG_&=y/'))
check "dkms.conf lists the registry's drivers, in its order, where the kernel has every option they need ($(prukit_drivers | paste -sd' ' -))" \
	test "$(dkms_list "${every_opt[@]}" | awk '{ print $1 }')" = "$(prukit_drivers)"
for d in $(prukit_drivers); do
	check "drivers/$d/: its Kbuild includes the gate, drivers/gate.mk" \
		grep -qxF 'include $(prukit_top)/drivers/gate.mk' "$PRUKIT_TOP/drivers/$d/Kbuild"
done
zz_list() {
	mkdir -p "$tmp/k"
	printf '%s\n' "$@" >"$tmp/k/.config"
	(kernel_source_dir=$tmp/k
	 . "$src/dkms.conf" >/dev/null
	 echo "${BUILT_MODULE_NAME[*]}")
}
check "dkms.conf lists a new driver's module where the kernel has its gate's option" \
	eval 'zz_list "${all_opts[@]}" CONFIG_MODULES=y CONFIG_PRUKIT_ZZ_EXAMPLE_DEP=y | grep -qw zz_example'
check "dkms.conf lists nothing of a folder without a registry line" \
	eval '! zz_list "${all_opts[@]}" CONFIG_MODULES=y CONFIG_PRUKIT_ZZ_EXAMPLE_DEP=y | grep -qw zz_unlisted'
# (without it, the same modules as dkms.conf lists for that kernel)
check "dkms.conf drops a new driver's module where the kernel lacks its gate's option" \
	eval 'test "$(zz_list "${all_opts[@]}" CONFIG_MODULES=y)" = "$(awk "{ print \$1 }" <<<"$full" | paste -sd" " -)"'
exit "$bad"
