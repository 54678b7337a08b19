#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Run prukit's KUnit suites on UML (user-mode Linux, x86-64 host), with KASAN
# and lockdep, inside Debian's linux-source-6.1.  prukit is grafted into the
# tree the way out-of-tree projects do it: drivers/prukit is a symlink to this
# tree, and drivers/Kconfig and drivers/Makefile gain one line each.  The
# build directory is cached, so a rerun takes seconds.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs gcc make flex bison bc python3
src=$("$PRUKIT_TOP/scripts/linux-source.sh" 6.1)
build=$PRUKIT_CACHE/kunit-build-$(basename "$(dirname "$src")")

ln -sfn "$PRUKIT_TOP" "$src/drivers/prukit"
grep -q '^source "drivers/prukit/Kconfig"' "$src/drivers/Kconfig" ||
	sed -i '$i source "drivers/prukit/Kconfig"' "$src/drivers/Kconfig"
grep -q '^obj-y.*+= prukit/' "$src/drivers/Makefile" ||
	echo 'obj-y				+= prukit/' >>"$src/drivers/Makefile"

mkdir -p "$build"
# The drivers' Kconfig entries, from drivers/registry (Kconfig sources them).
"$PRUKIT_TOP/scripts/registry.sh" kconfig >"$build/prukit-drivers.Kconfig"
export PRUKIT_DRIVERS_KCONFIG=$build/prukit-drivers.Kconfig
# The build directory is shared by every checkout (through the symlink
# above), and make goes by modification times: objects built from another
# checkout can look newer than this one's sources and be linked stale (seen
# as a KASAN stack-out-of-bounds in prusim_load_elf() after prusim.h grew).
# Whenever the checkout changes, prukit's objects are rebuilt.
if [ "$(cat "$build/.prukit-top" 2>/dev/null)" != "$PRUKIT_TOP" ]; then
	rm -rf "$build/drivers/prukit"
	echo "$PRUKIT_TOP" >"$build/.prukit-top"
fi
# The prusim validation programs, assembled and embedded for the KUnit suite.
"$PRUKIT_TOP/tests/kunit/prusim/gen.sh"
log=$PRUKIT_TOP/out/kunit.log
mkdir -p "$(dirname "$log")"
msg "KUnit on UML (KASAN, lockdep); build dir $build, log $log"
set +e
(cd "$src" && python3 tools/testing/kunit/kunit.py run --arch=um \
	--kunitconfig="$PRUKIT_TOP/tests/kunit/prukit.kunitconfig" \
	--build_dir="$build" --jobs="$(ncpus)" --timeout=600 --raw_output=all) >"$log" 2>&1
rc=$?
set -e

# One PASS/FAIL line per test case, from the KTAP output.
awk '
	/^ *# Subtest: / { suite = $3 }
	/^ *(not )?ok [0-9]+ / {
		name = $0; sub(/^ *(not )?ok [0-9]+ (- )?/, "", name); sub(/ #.*/, "", name)
		if (name == suite) next
		if ($1 == "ok") print "PASS: kunit " suite "." name
		else print "FAIL: kunit " suite "." name
	}' "$log"

failed=0
grep -qE '^ *not ok [0-9]+ ' "$log" && failed=1
cases=$(grep -cE '^ *(not )?ok [0-9]+ ' "$log" || true)
if [ "$rc" -ne 0 ] || [ "$cases" -eq 0 ]; then
	tail -n 30 "$log"
	echo "FAIL: kunit run (kunit.py exit $rc, $cases results)"
	failed=1
fi
# A KASAN report, lockdep splat or WARN fails the run even if no test did.
if [ "$cases" -eq 0 ]; then
	:
elif grep -nE 'BUG:|WARNING:|KASAN|possible (recursive|circular) locking|INFO: task .* blocked|Call Trace' "$log"; then
	echo "FAIL: kunit kernel log is clean"
	failed=1
else
	echo "PASS: kunit kernel log is clean (no KASAN, lockdep, WARN or BUG)"
fi
exit $failed
