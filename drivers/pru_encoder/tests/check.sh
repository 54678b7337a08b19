#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/pru_encoder/tests/check.sh - make check's step driver-pru_encoder:
# the firmware (pru_encoder-pru0.elf) runs in the prusim host tool with
# quadrature stimuli on PRU0's R31 bits 14..16, both boards' pin orders:
# forward and backward, reversals, wraps at the floor and the ceiling, index
# pulses, at the loop's edge-rate limit and beyond it (skipped states
# counted), every path's cycles between two samples measured on the trace,
# the event strobe and its arming, and the commands' results (enc_sim.py
# says what is checked).  Builds what it needs (prusim, the PRU toolchain,
# the image) from a clean clone.  Prints PASS:/FAIL: lines; exits non-zero
# on any failure.
#
# prukit-check-min: 34
set -uo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP" || exit 1

command -v python3 >/dev/null || need_pkgs python3

work=$(mktemp -d "${TMPDIR:-/tmp}/prukit-pru_encoder.XXXXXX")
trap 'rm -rf "$work"' EXIT

prusim_and_images "$work" pru_encoder-pru0.elf || exit 1
grep '^ *FW ' "$work/fw.log" | sed 's/^ */info: /'
mkdir -p "$work/run"
python3 "$PRUKIT_TOP/drivers/pru_encoder/tests/enc_sim.py" "$PRUKIT_TOP/out/tools/prusim" \
	"$work/fw/pru_encoder-pru0.elf" "$work/run"
