#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/pru_pwm/tests/check.sh - make check's step driver-pru_pwm: the
# driver's table builder (pru_pwm_table.c, built unchanged for the host)
# against the rounding rules of Documentation/pru_pwm.rst, and the
# pru_pwm firmware in the prusim host tool, every edge checked to the
# cycle, with commands posted while it plays (pwm_sim.py says what is
# checked).  Builds what it needs (prusim, the PRU toolchain, the images)
# from a clean clone.  Prints PASS:/FAIL: lines; exits non-zero on any
# failure.
#
# prukit-check-min: 25
set -uo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP" || exit 1

command -v python3 >/dev/null || need_pkgs python3

work=$(mktemp -d "${TMPDIR:-/tmp}/prukit-pru_pwm.XXXXXX")
trap 'rm -rf "$work"' EXIT

prusim_and_images "$work" pru_pwm-pru1.elf pwm-poke-pru0.elf || exit 1
if ! make -s -C drivers/pru_pwm/tests/table O="$work/table" "$work/table/pwm_table" \
	>"$work/table.log" 2>&1; then
	cat "$work/table.log"
	echo "FAIL: building drivers/pru_pwm/tests/table/pwm_table (pru_pwm_table.c on the host)"
	exit 1
fi
python3 drivers/pru_pwm/tests/pwm_sim.py "$PRUKIT_TOP/out/tools/prusim" "$work/fw" \
	"$work/table/pwm_table" "$work"
