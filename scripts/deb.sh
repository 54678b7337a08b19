#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# deb.sh [--check] - prukit's Debian packages (make deb), into out/deb/:
#   prukit-dkms      the modules' source for DKMS (scripts/lib.sh
#                    dkms_source), depmod.d and modprobe.d
#   prukit-firmware  the PRU firmware users run, prebuilt
#   prukit-overlays  the device-tree overlays, prebuilt, in /lib/firmware
#   prukit-tools     udev rules (/lib/udev/rules.d), beaglelogic-tcpd and
#                    prukit-pixeld with their systemd units and man pages,
#                    pixeld's configuration (a conffile), the ioctl headers
# all "Architecture: all", built with debhelper and dh-dkms (bookworm's) from
# packaging/debian and a staged tree (out/deb/build).  The version is
# dkms.conf's PACKAGE_VERSION: debian/changelog is generated from it.
# Firmware and overlays come from make firmware and make overlays here, so
# a board needs neither a PRU compiler nor a kernel source.
#
# --check: then what the packages hold, checked (PASS:/FAIL: lines), and
# lintian's verdict: no error or warning (overrides, with their reasons, in
# packaging/debian/*.lintian-overrides).
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs debhelper dh-dkms fakeroot dpkg-dev
[ "${1:-}" != --check ] || need_pkgs lintian
# PRUKIT_DEB_VERSION and PRUKIT_DEB_OUT: packages of another version into
# another directory (the package test's upgrade, scripts/vm.sh deb_test).
ver=${PRUKIT_DEB_VERSION:-$(make -s -C "$PRUKIT_TOP" version)}
out=${PRUKIT_DEB_OUT:-$PRUKIT_TOP/out/deb}
work=$out/build/prukit-$ver
rm -rf "$out"
mkdir -p "$work"

make -s -C "$PRUKIT_TOP" firmware >/dev/null || die "make firmware failed"
make -s -C "$PRUKIT_TOP" overlays >/dev/null || die "make overlays failed"
dkms_source "$work/src"
sed -i "s/^PACKAGE_VERSION=.*/PACKAGE_VERSION=\"$ver\"/" "$work/src/dkms.conf"
make -s -C "$PRUKIT_TOP" firmware_install overlays_install udev_install modprobe_install \
	depmod_install headers_install server_install tool_install DESTDIR="$work/root" \
	UDEV_RULES_DIR=/lib/udev/rules.d >"$out/install.log" 2>&1 ||
	{ cat "$out/install.log" >&2; die "make install into the staging tree failed"; }
# The firmware stripped of symbols and debug information (remoteproc loads
# the segments; the resource table and .pru_irq_map are sections that stay).
tc=$("$PRUKIT_TOP/scripts/pru-toolchain.sh")
for f in "$work"/root/lib/firmware/prukit/*.elf; do
	"$tc/pru-strip" --strip-all --remove-section=.comment "$f"
done
install -D -m 0644 "$PRUKIT_TOP/drivers/beaglelogic/server/beaglelogic-tcpd.8" \
	"$work/root/man/beaglelogic-tcpd.8"
install -D -m 0644 "$PRUKIT_TOP/tools/prukit/prukit.1" "$work/root/man/prukit.1"
install -D -m 0644 "$PRUKIT_TOP/tools/pixeld/prukit-pixeld.8" "$work/root/man/prukit-pixeld.8"

cp -a "$PRUKIT_TOP/packaging/debian" "$work/debian"
maint=$(git -C "$PRUKIT_TOP" log -1 --format='%an <%ae>')
sed -i "s|@MAINTAINER@|$maint|" "$work/debian/control"
cat >"$work/debian/changelog" <<EOT
prukit ($ver) unstable; urgency=medium

  * Built by make deb from commit $(git -C "$PRUKIT_TOP" rev-parse --short HEAD).

 -- $maint  $(git -C "$PRUKIT_TOP" log -1 --format=%aD)
EOT
(cd "$work" && dpkg-buildpackage -b --no-sign) >"$out/build.log" 2>&1 ||
	{ tail -n 40 "$out/build.log" >&2; die "dpkg-buildpackage failed, full log in $out/build.log"; }
mv "$out"/build/*.deb "$out"/build/*.changes "$out"/build/*.buildinfo "$out"/
msg "packages in ${out#"$PRUKIT_TOP"/}: $(cd "$out" && printf '%s ' ./*.deb)"
[ "${1:-}" = --check ] || exit 0

# --- what the packages hold --------------------------------------------------
failed=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; failed=1; }
contents() { dpkg-deb -c "$out/${1}_${ver}_all.deb" | awk '{ print $6 }' | sed 's|^\./|/|'; }
has() { # PKG PATH-REGEX WHAT
	if contents "$1" | grep -qE "$2"; then pass "$1: $3"; else fail "$1: $3"; fi
}
hasnt() {
	if contents "$1" | grep -qE "$2"; then fail "$1: $3"; else pass "$1: $3"; fi
}

for p in prukit-dkms prukit-firmware prukit-overlays prukit-tools; do
	f=$out/${p}_${ver}_all.deb
	if [ -f "$f" ] && [ "$(dpkg-deb -f "$f" Version)" = "$ver" ] &&
	   [ "$(dpkg-deb -f "$f" Architecture)" = all ]; then
		pass "$p ${ver}_all.deb built (the version of dkms.conf)"
	else
		fail "$p ${ver}_all.deb built (the version of dkms.conf)"
	fi
done

src=/usr/src/prukit-$ver
has prukit-dkms "^$src/dkms.conf$" "$src/dkms.conf"
has prukit-dkms "^$src/Kbuild$" "$src/Kbuild"
for d in $(prukit_drivers); do
	has prukit-dkms "^$src/drivers/$d/Kbuild$" "driver $d's Kbuild"
done
hasnt prukit-dkms "/tests/|/firmware/|/udev/|/server/|_kunit\\.c$|/sim/|/qemu/" \
	"no tests, firmware sources, simulator or QEMU model"
has prukit-dkms "^/lib/depmod.d/prukit.conf$" "depmod.d/prukit.conf"
has prukit-dkms "^/lib/modprobe.d/prukit.conf$" "modprobe.d/prukit.conf"
if dpkg-deb -f "$out/prukit-dkms_${ver}_all.deb" Depends | grep -qw dkms &&
   dpkg-deb -I "$out/prukit-dkms_${ver}_all.deb" postinst | grep -q "dkms"; then
	pass "prukit-dkms: Depends on dkms; its postinst has DKMS build the modules"
else
	fail "prukit-dkms: Depends on dkms; its postinst has DKMS build the modules"
fi
# The firmware users run: what make firmware_install installs, no test image.
for f in $(make -s -C "$PRUKIT_TOP/firmware" O="$PRUKIT_TOP/out/firmware" list-install); do
	has prukit-firmware "^/lib/firmware/prukit/${f##*/}$" "/lib/firmware/prukit/${f##*/}"
done
hasnt prukit-firmware "consumer-test|irq-test|irq-map" "no test firmware"
# Stripped, and what remoteproc loads is what make firmware built.
x=$out/extract/firmware
mkdir -p "$x"
dpkg-deb -x "$out/prukit-firmware_${ver}_all.deb" "$x"
bad=
for f in "$x"/lib/firmware/prukit/*.elf; do
	b=$PRUKIT_TOP/out/firmware/${f##*/}
	"$tc/pru-readelf" -S "$f" | grep -qE '\.symtab|\.debug_' && bad="$bad ${f##*/}(symbols)"
	if ! "$tc/pru-objcopy" -O binary "$f" "$x/a.bin" || ! "$tc/pru-objcopy" -O binary "$b" "$x/b.bin" ||
	   [ ! -s "$x/b.bin" ] || ! cmp -s "$x/a.bin" "$x/b.bin"; then
		bad="$bad ${f##*/}(contents)"
	fi
	[ "$("$tc/pru-readelf" -lW "$f" | grep LOAD)" = "$("$tc/pru-readelf" -lW "$b" | grep LOAD)" ] ||
		bad="$bad ${f##*/}(segments)"
	[ "$("$tc/pru-readelf" -SW "$f" | grep -oE '\] \.(resource_table|pru_irq_map|prukit_ctrl) ')" = \
	  "$("$tc/pru-readelf" -SW "$b" | grep -oE '\] \.(resource_table|pru_irq_map|prukit_ctrl) ')" ] ||
		bad="$bad ${f##*/}(sections)"
done
if [ -z "$bad" ]; then
	pass "prukit-firmware: stripped; segments, loaded bytes and the sections remoteproc and prukit read as built"
else
	fail "prukit-firmware: stripped; segments, loaded bytes and the sections remoteproc and prukit read as built:$bad"
fi
for f in "$PRUKIT_TOP"/out/overlays/*.dtbo; do
	has prukit-overlays "^/lib/firmware/${f##*/}$" "/lib/firmware/${f##*/}"
done
has prukit-tools "^/lib/udev/rules.d/60-prukit.rules$" "udev rules in /lib/udev/rules.d"
has prukit-tools "^/usr/sbin/beaglelogic-tcpd$" "/usr/sbin/beaglelogic-tcpd"
has prukit-tools "^/lib/systemd/system/beaglelogic-tcpd.service$" "its systemd unit"
has prukit-tools "^/usr/share/man/man8/beaglelogic-tcpd.8.gz$" "its man page"
has prukit-tools "^/usr/sbin/prukit-pixeld$" "/usr/sbin/prukit-pixeld"
has prukit-tools "^/usr/lib/prukit/prukit_pixeld/merge.py$" "prukit-pixeld's package in /usr/lib/prukit"
has prukit-tools "^/lib/systemd/system/prukit-pixeld.service$" "its systemd unit"
has prukit-tools "^/usr/share/man/man8/prukit-pixeld.8.gz$" "its man page"
has prukit-tools "^/etc/prukit/pixeld.conf$" "its configuration in /etc/prukit"
if dpkg-deb --ctrl-tarfile "$out/prukit-tools_${ver}_all.deb" | tar -xO ./conffiles 2>/dev/null |
	grep -qx /etc/prukit/pixeld.conf; then
	pass "prukit-tools: /etc/prukit/pixeld.conf is a conffile (an upgrade keeps the user's)"
else
	fail "prukit-tools: /etc/prukit/pixeld.conf is a conffile (an upgrade keeps the user's)"
fi
has prukit-tools "^/usr/include/prukit/ws281x.h$" "the ioctl headers"
has prukit-tools "^/usr/bin/prukit$" "/usr/bin/prukit"
has prukit-tools "^/usr/lib/prukit/prukit_tool/status.py$" "the prukit command's package in /usr/lib/prukit"
has prukit-tools "^/usr/share/prukit/am335x-pins.tsv$" "its pin table"
has prukit-tools "^/usr/share/man/man1/prukit.1.gz$" "its man page"
if dpkg-deb -I "$out/prukit-overlays_${ver}_all.deb" postrm | grep -q "sed -i -e '/^#prukit: /"; then
	pass "prukit-overlays: postrm takes prukit's lines out of uEnv.txt (tests/tool tests it)"
else
	fail "prukit-overlays: postrm takes prukit's lines out of uEnv.txt"
fi
# shellcheck disable=SC2016 # the postinst's own "$g", literally
if dpkg-deb -I "$out/prukit-tools_${ver}_all.deb" postinst | grep -q 'addgroup --quiet --system "\$g"' &&
   ! dpkg-deb -I "$out/prukit-tools_${ver}_all.deb" postinst | grep -q 'systemctl.*enable'; then
	pass "prukit-tools: postinst creates the rules' groups; beaglelogic-tcpd and prukit-pixeld are not enabled"
else
	fail "prukit-tools: postinst creates the rules' groups; beaglelogic-tcpd and prukit-pixeld are not enabled"
fi

# --- lintian ----------------------------------------------------------------
lintian --info --display-level '>=pedantic' "$out"/*.changes >"$out/lintian.log" 2>&1 || true
tags=$(grep -cE '^[EWIPX]: ' "$out/lintian.log" || true)
echo "INFO: lintian: $(grep -cE '^E: ' "$out/lintian.log" || true) errors," \
	"$(grep -cE '^W: ' "$out/lintian.log" || true) warnings," \
	"$(grep -cE '^[IPX]: ' "$out/lintian.log" || true) info/pedantic/experimental tags" \
	"($tags in all; out/deb/lintian.log)"
if lintian --fail-on error,warning "$out"/*.changes >/dev/null 2>&1; then
	pass "lintian: no error or warning"
else
	grep -E '^[EW]: ' "$out/lintian.log" | head -n 20
	fail "lintian: no error or warning"
fi
exit $failed
