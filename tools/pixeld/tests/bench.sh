#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# tools/pixeld/tests/bench.sh - prukit-pixeld's make bench figures (bench.py
# says how each is made):
#  - the parse + map cost per pixel of an E1.31 universe (170 pixels), an
#    OPC message and a DDP packet with push, in instructions callgrind
#    counts in Pixeld in-process (two runs of N1 and N2 packets, the
#    difference over the pixels: the interpreter's start-up cancels).  The
#    CPython interpreter's instructions on the host (x86-64), not a board's;
#  - the universes per CPU-second the daemon handles on one host core (its
#    accepted counter over its utime + stime while a sender blasts valid
#    E1.31 universes over loopback), and the fraction of such a core 48
#    strings x 600 pixels at the wire rate (9180 universes/s) needs;
#  - the time from a frame's last universe sent to the frame's write (the
#    daemon's FIFO output read), median and 99th percentile, alone and
#    under abuse (abuse.py bench).
# Prints BENCH: lines; exits non-zero if something failed (a FAIL: line
# says what).  Works in out/tests/pixeld-bench.
set -euo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP"

[ -x /usr/bin/python3 ] || need_pkgs python3
command -v valgrind >/dev/null || need_pkgs valgrind

out=$PRUKIT_TOP/out/tests/pixeld-bench
rm -rf "$out"
mkdir -p "$out"
rc=0
/usr/bin/python3 tools/pixeld/tests/bench.py ir "$out" || rc=1
/usr/bin/python3 tools/pixeld/tests/bench.py rate "$out" 4 || rc=1
/usr/bin/python3 tools/pixeld/tests/abuse.py bench "$out" || rc=1
exit $rc
