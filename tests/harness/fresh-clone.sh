#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# The entry points a developer runs first build what they need: in a copy of
# the tree with no out/ (git ls-files, as a fresh clone has it), each of
#   make vmrun KVER=6.1 SCRIPT=...   (a script that looks at what the guest got)
#   make vmtest KVERS=6.1 TESTS=10-boot
#   make bench PARTS=prusim
# must run to its end on its own.  The caches under $PRUKIT_CACHE are shared
# (they only make things faster), out/ is not: modules, firmware, overlays
# and tools are built in the copy.  Run by make check after the VM tests (so
# that a cold run has built the QEMU and fetched the kernels by then); about
# 3 minutes.
set -uo pipefail
. "$(dirname "$0")/../../scripts/lib.sh"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0
pass() { echo "PASS: fresh clone: $*"; }
fail() { echo "FAIL: fresh clone: $*"; bad=1; }

src=$tmp/src
copy_checkout "$src" || { fail "copying the tree (without out/)"; exit 1; }

# make vmrun: the guest must see prukit's firmware and modules, and /out
# must come back.
cat >"$tmp/probe.sh" <<'PROBE'
#!/bin/sh
set -e
ls /lib/firmware/prukit >/out/firmware
find /lib/modules/"$(uname -r)" -name 'prukit_pru.ko*' >/out/modules
echo done >/out/done
PROBE
chmod +x "$tmp/probe.sh"
if make -C "$src" vmrun KVER=6.1 SCRIPT="$tmp/probe.sh" OUT="$tmp/vmout" \
	>"$tmp/vmrun.log" 2>&1 &&
	grep -qx done "$tmp/vmout/done" 2>/dev/null &&
	grep -q '^blinky-pru0.elf$' "$tmp/vmout/firmware" &&
	grep -q 'prukit_pru.ko' "$tmp/vmout/modules" &&
	grep -q 'script exit status 0' "$tmp/vmrun.log"; then
	pass "make vmrun KVER=6.1 builds modules, firmware and overlays and runs the script" \
		"($(wc -l <"$tmp/vmout/firmware") firmware files in the guest)"
else
	tail -n 20 "$tmp/vmrun.log"
	fail "make vmrun KVER=6.1 builds modules, firmware and overlays and runs the script"
fi

# A script that fails makes vmrun fail.
printf '#!/bin/sh\nexit 3\n' >"$tmp/fails.sh"
chmod +x "$tmp/fails.sh"
if make -C "$src" vmrun KVER=6.1 SCRIPT="$tmp/fails.sh" OUT="$tmp/vmout2" \
	>"$tmp/vmrun2.log" 2>&1; then
	fail "make vmrun with a script that exits 3 fails"
elif grep -q 'script exit status 3' "$tmp/vmrun2.log"; then
	pass "make vmrun with a script that exits 3 fails and says so"
else
	tail -n 10 "$tmp/vmrun2.log"
	fail "make vmrun with a script that exits 3 fails and says so"
fi

# make vmtest with one test, in a second fresh copy (vmrun built the first).
src2=$tmp/src2
copy_checkout "$src2" || fail "copying the tree again"
if make -C "$src2" vmtest KVERS=6.1 TESTS=10-boot >"$tmp/vmtest.log" 2>&1 &&
	grep -qE '^[1-9][0-9]* passed, 0 failed' "$tmp/vmtest.log"; then
	pass "make vmtest KVERS=6.1 TESTS=10-boot: $(grep -E '^[0-9]+ passed' "$tmp/vmtest.log" | tail -n 1)"
else
	tail -n 20 "$tmp/vmtest.log"
	fail "make vmtest KVERS=6.1 TESTS=10-boot from a fresh clone"
fi

# make bench, its first part, in a third (it builds tools and firmware).
src3=$tmp/src3
copy_checkout "$src3" || fail "copying the tree a third time"
if make -C "$src3" bench PARTS=prusim >"$tmp/bench.log" 2>&1 &&
	grep -q 'M simulated cycles/s' "$tmp/bench.log" &&
	[ -x "$src3/out/tools/prusim" ] && [ -e "$src3/out/firmware/blinky-pru0.elf" ]; then
	pass "make bench PARTS=prusim builds the tools and firmware: $(grep -o '[0-9.]* M simulated cycles/s (CPU time)' "$tmp/bench.log")"
else
	tail -n 20 "$tmp/bench.log"
	fail "make bench PARTS=prusim from a fresh clone"
fi

# An unknown part is refused, naming the parts.
if make -C "$src3" bench PARTS=nope >"$tmp/bench2.log" 2>&1; then
	fail "make bench PARTS=nope fails"
elif grep -q "no part 'nope' (parts: prusim" "$tmp/bench2.log"; then
	pass "make bench PARTS=nope fails, naming the parts"
else
	cat "$tmp/bench2.log"
	fail "make bench PARTS=nope fails, naming the parts"
fi
exit $bad
