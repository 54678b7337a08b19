#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# checkpatch.pl --strict over every C source and header of prukit (kernel
# code, simulator, tools and PRU firmware alike), with the checkpatch.pl of
# Debian's linux-source-6.1; and the QEMU device in qemu/, which is QEMU
# code, with QEMU's own checkpatch.pl --strict (of the QEMU source
# scripts/qemu-build.sh builds), as are the patches to QEMU there.  One
# PASS/FAIL line per file.
#
# Exceptions, and only these:
# - include/compat.h exists to compare LINUX_VERSION_CODE, so the two
#   warnings that comparison raises are ignored there, and so is the use of
#   the interfaces older kernels have instead of the new ones;
# - code that is not built against kernel headers (PRU firmware, host tools,
#   test firmware) has no u32, BIT(), __packed or __section() to prefer, and
#   firmware registers are volatile;
# - the userspace half of the simulator's platform header defines those
#   kernel names itself, the way <linux/compiler.h> does.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

src=$("$PRUKIT_TOP/scripts/linux-source.sh" 6.1)
cp=(perl "$src/scripts/checkpatch.pl" --strict --no-tree --terse --show-types --no-summary
    --max-line-length=100 -f)
qsrc=$("$PRUKIT_TOP/scripts/qemu-build.sh" --source)
qcp=(perl "$qsrc/scripts/checkpatch.pl" --strict --no-tree --terse --no-summary --color=never -f)
# the same for qemu/*.patch, changes to QEMU's own files (no sign-off: not mailed)
qcp_patch=("${qcp[@]:0:${#qcp[@]}-1}" --no-signoff)

# check_file FILE: checkpatch's findings on FILE, then its PASS:/FAIL: line.
check_file() {
	local f=$1 out ignore
	case $f in
	include/compat.h) ignore=(--ignore LINUX_VERSION_CODE,CONSTANT_COMPARISON,DEPRECATED_API) ;;
	firmware/* | drivers/*/firmware/* | tools/* | tests/prusim/*)
		ignore=(--ignore PREFER_KERNEL_TYPES,BIT_MACRO,PREFER_DEFINED_ATTRIBUTE_MACRO,VOLATILE) ;;
	sim/prusim_platform.h)
		# Its userspace half defines what <linux/compiler.h> would.
		ignore=(--ignore PREFER_KERNEL_TYPES,PREFER_DEFINED_ATTRIBUTE_MACRO,COMPLEX_MACRO) ;;
	qemu/*)
		local q=("${qcp[@]}")
		[ "${f%.patch}" = "$f" ] || q=("${qcp_patch[@]}")
		if out=$("${q[@]}" "$f" 2>&1) && [ -z "$out" ]; then
			echo "PASS: checkpatch (QEMU's) $f"
		else
			printf '%s\n' "$out"
			echo "FAIL: checkpatch (QEMU's) $f"
		fi
		return
		;;
	*) ignore=() ;;
	esac
	if out=$("${cp[@]}" "${ignore[@]}" "$f" 2>&1) && [ -z "$out" ]; then
		echo "PASS: checkpatch $f"
	else
		printf '%s\n' "$out"
		echo "FAIL: checkpatch $f"
	fi
}

# One checkpatch per CPU at a time (it is single-threaded perl), each
# file's report in its own file, printed in order once all are done.
cd "$PRUKIT_TOP"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0
while IFS= read -r f; do
	while [ "$(jobs -rp | wc -l)" -ge "$(ncpus)" ]; do
		wait -n || true
	done
	n=$((n + 1))
	check_file "$f" >"$tmp/$n" 2>&1 &
done < <(git ls-files --cached --others --exclude-standard -- '*.c' '*.h' 'qemu/*.patch' | sort)
wait
failed=0
for i in $(seq 1 "$n"); do
	cat "$tmp/$i"
	grep -q '^PASS: checkpatch ' "$tmp/$i" || failed=1
done
exit $failed
