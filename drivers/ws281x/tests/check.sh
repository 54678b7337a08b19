#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/ws281x/tests/check.sh - make check's step driver-ws281x: the
# ws281x firmware (ws281x-pru0.elf, ws281x-pru1.elf) run in the prusim host
# tool, its edges checked to the cycle and one capture decoded by sigrok's
# rgb_led_ws281x (ws281x_sim.py says what is checked); and the driver's
# frame conversion, ws281x_conv.c built for the host, against a reference
# (tests/conv/conv_test.c).  Builds what it needs (prusim, the PRU
# toolchain, the two images) from a clean clone.  Prints
# PASS:/FAIL: lines, and info: lines with the worst edge error per pin kind
# and the cycles per frame; exits non-zero on any failure.
#
# prukit-check-min: 460
set -uo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP" || exit 1

command -v sigrok-cli >/dev/null || need_pkgs sigrok-cli
command -v python3 >/dev/null || need_pkgs python3

work=$(mktemp -d "${TMPDIR:-/tmp}/prukit-ws281x.XXXXXX")
trap 'rm -rf "$work"' EXIT

prusim_and_images "$work" ws281x-pru0.elf ws281x-pru1.elf || exit 1
fw=$work/fw
grep '^ *FW ' "$work/fw.log" | sed 's/^ */info: /'

# The uapi header builds in a user program, and its ioctl number is the one
# the VM test (tests/vm/cases/78-ws281x) and Documentation/ws281x.rst use.
printf '%s\n' '#include <stdio.h>' '#include <prukit/ws281x.h>' \
	'int main(void) { printf("0x%x\n", (unsigned int)WS281X_IOC_COMMIT); return 0; }' \
	>"$work/uapi.c"
uapi_rc=1
if cc -Wall -Werror -I include/uapi -o "$work/uapi" "$work/uapi.c" 2>"$work/uapi.log" &&
   [ "$("$work/uapi")" = 0xb900 ]; then
	echo "PASS: include/uapi/prukit/ws281x.h builds in a program; WS281X_IOC_COMMIT is 0xb900"
	uapi_rc=0
else
	cat "$work/uapi.log"
	echo "FAIL: include/uapi/prukit/ws281x.h in a program (WS281X_IOC_COMMIT 0xb900)"
fi

# The driver's conversion (drivers/ws281x/ws281x_conv.c), built unchanged
# for the host, against a reference bit by bit on hundreds of controllers
# and frames (tests/conv/conv_test.c): a PASS:/FAIL: line per case.
conv_rc=1
if make -s -C drivers/ws281x/tests/conv O="$work/conv" "$work/conv/conv_test" \
	>"$work/conv.log" 2>&1; then
	"$work/conv/conv_test" && conv_rc=0
else
	cat "$work/conv.log"
	echo "FAIL: building drivers/ws281x/tests/conv/conv_test (ws281x_conv.c on the host)"
fi

mkdir -p "$work/run"
python3 "$PRUKIT_TOP/drivers/ws281x/tests/ws281x_sim.py" "$PRUKIT_TOP/out/tools/prusim" \
	"$fw" "$work/run" && [ "$uapi_rc" = 0 ] && exit "$conv_rc"
