#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# tests/rpmsg-fw/run.sh - prukit's rpmsg firmware (firmware/lib/rpmsg.c,
# firmware/rpmsg-echo, firmware/rpmsg-neopixel) against a host-side stand-in
# for Linux's remoteproc/virtio_rpmsg, in the prusim core, without a kernel.
#
#   1. build the firmware, the prusim tool and the harness (ASan + UBSan)
#   2. the library's share of IRAM/DRAM, from the link maps
#   3. rpmsg_fw_test echo: resource table, irq map, DRIVER_OK wait, name
#      service, echo of 1..496 bytes, a burst larger than the rings, kick
#      suppression, cycles per message, malformed rings, bad resource tables
#   4. rpmsg_fw_test rpmsg-neopixel: the WS2812 wire timing of every bit,
#      reset, malformed lines; its pin trace goes through "prusim --trace-in
#      --events --vcd" and ws2812_decode.py decodes the tool's event list
#
# Prints PASS:/FAIL: lines and exits non-zero if anything failed.
set -euo pipefail
# shellcheck source=SCRIPTDIR/../../scripts/lib.sh
. "$(dirname "$0")/../../scripts/lib.sh"

command -v python3 >/dev/null || need_pkgs python3

T=$PRUKIT_TOP/tests/rpmsg-fw
out=$PRUKIT_TOP/out/tests/rpmsg-fw
fw=$PRUKIT_TOP/out/firmware
prusim=$PRUKIT_TOP/out/tools/prusim
CC=${CC:-cc}
failed=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; failed=1; }

mkdir -p "$out"
bin=$("$PRUKIT_TOP/scripts/pru-toolchain.sh")

# 1. Builds
if make -C "$PRUKIT_TOP/firmware" CROSS_COMPILE="$bin/pru-" O="$fw" >"$out/firmware.log" 2>&1; then
	pass "build firmware"
else
	tail -n 20 "$out/firmware.log"
	fail "build firmware"
	exit 1
fi
if make -C "$PRUKIT_TOP/tools/prusim" >"$out/prusim.log" 2>&1; then
	pass "build tools/prusim"
else
	tail -n 20 "$out/prusim.log"
	fail "build tools/prusim"
	exit 1
fi
if "$CC" -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -Wall -Wextra -Werror \
	-I"$PRUKIT_TOP/sim" -I"$PRUKIT_TOP/firmware/include" -I"$PRUKIT_TOP/drivers/rpmsg_pru" \
	-o "$out/rpmsg_fw_test" "$T/rpmsg_fw_test.c" \
	"$PRUKIT_TOP"/sim/prusim_{core,mem,elf,disasm,stim}.c >"$out/harness.log" 2>&1; then
	pass "build rpmsg_fw_test"
else
	cat "$out/harness.log"
	fail "build rpmsg_fw_test"
	exit 1
fi

# 2. Sizes: input sections of lib/rpmsg.c.o and lib/ocp_copy.S.o in each link map
for img in rpmsg-echo-pru0 rpmsg-echo-pru1 rpmsg-neopixel-pru0; do
	map=$fw/obj/${img%-pru?}/${img##*-}/$img.map
	line=$(READELF="$bin/pru-readelf" NM="$bin/pru-nm" "$PRUKIT_TOP/firmware/fwinfo.sh" \
		"$fw/$img.elf" "$img.elf" 2>&1 || true)
	if [ ! -f "$map" ]; then
		fail "size $img: no link map $map"
		continue
	fi
	iram=''
	dram=''
	read -r iram dram < <(python3 - "$map" <<'EOF'
import re, sys
iram = dram = 0
in_map = False
pending = None
for line in open(sys.argv[1]):
    if line.startswith("Linker script and memory map"):
        in_map = True
        continue
    if not in_map:
        continue
    m = re.match(r"^ (\.\S+)\s*$", line)
    if m:
        pending = m.group(1)
        continue
    m = re.match(r"^ (\.\S+)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S+)$", line)
    if m:
        name = m.group(1) or pending
        pending = None
        if not re.search(r"/lib/(rpmsg\.c|ocp_copy\.S)\.o$", m.group(4)):
            continue
        size = int(m.group(3), 16)
        if name.startswith(".text"):
            iram += size
        elif re.match(r"\.(resource_table|data|rodata|bss)", name):
            dram += size
    else:
        pending = None
print(iram, dram)
EOF
) || true
	if [ "${iram:-0}" -gt 0 ] && [ "${dram:-0}" -gt 0 ] && [ "$iram" -lt 2048 ] && [ -n "$line" ]; then
		pass "size $img: library (rpmsg.c + ocp_copy.S) iram $iram, dram $dram bytes" \
			"(+ the caller's struct prukit_rpmsg); image:$(echo "${line#*"$img.elf"}" |
			tr -s ' ')"
	else
		fail "size $img: library iram '$iram' dram '$dram', build line '$line'"
	fi
done

# 3. Echo on both cores
"$out/rpmsg_fw_test" echo "$fw/rpmsg-echo-pru0.elf" "$fw/rpmsg-echo-pru1.elf" || failed=1

# 4. NeoPixel, then the tool's view of the same pin trace
np=$out/rpmsg-neopixel
rm -f "$np.trace" "$np.events" "$np.vcd"
"$out/rpmsg_fw_test" rpmsg-neopixel "$fw/rpmsg-neopixel-pru0.elf" "$np.trace" || failed=1
if [ -f "$np.trace" ] &&
   "$prusim" --trace-in "$np.trace" --events "$np.events" \
	--vcd "$np.vcd" >"$out/trace-in.log" 2>&1; then
	pass "prusim --trace-in: rpmsg-neopixel.events, rpmsg-neopixel.vcd ($(wc -l <"$np.events") edges)"
else
	cat "$out/trace-in.log" 2>/dev/null || true
	fail "prusim --trace-in of the rpmsg-neopixel pin trace"
fi
# The frames the harness sent, GRB per pixel: pixel 0 = "0 0xff 0 127" twice,
# then pixels 5, 6, 7 added, then pixel 8
frame() {
	python3 -c '
import sys
f = bytearray(72)
for a in sys.argv[1:]:
    i, h = a.split(":")
    f[3 * int(i):3 * int(i) + 3] = bytes.fromhex(h)
print(f.hex())' "$@"
}
f1=$(frame 0:00ff7f)
f3=$(frame 0:00ff7f 5:020103 6:20103f 7:ff0001)
f4=$(frame 0:00ff7f 5:020103 6:20103f 7:ff0001 8:010101)
if [ -f "$np.events" ]; then
	python3 "$T/ws2812_decode.py" "$np.events" P9_29 "$f1" "$f1" "$f3" "$f4" ||
		failed=1
	# and the decoder is not blind: a wrong expectation must fail
	if python3 "$T/ws2812_decode.py" "$np.events" P9_29 "$f1" "$f1" "$f4" "$f4" \
		>/dev/null; then
		fail "ws2812_decode.py accepts a wrong frame"
	else
		pass "ws2812_decode.py rejects a wrong frame"
	fi
fi

exit $failed
