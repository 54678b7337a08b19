#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/hub75/tests/check.sh - make check's step driver-hub75:
#  - tools/hub75-decode.py on hand-made pin sequences whose picture is known
#    (hub75_decode_selftest.py), faults included: the decoder the other
#    checks trust;
#  - the firmware (hub75-pru0.elf, hub75-pru1.elf) in the prusim host tool
#    on sixteen layouts (the Octoscroller's 8 outputs of one and of three
#    panels, FM6126A/FM6127 register words, outdoor panels, 12 planes
#    among them): every pixel
#    decoded exactly, every lit time, the refresh lengths, START's checks
#    (hub75_sim.py);
#  - the conversion, hub75_conv.c built for the host with AddressSanitizer
#    and UBSan, against hub75_model.py: every level, frame buffers, partial
#    updates (tests/conv/conv_check.py).
# Builds what it needs (prusim, the PRU toolchain, the two images) from a
# clean clone.  Prints PASS:/FAIL: lines; exits non-zero on any failure.
#
# prukit-check-min: 235
set -uo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP" || exit 1

command -v python3 >/dev/null || need_pkgs python3
command -v cc >/dev/null || need_pkgs gcc libc6-dev

work=$(mktemp -d "${TMPDIR:-/tmp}/prukit-hub75.XXXXXX")
trap 'rm -rf "$work"' EXIT

rc=0
python3 drivers/hub75/tests/hub75_decode_selftest.py || rc=1

# with AddressSanitizer and UBSan: an access outside the frame buffer, the
# image or the tables, or a leak, fails the run
san="-fsanitize=address,undefined -fno-sanitize-recover=all"
if make -s -C drivers/hub75/tests/conv O="$work/conv" "$work/conv/conv_test" \
	CFLAGS="-O1 -g -fno-omit-frame-pointer $san" LDFLAGS="$san" \
	>"$work/conv.log" 2>&1; then
	python3 drivers/hub75/tests/conv/conv_check.py "$work/conv/conv_test" "$work/conv" || rc=1
else
	cat "$work/conv.log"
	echo "FAIL: building drivers/hub75/tests/conv/conv_test (hub75_conv.c on the host)"
	rc=1
fi

prusim_and_images "$work" hub75-pru0.elf hub75-pru1.elf || exit 1
grep '^ *FW ' "$work/fw.log" | sed 's/^ */info: /'
mkdir -p "$work/run"
python3 drivers/hub75/tests/hub75_sim.py "$PRUKIT_TOP/out/tools/prusim" "$work/fw" "$work/run" || rc=1
exit "$rc"
