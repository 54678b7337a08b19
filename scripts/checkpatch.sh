#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# checkpatch.pl --strict over every C source and header of prukit (kernel
# code, simulator, tools and PRU firmware alike), with the checkpatch.pl of
# Debian's linux-source-6.1.  One PASS/FAIL line per file.
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

failed=0
cd "$PRUKIT_TOP"
while IFS= read -r f; do
	case $f in
	include/compat.h) ignore=(--ignore LINUX_VERSION_CODE,CONSTANT_COMPARISON,DEPRECATED_API) ;;
	firmware/* | drivers/*/firmware/* | tools/* | tests/prusim/*)
		ignore=(--ignore PREFER_KERNEL_TYPES,BIT_MACRO,PREFER_DEFINED_ATTRIBUTE_MACRO,VOLATILE) ;;
	sim/prusim_platform.h)
		# Its userspace half defines what <linux/compiler.h> would.
		ignore=(--ignore PREFER_KERNEL_TYPES,PREFER_DEFINED_ATTRIBUTE_MACRO,COMPLEX_MACRO) ;;
	*) ignore=() ;;
	esac
	if out=$("${cp[@]}" "${ignore[@]}" "$f" 2>&1) && [ -z "$out" ]; then
		echo "PASS: checkpatch $f"
	else
		printf '%s\n' "$out"
		echo "FAIL: checkpatch $f"
		failed=1
	fi
done < <(git ls-files --cached --others --exclude-standard -- '*.c' '*.h' | sort)
exit $failed
