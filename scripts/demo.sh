#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make demo: on a fresh machine, build what is needed, boot the emulated
# BeagleBone (Debian's 6.1 kernel, pru_sim's PRU-ICSS) once and run in it
# (tests/vm/demo/all):
#
#  - the PRU Cookbook's NeoPixel example (firmware/rpmsg-neopixel) and
#    prukit's rainbow client through /dev/rpmsg_pru30 (tests/vm/demo/neopixel);
#  - prukit's ws281x driver (tests/vm/demo/ws281x): LED 0 of the shipped
#    overlay's string on P9_29 as a Linux LED (rgb:status-0, the timer
#    trigger), then an animation written to /dev/ws281xN on the four strings
#    of the test controller ws281x-mix (both PRUs, R30 and GPIO pins, an RGBW
#    string).
#
# What the simulated pins did is decoded by sigrok's rgb_led_ws281x decoder
# (GRB strings; the others by tools/ws281x-show.py's own decoder, which must
# agree with sigrok's where both apply) and shown as coloured blocks in the
# terminal, PNGs and GIFs in out/demo, with VCD files for PulseView/GTKWave.
# The demo fails unless every decoded frame is what the guest sent.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs python3-pil sigrok-cli
out=$PRUKIT_TOP/out/demo
rm -rf "$out"
mkdir -p "$out"

make -s -C "$PRUKIT_TOP" firmware tools >/dev/null
msg "booting the emulated BeagleBone (Linux 6.1 under QEMU, PRUs simulated by pru_sim)"
"$PRUKIT_TOP/scripts/vm.sh" run 6.1 "$PRUKIT_TOP/tests/vm/demo/all" "$PRUKIT_TOP/tests/vm/demo" "$out"

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

# prukit's ws281x driver: the traces tests/vm/demo/ws281x saved
for part in ws281x-leds ws281x-strings; do
	"$PRUKIT_TOP/out/tools/prusim" --trace-in "$out/$part.bin" --events "$out/$part.events" \
		--vcd "$out/$part.vcd"
done
echo
echo "prukit's ws281x driver, LED 0 of the string on P9_29 as a Linux LED (rgb:status-0:"
echo "\"255 0 127\" > multi_intensity, brightness 255, the timer trigger, none), decoded by"
echo "sigrok's rgb_led_ws281x and by ws281x-show.py's own decoder (they must agree):"
/usr/bin/python3 "$PRUKIT_TOP/tools/ws281x-show.py" "$out/ws281x-leds.vcd" --pin P9_29:grb:24 \
	--strip "$out/ws281x-leds.png" --gif "$out/ws281x-leds.gif" --delay 250 \
	--expect "$out/ws281x-leds.expect"
echo
echo "The four strings of ws281x-mix, the first 4 bits of a frame: each PRU's strings share"
echo "the 1250 ns bit slot; GPIO pins follow the slot by the bank write's latency, PRU1 runs"
echo "35 cycles behind PRU0 (both time the slots on the IEP counter):"
/usr/bin/python3 "$PRUKIT_TOP/tools/prusim-wave.py" "$out/ws281x-strings.events" \
	--from "$(head -n 1 "$out/ws281x-strings.events" | cut -d' ' -f1)" --cycles 1000 --width 100 \
	--pins P9_30,gpio1_12,P8_42,gpio2_2 --png "$out/ws281x-strings-wave.png"
echo
echo "The animation written through /dev/ws281xN, decoded string by string (in R, G, B(, W) order"
echo "whatever the chips' order on the wire): P9_30 by sigrok's rgb_led_ws281x and"
echo "ws281x-show.py's decoder, the RGBW, RGB and BRG strings by ws281x-show.py's:"
/usr/bin/python3 "$PRUKIT_TOP/tools/ws281x-show.py" "$out/ws281x-strings.vcd" --pin P9_30:grb:6 --pin gpio1_12:grbw:4 \
	--pin P8_42:rgb:5 --pin gpio2_2:brg:3 \
	--strip "$out/ws281x-strings.png" --gif "$out/ws281x-strings.gif" --delay 120 \
	--expect "$out/ws281x-strings.sent"
echo
msg "pictures: $out/rainbow.gif, $out/rainbow.png, $out/frames/frame-*.png," \
	"$out/neopixel-led0.png; VCD for PulseView/GTKWave: $out/neopixel.vcd"
msg "ws281x: $out/ws281x-leds.png, $out/ws281x-leds.gif, $out/ws281x-strings.png," \
	"$out/ws281x-strings.gif, $out/ws281x-strings-wave.png; VCD: $out/ws281x-leds.vcd," \
	"$out/ws281x-strings.vcd"
