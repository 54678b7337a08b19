#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
#
# fwinfo.sh ELF [NAME] - check a freshly linked prukit firmware and print its
# memory use:   "  FW      NAME  iram <used>/8192  dram <used>/8192"
# Fails (non-zero) unless the ELF is a PRU executable whose code starts at
# IRAM address 0 and that carries a .resource_table.
# Uses $READELF and $NM (default pru-readelf, pru-nm).
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scripts/lib.sh
. "$(dirname "$0")/../scripts/lib.sh"

elf=$1
name=${2:-$(basename "$elf")}
READELF=${READELF:-pru-readelf}
NM=${NM:-pru-nm}

fail() { die "$name: $*"; }

[ -f "$elf" ] || fail "no such file: $elf"

# ELF32, little endian, e_machine 144 (EM_TI_PRU), executable
read -r -a ident < <(od -An -tu1 -w20 -N20 "$elf")
[ "${ident[0]}${ident[1]}${ident[2]}${ident[3]}" = "127697670" ] || fail "not an ELF file"
[ "${ident[4]}" = 1 ] || fail "not ELF32"
[ "${ident[5]}" = 1 ] || fail "not little endian"
[ $(( ident[16] | ident[17] << 8 )) = 2 ] || fail "not an executable (ET_EXEC)"
machine=$(( ident[18] | ident[19] << 8 ))
[ "$machine" = 144 ] || fail "e_machine is $machine, not 144 (TI PRU)"

entry=$("$READELF" -h "$elf" | awk '/Entry point address:/ { print $4 }')
[ -n "$entry" ] || fail "cannot read the entry point"
# remoteproc masks IRAM addresses to the low 20 bits; the code must start at 0
[ $(( entry & 0xfffff )) = 0 ] || fail "entry point $entry is not IRAM address 0"

# section name -> address, size
declare -A sec_addr sec_size
while read -r sname saddr ssize; do
	sec_addr[$sname]=$saddr
	sec_size[$sname]=$ssize
done < <("$READELF" -SW "$elf" | sed -n 's/^ *\[ *[0-9]*\] //p' |
	 awk '$1 ~ /^\./ { print $1, $3, $5 }')

[ -n "${sec_addr[.text]:-}" ] || fail "no .text section"
[ $(( 0x${sec_addr[.text]} )) = $(( 0x20000000 )) ] ||
	fail ".text starts at 0x${sec_addr[.text]}, not at IRAM 0 (0x20000000)"
[ -n "${sec_addr[.resource_table]:-}" ] || fail "no .resource_table section"
[ $(( 0x${sec_size[.resource_table]} )) -ge 16 ] ||
	fail ".resource_table is only $(( 0x${sec_size[.resource_table]} )) bytes"

sym() {
	local v
	v=$("$NM" "$elf" | awk -v s="$1" '$3 == s { print $1 }')
	[ -n "$v" ] || fail "symbol $1 missing (not linked with am335x-pru*.ld?)"
	echo $(( 0x$v ))
}
iram=$(sym __prukit_imem_used)
dram=$(sym __prukit_dmem_used)

printf '  FW      %-22s iram %d/8192  dram %d/8192\n' "$name" "$iram" "$dram"
