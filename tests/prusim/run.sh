#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# tests/prusim/run.sh - validation suite of the prusim PRU-ICSS simulator.
#
#   1. the disassembler against pru-objdump on every instruction form
#   2. assembly and C firmware with expected registers, cycle counts, pin
#      edges (asm/*.S, c/*.c; see runner.py), each also run without idle
#      skipping to prove skipping exact
#   3. a bit-banged UART decoded from the VCD by sigrok's own decoder
#   4. unit tests of the embedding API (unit_test.c)
#   5. CLI details: --trace, --until-halt, stimulus file errors
#   6. the core's hygiene: only the allowed C library calls, no mutable
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
	diff "$out/disasm.objdump.txt" "$out/disasm.prusim.txt" | head -n 10
	fail "disasm: differs from pru-objdump"
fi

# 2. Firmware with expectations
python3 "$T/runner.py" --prusim "$prusim" --tools "$bin" --out "$out" --testdir "$T" \
	"$T"/asm/*.S "$T"/c/*.c || failed=1

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
"$CC" -O2 -Wall -Wextra -Werror -I"$PRUKIT_TOP/sim" -o "$out/unit_test" "$T/unit_test.c" \
	"$PRUKIT_TOP"/sim/prusim_{core,mem,elf,disasm}.c
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
if [ $rc -eq 1 ] && [[ $err == *"bad-stimulus.txt:3: cycles must increase"* ]]; then
	pass "cli: a malformed stimulus file is rejected with its line number"
else
	fail "cli: bad stimulus file: exit $rc, '$err'"
fi

# 6. Hygiene of the core: it must build in the kernel, so no C library calls
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
