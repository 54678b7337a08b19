#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make demo: on a fresh machine, build what is needed, boot the emulated
# BeagleBone (Debian's 6.1 kernel under QEMU, with prukit's PRU-ICSS at its
# AM335x addresses and the kernel's own pruss, pruss_intc and pru_rproc:
# the board path, Documentation/qemu-pruss.rst) and run in it
# (tests/vm/demo/board):
#
#  - prukit's ws281x driver (tests/vm/demo/ws281x): LED 0 of the shipped
#    overlay's string on P9_29 as a Linux LED (rgb:status-0, the timer
#    trigger), then an animation written to /dev/ws281xN on the four strings
#    of the test controller ws281x-mix (both PRUs, R30 and GPIO pins, an RGBW
#    string);
#  - prukit's beaglelogic driver (tests/vm/demo/logic): sigrok-cli -d
#    beaglelogic captures a UART line and an SPI bus into a session
#    (logic.sr, for PulseView), which sigrok's uart and spi decoders
#    decode and tools/logic-show.py draws (logic-uart.png, logic-spi.png);
#  - prukit's hub75 driver (tests/vm/demo/matrix): a picture and scrolling
#    text written with cat to /dev/fbN of a 64x32 HUB75 panel, decoded from
#    the pins by tools/hub75-decode.py and drawn as the panel would look
#    (drivers/hub75/tests/hub75_demo.py: matrix-picture.png,
#    matrix-scroll.gif, matrix-scroll.png); then a picture on the
#    Octoscroller's 24 panels, every output decoded (matrix-wall.png);
#  - prukit's pru_pwm driver (tests/vm/demo/servo): four servos swept
#    through the PWM chip's sysfs files after prukit servo set them, every
#    pulse measured from the pins and drawn over time
#    (drivers/pru_pwm/tests/servo_demo.py: servo.png, servo.vcd);
#  - prukit's pru_encoder driver (tests/vm/demo/encoder): a simulated
#    encoder turned back and forth on PRU0's inputs, its count read through
#    sysfs after each stretch and drawn against the encoder's position
#    (drivers/pru_encoder/tests/encoder_demo.py: encoder.png);
#  - prukit-pixeld (tests/vm/demo/pixels): E1.31 from PyPI's sacn in the
#    guest onto the four strings of ws281x-mix, then, after a reload, onto
#    the 64x32 panel over 12 synchronized universes, decoded from the pins
#    (tools/ws281x-show.py: pixeld-strings.gif, pixeld-strings.png;
#    tools/pixeld/tests/pixeld_demo.py: pixeld-panel.gif, pixeld-panel.png);
#  - the PRU Cookbook's NeoPixel example (firmware/rpmsg-neopixel) and
#    prukit's rainbow client through /dev/rpmsg_pru30 (tests/vm/demo/neopixel),
#    on the kernel's pru_rproc with the kick prukit_pru gives it
#    (Documentation/rpmsg-kick.rst).
#
# What the simulated pins did is decoded by sigrok's rgb_led_ws281x decoder
# (GRB strings; the others by tools/ws281x-show.py's own decoder, which must
# agree with sigrok's where both apply) and shown as coloured blocks in the
# terminal, PNGs and GIFs in out/demo, with VCD files for PulseView/GTKWave.
# The demo fails unless every decoded frame is what the guest sent.
set -euo pipefail
. "$(dirname "$0")/lib.sh"
# The demo's boot has the PRUs on their own thread (vm.sh's threaded
# clock, as the demo was made and measured); PRUKIT_VM_CLOCK=lockstep
# make demo boots it in lockstep.
export PRUKIT_VM_CLOCK=${PRUKIT_VM_CLOCK:-thread}

need_pkgs python3-pil sigrok-cli
out=$PRUKIT_TOP/out/demo
rm -rf "$out"
mkdir -p "$out"

make -s -C "$PRUKIT_TOP" firmware tools >/dev/null
# the guest's parts, and the frames its matrix part draws
in=$(mktemp -d)
trap 'rm -rf "$in"' EXIT
cp -r "$PRUKIT_TOP/tests/vm/demo/." "$in/"
/usr/bin/python3 "$PRUKIT_TOP/drivers/hub75/tests/hub75_demo.py" frames "$in/matrix-frames"
# make demo KVER=6.12-ti: the same on another kernel (Documentation/kernels.rst)
kver=${PRUKIT_VM_KVER:-6.1}
kernel_flavour "$kver" >/dev/null
msg "booting the emulated BeagleBone ($kver under QEMU, the kernel's own PRU drivers on a simulated PRU-ICSS)"
"$PRUKIT_TOP/scripts/vm.sh" run "$kver" "$in/board" "$in" "$out"

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

# prukit's beaglelogic driver: the session sigrok-cli saved in the guest
echo
echo "prukit's beaglelogic driver: sigrok-cli -d beaglelogic captured a UART line (P8_45,"
echo "1 Mbaud) and an SPI bus (P8_44 CS#, P8_46 SCLK, P8_43 MOSI, P8_41 MISO; 2 MHz) at"
echo "20 MHz; every sample checked against the stimulus, and sigrok's uart and spi decoders"
echo "must print exactly the bytes sent:"
read -r t0 step <"$out/logic.txt"
python3 "$PRUKIT_TOP/drivers/beaglelogic/tests/bl_decode.py" "$out/logic.sr" "$t0" "$step"
chans=(--channel P8_45=UART --channel P8_44=SPI_CS# --channel P8_46=SPI_SCLK
	--channel P8_43=SPI_MOSI --channel P8_41=SPI_MISO)
uart=(--decode "uart:rx=P8_45:baudrate=1000000@rx-data@UART")
spi=(--decode "spi:clk=P8_46:mosi=P8_43:miso=P8_41:cs=P8_44@mosi-data@MOSI"
	--decode "spi:clk=P8_46:mosi=P8_43:miso=P8_41:cs=P8_44@miso-data@MISO")
echo
echo "decoded by sigrok's uart and spi decoders:"
/usr/bin/python3 "$PRUKIT_TOP/tools/logic-show.py" "$out/logic.sr" "${chans[@]}" "${uart[@]}" \
	"${spi[@]}" --png "$out/logic.png"
# the first whole period of the stimulus, and its SPI transfers up close:
# the samples where they begin, and their lengths
read -r period_at period_n spi_at spi_n < <(python3 - "$t0" "$step" <<PY
import sys
sys.path.insert(0, "$PRUKIT_TOP/drivers/beaglelogic/tests/vm/lib")
import bl_stim
t0, step = int(sys.argv[1]), int(sys.argv[2])
p = bl_stim.SERIAL_PERIOD
spi = [f for f in bl_stim.serial_events()[0] if f[0] == "spi"]
at = ((p - t0 % p) % p + step - 1) // step
print(at, p // step, at + (spi[0][1] - 400) // step, (spi[-1][2] - spi[0][1] + 800) // step)
PY
)
/usr/bin/python3 "$PRUKIT_TOP/tools/logic-show.py" "$out/logic.sr" "${chans[@]}" "${uart[@]}" \
	--from "$period_at" --samples "$period_n" --png "$out/logic-uart.png" >/dev/null
/usr/bin/python3 "$PRUKIT_TOP/tools/logic-show.py" "$out/logic.sr" "${chans[@]}" "${spi[@]}" \
	--from "$spi_at" --samples "$spi_n" --png "$out/logic-spi.png" >/dev/null

# prukit's hub75 driver: the pins of every frame the guest drew
echo
echo "prukit's hub75 driver: a 64x32 HUB75 panel on PRU1's R30 (PRUKIT-HUB75-00A0), a picture"
echo "and scrolling text written with cat to /dev/fbN; what the panel shows, decoded from the"
echo "pins by tools/hub75-decode.py (8 bit planes, CIE 1931 levels; every pixel must be exact);"
echo "then the Octoscroller's 24 panels (8 outputs x 3 64x32 on GPIO, PRU0), each output decoded:"
mkdir -p "$out/matrix"
mv "$out"/hub75.json "$out"/picture.* "$out"/scroll-* "$out"/wall.* "$out/matrix/"
/usr/bin/python3 "$PRUKIT_TOP/drivers/hub75/tests/hub75_demo.py" show "$out/matrix" "$out"

# prukit's pru_pwm driver: the servo sweep
echo
echo "prukit's pru_pwm driver: four servos (P8_27 - P8_30, PRUKIT-PWM-00A0) swept between 600 and"
echo "2400 us at 50 Hz; every pulse measured from the pins (each must be a width written):"
/usr/bin/python3 "$PRUKIT_TOP/drivers/pru_pwm/tests/servo_demo.py" "$PRUKIT_TOP/out/tools/prusim" "$out"

# prukit's pru_encoder driver: the count against the encoder's position
echo
echo "prukit's pru_encoder driver: a simulated encoder on P8_16/P8_15 (PRUKIT-ENCODER-00A0) turned"
echo "back and forth; the count read from sysfs after each stretch (it must be the position):"
/usr/bin/python3 "$PRUKIT_TOP/drivers/pru_encoder/tests/encoder_demo.py" "$out"

echo
echo "prukit-pixeld: E1.31 (sACN) from PyPI's sacn in the guest, as xLights would send it, onto the"
echo "four strings of ws281x-mix (universe 1), decoded from the pins (P9_30 by sigrok's"
echo "rgb_led_ws281x, the others by ws281x-show.py's decoder; every frame must be what was sent):"
"$PRUKIT_TOP/out/tools/prusim" --trace-in "$out/pixeld-strings.bin" \
	--events "$out/pixeld-strings.events" --vcd "$out/pixeld-strings.vcd"
/usr/bin/python3 "$PRUKIT_TOP/tools/ws281x-show.py" "$out/pixeld-strings.vcd" --pin P9_30:grb:6 \
	--pin gpio1_12:grbw:4 --pin P8_42:rgb:5 --pin gpio2_2:brg:3 \
	--strip "$out/pixeld-strings.png" --gif "$out/pixeld-strings.gif" --delay 120 \
	--expect "$out/pixeld-strings.sent"
echo
echo "... then, after a reload, onto the 64x32 panel: 8 frames of 12 universes each, released at"
echo "once by a sync packet, decoded from the pins (every pixel must be what was sent):"
/usr/bin/python3 "$PRUKIT_TOP/tools/pixeld/tests/pixeld_demo.py" "$out/pixeld" "$out"

echo
msg "pictures: $out/rainbow.gif, $out/rainbow.png, $out/frames/frame-*.png," \
	"$out/neopixel-led0.png, $out/logic-uart.png, $out/logic-spi.png, $out/logic.png;" \
	"VCD for PulseView/GTKWave: $out/neopixel.vcd; the sigrok session for PulseView:" \
	"$out/logic.sr"
msg "pru_pwm: $out/servo.png; VCD: $out/servo.vcd; pru_encoder: $out/encoder.png"
msg "hub75: $out/matrix-picture.png, $out/matrix-scroll.gif, $out/matrix-scroll.png," \
	"$out/matrix-wall.png"
msg "prukit-pixeld: $out/pixeld-strings.gif, $out/pixeld-strings.png, $out/pixeld-panel.gif," \
	"$out/pixeld-panel.png; VCD: $out/pixeld-strings.vcd"
msg "ws281x: $out/ws281x-leds.png, $out/ws281x-leds.gif, $out/ws281x-strings.png," \
	"$out/ws281x-strings.gif, $out/ws281x-strings-wave.png; VCD: $out/ws281x-leds.vcd," \
	"$out/ws281x-strings.vcd"
