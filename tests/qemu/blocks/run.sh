#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# tests/qemu/blocks/run.sh QEMU [OUTDIR] - the AM335x blocks of the VM's
# board (qemu/, Documentation/qemu-pruss.rst) as QEMU sees them, before any
# guest code runs: QEMU is started paused (-S) with pruss=on, and its
# monitor asked for the device tree, the memory map and a few registers
# (xp: a physical read through the bus, as the guest's would be).
#
#   devices     one QOM device per block: the PRU-ICSS, four GPIO banks
#               (bank 0..3), the pads, PRCM, the test port, and QEMU's
#               unimplemented devices over the rest of L4_WKUP, L4_PER and
#               L4_FAST
#   map         each block at its AM335x address, the unimplemented devices
#               below them (priority -1000)
#   reset       PRCM's reset values reach the blocks through its lines: the
#               PRU-ICSS is held in reset (RSTCTRL reads PRU_ICSS_LRST, a
#               read of the PRU-ICSS is an unmodelled access "while PRCM
#               holds it in reset"), every GPIO bank's clock is off (CLKCTRL
#               reads IDLEST disabled, a read of the bank is an unmodelled
#               access "while PRCM gates its clocks"); a pad reads its reset
#               value, the test port its ID
#   l4          a read of the rest of L4_PER is logged by the unimplemented
#               device
#   system_reset  the same values after a reset of the machine
#
# Then QEMU's qtest protocol (-accel qtest: reads and writes through the
# bus, no CPU) drives what the lines between the blocks carry:
#   lrst        releasing PRU_ICSS_LRST in RM_PER_RSTCTRL lets the PRU-ICSS
#               answer (PRU0's CONTROL reads its reset value), its RAM
#               takes a word and gives it back, also as a narrower read and
#               after a narrower write (little-endian bytes), and asserting
#               the reset again clears the RAM
#   clk         enabling GPIO1's MODULEMODE in its CLKCTRL clocks the bank
#               (REVISION reads, OE takes a value); disabling it gates the
#               bank (IDLEST disabled, an access is an unmodelled one) and
#               the bank keeps its registers until it is clocked again
#   pads        a pad register keeps its low 7 bits
#
# One PASS:/FAIL: line per check; exit status 1 if one failed.
set -uo pipefail
bin=${1:?usage: run.sh QEMU [OUTDIR]}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
bad=0
pass() { echo "PASS: qemu blocks: $*"; }
fail() { echo "FAIL: qemu blocks: $*"; bad=1; }

# xp ADDR: the monitor command that reads the word at ADDR
reads=(0x44e00c00 0x44e000ac 0x44e10800 0x5f000000 0x4804c000 0x4a300000 0x480c0000)
{
	echo "info qtree"
	echo "info mtree"
	for a in "${reads[@]}"; do echo "xp /1wx $a"; done
	echo "system_reset"
	for a in "${reads[@]:0:4}"; do echo "xp /1wx $a"; done
	echo "quit"
} >"$out/monitor.in"
rm -f "$out/qemu.log"
if ! timeout 120 "$bin" -M vexpress-a15,pruss=on -S -nodefaults -display none \
	-d unimp -D "$out/qemu.log" -monitor stdio <"$out/monitor.in" >"$out/monitor.out" 2>&1; then
	tail -n 20 "$out/monitor.out" | sed 's/^/    /'
	fail "$bin exited with an error ($out/monitor.out)"
	exit 1
fi
tr -d '\r' <"$out/monitor.out" >"$out/monitor.txt"
mon=$out/monitor.txt

# devices
want_dev() {
	local n
	n=$(grep -c "dev: $1, id" "$mon")
	if [ "$n" -eq "$2" ]; then
		pass "devices: $2 x $1"
	else
		fail "devices: $n x $1, $2 expected"
	fi
}
want_dev am335x-pruss 1
want_dev am335x-gpio 4
want_dev am335x-pads 1
want_dev am335x-prcm 1
want_dev am335x-pruss-port 1
banks=$(grep -A3 'dev: am335x-gpio, id' "$mon" | sed -n 's/^ *bank = \([0-9]*\).*/\1/p' | sort | tr '\n' ' ')
if [ "$banks" = "0 1 2 3 " ]; then
	pass "devices: the GPIO banks are banks 0 1 2 3"
else
	fail "devices: the GPIO banks' property bank: \"$banks\", 0 1 2 3 expected"
fi
for l4 in l4_wkup l4_per l4_fast; do
	if grep -A3 'dev: unimplemented-device, id' "$mon" | grep -q "name = \"am335x.$l4\""; then
		pass "devices: the rest of ${l4^^} is an unimplemented device"
	else
		fail "devices: no unimplemented device am335x.$l4"
	fi
done

# map: "START-END (prio P, i/o): NAME" in the system address space
want_map() {
	local start=$1 end=$2 prio=$3 name=$4
	if grep -qE "^ *0*$start-0*$end \(prio $prio, i/o\): $name\$" "$mon"; then
		pass "map: $name at 0x$start-0x$end (priority $prio)"
	else
		fail "map: no $name at 0x$start-0x$end (priority $prio): $(grep -E ": $name\$" "$mon" | head -n 1)"
	fi
}
want_map 4a300000 4a37ffff 0 am335x-pruss.icss
want_map 44e07000 44e07fff 0 am335x-gpio0
want_map 4804c000 4804cfff 0 am335x-gpio1
want_map 481ac000 481acfff 0 am335x-gpio2
want_map 481ae000 481aefff 0 am335x-gpio3
want_map 44e10800 44e10a37 0 am335x-pads
want_map 44e00c00 44e00cff 0 am335x-prcm.prm-per
want_map 44e00000 44e004ff 0 am335x-prcm.cm
want_map 5f000000 5f000fff 0 am335x-pruss-port
want_map 44c00000 44ffffff -1000 am335x.l4_wkup
want_map 48000000 48ffffff -1000 am335x.l4_per
want_map 4a000000 4affffff -1000 am335x.l4_fast

# reset: the xp lines, in order ("ADDR: 0xVALUE")
# (or "ADDR: Cannot access memory": every read has its line)
mapfile -t vals < <(sed -n 's/^0*\([0-9a-f]\{1,16\}\): \(.*\)$/\1 \2/p' "$mon")
want_read() {
	local i=$1 addr=$2 val=$3 what=$4 got=${vals[$1]:-}
	if [ "$got" = "$addr $val" ]; then
		pass "$what: 0x$addr reads $val"
	else
		fail "$what: 0x$addr reads \"${got#* }\" (read $i: \"$got\"), $val expected"
	fi
}
if [ "${#vals[@]}" -ne 11 ]; then
	fail "reset: ${#vals[@]} register reads answered, 11 expected"
fi
want_read 0 44e00c00 0x00000002 "reset: PRM_PER RM_PER_RSTCTRL holds the PRU-ICSS in reset"
want_read 1 44e000ac 0x00030000 "reset: CM_PER GPIO1_CLKCTRL is disabled"
want_read 2 44e10800 0x00000027 "reset: pad conf_gpmc_ad0 is mode 7, receiver on"
want_read 3 5f000000 0x4d535250 "reset: the test port's ID"
want_read 4 4804c000 0x00000000 "reset: GPIO1 REVISION while its clock is off"
want_read 5 4a300000 0x00000000 "reset: the PRU-ICSS's RAM while it is held in reset"
want_read 6 480c0000 0x00000000 "l4: L4_PER past the blocks"
want_read 7 44e00c00 0x00000002 "system_reset: RM_PER_RSTCTRL"
want_read 8 44e000ac 0x00030000 "system_reset: GPIO1_CLKCTRL"
want_read 9 44e10800 0x00000027 "system_reset: conf_gpmc_ad0"
want_read 10 5f000000 0x4d535250 "system_reset: the test port's ID"

# want_log LOG WHAT TEXT: LOG (QEMU's -D file) has a line with TEXT
want_log() {
	if grep -qF -- "$3" "$1"; then
		pass "$2"
	else
		fail "$2: no line \"$3\" in $1"
	fi
}
# log_lines LOG N WHAT: the model's lines in LOG are N, no more
log_lines() {
	local n
	n=$(grep -c '^am335x' "$1")
	if [ "$n" -eq "$2" ]; then
		pass "$3"
	else
		grep '^am335x' "$1" | head -n 10 | sed 's/^/    /'
		fail "${3%%:*}: the model logged $n lines, $2 expected"
	fi
}
want_log "$out/qemu.log" "reset: a read of a gated GPIO bank is an unmodelled access" \
	"am335x-pruss: GPIO1 read at 0x000 while PRCM gates its clocks"
want_log "$out/qemu.log" "reset: a read of the PRU-ICSS in reset is an unmodelled access" \
	"am335x-pruss: PRU-ICSS read of 4 bytes at 0x00000 while PRCM holds it in reset"
want_log "$out/qemu.log" "l4: the unimplemented device logs a read of L4_PER" \
	"am335x.l4_per: unimplemented device read  (size 4, offset 0x0c0000)"
log_lines "$out/qemu.log" 3 "monitor: the model logged those 3 lines and no other"

# qtest: "COMMAND|REPLY" (a read's reply is its value)
steps=(
	"readl 0x44e00c00|0x2"
	"writel 0x44e00c00 0x0|"
	"readl 0x4a322000|0x1"
	"writel 0x4a300000 0x12345678|"
	"readl 0x4a300000|0x12345678"
	"readw 0x4a300002|0x1234"
	"writeb 0x4a300001 0xab|"
	"readl 0x4a300000|0x1234ab78"
	"writel 0x44e00c00 0x2|"
	"writel 0x44e00c00 0x0|"
	"readl 0x4a300000|0x0"
	"writel 0x44e000ac 0x2|"
	"readl 0x44e000ac|0x2"
	"readl 0x4804c000|0x50600801"
	"readl 0x4804c134|0xffffffff"
	"writel 0x4804c134 0xfffffffe|"
	"readl 0x4804c134|0xfffffffe"
	"writel 0x44e000ac 0x0|"
	"readl 0x44e000ac|0x30000"
	"readl 0x4804c134|0x0"
	"writel 0x44e000ac 0x2|"
	"readl 0x4804c134|0xfffffffe"
	"writel 0x44e10800 0xff|"
	"readl 0x44e10800|0x7f"
)
what=(
	"lrst: RM_PER_RSTCTRL holds the PRU-ICSS in reset"
	"lrst: release it"
	"lrst: released, PRU0 CONTROL reads its reset value"
	"lrst: a word into PRU0's data RAM"
	"lrst: ... reads back"
	"lrst: ... its upper half as a 16-bit read"
	"lrst: a byte into it"
	"lrst: ... lands in the word, little-endian"
	"lrst: assert the reset again"
	"lrst: and release it"
	"lrst: the reset cleared the RAM"
	"clk: enable GPIO1's MODULEMODE"
	"clk: CLKCTRL reads enabled (IDLEST functional)"
	"clk: the clocked bank's REVISION"
	"clk: its OE (every line an input)"
	"clk: make line 0 an output"
	"clk: OE reads back"
	"clk: disable MODULEMODE"
	"clk: CLKCTRL reads IDLEST disabled"
	"clk: a gated bank reads 0"
	"clk: enable it again"
	"clk: the bank kept its OE while gated"
	"pads: write 0xff to conf_gpmc_ad0"
	"pads: it keeps the low 7 bits"
)
printf '%s\n' "${steps[@]%%|*}" >"$out/qtest.in"
rm -f "$out/qtest.log" "$out/qtest.out"
# qtest has no quit: QEMU runs until every command has its reply (or 60 s)
"$bin" -M vexpress-a15,pruss=on -accel qtest -qtest stdio -qtest-log none \
	-nodefaults -display none -d unimp -D "$out/qtest.log" \
	<"$out/qtest.in" >"$out/qtest.out" 2>"$out/qtest.err" &
qpid=$!
replied() {
	local n
	n=$(grep -cE '^(OK|ERR|FAIL)' "$out/qtest.out" 2>/dev/null)
	echo "${n:-0}"
}
deadline=$((SECONDS + 60))
while [ "$(replied)" -lt ${#steps[@]} ] && kill -0 $qpid 2>/dev/null &&
	[ $SECONDS -lt $deadline ]; do
	sleep 0.1
done
if ! kill -0 $qpid 2>/dev/null; then
	tail -n 20 "$out/qtest.err" | sed 's/^/    /'
	fail "$bin -accel qtest exited before it answered ($(replied) of ${#steps[@]} replies, $out/qtest.err)"
fi
kill $qpid 2>/dev/null
wait $qpid 2>/dev/null
mapfile -t replies < <(tr -d '\r' <"$out/qtest.out" | grep -E '^(OK|ERR|FAIL)')
for i in "${!steps[@]}"; do
	want=OK
	val=${steps[$i]#*|}
	[ -z "$val" ] || want=$(printf 'OK 0x%016x' "$val")
	if [ "${replies[$i]:-}" = "$want" ]; then
		pass "${what[$i]}: ${steps[$i]%%|*}${val:+ = $val}"
	else
		fail "${what[$i]}: ${steps[$i]%%|*}: \"${replies[$i]:-no reply}\", \"$want\" expected"
	fi
done
want_log "$out/qtest.log" "clk: the read of the gated bank is an unmodelled access" \
	"am335x-pruss: GPIO1 read at 0x134 while PRCM gates its clocks"
log_lines "$out/qtest.log" 1 "qtest: the model logged that line and no other"
exit $bad
