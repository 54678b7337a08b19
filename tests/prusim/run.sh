#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# tests/prusim/run.sh - validation suite of the prusim PRU-ICSS simulator.
#
#   1. the disassembler against pru-objdump on every instruction form
#   2. assembly and C firmware with expected registers, cycle counts, pin
#      edges (asm/*.S, c/*.c; see runner.py), each also run without idle
#      skipping to prove skipping exact; firmware/input-echo with and
#      without skipping gives the same JSON and events
#   3. a bit-banged UART decoded from the VCD by sigrok's own decoder
#   4. unit tests of the embedding API and the shared stimulus parser
#      (unit_test.c, built with ASan and UBSan), random idle waits run
#      skipped in slices against stepped
#   5. CLI details: --trace, --until-halt, stimulus file errors
#   6. binary pin traces: --trace-out then --trace-in gives the VCD and the
#      event list of the run itself; origin handling; corrupt traces fail
#   7. the core's hygiene: only the allowed C library calls, no mutable
#      static data
#
# Prints PASS:/FAIL: lines and exits non-zero if anything failed.  The
# kernel build of the core is checked by tests/prusim/kbuild/kcheck.sh.
set -euo pipefail
. "$(dirname "$0")/../../scripts/lib.sh"

need_pkgs sigrok-cli binutils
command -v python3 >/dev/null || need_pkgs python3

T=$PRUKIT_TOP/tests/prusim
out=$PRUKIT_TOP/out/tests/prusim
prusim=$PRUKIT_TOP/out/tools/prusim
CC=${CC:-cc}
failed=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; failed=1; }
# squeeze whitespace: objdump and prusim may differ only in spacing
normalise() { sed -e 's/[[:space:]]\+/ /g' -e 's/^ //' -e 's/ $//'; }

mkdir -p "$out"
bin=$("$PRUKIT_TOP/scripts/pru-toolchain.sh")
if make -C "$PRUKIT_TOP/tools/prusim" >"$out/make.log" 2>&1; then
	pass "build tools/prusim"
else
	tail -n 20 "$out/make.log"
	fail "build tools/prusim"
	exit 1
fi

# 1. Disassembler
python3 "$T/gen_disasm_words.py" >"$out/disasm.S" 2>"$out/disasm.count"
"$bin/pru-as" -o "$out/disasm.o" "$out/disasm.S"
"$bin/pru-ld" --defsym=__IMEM_SIZE=0x100000 -e 0x20000000 -o "$out/disasm.elf" "$out/disasm.o"
"$bin/pru-strip" -o "$out/disasm.stripped.elf" "$out/disasm.elf"
"$bin/pru-objdump" -d -z "$out/disasm.stripped.elf" | grep -P '^\s*[0-9a-f]+:\t' |
	normalise >"$out/disasm.objdump.txt"
"$prusim" --disasm "$out/disasm.stripped.elf" | normalise >"$out/disasm.prusim.txt"
words=$(grep -c '\.word' "$out/disasm.S")
lines=$(wc -l <"$out/disasm.objdump.txt")
if [ "$lines" -lt "$words" ]; then
	fail "disasm: pru-objdump printed $lines lines for $words generated words"
elif cmp -s "$out/disasm.objdump.txt" "$out/disasm.prusim.txt"; then
	pass "disasm: $lines instructions ($words generated words) as pru-objdump prints them"
else
	diff "$out/disasm.objdump.txt" "$out/disasm.prusim.txt" | head -n 10 || true
	fail "disasm: differs from pru-objdump"
fi

# 2. Firmware with expectations
python3 "$T/runner.py" --prusim "$prusim" --tools "$bin" --out "$out" --testdir "$T" \
	"$T"/asm/*.S "$T"/c/*.c || failed=1

# 2b. Skipping is exact for real firmware: the full JSON and the event list
# with and without --no-skip must be identical.  skipcmp NAME WANT_INSNS
# PRUSIM_ARGS...: WANT_INSNS is PRU0's instruction count (the kernel driver
# decides from it that a slice was mostly skipped).
skipcmp() {
	local name=$1 want=$2 d=$out/skipcmp-$1 rc=0 rc2=0 got
	shift 2
	"$prusim" "$@" --json --events "$d.events" >"$d.json" 2>&1 || rc=$?
	"$prusim" "$@" --json --events "$d.noskip.events" --no-skip >"$d.noskip.json" 2>&1 || rc2=$?
	got=$(tail -n 1 "$d.json" |
		python3 -c 'import json, sys; print(json.load(sys.stdin)["pru"][0]["instructions"])' \
		2>/dev/null || echo none)
	if [ $rc -eq 0 ] && [ $rc2 -eq 0 ] && cmp -s "$d.json" "$d.noskip.json" &&
	   cmp -s "$d.events" "$d.noskip.events" && [ "$got" = "$want" ]; then
		pass "skip-exact $name: --json and --events equal --no-skip's, PRU0 ran $want instructions"
	else
		fail "skip-exact $name: exit $rc/$rc2, PRU0 instructions $got (want $want), JSON $(cmp -s "$d.json" "$d.noskip.json" && echo equal || echo differs)"
	fi
}
# firmware/input-echo, built by the firmware Makefile into our own directory
fw=$out/firmware
if make -s -C "$PRUKIT_TOP/firmware" O="$fw" CROSS_COMPILE="$bin/pru-" \
	"$fw/input-echo-pru0.elf" "$fw/input-echo-pru1.elf" >"$out/firmware.log" 2>&1; then
	echo_elf=$fw/input-echo-pru0.elf
	printf '0 0\n1000 0x1\n1500 0x3\n1530 0x2\n2000 0x8001\n2001 0\nrepeat 3000\n' >"$out/echo-stim.txt"
	# the case of the instruction count bug (748036 instead of 10000)
	skipcmp input-echo 10000 --pru0 "$echo_elf" --r31-0 "$out/echo-stim.txt" --max-cycles 10000
	# many periods, and runs split by unrouted events (each a prusim_run() call)
	skipcmp input-echo-long 3000000 --pru0 "$echo_elf" --r31-0 "$out/echo-stim.txt" \
		--max-cycles 3000000 --event 1234567:40 --event 2000003:41
	# both cores: PRU0's input never changes, PRU1's repeats
	printf '0 0x5\n' >"$out/echo-stim-const.txt"
	skipcmp input-echo-const 1000000 --pru0 "$echo_elf" \
		--pru1 "$fw/input-echo-pru1.elf" \
		--r31-0 "$out/echo-stim-const.txt" --r31-1 "$out/echo-stim.txt" --max-cycles 1000000
else
	tail -n 20 "$out/firmware.log"
	fail "skip-exact: building firmware/input-echo failed"
fi

# 3. UART: sigrok's decoder reads our VCD (5 ns timescale = 200 MHz samplerate)
uart_text() {
	sigrok-cli -I vcd -i "$out/uart.vcd" -P "uart:rx=P9_31:baudrate=$1" -A uart=rx-data |
		python3 -c 'import sys; print("".join(chr(int(w.split()[-1], 16)) for w in sys.stdin if w.strip()), end="")'
}
rate=$(sigrok-cli -I vcd -i "$out/uart.vcd" --show | sed -n 's/^Samplerate: //p')
if [ "$rate" = 200000000 ]; then
	pass "vcd: sigrok-cli reads the VCD at 200 MHz"
else
	fail "vcd: sigrok-cli reports samplerate '$rate', expected 200000000"
fi
want=$'Hello from prusim!\r\n'
got=$(uart_text 115200; echo x)
got=${got%x}
if [ "$got" = "$want" ]; then
	pass "uart: sigrok-cli decodes 'Hello from prusim!\\r\\n' at 115200 baud"
else
	fail "uart: sigrok-cli decoded $(printf %q "$got")"
fi
got=$(uart_text 57600; echo x)
if [ "${got%x}" != "$want" ]; then
	pass "uart: the decode at the wrong baud rate (57600) fails, as it must"
else
	fail "uart: the text decodes at 57600 baud too; the check proves nothing"
fi

# 4. Embedding API
"$bin/pru-as" -o "$out/loader.o" "$T/fw/loader.S"
"$bin/pru-ld" -o "$out/loader.elf" "$out/loader.o"
read -r rsc_off rsc_size < <("$bin/pru-readelf" -SW "$out/loader.elf" |
	sed -n 's/.*\.resource_table *[A-Z]* *[0-9a-f]* \([0-9a-f]*\) \([0-9a-f]*\).*/0x\1 0x\2/p')
"$CC" -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -Wall -Wextra -Werror \
	-I"$PRUKIT_TOP/sim" -o "$out/unit_test" "$T/unit_test.c" \
	"$PRUKIT_TOP"/sim/prusim_{core,mem,elf,disasm,stim}.c
"$out/unit_test" "$out/loader.elf" "$rsc_off" "$rsc_size" || failed=1

# 5. CLI behaviour not covered by the firmware tests
trace_lines=$("$prusim" --trace --pru0 "$out/alu.pru0.elf" | grep -cE '^[0-9]+ pru0 [0-9a-f]{4}: [0-9a-f]{8}  ')
first=$("$prusim" --trace --pru0 "$out/alu.pru0.elf" | head -n 1)
if [ "$trace_lines" = 35 ] && [ "$first" = $'0 pru0 0000: 24fff0e1  ldi\tr1, 65520' ]; then
	pass "cli: --trace prints the 35 instructions of asm/alu.S with cycle, core, pc, disassembly"
else
	fail "cli: --trace printed $trace_lines lines, first '$first'"
fi
rc=0
"$prusim" --pru0 "$out/toggle.pru0.elf" --max-cycles 100 --until-halt >/dev/null 2>&1 || rc=$?
if [ $rc -eq 2 ]; then
	pass "cli: --until-halt fails (exit 2) when the firmware does not halt"
else
	fail "cli: --until-halt on an endless loop exited $rc, expected 2"
fi
printf '0 1\n10 2\n5 3\n' >"$out/bad-stimulus.txt"
rc=0
err=$("$prusim" --pru0 "$out/alu.pru0.elf" --r31-0 "$out/bad-stimulus.txt" 2>&1) || rc=$?
if [ $rc -eq 1 ] && [[ $err == *"bad-stimulus.txt: line 3: cycles must increase"* ]]; then
	pass "cli: a malformed stimulus file is rejected with its line number"
else
	fail "cli: bad stimulus file: exit $rc, '$err'"
fi

# 6. Binary pin traces and event lists
tc() { python3 "$T/tracecheck.py" "$@"; }
tdir=$out/trace
rm -rf "$tdir"
mkdir -p "$tdir"
# roundtrip NAME PRUSIM_ARGS...: one run writes VCD, events and a binary
# trace; a second run writes only the VCD; the trace converts back to both.
roundtrip() {
	local name=$1 d=$tdir/$1 rc=0 n
	shift
	"$prusim" "$@" --json --vcd "$d.vcd" --events "$d.events" --trace-out "$d.trace" \
		>"$d.json" || rc=$?
	"$prusim" "$@" --vcd "$d.plain.vcd" >/dev/null || true
	n=$(python3 -c 'import json, sys; print(json.load(sys.stdin)["pin_changes"])' \
		<"$d.json" 2>/dev/null || echo none)
	if [ "$rc" != 0 ] || [ "$n" = none ] || [ "$n" -lt 2 ]; then
		fail "trace $name: the run failed (exit $rc) or changed fewer than 2 pins ($n)"
		return
	fi
	if [ "$(wc -l <"$d.events")" = "$n" ] &&
	   ! grep -qvE '^[0-9]+ [A-Za-z0-9_]+ [01]$' "$d.events" &&
	   [ "$(stat -c %s "$d.trace")" = $((48 + 16 * n)) ]; then
		pass "trace $name: $n changes: $n event lines, a trace of 48 + 16 * $n bytes"
	else
		fail "trace $name: $(wc -l <"$d.events") event lines, trace of $(stat -c %s "$d.trace") bytes for $n changes"
	fi
	if cmp -s "$d.vcd" "$d.plain.vcd" && tc agree "$d.vcd" "$d.events"; then
		pass "trace $name: --events lists what the VCD shows; extra outputs leave the VCD as is"
	else
		fail "trace $name: the events and the VCD disagree, or the VCD changed"
	fi
	if "$prusim" --trace-in "$d.trace" --vcd "$d.conv.vcd" --events "$d.conv.events" &&
	   cmp -s "$d.vcd" "$d.conv.vcd" && cmp -s "$d.events" "$d.conv.events"; then
		pass "trace $name: --trace-in gives the same VCD and events as the run"
	else
		fail "trace $name: --trace-in output differs from the run's"
	fi
}
roundtrip pins --pru0 "$out/pins.pru0.elf" --pru1 "$out/pins.pru1.elf"
roundtrip uart --pru0 "$out/uart.pru0.elf"
roundtrip toggle --pru0 "$out/toggle.pru0.elf" --max-cycles 40
roundtrip gpio --pru0 "$out/gpio.pru0.elf"

# A trace whose origin is not 0 (as the QEMU PRU-ICSS writes them): times relative to
# it, changes before it give the levels at time 0 of the VCD.
d=$tdir/pins
tc patch "$d.trace" "$d.origin.trace" origin=2
"$prusim" --trace-in "$d.origin.trace" --vcd "$d.origin.vcd" --events "$d.origin.events" || true
want=$(awk '{ printf "%d %s %s\n", $1 - 2, $2, $3 }' "$d.events")
last=$(tail -n 1 "$d.origin.vcd")
end=$(tail -n 1 "$d.vcd")
if [ "$want" = "$(cat "$d.origin.events" 2>/dev/null)" ] && grep -q '^-1 P9_31 1$' "$d.origin.events" &&
   tc agree "$d.origin.vcd" "$d.origin.events" && [ "$last" = "#$((${end#\#} - 2))" ] &&
   sed -n '/^\$dumpvars/,/^\$end/p' "$d.origin.vcd" | grep -q '^1'; then
	pass "trace: origin 2: event cycles and VCD times 2 less, earlier changes set the levels at 0"
else
	fail "trace: origin 2 not applied (events, initial levels or final time $last)"
fi
tc patch "$d.trace" "$d.dropped.trace" dropped=5
rc=0
err=$("$prusim" --trace-in "$d.dropped.trace" --events "$d.dropped.events" 2>&1) || rc=$?
if [ $rc -eq 0 ] && [[ $err == *"5 older pin changes were dropped"* ]] &&
   cmp -s "$d.events" "$d.dropped.events"; then
	pass "trace: a trace with dropped records converts with a warning"
else
	fail "trace: dropped records: exit $rc, '$err'"
fi

# corrupt NAME MESSAGE: $tdir/NAME.trace must be rejected with MESSAGE
corrupt() {
	local rc=0 err
	rm -f "$tdir/bad.vcd" "$tdir/bad.events"
	err=$("$prusim" --trace-in "$tdir/$1.trace" --vcd "$tdir/bad.vcd" --events "$tdir/bad.events" 2>&1) ||
		rc=$?
	if [ $rc -eq 1 ] && [[ $err == *"$1.trace: $2"* ]] &&
	   [ ! -e "$tdir/bad.vcd" ] && [ ! -e "$tdir/bad.events" ]; then
		pass "trace: rejects $1 ('$2'), writes nothing"
	else
		fail "trace: $1: exit $rc, '$err'"
	fi
}
tc patch "$d.trace" "$tdir/magic.trace" magic=PRUTRACX
head -c $((48 + 16 * 10 + 7)) "$d.trace" >"$tdir/truncated.trace"
head -c 40 "$d.trace" >"$tdir/short-header.trace"
: >"$tdir/empty.trace"
{ cat "$d.trace"; printf 'junk'; } >"$tdir/extra.trace"
tc patch "$d.trace" "$tdir/version.trace" version=1
tc patch "$d.trace" "$tdir/rec-size.trace" rec_size=24
tc patch "$d.trace" "$tdir/count.trace" count=1000
tc patch "$d.trace" "$tdir/order.trace" rec30.cycle=1
tc patch "$d.trace" "$tdir/pin.trace" rec3.pin=192
tc patch "$d.trace" "$tdir/level.trace" rec3.level=2
tc patch "$d.trace" "$tdir/reserved.trace" rec3.reserved=1
tc patch "$d.trace" "$tdir/end.trace" end=20
tc patch "$d.trace" "$tdir/origin.trace" origin=40
corrupt magic 'not a prusim pin trace (no "PRUTRACE" magic)'
corrupt truncated 'the header announces 45 records but the file holds 167 bytes of records (truncated)'
corrupt short-header 'truncated header (40 of 48 bytes)'
corrupt empty 'not a prusim pin trace'
corrupt extra 'the header announces 45 records but the file holds 724 bytes of records (extra data)'
corrupt version 'trace format version 1, this prusim reads version 2'
corrupt rec-size 'record size 24, expected 16'
corrupt count 'the header announces 1000 records'
corrupt order 'record 30: cycle 1 is before the previous one'
corrupt pin 'record 3: pin 192 out of range (0..191)'
corrupt level 'record 3: level 2 is not 0 or 1'
corrupt reserved 'record 3: reserved bytes are not zero'
corrupt end 'record 43: cycle 32 is after the end (20)'
corrupt origin 'end cycle 33 is before the origin 40'
rc=0
err=$("$prusim" --trace-in "$d.trace" --pru0 "$out/pins.pru0.elf" --vcd "$tdir/x.vcd" 2>&1) || rc=$?
rc2=0
"$prusim" --trace-in "$d.trace" >/dev/null 2>&1 || rc2=$?
if [ $rc -eq 1 ] && [[ $err == *"--trace-in converts a trace"* ]] && [ $rc2 -eq 1 ]; then
	pass "trace: --trace-in refuses firmware and needs --vcd or --events"
else
	fail "trace: --trace-in with --pru0 exited $rc ('$err'), without outputs $rc2"
fi

# 7. Hygiene of the core: it must build in the kernel, so no C library calls
# beyond what the kernel provides, and no mutable static state.
allowed='memcmp memcpy memmove memset snprintf strlen vsnprintf'
mkdir -p "$out/hygiene"
for f in "$PRUKIT_TOP"/sim/*.c; do
	"$CC" -O2 -fno-pic -fno-stack-protector -Wall -Wextra -Werror -c -o "$out/hygiene/$(basename "$f" .c).o" "$f"
done
undef=$(nm -u "$out"/hygiene/*.o | awk 'NF == 2 { print $2 }' | sort -u |
	grep -vxF -f <(tr ' ' '\n' <<<"$allowed") |
	grep -vx 'prusim_[a-z0-9_]*' || true)
if [ -z "$undef" ]; then
	pass "hygiene: the core calls only $allowed"
else
	fail "hygiene: the core calls $(echo $undef)"
fi
data=$(nm "$out"/hygiene/*.o | awk '$2 ~ /^[BbDdCGgSs]$/ { print $3 }')
if [ -z "$data" ]; then
	pass "hygiene: no writable static data in the core"
else
	fail "hygiene: writable static data: $(echo $data)"
fi

exit $failed
