#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/beaglelogic/tests/check.sh - make check's step driver-beaglelogic:
# the uapi header's ioctl numbers are BeagleLogic's, and the firmware
# (beaglelogic-pru0.elf, beaglelogic-pru1.elf) runs in the prusim host tool:
# every path of the sampler, one-shot and continuous, the PocketBeagle's
# swapped roles, each sample checked against the stimulus, and the storer's
# triggers (bl_sim.py says what is checked).  Builds what it needs (prusim,
# the PRU toolchain, the two images) from a clean clone.  Prints PASS:/FAIL:
# lines; exits non-zero on any failure.
#
# prukit-check-min: 117
set -uo pipefail
# shellcheck source=../../../scripts/lib.sh
. "$(dirname "$0")/../../../scripts/lib.sh"
cd "$PRUKIT_TOP" || exit 1

command -v python3 >/dev/null || need_pkgs python3

work=$(mktemp -d "${TMPDIR:-/tmp}/prukit-beaglelogic.XXXXXX")
trap 'rm -rf "$work"' EXIT

prusim_and_images "$work" beaglelogic-pru0.elf beaglelogic-pru1.elf || exit 1
fw=$work/fw
grep '^ *FW ' "$work/fw.log" | sed 's/^ */info: /'

# The ioctl numbers as the original's clients use them (the values of
# ../shared/reference's ABI facts; _IOC encodes them alike on ARM and x86).
cat >"$work/uapi.c" <<'C'
#include <stdio.h>
#include <prukit/beaglelogic.h>
static const unsigned int nr[] = {
	IOCTL_BL_GET_VERSION, IOCTL_BL_GET_SAMPLE_RATE, IOCTL_BL_SET_SAMPLE_RATE,
	IOCTL_BL_GET_SAMPLE_UNIT, IOCTL_BL_SET_SAMPLE_UNIT, IOCTL_BL_GET_TRIGGER_FLAGS,
	IOCTL_BL_SET_TRIGGER_FLAGS, IOCTL_BL_GET_CUR_INDEX, IOCTL_BL_CACHE_INVALIDATE,
	IOCTL_BL_GET_BUFFER_SIZE, IOCTL_BL_SET_BUFFER_SIZE, IOCTL_BL_GET_BUFUNIT_SIZE,
	IOCTL_BL_SET_BUFUNIT_SIZE, IOCTL_BL_FILL_TEST_PATTERN, IOCTL_BL_START, IOCTL_BL_STOP,
};
int main(void)
{
	unsigned int i;

	for (i = 0; i < sizeof(nr) / sizeof(nr[0]); i++)
		printf("%s%x", i ? " " : "", nr[i]);
	printf("\n");
	return 0;
}
C
want="80046b20 80046b21 40046b21 80046b22 40046b22 80046b23 40046b23 80046b24 6b25"
want="$want 80046b26 40046b26 80046b27 40046b27 6b28 6b29 6b2a"
uapi_rc=1
if cc -Wall -Werror -I include/uapi -o "$work/uapi" "$work/uapi.c" 2>"$work/uapi.log" &&
   [ "$("$work/uapi")" = "$want" ]; then
	echo "PASS: include/uapi/prukit/beaglelogic.h builds in a program; its 16 ioctls are BeagleLogic's"
	uapi_rc=0
else
	cat "$work/uapi.log"
	echo "FAIL: include/uapi/prukit/beaglelogic.h: ioctls $("$work/uapi" 2>/dev/null), want $want"
fi

mkdir -p "$work/run"
python3 "$PRUKIT_TOP/drivers/beaglelogic/tests/bl_sim.py" "$PRUKIT_TOP/out/tools/prusim" \
	"$fw" "$work/run" && exit "$uapi_rc"
exit 1
