#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# gen.sh - generate the data of the prusim KUnit suite: build the validation
# programs of tests/prusim (asm/*.S, c/*.c) with the PRU toolchain and write
# their firmware and checks to out/kunit/prusim/prusim_kunit_data.h, where
# tests/kunit/prusim/Kbuild finds it.  Run it before every kernel build that
# enables CONFIG_PRUKIT_PRUSIM_KUNIT_TEST (scripts/kunit.sh does); the file
# is rewritten only when its contents change.
set -euo pipefail
. "$(dirname "$0")/../../../scripts/lib.sh"

command -v python3 >/dev/null || need_pkgs python3
bin=$("$PRUKIT_TOP/scripts/pru-toolchain.sh")
out=$PRUKIT_TOP/out/kunit/prusim
mkdir -p "$out"
python3 "$PRUKIT_TOP/tests/kunit/prusim/gen.py" --tools "$bin" --build "$out/build" \
	--out "$out/prusim_kunit_data.h"
msg "prusim KUnit data: $out/prusim_kunit_data.h"
