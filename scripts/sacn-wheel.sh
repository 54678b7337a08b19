#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Print the path of PyPI's "sacn" (an E1.31 sender and receiver in pure
# Python, MIT, github.com/Hundemeier/sacn), the real E1.31 sender the VM
# tests of prukit-pixeld run in the guest: one wheel, pinned by version and
# SHA-256, downloaded once with pip into $PRUKIT_CACHE/pypi.  The guest
# imports it from the wheel (a zip on sys.path), so nothing is installed.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

SACN_VERSION=1.11.0
SACN_SHA256=4c0c294746c6b8e9290bcc3db7b15483b28a716247d9d762de18597fb703a4fc
whl=$PRUKIT_CACHE/pypi/sacn-$SACN_VERSION-py3-none-any.whl

if [ ! -e "$whl" ]; then
	/usr/bin/python3 -m pip --version >/dev/null 2>&1 || need_pkgs python3-pip
	mkdir -p "$PRUKIT_CACHE/pypi"
	tmp=$(mktemp -d "$PRUKIT_CACHE/pypi/dl.XXXXXX")
	run_logged "$tmp.log" /usr/bin/python3 -m pip download --no-deps --only-binary=:all: \
		--disable-pip-version-check -d "$tmp" "sacn==$SACN_VERSION"
	got=$(sha256sum "$tmp/${whl##*/}" | cut -d' ' -f1)
	[ "$got" = "$SACN_SHA256" ] ||
		die "sacn $SACN_VERSION: SHA-256 $got, not the pinned $SACN_SHA256"
	mv "$tmp/${whl##*/}" "$whl"
	rm -rf "$tmp" "$tmp.log"
fi
echo "$whl"
