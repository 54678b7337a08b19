#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# tools/pixeld/tests/check.sh - prukit-pixeld's host checks (make check's
# step "pixeld"):
#  - pixeld_check.py: its mapping and protocol rules in the process with a
#    clock of our own, and the program's command line, signals and sockets;
#  - fuzz.py: bad input at every receiver, bounded in time: only counted
#    drops, no crash, no growth;
#  - abuse.py check: a sender's frames while others flood it (random CIDs,
#    lost sync, tiny OPC messages, cycling sync universes): shown whole, in
#    order;
#  - its systemd unit, as make install writes it, by systemd-analyze verify.
# The daemon on the devices, with real senders: the VM test 94-pixeld.
set -uo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP" || exit 1
command -v systemd-analyze >/dev/null || need_pkgs systemd

rc=0
/usr/bin/python3 tools/pixeld/tests/pixeld_check.py || rc=1
/usr/bin/python3 tools/pixeld/tests/fuzz.py --seconds "${PIXELD_FUZZ_SECONDS:-40}" || rc=1
/usr/bin/python3 tools/pixeld/tests/abuse.py check "$PRUKIT_TOP/out/tests/pixeld-abuse" || rc=1

tmp=$(mktemp -d)
sed "s|@SBINDIR@|$PRUKIT_TOP/tools/pixeld|" tools/pixeld/prukit-pixeld.service \
	>"$tmp/prukit-pixeld.service"
if out=$(systemd-analyze verify --man=no "$tmp/prukit-pixeld.service" 2>&1) && [ -z "$out" ]; then
	echo "PASS: pixeld: its systemd unit passes systemd-analyze verify"
else
	echo "FAIL: pixeld: its systemd unit passes systemd-analyze verify: $out"
	rc=1
fi
rm -rf "$tmp"
exit $rc
