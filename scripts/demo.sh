#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make demo: on a fresh machine, build what is needed, boot the emulated
# BeagleBone (Debian's 6.1 kernel, pru_sim's PRU-ICSS) and run the PRU
# Cookbook's NeoPixel example (firmware/rpmsg-neopixel) and prukit's rainbow
# client through /dev/rpmsg_pru30.  The 24 LEDs' colours are decoded from the simulated
# P9_29 by sigrok's rgb_led_ws281x decoder and shown as coloured blocks in the
# terminal, a PNG strip per frame, one PNG of all frames and a GIF in out/demo.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs python3-pil sigrok-cli
out=$PRUKIT_TOP/out/demo
rm -rf "$out"
mkdir -p "$out"

make -s -C "$PRUKIT_TOP" firmware tools >/dev/null
msg "booting the emulated BeagleBone (Linux 6.1 under QEMU, PRUs simulated by pru_sim)"
"$PRUKIT_TOP/scripts/vm.sh" run 6.1 "$PRUKIT_TOP/tests/vm/demo/neopixel" "" "$out"

"$PRUKIT_TOP/out/tools/prusim" --trace-in "$out/trace.bin" --events "$out/neopixel.events" \
	--vcd "$out/neopixel.vcd"
echo
echo "P9_29, the first LED's 24 bits (GRB, MSB first) of the Cookbook's frame:"
/usr/bin/python3 "$PRUKIT_TOP/tools/prusim-wave.py" "$out/neopixel.events" \
	--from "$(head -n 1 "$out/neopixel.events" | cut -d' ' -f1)" --cycles 5600 --width 112 \
	--png "$out/neopixel-led0.png"
echo
echo "The 24 LEDs, decoded from P9_29 by sigrok's rgb_led_ws281x (frame 0: the Cookbook's"
echo "\"0 0xff 0 127\"; then rainbow.py):"
{
	echo "#ff007f$(printf ' #000000%.0s' $(seq 23))"
	cat "$out/rainbow.sent"
} >"$out/sent.txt"
/usr/bin/python3 "$PRUKIT_TOP/tools/ws281x-show.py" "$out/neopixel.vcd" --pin P9_29 \
	--png-dir "$out/frames" --strip "$out/rainbow.png" --gif "$out/rainbow.gif" \
	--expect "$out/sent.txt"
echo
msg "pictures: $out/rainbow.gif, $out/rainbow.png, $out/frames/frame-*.png," \
	"$out/neopixel-led0.png; VCD for PulseView/GTKWave: $out/neopixel.vcd"
