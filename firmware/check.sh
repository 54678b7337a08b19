#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
#
# firmware/check.sh - build all PRU firmware and check the ELF files.
#
#   firmware/check.sh            (uses CROSS_COMPILE if set, else
#                                 scripts/pru-toolchain.sh; O= as for make)
#
# Prints PASS:/FAIL: lines; exits non-zero if any check failed.
#
# "cond && pass ... || fail ..." is used on purpose: pass always succeeds.
# shellcheck disable=SC2015
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scripts/lib.sh
. "$(dirname "$0")/../scripts/lib.sh"

FW=$PRUKIT_TOP/firmware
if [ -z "${CROSS_COMPILE:-}" ]; then
	CROSS_COMPILE=$("$PRUKIT_TOP/scripts/pru-toolchain.sh")/pru-
fi
CC=${CROSS_COMPILE}gcc
READELF=${CROSS_COMPILE}readelf
OBJDUMP=${CROSS_COMPILE}objdump
OBJCOPY=${CROSS_COMPILE}objcopy
NM=${CROSS_COMPILE}nm
OUT=${O:-$PRUKIT_TOP/out/firmware}
case $OUT in /*) ;; *) OUT=$FW/$OUT ;; esac
command -v python3 >/dev/null || die "python3 is needed for the timing check"

work=$(mktemp -d "${TMPDIR:-/tmp}/prukit-fwcheck.XXXXXX")
trap 'rm -rf "$work"' EXIT

failed=0
passed=0
pass() { echo "PASS: $*"; passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

fwmake() { make --no-print-directory -C "$FW" CROSS_COMPILE="$CROSS_COMPILE" "$@"; }

# --- helpers reading an ELF -------------------------------------------------

# u16/u32 little endian at byte offset $2 of file $1
u16() { od -An -tu2 -j "$2" -N2 "$1" | tr -d ' '; }
u32() { od -An -tu4 -j "$2" -N4 "$1" | tr -d ' '; }

# "name addr size flags" for every section
sections() {
	"$READELF" -SW "$1" | sed -n 's/^ *\[ *[0-9]*\] //p' |
		awk '$1 ~ /^\./ { f = ""; if (NF >= 10) f = $7; print $1, $3, $5, f }'
}
sec_field() { sections "$1" | awk -v s="$2" -v f="$3" '$1 == s { print $f }'; }

# section names mapped to PT_LOAD segments
loaded_sections() {
	"$READELF" -lW "$1" | awk '
		/^Program Headers:/ { ph = 1; next }
		ph && /^ *Type/ { next }
		ph && NF == 0 { ph = 0; next }
		ph && $1 !~ /^\[/ { type[n++] = $1; next }
		/Section to Segment mapping/ { map = 1; next }
		map && /^ *[0-9]+ / && type[$1 + 0] == "LOAD" {
			for (i = 2; i <= NF; i++)
				print $i
		}'
}

sym() { "$NM" "$1" | awk -v s="$2" '$3 == s { print $1 }'; }

dump_section() { "$OBJCOPY" --dump-section "$2=$3" "$1" "$work/objcopy.junk" 2>/dev/null; }

# --- 1. build ---------------------------------------------------------------

# -B: relink everything so that the log shows each image's memory use
if fwmake -B O="$OUT" >"$work/build.log" 2>&1; then
	pass "build: make -C firmware -B O=$OUT"
else
	sed 's/^/    /' "$work/build.log"
	fail "build: make -C firmware failed"
	exit 1
fi
read -r -a elfs <<<"$(fwmake -s O="$OUT" list)"
[ ${#elfs[@]} -gt 0 ] && pass "build: ${#elfs[@]} firmware images" || fail "build: no firmware"

# --- 2. checks on every firmware image --------------------------------------

check_elf() {
	local elf=$1 name=$2 t

	# ELF header: magic, ELF32, little endian, ET_EXEC, EM_TI_PRU (144)
	t=$(od -An -tx1 -N6 "$elf" | tr -d ' ')
	if [ "$t" = 7f454c460101 ] && [ "$(u16 "$elf" 16)" = 2 ] &&
	   [ "$(u16 "$elf" 18)" = 144 ]; then
		pass "$name: ELF32 LE executable, e_machine 144"
	else
		fail "$name: header ident=$t type=$(u16 "$elf" 16) machine=$(u16 "$elf" 18)"
	fi

	# entry: IRAM address 0 once remoteproc masks it, and it is _start
	local entry start
	entry=$(u32 "$elf" 24)
	start=$(sym "$elf" _start)
	if [ $((entry & 0xfffff)) = 0 ] && [ -n "$start" ] && [ $((0x$start)) = "$entry" ]; then
		pass "$name: entry $(printf 0x%08x "$entry") = _start, IRAM 0 after masking"
	else
		fail "$name: entry $(printf 0x%08x "$entry"), _start ${start:-missing}"
	fi

	# .text starts at IRAM 0 and its first instruction is _start
	local taddr first
	taddr=$(sec_field "$elf" .text 2)
	# (awk reads to the end: leaving early would kill objdump with SIGPIPE,
	# which pipefail turns into a failure of the whole script.)
	first=$("$OBJDUMP" -d "$elf" | awk '/^[0-9a-f]+ <.*>:$/ && !n++ { print }')
	if [ "$taddr" = 20000000 ] && [ "$first" = "20000000 <_start>:" ]; then
		pass "$name: .text at 0x20000000 (IRAM 0) begins with _start"
	else
		fail "$name: .text at 0x${taddr:-none}, first symbol '$first'"
	fi

	# .resource_table: loaded, version 1, reserved 0, offsets inside the table
	local raddr rsize ver num r0 r1 i off bad=
	raddr=$(sec_field "$elf" .resource_table 2)
	rsize=$(sec_field "$elf" .resource_table 3)
	if [ -z "$raddr" ]; then
		fail "$name: no .resource_table"
	elif ! loaded_sections "$elf" | grep -qx .resource_table; then
		fail "$name: .resource_table is not in a PT_LOAD segment"
	elif ! dump_section "$elf" .resource_table "$work/rsc.bin"; then
		fail "$name: cannot extract .resource_table"
	else
		rsize=$((0x$rsize))
		ver=$(u32 "$work/rsc.bin" 0)
		num=$(u32 "$work/rsc.bin" 4)
		r0=$(u32 "$work/rsc.bin" 8)
		r1=$(u32 "$work/rsc.bin" 12)
		[ $((0x$raddr % 4)) = 0 ] || bad+=" address 0x$raddr not 4-aligned;"
		[ "$rsize" -ge 16 ] || bad+=" size $rsize < 16;"
		[ "$ver" = 1 ] || bad+=" ver=$ver;"
		[ "$r0" = 0 ] && [ "$r1" = 0 ] || bad+=" reserved=$r0,$r1;"
		if [ $((16 + 4 * num)) -gt "$rsize" ]; then
			bad+=" $num offsets do not fit in $rsize bytes;"
		else
			for ((i = 0; i < num; i++)); do
				off=$(u32 "$work/rsc.bin" $((16 + 4 * i)))
				if [ "$off" -lt $((16 + 4 * num)) ] ||
				   [ $((off + 4)) -gt "$rsize" ] || [ $((off % 4)) != 0 ]; then
					bad+=" offset[$i]=$off out of range;"
				fi
			done
		fi
		if [ -z "$bad" ]; then
			pass "$name: .resource_table at 0x$raddr, $rsize bytes, ver 1, $num entries"
		else
			fail "$name: .resource_table:$bad"
		fi
	fi

	# .pru_irq_map (optional): never loaded, well formed
	if [ -n "$(sec_field "$elf" .pru_irq_map 2)" ]; then
		check_irq_map "$elf" "$name"
	fi

	# the build printed its memory use, matching the ELF's sections
	local iram line
	iram=$(( 0x$(sec_field "$elf" .text 3) ))
	line=$(grep -E "^  FW      $name +iram [0-9]+/8192  dram [0-9]+/8192$" \
		"${3:-$work/build.log}" || true)
	if [ -n "$line" ] && [[ $line == *" iram $iram/8192 "* ]]; then
		pass "$name: build printed '${line#  FW      }'"
	else
		fail "$name: iram/dram line '$line' missing or wrong (.text is $iram bytes)"
	fi
}

check_irq_map() {
	local elf=$1 name=$2 flags size type num i ev ch host bad=
	flags=$(sec_field "$elf" .pru_irq_map 4)
	if loaded_sections "$elf" | grep -qx .pru_irq_map || [[ $flags == *A* ]]; then
		fail "$name: .pru_irq_map is allocated/loaded (flags '$flags')"
	else
		pass "$name: .pru_irq_map present, in no PT_LOAD segment, not SHF_ALLOC"
	fi
	if ! dump_section "$elf" .pru_irq_map "$work/irq.bin"; then
		fail "$name: cannot extract .pru_irq_map"
		return
	fi
	size=$(stat -c %s "$work/irq.bin")
	read -r -a b < <(od -An -tu1 -v -w1000 "$work/irq.bin")
	type=${b[0]:-x}
	num=${b[1]:-0}
	[ "$type" = 0 ] || bad+=" type=$type;"
	[ "$size" = $((2 + 3 * num)) ] || bad+=" size $size != 2 + 3 * $num;"
	for ((i = 0; i < num && 2 + 3 * i + 2 < size; i++)); do
		ev=${b[2 + 3 * i]}; ch=${b[3 + 3 * i]}; host=${b[4 + 3 * i]}
		[ "$ev" -lt 64 ] && [ "$ch" -lt 10 ] && [ "$host" -lt 10 ] ||
			bad+=" entry $i = ($ev, $ch, $host) out of range;"
	done
	if [ -z "$bad" ]; then
		pass "$name: .pru_irq_map well formed ($num events)"
	else
		fail "$name: .pru_irq_map:$bad"
	fi
	IRQ_BYTES="${b[*]}"
}

for e in "${elfs[@]}"; do
	check_elf "$OUT/$e" "$e"
done

# --- 3. hello: R30 writes and pulse timing -----------------------------------

hello_macro() { awk -v m="$2" '$1 == "#define" && $2 == m { print $3 }' "$1"; }

check_hello() {
	local core=$1 name=hello-pru$1 elf=$OUT/hello-pru$1.elf cflags
	[ -f "$elf" ] || { fail "$name: not built"; return; }
	cflags=$(fwmake -s print-cflags-hello-pru"$core")
	# shellcheck disable=SC2086 # word splitting of the flags is intended
	if ! "$CC" $cflags -E -dM "$FW/hello/hello.c" >"$work/hello.macros" ||
	   ! "$CC" $cflags -E -P "$FW/hello/hello.c" >"$work/hello.i"; then
		fail "$name: cannot preprocess hello.c with its build flags"
		return
	fi
	local bit pulses high low calls
	bit=$(hello_macro "$work/hello.macros" HELLO_BIT)
	pulses=$(hello_macro "$work/hello.macros" HELLO_PULSES)
	high=$(hello_macro "$work/hello.macros" HELLO_HIGH_CYCLES)
	low=$(hello_macro "$work/hello.macros" HELLO_LOW_CYCLES)
	if [ -z "$bit" ] || [ -z "$pulses" ] || [ -z "$high" ] || [ -z "$low" ]; then
		fail "$name: cannot read HELLO_* from hello.c"
		return
	fi
	# write_r30() calls in main(): all uses minus the one definition in pru.h
	calls=$(( $(grep -o 'write_r30 *(' "$work/hello.i" | wc -l) - 1 ))

	"$OBJDUMP" -d --no-show-raw-insn "$elf" >"$work/$name.dis"
	# every instruction whose destination is r30 (or a field of it)
	local writes movs
	writes=$(awk -F'\t' 'NF >= 3 && $3 ~ /^(r30|r30\.[bw][0-9])(,|$)/' "$work/$name.dis" |
		 wc -l)
	movs=$(awk -F'\t' '$2 ~ /^mov$/ && $3 ~ /^r30, r[0-9]+$/' "$work/$name.dis" | wc -l)
	if [ "$writes" = "$calls" ] && [ "$movs" = "$calls" ] && [ "$calls" -gt 0 ]; then
		pass "$name: each of the $calls write_r30() calls is one 'mov r30, rN'"
	else
		fail "$name: $calls write_r30() calls, but $writes instructions write r30" \
		     "and $movs are 'mov r30, rN'"
		awk -F'\t' '$3 ~ /^r30/' "$work/$name.dis" | sed 's/^/    /'
	fi

	# Straight-line count between the first two r30 writes in address order:
	# 1 cycle per instruction, "ldi rX, N; sub rX, rX, 1; qbne" = 1 + 2N.
	local between
	between=$(awk -F'\t' '
		$2 == "mov" && $3 ~ /^r30, / { n++; if (n == 2) { print c; exit } next }
		n == 1 && NF >= 2 {
			if ($2 == "ldi") { split($3, a, ", "); ldi[a[1]] = a[2] + 0 }
			if ($2 == "qbne") { split($3, a, ", "); c += 2 * ldi[a[2]]; next }
			if ($2 == "sub") next
			c++
		}' "$work/$name.dis")
	if [ "${between:-x}" = $((high - 1)) ]; then
		pass "$name: disassembly: $high cycles from set to clear of r30" \
		     "($((high - 1)) between the writes)"
	else
		fail "$name: disassembly: ${between:-?} cycles between the r30 writes," \
		     "want $((high - 1))"
	fi

	# Full trace from _start to HALT, once with R30 = 0 and once with all
	# other bits set: exact pulse count, widths, bit and untouched other bits.
	local init res
	for init in 0 $((0xffffffff & ~(1 << bit))); do
		if ! "$FW/pru-trace.py" --r30 "$init" "$work/$name.dis" >"$work/$name.trace" \
			2>"$work/trace.err"; then
			fail "$name: pru-trace: $(cat "$work/trace.err")"
			continue
		fi
		res=$(check_pulses "$work/$name.trace" $((init | (1 << bit))) \
			$((init & ~(1 << bit))) "$high" "$low")
		if [ "$res" = "ok $((2 * pulses))" ]; then
			pass "$name: trace (R30=$(printf 0x%08x "$init")): $pulses pulses on bit" \
			     "$bit, $high/$low cycles high/low, then HALT"
		else
			fail "$name: trace (R30=$(printf 0x%08x "$init")): ${res//$'\n'/; }" \
			     "(want $((2 * pulses)) writes)"
		fi
	done
}

# check_pulses TRACE ON OFF HIGH LOW: R30 must alternate ON, OFF, ... with
# HIGH cycles from each ON write to the next OFF write, LOW cycles from each
# OFF write to the next ON write (or to HALT), all bits known, no R31 write.
# Prints "ok <number of writes>" or what is wrong.
check_pulses() {
	awk -v on="$(printf 0x%08x "$2")" -v off="$(printf 0x%08x "$3")" \
	    -v high="$4" -v low="$5" '
		$1 == "R31" { print "unexpected R31 write at cycle " $2; bad = 1 }
		$1 == "R30" {
			n++
			want = (n % 2) ? on : off
			if ($3 != want || $4 != "0xffffffff") {
				printf "write %d = %s (known bits %s), want %s\n", n, $3, $4, want
				bad = 1
			}
			if (n > 1 && $2 - last != ((n % 2) ? low : high)) {
				printf "write %d: %d cycles after the previous one, want %d\n",
				       n, $2 - last, (n % 2) ? low : high
				bad = 1
			}
			last = $2
		}
		$1 == "HALT" {
			halted = 1
			if (n && $2 - last != low) {
				printf "halt %d cycles after the last write, want %d\n",
				       $2 - last, low
				bad = 1
			}
		}
		END {
			if (!halted) { print "no HALT"; bad = 1 }
			if (!bad) print "ok " n
		}' "$1"
}

for core in $(fwmake -s print-cores-hello); do
	check_hello "$core"
done

# --- 4. linker script and Makefile self-test ---------------------------------

st=$work/selftest
mkdir -p "$st"
cat >"$st/fw.mk" <<'EOF'
fw-srcs := selftest.c
fw-cores := 1
fw-stack-size := 0x300
fw-heap-size := 0x40
EOF
cat >"$st/selftest.c" <<'EOF'
#include <stdint.h>
#include <prukit/pru.h>
#include <prukit/resource_table.h>
#include <prukit/irq_map.h>
#include <am335x/pruss_cfg.h>
#include <am335x/pruss_ctrl.h>
#include <am335x/pruss_intc.h>
#include <am335x/pruss_iep.h>
#include <am335x/gpio.h>

PRUKIT_RESOURCE_TABLE_EMPTY();
PRUKIT_IRQ_MAP(PRUKIT_IRQ_EVT(16, 2, 2), PRUKIT_IRQ_EVT(17, 0, 0), PRUKIT_IRQ_EVT(63, 9, 9));

uint32_t shared_init[4] __attribute__((section(".shared"))) = { 0x11111111, 2, 3, 4 };
uint32_t shared_mbox[8] __attribute__((section(".shared_noinit")));
uint32_t noinit_word __attribute__((section(".noinit")));
uint32_t zeroed[5];
uint32_t counter = 0x12345678;

int main(void)
{
	uint32_t t0;

	pruss_ocp_master_enable();
	pru_cycle_counter_restart();
	t0 = pru_cycle_counter_read();
	pru_iep_start(5);
	pru_intc_clear_event(17);
	pru_intc_map_event(20, 3);
	if (read_r31() & PRU_R31_HOST0)
		r31_strobe_event(16);
	am335x_gpio_set(AM335X_GPIO1_BASE, AM335X_GPIO_MASK(53));
	shared_mbox[0] = shared_init[1] + counter + zeroed[2] + noinit_word;
	shared_mbox[1] = pru_cycle_counter_read() - t0 + pru_iep_count();
	pru_halt();
}
EOF
sto=$work/out
if fwmake O="$sto" EXTRA_FW="$st" "$sto/selftest-pru1.elf" >"$work/st.log" 2>&1; then
	pass "selftest: an extra firmware folder (fw.mk + source) builds"
	ste=$sto/selftest-pru1.elf
	IRQ_BYTES=
	check_elf "$ste" selftest-pru1.elf "$work/st.log"
	[ "$IRQ_BYTES" = "0 3 16 2 2 17 0 0 63 9 9" ] &&
		pass "selftest: .pru_irq_map holds exactly the PRUKIT_IRQ_MAP() entries" ||
		fail "selftest: .pru_irq_map bytes '$IRQ_BYTES'"
	[ ! -e "$sto/selftest-pru0.elf" ] && [ "$(sym "$ste" __prukit_pru_core)" = 00000001 ] &&
		pass "selftest: fw-cores := 1 builds only the PRU1 image, with am335x-pru1.ld" ||
		fail "selftest: fw-cores/linker script selection"
	# the core's own CTRL block is PRU1's (0x24000) for PRUKIT_PRU_CORE=1
	"$OBJDUMP" -d --no-show-raw-insn "$ste" >"$work/st.dis"
	grep -Eq 'ldi[[:space:]]+r[0-9]+\.w2, 2$' "$work/st.dis" &&
		grep -Eq 'ldi[[:space:]]+r[0-9]+\.w0, 16384$' "$work/st.dis" &&
		pass "selftest: PRUSS_LOCAL_CTRL is 0x24000 on PRU1" ||
		fail "selftest: no access to 0x24000 (PRU1 CTRL) in the code"
	grep -Eq 'lbco[[:space:]]+r[0-9]+\.b0, 4, 4, 4' "$work/st.dis" &&
		pass "selftest: CFG SYSCFG read via constant table C4 (lbco)" ||
		fail "selftest: SYSCFG not read through C4"
	loaded=$(loaded_sections "$ste" | tr '\n' ' ')
	shaddr=$(sec_field "$ste" .shared 2)
	dump_section "$ste" .shared "$work/shared.bin" || true
	[ "$shaddr" = 00010000 ] && [[ " $loaded " == *" .shared "* ]] &&
		[ "$(u32 "$work/shared.bin" 0)" = $((0x11111111)) ] &&
		pass "selftest: .shared loaded at 0x10000 with its data" ||
		fail "selftest: .shared at 0x$shaddr, loaded: $loaded"
	nladdr=$(sec_field "$ste" .shared_noinit 2)
	[ -n "$nladdr" ] && [ $((0x$nladdr)) -ge $((0x10000)) ] &&
		[ $((0x$nladdr)) -lt $((0x13000)) ] &&
		[[ " $loaded " != *" .shared_noinit "* ]] &&
		pass "selftest: .shared_noinit at 0x$nladdr in shared RAM, not loaded" ||
		fail "selftest: .shared_noinit at 0x$nladdr, loaded: $loaded"
	used=$(( 0x$(sym "$ste" __prukit_dmem_used) ))
	want=$(( 0x$(sym "$ste" __prukit_noinit_end) + 0x40 + 0x300 ))
	[ "$used" = "$want" ] &&
		[ "$((0x$(sym "$ste" __prukit_stack_bottom)))" = $((0x2000 - 0x300)) ] &&
		grep -q "selftest-pru1.elf .*dram $used/8192" "$work/st.log" &&
		pass "selftest: dram $used = data+bss+noinit + heap 0x40 + stack 0x300" ||
		fail "selftest: dram use $used, want $want"
else
	sed 's/^/    /' "$work/st.log"
	fail "selftest: build failed"
fi

# GCC already emits .pru_irq_map without SHF_ALLOC; an assembler source may
# not, and the linker script must still keep it out of the loaded image.
sa=$work/selftest-asm
mkdir -p "$sa"
printf 'fw-srcs := main.c irqmap.S\nfw-cores := 0\n' >"$sa/fw.mk"
printf '%s\n' '#include <prukit/resource_table.h>' 'PRUKIT_RESOURCE_TABLE_EMPTY();' \
	'int main(void) { for (;;) ; }' >"$sa/main.c"
printf '\t.section .pru_irq_map, "a", @progbits\n\t.byte 0, 1, 18, 3, 3\n' >"$sa/irqmap.S"
if fwmake O="$sto" EXTRA_FW="$sa" "$sto/selftest-asm-pru0.elf" >"$work/sa.log" 2>&1; then
	pass "selftest-asm: C + .S firmware builds"
	IRQ_BYTES=
	check_irq_map "$sto/selftest-asm-pru0.elf" selftest-asm-pru0.elf
	[ "$IRQ_BYTES" = "0 1 18 3 3" ] &&
		pass "selftest-asm: allocatable .pru_irq_map input kept, with its bytes" ||
		fail "selftest-asm: .pru_irq_map bytes '$IRQ_BYTES'"
else
	sed 's/^/    /' "$work/sa.log"
	fail "selftest-asm: build failed"
fi

# Negative cases: each must fail to build, with the expected message.
neg() {
	local what=$1 msg=$2 src=$3 mk=${4:-} d=$work/neg-$1
	mkdir -p "$d"
	printf 'fw-srcs := t.c\nfw-cores := 0\n%s\n' "$mk" >"$d/fw.mk"
	printf '%s\n' "$src" >"$d/t.c"
	if fwmake O="$work/negout" EXTRA_FW="$d" "$work/negout/neg-$what-pru0.elf" \
		>"$d/log" 2>&1; then
		fail "reject $what: it built"
	elif grep -q "$msg" "$d/log"; then
		pass "reject $what: '$msg'"
	else
		sed 's/^/    /' "$d/log"
		fail "reject $what: failed without '$msg'"
	fi
	[ ! -e "$work/negout/neg-$what-pru0.elf" ] || fail "reject $what: ELF left behind"
}
RSC='#include <prukit/resource_table.h>
PRUKIT_RESOURCE_TABLE_EMPTY();'
neg norsc "no .resource_table" 'int main(void) { for (;;) ; }'
neg dram "data RAM overflow" "$RSC
unsigned char big[0x1f00]; int main(void) { big[1] = 1; for (;;) ; }"
neg stack "data RAM overflow" "$RSC
int main(void) { for (;;) ; }" "fw-stack-size := 0x1ff0"
neg iram "region \`imem' overflowed" "$RSC
int main(void) { asm volatile(\".fill 2100, 4, 0\"); for (;;) ; }"
neg ctor "constructors are not supported" "$RSC
volatile int x; __attribute__((constructor)) static void c(void) { x = 1; }
int main(void) { for (;;) ; }"
neg entry "is not IRAM address 0" "$RSC
int main(void) { for (;;) ; }" "fw-ldflags := -Wl,--entry=main"

echo "firmware: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
