#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# make demo: on a fresh machine, build what is needed, boot the emulated
# BeagleBone (Debian's 6.1 kernel, pru_sim's PRU-ICSS), run firmware from
# firmware/examples through remoteproc exactly as the PRU Cookbook does, and
# show what the PRU's pins did: a terminal rendering and out/demo/*.png.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs python3-pil
out=$PRUKIT_TOP/out/demo
rm -rf "$out"
mkdir -p "$out"

make -s -C "$PRUKIT_TOP" firmware tools >/dev/null
msg "booting the emulated BeagleBone (Linux 6.1 under QEMU, PRUs simulated by pru_sim)"
"$PRUKIT_TOP/scripts/vm.sh" run 6.1 "$PRUKIT_TOP/tests/vm/demo/blinky" "" "$out"

prusim=$PRUKIT_TOP/out/tools/prusim
"$prusim" --trace-in "$out/trace.bin" --events "$out/blinky.events" --vcd "$out/blinky.vcd"
wave=(/usr/bin/python3 "$PRUKIT_TOP/tools/prusim-wave.py" "$out/blinky.events")
echo
echo "PRU0 R30 bits 0..7 (BeagleBone P9 header pins), first 3 us:"
"${wave[@]}" --cycles 600 --width 96 --png "$out/blinky-3us.png"
echo
echo "The whole count, 0..255 (128 us):"
"${wave[@]}" --cycles 25700 --width 96 --png "$out/blinky-128us.png"
echo
msg "pictures: $out/blinky-3us.png, $out/blinky-128us.png; VCD for PulseView/GTKWave: $out/blinky.vcd"
