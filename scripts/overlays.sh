#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# overlays.sh [--build | --check] - build prukit's device-tree overlays, and
# with --check prove them against real base trees.
#
# --build (the default; "make overlays"): every overlays/*.dtso compiled by
# scripts/dtso-build.sh (cpp with prukit's own dt-bindings headers + dtc -@,
# any warning is an error) into out/overlays/*.dtbo.  Needs only cpp and
# device-tree-compiler: no kernel source, no network; a few seconds.
#
# --check ("make check"): the build, and
#  1. the overlays, and the emulated board's trees of tests/vm/, built again
#     with the dt-bindings headers of every kernel series below; each blob
#     must be identical to the one prukit's headers gave.
#  2. The pin table sim/am335x-pins.tsv checked against each
#     kernel's am33xx.h, and the pin check of each overlay's blob: the PRU
#     signals and GPIOs its "prukit-pins:" lines name are muxed to the right
#     mode by a pinctrl-single group some node's pinctrl-0 applies, r31
#     (input) pads have INPUT_EN, every pad is a known AM335x pad and appears
#     once.  The table's GPIO rows against the gpio-line-names of the board trees of step 4 and the
#     kernel's own pinmux comments.
#  3. Documentation/devicetree/bindings/**/*.yaml (N >= 0): yamllint,
#     dt-doc-validate, and the examples compiled and checked with dt-validate,
#     once per kernel series with that kernel's bindings.
#  4. am335x-boneblack and am335x-pocketbeagle built with -@ from Debian's
#     linux-source 6.1 and 6.12; every overlay applied with fdtoverlay; the
#     merged tree checked with dt-validate against the kernel's bindings plus
#     ours; it must not add any message to those of the base tree alone; the
#     "prukit-expect:" lines of each overlay are asserted with fdtget; the
#     pin check again on the merged tree, plus: no pad of the overlay in a
#     pinctrl group an enabled node of the base tree uses, unless the overlay
#     names that board function in "prukit-conflicts:".  An overlay with a
#     "prukit-boards:" line is checked on those boards' trees only (SKIP in
#     the summary of the others).
#  5. Self-tests that prove steps 2-4 can fail: the bogus-property overlay
#     and binding fixtures below, and the pin-check fixtures in
#     tests/overlays/*.dtso, each of which must be rejected for exactly the
#     reason its "prukit-selftest:" line names (or pass if it says "pass").
#
# Prints PASS:/FAIL: lines (--check: and a SUMMARY: line per overlay x base
# tree); exits non-zero if anything failed.  Processed schemas, base dtbs and
# dt-validate results are cached under $PRUKIT_CACHE/dt keyed by their inputs.
#
# Environment (--check): PRUKIT_DT_SERIES (default "6.1 6.12"),
# PRUKIT_DT_BOARDS (default "am335x-boneblack am335x-pocketbeagle"),
# PRUKIT_JOBS (1 or 2).
set -euo pipefail
. "$(dirname "$0")/lib.sh"

MODE=build
case ${1:-} in
"" | --build) ;;
--check) MODE=check ;;
*) echo "usage: ${0##*/} [--build | --check]" >&2; exit 2 ;;
esac

SERIES=${PRUKIT_DT_SERIES:-"6.1 6.12"}
BOARDS=${PRUKIT_DT_BOARDS:-"am335x-boneblack am335x-pocketbeagle"}
JOBS=${PRUKIT_JOBS:-2}
[ "$JOBS" -ge 1 ] 2>/dev/null || JOBS=1
[ "$JOBS" -le 2 ] || JOBS=2

# dtschema from PyPI, used whenever Debian's dt-schema is older than this pin
# (bookworm has 2022.08).  6.12 needs at least 2023.9 (its
# DT_SCHEMA_MIN_VERSION), and 2022.08 takes about 80 s per merged tree where
# 2024.11 takes about 10 s: a fully cold --check took 652 s with 2022.08 for
# the 6.1 trees; with 2024.11 for both, the 6.1 part cold (6.12 cached), 119 s.
# One version for every tree also makes the series comparable.  Exact pins,
# installed without dependency resolution; libfdt comes from python3-libfdt.
DTSCHEMA_PIP_VERSION=2024.11
DTSCHEMA_PIP_PKGS="dtschema==$DTSCHEMA_PIP_VERSION jsonschema==4.17.3 attrs==23.2.0
	pyrsistent==0.20.0 ruamel.yaml==0.18.6 ruamel.yaml.clib==0.2.8 rfc3987==1.3.8"

# dtc checks the kernel itself disables for its dtbs (scripts/Makefile.lib);
# only used for the base trees, whose warnings are logged, not fatal.
BASE_DTC_FLAGS="-Wno-unit_address_vs_reg -Wno-avoid_unnecessary_addr_size -Wno-alias_paths
	-Wno-graph_child_address -Wno-simple_bus_reg -Wno-unique_unit_address
	-Wno-interrupt_provider"

OVL_SRC=$PRUKIT_TOP/overlays
PIN_TABLE=$PRUKIT_TOP/sim/am335x-pins.tsv
FIXTURES=$PRUKIT_TOP/tests/overlays
BIND_SRC=$PRUKIT_TOP/Documentation/devicetree/bindings
OUT=$PRUKIT_TOP/out/overlays
WORK=$OUT/check
CACHE=$PRUKIT_CACHE/dt
DTSO_BUILD=$PRUKIT_TOP/scripts/dtso-build.sh

nfail=0
npass=0
pass() { printf 'PASS: %s\n' "$*"; npass=$((npass + 1)); }
fail() { printf 'FAIL: %s\n' "$*"; nfail=$((nfail + 1)); }
# Show the first lines of a message file, indented and cut to 200 columns.
show() { sed -n "1,${2:-12}p" "$1" | cut -c1-200 | sed 's/^/    /'; }

sha() { sha256sum "$@" | cut -c1-16; }

overlays=()
for src in "$OVL_SRC"/*.dtso; do
	[ -e "$src" ] || continue
	overlays+=("$(basename "$src" .dtso)")
done

# ------------------------------------------------------------ --build

if [ "$MODE" = build ]; then
	mkdir -p "$OUT"
	# Each blob is replaced in one rename (dtso-build.sh), and only blobs
	# whose source is gone are removed: a make deb or test reading
	# out/overlays meanwhile never finds it half empty.
	for f in "$OUT"/*.dtbo; do
		[ -e "$f" ] || continue
		[ -e "$OVL_SRC/$(basename "$f" .dtbo).dtso" ] || rm -f "$f"
	done
	[ ${#overlays[@]} -gt 0 ] || fail "overlays: no overlays/*.dtso found"
	for o in "${overlays[@]}"; do
		if "$DTSO_BUILD" "$OVL_SRC/$o.dtso" "$OUT/$o.dtbo" 2>"$OUT/$o.log"; then
			pass "build $o.dtbo (cpp with prukit's dt-bindings headers + dtc -@, no warnings)"
			rm -f "$OUT/$o.log"
		else
			fail "build $o.dtbo:"
			show "$OUT/$o.log" 20
		fi
	done
	msg "overlays in ${OUT#"$PRUKIT_TOP"/}: ${overlays[*]/%/.dtbo}; validate with" \
		"scripts/overlays.sh --check (make check)"
	printf '%d passed, %d failed\n' "$npass" "$nfail"
	[ "$nfail" -eq 0 ] || exit 1
	exit 0
fi

# ------------------------------------------------------------ --check

need_pkgs cpp device-tree-compiler dt-schema python3-libfdt python3-venv yamllint xz-utils
for t in cpp dtc fdtoverlay fdtget dt-validate dt-mk-schema dt-doc-validate dt-extract-example \
	yamllint; do
	command -v "$t" >/dev/null || die "$t not found after installing packages"
done
DTC_VERSION=$(dtc --version | sed -n 's/^Version: DTC //p')

rm -rf "$WORK"
rm -f "$OUT"/*.dtbo
mkdir -p "$OUT" "$WORK" "$CACHE"

# ---------------------------------------------------------------- dt-schema

# Install the pinned PyPI dtschema into a venv under the cache (once).
dtschema_venv() {
	local dir=$CACHE/dtschema-$DTSCHEMA_PIP_VERSION-venv
	if [ ! -e "$dir/.complete" ]; then
		msg "installing dtschema $DTSCHEMA_PIP_VERSION from PyPI into $dir"
		rm -rf "$dir"
		/usr/bin/python3 -m venv --system-site-packages "$dir"
		# shellcheck disable=SC2086
		run_logged "$CACHE/dtschema-pip.log" "$dir/bin/pip" install --no-deps \
			--ignore-installed --disable-pip-version-check $DTSCHEMA_PIP_PKGS
		[ "$("$dir/bin/dt-validate" --version)" = "$DTSCHEMA_PIP_VERSION" ] ||
			die "dtschema venv in $dir does not report $DTSCHEMA_PIP_VERSION"
		touch "$dir/.complete"
	fi
	echo "$dir/bin"
}

# Pick the dt-schema tools for one kernel tree: Debian's if at least the pin,
# else the pin (which must satisfy the tree's DT_SCHEMA_MIN_VERSION).
# Sets DTBIN (directory of the tools, or empty for PATH) and DTVER.
pick_dtschema() {
	local k=$1 min deb
	min=$(sed -n 's/^DT_SCHEMA_MIN_VERSION = //p' "$k/Documentation/devicetree/bindings/Makefile")
	deb=$(dt-doc-validate --version)
	if ! printf '%s\n%s\n' "$DTSCHEMA_PIP_VERSION" "$deb" | sort -Vc 2>/dev/null; then
		DTBIN=$(dtschema_venv) || die "could not install dtschema $DTSCHEMA_PIP_VERSION"
		DTBIN=$DTBIN/
		DTVER=$DTSCHEMA_PIP_VERSION
	else
		DTBIN=
		DTVER=$deb
	fi
	[ -z "$min" ] || printf '%s\n%s\n' "$min" "$DTVER" | sort -Vc 2>/dev/null ||
		die "kernel $k needs dtschema >= $min, $DTVER is older"
}

# ------------------------------------------------------------ kernel trees

declare -A KDIR KNAME DTB_BIN DTS_VER
ours=()
while IFS= read -r f; do ours+=("$f"); done < <(find "$BIND_SRC" -name '*.yaml' 2>/dev/null | sort)

for s in $SERIES; do
	k=$("$PRUKIT_TOP/scripts/linux-source.sh" "$s" dt) || die "linux-source.sh $s dt failed"
	[ -d "$k/arch/arm/boot/dts" ] || die "no arch/arm/boot/dts in $k"
	KDIR[$s]=$k
	KNAME[$s]=$(basename "$(dirname "$k")")
	pick_dtschema "$k"
	DTB_BIN[$s]=$DTBIN
	DTS_VER[$s]=$DTVER
	msg "linux-source $s: ${KNAME[$s]}, dt-schema ${DTS_VER[$s]}"
done

# ----------------------------------------------------------------- overlays

[ ${#overlays[@]} -gt 0 ] || fail "overlays: no overlays/*.dtso found"
FIRST_SERIES=${SERIES%% *}

declare -A OVL_OK
for o in "${overlays[@]}"; do
	src=$OVL_SRC/$o.dtso
	OVL_OK[$o]=1
	if "$DTSO_BUILD" "$src" "$OUT/$o.dtbo" 2>"$WORK/$o.dtbo.log"; then
		pass "build $o.dtbo with prukit's dt-bindings headers (dtso-build.sh: cpp + dtc -@, no warnings)"
	else
		fail "build $o.dtbo with prukit's dt-bindings headers:"
		show "$WORK/$o.dtbo.log" 20
		OVL_OK[$o]=0
		continue
	fi
	for s in $SERIES; do
		mkdir -p "$WORK/$s"
		if "$DTSO_BUILD" --kdir "${KDIR[$s]}" "$src" "$WORK/$s/$o.dtbo" \
			2>"$WORK/$s/$o.dtbo.log"; then
			pass "build $o.dtbo with linux-$s dt-bindings (dtso-build.sh: cpp + dtc -@, no warnings)"
		else
			fail "build $o.dtbo with linux-$s dt-bindings:"
			show "$WORK/$s/$o.dtbo.log" 20
			OVL_OK[$o]=0
			continue
		fi
		if cmp -s "$OUT/$o.dtbo" "$WORK/$s/$o.dtbo"; then
			pass "$o.dtbo identical whether built with prukit's or linux-$s dt-bindings headers"
		else
			fail "$o.dtbo differs between prukit's and linux-$s dt-bindings headers"
			OVL_OK[$o]=0
		fi
	done
	if ! grep -q 'prukit-expect:' "$src"; then
		fail "$o: no 'prukit-expect:' lines in $o.dtso, nothing to assert in merged trees"
		OVL_OK[$o]=0
	fi
done

# The emulated board's trees (scripts/vm.sh builds them with prukit's headers
# too): the same blob with every kernel's headers.
for src in "$PRUKIT_TOP"/tests/vm/board/*.dtso "$PRUKIT_TOP"/tests/vm/overlays/*.dtso; do
	[ -e "$src" ] || continue
	rel=${src#"$PRUKIT_TOP"/}
	n=vm-$(basename "$src" .dtso)
	if ! "$DTSO_BUILD" "$src" "$WORK/$n.dtbo" 2>"$WORK/$n.log"; then
		fail "build $rel with prukit's dt-bindings headers:"
		show "$WORK/$n.log" 10
		continue
	fi
	for s in $SERIES; do
		if "$DTSO_BUILD" --kdir "${KDIR[$s]}" "$src" "$WORK/$n-$s.dtbo" 2>"$WORK/$n-$s.log" &&
			cmp -s "$WORK/$n.dtbo" "$WORK/$n-$s.dtbo"; then
			pass "$rel: identical whether built with prukit's or linux-$s dt-bindings headers"
		else
			fail "$rel: not the same blob with prukit's and linux-$s dt-bindings headers"
			show "$WORK/$n-$s.log" 10
		fi
	done
done

# ---------------------------------------------------------------- pin check
#
# The pin table (sim/am335x-pins.tsv) says which pad carries which
# PRU signal in which mux mode, on which header pin, and which board function
# already uses it.  An overlay names the signals its firmware uses in
# "prukit-pins:" lines and the board functions it takes pads from in
# "prukit-conflicts:" lines.  Trees are read by decompiling them (dtc -O dts)
# into a table; the checks are one awk program run on the overlay's blob and
# on every merged tree.

# dt_table DTB OUT: one line per fact the pin check needs, fields separated by
# TABs: "node PATH ENABLED PHANDLE" (ENABLED: status okay or absent, here and
# in every ancestor), "group PATH CELLS..." (pinctrl-single,pins),
# "pinctrl PATH N PHANDLES..." (pinctrl-N), "cells PATH N" (#pinctrl-cells),
# "sym LABEL PATH" (__symbols__), "fixup LABEL FRAGMENT" (a fragment whose
# target is LABEL), "tpath FRAGMENT PATH" (target-path).  Numbers decimal.
# shellcheck disable=SC2016 # an awk program
DT_TABLE_AWK='
function num(s,   v, i, c) {
	s = tolower(s)
	if (s !~ /^0x/) return s + 0
	v = 0
	for (i = 3; i <= length(s); i++) {
		c = index("0123456789abcdef", substr(s, i, 1))
		if (!c) return -1
		v = v * 16 + c - 1
	}
	return v
}
function cells(v,   t, n, i, o) {
	gsub(/[<>,;]/, " ", v)
	n = split(v, t, " ")
	o = ""
	for (i = 1; i <= n; i++) o = o (i > 1 ? " " : "") num(t[i])
	return o
}
function str(v) { sub(/^"/, "", v); sub(/";$/, "", v); return v }
function cur() { return d > 0 ? path[d] : "/" }
BEGIN { d = -1; OFS = "\t" }
/^\/dts-v1\/;$/ || /^\/memreserve\// || /^[ \t]*$/ { next }
/ \{$/ {
	name = $0
	sub(/^[ \t]+/, "", name)
	sub(/ \{$/, "", name)
	d++
	path[d] = d == 0 ? "/" : (d == 1 ? "" : path[d - 1]) "/" name
	en[d] = d == 0 ? 1 : en[d - 1]
	ph[d] = "-"
	next
}
/^[ \t]*\};$/ { print "node", cur(), en[d], ph[d]; d--; next }
{
	line = $0
	sub(/^[ \t]+/, "", line)
	i = index(line, " = ")
	if (i) { pn = substr(line, 1, i - 1); pv = substr(line, i + 3) }
	else { pn = line; sub(/;$/, "", pn); pv = "" }
	if (pn == "status")
		en[d] = (d == 0 || en[d - 1]) && (pv == "\"okay\";" || pv == "\"ok\";")
	else if (pn == "phandle") ph[d] = cells(pv)
	else if (pn ~ /^pinctrl-[0-9]+$/) print "pinctrl", cur(), substr(pn, 9), cells(pv)
	else if (pn == "pinctrl-single,pins") print "group", cur(), cells(pv)
	else if (pn == "#pinctrl-cells") print "cells", cur(), cells(pv)
	else if (pn == "target-path") print "tpath", cur(), str(pv)
	else if (cur() == "/__symbols__") print "sym", pn, str(pv)
	else if (cur() == "/__fixups__") {
		n = split(str(pv), t, /\\0/)
		for (j = 1; j <= n; j++)
			if (t[j] ~ /:target:0$/) { sub(/:target:0$/, "", t[j]); print "fixup", pn, t[j] }
	}
}'

dt_table() { dtc -q -I dtb -O dts "$1" | awk "$DT_TABLE_AWK" >"$2"; }

# The pin table itself, against one kernel's am33xx.h: prints one line per
# problem and, last, "ROWS PADS" counts.  Files: FS=TAB the table, then the
# header with the default FS.
# shellcheck disable=SC2016 # an awk program
PIN_TABLE_AWK='
function num(s,   v, i, c) {
	s = tolower(s)
	if (s !~ /^0x[0-9a-f]+$/) return -1
	v = 0
	for (i = 3; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
	return v
}
FNR == 1 { file++ }
file == 1 && /^# conflict: / { split(substr($0, 13), c, "\t"); known_fn[c[1]] = 1; next }
file == 1 && (/^#/ || /^[ \t]*$/) { next }
file == 1 {
	rows++
	where = "line " FNR
	if (NF != 8) { print where ": " NF " fields, not 8"; next }
	row_pad[rows] = $1; row_off[rows] = $2; row_at[rows] = where
	o = num($2)
	if (o < 0) print where ": offset " $2 " is not a hex number"
	if ($5 !~ /^[0-7]$/) print where ": mode " $5 " is not 0-7"
	if ($6 !~ /^(pru[01]_r3[01]|gpio[0-3])_([0-9]|[12][0-9]|3[01])$/)
		print where ": signal " $6 " is not pruN_r30_B/pruN_r31_B/gpioB_N"
	else if (($6 ~ /^gpio/) != ($5 == 7)) print where ": " $6 " in mode " $5 ": GPIOs are mode 7, PRU signals never"
	if ($3 !~ /^(P[89]_[0-9]+[AB]?|-)$/) print where ": Black pin " $3 " is not P8_N/P9_N"
	if ($4 !~ /^(P[12]\.[0-9][0-9]|-)$/) print where ": Pocket pin " $4 " is not P1.NN/P2.NN"
	if ($3 == "-" && $4 == "-") print where ": " $1 " is on no header"
	if ($7 != "-" && !($7 in known_fn)) print where ": black_conflict " $7 " has no \"# conflict:\" line"
	if ($8 != "-" && !($8 in known_fn)) print where ": pocket_conflict " $8 " has no \"# conflict:\" line"
	if ((o, $5) in mux) print where ": " $1 " mode " $5 " also on line " mux[o, $5]
	mux[o, $5] = FNR
	if ((o, $6) in sig) print where ": " $6 " on " $1 " twice"
	sig[o, $6] = 1
	if ($6 ~ /^gpio/) { if ($6 in gpad) print where ": " $6 " also on " gpad[$6]; gpad[$6] = $1 }
	k = $1 "\t" $2 "\t" $3 "\t" $4 "\t" $7 "\t" $8
	if (o in padrow && padrow[o] != k) print where ": " $1 ": name, headers or conflicts differ from another row of the same pad"
	if (!(o in padrow)) {
		pads++
		padrow[o] = k
		if ($3 != "-") { if ($3 in bpin) print where ": Black " $3 " also on " bpin[$3]; bpin[$3] = $1 }
		if ($4 != "-") { if ($4 in ppin) print where ": Pocket " $4 " also on " ppin[$4]; ppin[$4] = $1 }
	}
	next
}
$1 == "#define" && $2 ~ /^AM335X_PIN_/ { def[$2] = num($3) }
END {
	for (i = 1; i <= rows; i++)
		if (!(row_pad[i] in def)) print row_at[i] ": " row_pad[i] " is not defined in am33xx.h"
		else if (def[row_pad[i]] != num(row_off[i]))
			print row_at[i] ": " row_pad[i] " is " row_off[i] " here, " sprintf("0x%x", def[row_pad[i]]) " in am33xx.h"
	print rows " " pads
}'

# The pin check.  -v what=blob|merged, pins and conflicts (the overlay's
# declarations, space separated), board (black, pocket or empty: the pin
# table column of conflicts); files: src=tsv TABLE src=hdr AM33XX_H
# src=blob BLOB_TABLE [src=merged MERGED_TABLE].  Prints "PASS<TAB>message"
# and "FAIL<TAB>tag<TAB>message"; the tags are what the self-test fixtures
# name: cells, unref, unknown, twice, signal, mode, input, undeclared,
# conflictname, merge, conflict.
# shellcheck disable=SC2016 # an awk program
PINCHECK_AWK='
function num(s,   v, i, c) {
	s = tolower(s)
	if (s !~ /^0x/) return s + 0
	v = 0
	for (i = 3; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
	return v
}
function bor(a, b,   r, m) {
	r = 0; m = 1
	while (a > 0 || b > 0) {
		if (a % 2 == 1 || b % 2 == 1) r += m
		a = int(a / 2); b = int(b / 2); m *= 2
	}
	return r
}
function hx(n) { return sprintf("0x%x", n) }
function pins_of(o,   s) {
	s = ""
	if (hb[o] != "" && hb[o] != "-") s = "Black " hb[o]
	if (hp[o] != "" && hp[o] != "-") s = s (s == "" ? "" : ", ") "Pocket " hp[o]
	return s
}
function pad(o,   n) {
	n = (o in pname) ? pname[o] : "pad " hx(o)
	return n (pins_of(o) != "" ? " (" pins_of(o) ")" : "") 
}
function base(p) { sub(/.*\//, "", p); return p }
function parent(p) { sub(/\/[^\/]*$/, "", p); return p == "" ? "/" : p }
# a node by label if it has one
function lbl(s, p) { return ((s, p) in rsym) ? "&" rsym[s, p] : p }
function blobnode(p,   f) {
	f = p
	sub(/\/__overlay__.*/, "", f)
	if (("blob", f) in fix) return "&" fix["blob", f] substr(p, length(f) + 13)
	return p
}
function ok(m) { print "PASS\t" m }
function bad(tag, m) { print "FAIL\t" tag "\t" m; nbad++ }
# users S GROUP IDX NEEDEN: nodes whose pinctrl-IDX (IDX < 0: any) holds the
# phandle of GROUP; NEEDEN: only enabled ones
function users(s, g, idx, needen,   ph, k, n, v, i, r, nm) {
	if (!((s, g) in phof)) return ""
	ph = phof[s, g]
	r = ""
	for (k = 1; k <= np[s]; k++) {
		if (idx >= 0 && pi[s, k] != idx) continue
		if (needen && !en[s, pp[s, k]]) continue
		n = split(pv[s, k], v, " ")
		for (i = 1; i <= n; i++)
			if (v[i] == ph) {
				nm = s == "blob" ? blobnode(pp[s, k]) : lbl(s, pp[s, k])
				r = r (r == "" ? "" : ", ") nm
				break
			}
	}
	return r
}
# where a group of the blob lands in the merged tree
function mpath(gp,   f, rest, t) {
	f = gp
	sub(/\/__overlay__.*/, "", f)
	rest = substr(gp, length(f) + 13)
	if (("blob", f) in fix) {
		if (!(("merged", fix["blob", f]) in sym)) return ""
		t = sym["merged", fix["blob", f]]
	} else if (("blob", f) in tpath) t = tpath["blob", f]
	else return ""
	return t (t == "/" && rest != "" ? substr(rest, 2) : rest)
}
# add the pads of group G (tree S) to the applied set
function apply(s, g, name,   c, v, j, o) {
	c = split(cellsof[s, g], v, " ")
	for (j = 1; j + 2 <= c; j += 3) {
		o = v[j] + 2048
		amode[o] = bor(v[j + 1], v[j + 2]) % 8
		aval[o] = bor(v[j + 1], v[j + 2])
		agrp[o] = name
	}
}
function signals(   i, s, n, p, k, o, found, wrong) {
	for (i = 1; i <= ndecl; i++) {
		s = decl[i]
		if (!(s in sigpads)) {
			bad("signal", "prukit-pins names " s ", which is no signal of the pin table")
			continue
		}
		n = split(sigpads[s], p, " ")
		found = ""
		wrong = ""
		for (k = 1; k <= n; k++) {
			o = p[k]
			if (!(o in amode)) continue
			if (amode[o] == sigmode[s, o]) found = o
			else wrong = wrong "; " pad(o) " is in mode " amode[o] ", " s " needs " sigmode[s, o]
		}
		if (found == "") {
			if (wrong != "") bad("mode", s " is not muxed: " substr(wrong, 3))
			else bad("mode", s " is not muxed: none of its pads is in a group a pinctrl-0 applies")
			continue
		}
		o = found
		if (s ~ /_r31_/ && int(aval[o] / 32) % 2 == 0) {
			bad("input", s " on " pad(o) ": conf " hx(aval[o] - amode[o]) " lacks INPUT_EN (bit 5): the receiver is off, r31 would read 0")
			continue
		}
		ok(s " on " pad(o) ": mode " amode[o] (s ~ /_r31_/ ? ", INPUT_EN" : "") ", group " agrp[o])
	}
	for (o in amode)
		if ((o, amode[o]) in bysig && !(bysig[o, amode[o]] in isdecl))
			bad("undeclared", pad(o) " is muxed to " bysig[o, amode[o]] " (mode " amode[o] "), which prukit-pins does not list")
}
function blobchecks(   i, gp, c, v, j, o, refs, npads, names) {
	if (ng["blob"] == 0 && ndecl == 0) {
		ok("no prukit-pins and no pinctrl groups: it uses no pins")
		return
	}
	npads = 0
	names = ""
	for (i = 1; i <= ng["blob"]; i++) {
		gp = gl["blob", i]
		names = names (names == "" ? "" : ", ") base(gp)
		c = split(cellsof["blob", gp], v, " ")
		if (c == 0 || c % 3 != 0) {
			bad("cells", "group " base(gp) " has " c " cells, not AM33XX_PADCONF() triples (offset conf mux)")
			continue
		}
		refs = users("blob", gp, 0, 0)
		if (refs == "") bad("unref", "group " base(gp) " is in no pinctrl-0 of the overlay: it would never be applied")
		for (j = 1; j + 2 <= c; j += 3) {
			o = v[j] + 2048
			npads++
			if (!(o in known))
				bad("unknown", "group " base(gp) ": pinctrl offset " hx(v[j]) " (pad " hx(o) ") is no AM335x pad of am33xx.h")
			if (o in seen) bad("twice", pad(o) " is muxed twice: in " seen[o] " and " base(gp))
			else seen[o] = base(gp)
		}
		if (refs != "") apply("blob", gp, base(gp) " (pinctrl-0 of " refs ")")
	}
	for (i = 1; i <= nconf; i++)
		if (!(conf[i] in cname))
			bad("conflictname", "prukit-conflicts names " conf[i] ", which the pin table does not define")
	signals()
	if (nbad == 0)
		ok(npads " pad(s) in " ng["blob"] " group(s) (" names "): known AM335x pads, none twice, each group in a pinctrl-0" (nconf ? "; declared conflicts: " conflicts : ""))
}
function mergedchecks(   i, gp, mp, refs, k, n, v, j, c, w, o, g, node, fn, key, nconfl) {
	for (i = 1; i <= ng["blob"]; i++) {
		gp = gl["blob", i]
		c = split(cellsof["blob", gp], v, " ")
		for (j = 1; j + 2 <= c; j += 3) ovpad[v[j] + 2048] = 1
		mp = mpath(gp)
		if (mp == "" || !(("merged", mp) in cellsof)) {
			bad("merge", "group " base(gp) " is not in the merged tree (fragment target unresolved)")
			continue
		}
		ours[mp] = 1
		if (cellsof["merged", mp] != cellsof["blob", gp]) {
			bad("merge", "group " mp " differs from the overlay in the merged tree")
			continue
		}
		if (pcells["merged", parent(mp)] != 2) {
			bad("cells", "#pinctrl-cells of " lbl("merged", parent(mp)) " is " pcells["merged", parent(mp)] ", AM33XX_PADCONF() groups need 2")
			continue
		}
		refs = users("merged", mp, 0, 1)
		if (refs == "") {
			bad("merge", "group " lbl("merged", mp) " is in no pinctrl-0 of an enabled node: never applied")
			continue
		}
		apply("merged", mp, lbl("merged", mp))
		ok("group " lbl("merged", mp) " applied by pinctrl-0 of enabled " refs)
	}
	signals()
	# pads of the overlay in a group an enabled node of the base tree uses
	nconfl = 0
	for (k = 1; k <= np["merged"]; k++) {
		node = pp["merged", k]
		if (!en["merged", node]) continue
		n = split(pv["merged", k], w, " ")
		for (i = 1; i <= n; i++) {
			g = byph["merged", w[i]]
			if (g == "" || (g in ours) || !(("merged", g) in cellsof)) continue
			c = split(cellsof["merged", g], v, " ")
			for (j = 1; j + 2 <= c; j += 3) {
				o = v[j] + 2048
				if (!(o in ovpad)) continue
				key = o SUBSEP g SUBSEP node
				if (key in done) continue
				done[key] = 1
				nconfl++
				fn = "-"
				if (board == "black" && (o in bc)) fn = bc[o]
				if (board == "pocket" && (o in pc)) fn = pc[o]
				w0 = pad(o) " is also in " lbl("merged", g) ", pinctrl-" pi["merged", k] " of enabled " lbl("merged", node)
				if (lbl("merged", node) ~ /^&pru[01]$/)
					bad("conflict", w0 ", pins the base tree gives that PRU core: set its pinctrl-" pi["merged", k] " in the overlay (replacing them) or use another pad")
				else if (fn != "-" && (fn in isconf))
					ok(w0 ": declared conflict " fn (cname[fn] != "-" ? " (BeagleBoard images: " cname[fn] " in uEnv.txt frees it)" : " (no uEnv.txt line frees it)"))
				else if (fn != "-")
					bad("conflict", w0 ": board function " fn " not declared (prukit-conflicts: " fn ")")
				else
					bad("conflict", w0 ", no board function of the pin table: take the pad from that node in the overlay, or use another")
			}
		}
	}
	if (nconfl == 0) ok("no pad of the overlay in a pinctrl group of another enabled node")
}
BEGIN {
	ndecl = split(pins, decl, " ")
	for (i = 1; i <= ndecl; i++) isdecl[decl[i]] = 1
	nconf = split(conflicts, conf, " ")
	for (i = 1; i <= nconf; i++) isconf[conf[i]] = 1
}
src == "tsv" && /^# conflict: / { split(substr($0, 13), c, "\t"); cname[c[1]] = c[2]; next }
src == "tsv" && (/^#/ || NF == 0) { next }
src == "tsv" {
	o = num($2)
	n = tolower($1)
	sub(/^am335x_pin_/, "", n)
	pname[o] = n; hb[o] = $3; hp[o] = $4; bc[o] = $7; pc[o] = $8
	sigmode[$6, o] = $5
	sigpads[$6] = sigpads[$6] " " o
	bysig[o, $5] = $6
	next
}
src == "hdr" && $1 == "#define" && $2 ~ /^AM335X_PIN_/ && $3 ~ /^0x[0-9a-fA-F]+$/ {
	o = num($3)
	known[o] = 1
	if (!(o in pname)) { n = tolower($2); sub(/^am335x_pin_/, "", n); pname[o] = n }
	next
}
src == "blob" || src == "merged" {
	if ($1 == "node") { en[src, $2] = $3; if ($4 != "-") { byph[src, $4] = $2; phof[src, $2] = $4 } }
	else if ($1 == "group") {
		v = ""
		for (i = 3; i <= NF; i++) v = v (i > 3 ? " " : "") $i
		cellsof[src, $2] = v
		gl[src, ++ng[src]] = $2
	} else if ($1 == "pinctrl") {
		np[src]++
		pp[src, np[src]] = $2; pi[src, np[src]] = $3
		v = ""
		for (i = 4; i <= NF; i++) v = v (i > 4 ? " " : "") $i
		pv[src, np[src]] = v
	} else if ($1 == "cells") pcells[src, $2] = $3
	else if ($1 == "fixup") fix[src, $3] = $2
	else if ($1 == "tpath") tpath[src, $2] = $3
	else if ($1 == "sym") { sym[src, $2] = $3; if (!((src, $3) in rsym)) rsym[src, $3] = $2 }
}
END { if (what == "blob") blobchecks(); else mergedchecks() }'

# decl_lines KEY DTSO: the words of the "KEY: ..." lines of DTSO, one line;
# only a line that starts with KEY (after comment leaders) counts.
decl_lines() {
	sed -n "s|^[[:space:]/*]*$1:[[:space:]]*||p" "$2" | tr '\n' ' ' | sed 's/[[:space:]]*$//'
}

# pincheck DTSO BLOB_TABLE [MERGED_TABLE BOARD]: the pin check's lines.
pincheck() {
	local dtso=$1 blob=$2 merged=${3:-} board=${4:-} pins confs what=blob
	local -a files=(src=tsv "$PIN_TABLE" src=hdr "$AM33XX_H" src=blob "$blob")
	pins=$(decl_lines prukit-pins "$dtso")
	confs=$(decl_lines prukit-conflicts "$dtso")
	if [ -n "$merged" ]; then
		what=merged
		files+=(src=merged "$merged")
	fi
	awk -v what="$what" -v pins="$pins" -v conflicts="$confs" -v board="$board" \
		"$PINCHECK_AWK" "${files[@]}"
}

# report_pins PREFIX FILE: PASS:/FAIL: lines for a pincheck output; returns
# non-zero if it has a failure.
report_pins() {
	local prefix=$1 r=0 kind tag m
	while IFS=$'\t' read -r kind tag m; do
		if [ "$kind" = PASS ]; then
			pass "$prefix: pins: $tag"
		else
			fail "$prefix: pins ($tag): $m"
			r=1
		fi
	done <"$2"
	return $r
}

# board_column BOARD: which conflict column of the pin table a base tree uses.
board_column() {
	case $1 in
	am335x-boneblack) echo black ;;
	am335x-pocketbeagle) echo pocket ;;
	*) echo "" ;;
	esac
}

# An overlay (or fixture) made for some boards only says so in a
# "prukit-boards: BOARD..." line (base tree names, as in PRUKIT_DT_BOARDS);
# it is checked on those trees alone, and the others get a SKIP summary.
KNOWN_BOARDS="am335x-boneblack am335x-pocketbeagle"
# for_board DTSO BOARD: true if DTSO is meant for BOARD.
for_board() {
	local want
	want=$(decl_lines prukit-boards "$1")
	[ -z "$want" ] || [[ " $want " == *" $2 "* ]]
}
# check_boards DTSO NAME: a FAIL for every name of prukit-boards that is no
# known base tree (a typo would silently skip every check); false if any.
check_boards() {
	local b r=0
	for b in $(decl_lines prukit-boards "$1"); do
		if [[ " $KNOWN_BOARDS " != *" $b "* ]]; then
			fail "$2: prukit-boards names $b, which is none of: $KNOWN_BOARDS"
			r=1
		fi
	done
	return $r
}
for o in "${overlays[@]}"; do
	check_boards "$OVL_SRC/$o.dtso" "$o" || OVL_OK[$o]=0
done

AM33XX_H=${KDIR[$FIRST_SERIES]}/include/dt-bindings/pinctrl/am33xx.h
mkdir -p "$WORK/pins"
for s in $SERIES; do
	h=${KDIR[$s]}/include/dt-bindings/pinctrl/am33xx.h
	if awk -F'\t' "$PIN_TABLE_AWK" "$PIN_TABLE" FS=' ' "$h" >"$WORK/pins/table-$s" 2>&1 &&
		[ "$(wc -l <"$WORK/pins/table-$s")" -eq 1 ]; then
		read -r rows pads <"$WORK/pins/table-$s"
		pass "pin table ${PIN_TABLE#"$PRUKIT_TOP"/}: $rows rows, $pads pads, well formed," \
			"every pad name and offset as in linux-$s am33xx.h"
	else
		fail "pin table ${PIN_TABLE#"$PRUKIT_TOP"/} against linux-$s am33xx.h:"
		show "$WORK/pins/table-$s" 20
	fi
done

# The pin check of each overlay's blob (the same for every series).
for o in "${overlays[@]}"; do
	[ "${OVL_OK[$o]}" = 1 ] || continue
	dt_table "$OUT/$o.dtbo" "$WORK/pins/$o.blob"
	pincheck "$OVL_SRC/$o.dtso" "$WORK/pins/$o.blob" >"$WORK/pins/$o.blob.out"
	report_pins "$o.dtbo" "$WORK/pins/$o.blob.out" || true
done

# ------------------------------------------------------------- base trees

# build_base SERIES BOARD: print the path of a cached -@ dtb of the board.
build_base() {
	local s=$1 b=$2 k=${KDIR[$1]} src dir
	dir=$CACHE/base/${KNAME[$s]}-dtc$DTC_VERSION
	if [ ! -e "$dir/$b.dtb" ]; then
		src=$(find "$k/arch/arm/boot/dts" -name "$b.dts" | head -n 1)
		[ -n "$src" ] || { echo "no $b.dts in $k" >&2; return 1; }
		mkdir -p "$dir"
		cpp -nostdinc -undef -D__DTS__ -x assembler-with-cpp \
			-I "$k/scripts/dtc/include-prefixes" -I "$(dirname "$src")" \
			-o "$dir/$b.pre" "$src" 2>"$dir/$b.log" || { cat "$dir/$b.log" >&2; return 1; }
		# shellcheck disable=SC2086
		dtc -@ -I dts -O dtb -b 0 -i "$(dirname "$src")" \
			-i "$k/scripts/dtc/include-prefixes" $BASE_DTC_FLAGS \
			-o "$dir/$b.dtb.tmp" "$dir/$b.pre" 2>>"$dir/$b.log" ||
			{ cat "$dir/$b.log" >&2; return 1; }
		mv "$dir/$b.dtb.tmp" "$dir/$b.dtb"
	fi
	echo "$dir/$b.dtb"
}

declare -A BASE
for s in $SERIES; do
	for b in $BOARDS; do
		if BASE[$s/$b]=$(build_base "$s" "$b"); then
			pass "base tree $s/$b.dtb built with dtc -@ (${KNAME[$s]})"
		else
			fail "base tree $s/$b.dtb could not be built from ${KNAME[$s]}"
			BASE[$s/$b]=
		fi
	done
done

# The GPIO rows of the pin table against the kernel: each row's header pins
# against the gpio-line-names of the board trees (gpioB_N is line N of the
# node labelled gpioB), where the trees' names differ as the table's
# "# line-name:" lines say; every line a tree names after a header pin must
# have its row; and each row's pad against the kernel's own dts comments
# "AM33XX_PADCONF(AM335X_PIN_pad, ..., MUX_MODE7) /* ... gpioB_N */" (or
# gpioB[N]), the gpio most of them name for the pad.  A pad no comment names
# is confirmed through the header pin of its PRU rows (the table's checks
# keep a pad's rows on one header pin), or rests on the datasheet alone.
# pin_table_vs_trees TSV KDIR SERIES BOARD=DTB...: prints "PASS<TAB>msg" and
# "FAIL<TAB>msg" lines.
pin_table_vs_trees() {
	python3 - "$@" <<'PY'
import collections, glob, re, subprocess, sys
tsv, kdir, series = sys.argv[1:4]
dtbs = [a.split("=", 1) for a in sys.argv[4:]]
COL = {"am335x-boneblack": 2, "am335x-pocketbeagle": 3}
HEADER = re.compile(r"P[89]_\d+[AB]?|P[12]\.\d\d")
rows, alias, pru_pads = [], {}, set()
for line in open(tsv):
    if line.startswith("# line-name:"):
        f = line[len("# line-name:"):].strip().split("\t")
        alias[f[0], f[1]] = None if f[2] == "-" else f[2]
    if line.startswith("#") or not line.strip():
        continue
    f = line.rstrip("\n").split("\t")
    if f[5].startswith("gpio"):
        rows.append(f)
    else:
        pru_pads.add(f[0])

def out(ok, msg):
    print(("PASS\t" if ok else "FAIL\t") + msg)

def norm(name):
    m = re.fullmatch(r"P([89])_(\d+)", name)
    return "P%s_%02d" % (m[1], int(m[2])) if m else name

def line_names(dtb):
    names = {}
    for b in range(4):
        path = subprocess.run(["fdtget", "-t", "s", dtb, "/__symbols__", "gpio%d" % b],
                              capture_output=True, text=True).stdout.strip()
        raw = subprocess.run(["fdtget", "-t", "bx", dtb, path, "gpio-line-names"],
                             capture_output=True, text=True).stdout.split()
        for n, s in enumerate(bytes(int(x, 16) for x in raw).split(b"\0")[:-1]):
            w = s.decode().split()
            names["gpio%d_%d" % (b, n)] = w[0] if w and HEADER.fullmatch(w[0]) else None
    return names

for board, dtb in dtbs:
    names = line_names(dtb)
    where = "linux-%s %s's gpio-line-names" % (series, board)
    if not names:
        out(False, "pin table: no gpio-line-names in %s" % dtb)
        continue
    table, bad, unnamed, nalias = {}, [], [], 0
    for f in rows:
        if f[COL[board]] == "-":
            continue
        if f[5] in table:
            bad.append("%s on two rows (%s, %s)" % (f[5], table[f[5]], f[COL[board]]))
        table[f[5]] = f[COL[board]]
    for g, pin in sorted(table.items()):
        theirs = names.get(g)
        if theirs is None:
            unnamed.append("%s = %s" % (g, pin))
            continue
        ours = alias.get((board, theirs), norm(theirs))
        nalias += (board, theirs) in alias
        if ours != pin:
            bad.append("%s: the table says %s, the tree %s" % (g, pin, theirs))
    for g, theirs in sorted(names.items()):
        if theirs and alias.get((board, theirs), "") is not None and g not in table:
            bad.append("%s: the tree names it %s, the table has no row for it there" % (g, theirs))
    if bad:
        out(False, "pin table: GPIO rows and %s differ: %s" % (where, "; ".join(bad)))
    else:
        out(True, "pin table: the %d GPIO rows with a header pin on %s match %s (%d via '# line-name:'%s)"
            % (len(table), board, where, nalias,
               "; not named there: " + ", ".join(unnamed) if unnamed else ""))

named = collections.defaultdict(collections.Counter)
pat = re.compile(r"AM33XX_PADCONF\((AM335X_PIN_\w+),[^)]*MUX_MODE7\)(.*)")
for f in glob.glob(kdir + "/arch/arm/boot/dts/**/am33*.dts*", recursive=True):
    for line in open(f, errors="replace"):
        m = pat.search(line)
        g = re.findall(r"gpio([0-3])(?:_|\[)(\d+)", m[2]) if m else []
        if len(g) == 1:
            named[m[1]]["gpio%s_%s" % g[0]] += 1
bad, by_comment, by_pru, alone = [], 0, 0, []
for f in rows:
    pad, g = f[0], f[5]
    if named[pad]:
        top = named[pad].most_common(1)[0]
        if top[0] == g:
            by_comment += 1
        else:
            bad.append("%s is %s here, %s in %d dts comment(s)" % (pad, g, top[0], top[1]))
    elif pad in pru_pads:
        by_pru += 1
    else:
        alone.append("%s %s" % (pad[len("AM335X_PIN_"):].lower(), g))
if bad:
    out(False, "pin table: GPIO rows' pads differ from linux-%s's dts comments: %s" % (series, "; ".join(bad)))
else:
    out(True, "pin table: GPIO rows' pads: %d as linux-%s's dts comments name them, %d through the"
        " header pins of their PRU rows, %d on the datasheet alone (%s)"
        % (by_comment, series, by_pru, len(alone), ", ".join(alone)))
PY
}

# report_lines FILE: PASS:/FAIL: lines for "PASS<TAB>msg"/"FAIL<TAB>msg".
report_lines() {
	local kind m
	while IFS=$'\t' read -r kind m; do
		if [ "$kind" = PASS ]; then pass "$m"; else fail "$m"; fi
	done <"$1"
}

for s in $SERIES; do
	args=()
	for b in $BOARDS; do
		[ -n "${BASE[$s/$b]}" ] && [ -n "$(board_column "$b")" ] && args+=("$b=${BASE[$s/$b]}")
	done
	if ! pin_table_vs_trees "$PIN_TABLE" "${KDIR[$s]}" "$s" "${args[@]}" >"$WORK/pins/trees-$s" \
		2>"$WORK/pins/trees-$s.err"; then
		fail "pin table against the linux-$s trees: the comparison itself failed:"
		show "$WORK/pins/trees-$s.err" 8
	fi
	report_lines "$WORK/pins/trees-$s"
done
# ... and that comparison can fail: gpmc_ad12's GPIO row given gpmc_ad13's GPIO.
sed 's/^\(AM335X_PIN_GPMC_AD12\t.*\t7\t\)gpio1_12\t/\1gpio1_13\t/' "$PIN_TABLE" >"$WORK/pins/table-bad.tsv"
s=$FIRST_SERIES
if [ -z "${BASE[$s/am335x-boneblack]:-}" ]; then
	msg "no linux-$s am335x-boneblack tree in this run: the GPIO row self-test is left out"
elif ! cmp -s "$PIN_TABLE" "$WORK/pins/table-bad.tsv" &&
	pin_table_vs_trees "$WORK/pins/table-bad.tsv" "${KDIR[$s]}" "$s" \
		"am335x-boneblack=${BASE[$s/am335x-boneblack]}" >"$WORK/pins/trees-bad" 2>&1 &&
	grep -q '^FAIL.*gpio1_12: the tree names it P8_12, the table has no row' "$WORK/pins/trees-bad" &&
	grep -q '^FAIL.*AM335X_PIN_GPMC_AD12 is gpio1_13 here, gpio1_12' "$WORK/pins/trees-bad"; then
	pass "self-test: a GPIO row with the wrong GPIO is caught by the line names and the dts comments"
else
	fail "self-test: a GPIO row with the wrong GPIO (gpmc_ad12 = gpio1_13) is not caught:"
	show "$WORK/pins/trees-bad" 5
fi

# ------------------------------------------------------------ bindings tree

# One bindings tree per kernel, as if ours were upstream: the kernel's files
# (symlinks), its vendor-prefixes.yaml extended by "prukit," (as upstreaming a
# vendor prefix would do), our YAML files at their relative paths, and two
# self-test fixtures under prukit-selftest/ (their compatibles match nothing
# in a real tree).

# write_fixture DIR good|bad: a small valid binding; "bad" leaves a required
# property out of its example.
write_fixture() {
	local dir=$1 v=$2 req='        prukit,widgets = <4>;'
	[ "$v" = good ] || req='        /* prukit,widgets left out on purpose */'
	mkdir -p "$dir"
	cat >"$dir/prukit,selftest-$v.yaml" <<EOF
# SPDX-License-Identifier: (GPL-2.0-only OR BSD-2-Clause)
%YAML 1.2
---
\$id: http://devicetree.org/schemas/prukit-selftest/prukit,selftest-$v.yaml#
\$schema: http://devicetree.org/meta-schemas/core.yaml#

title: prukit self-test widget ($v)

maintainers:
  - prukit developers <prukit@example.org>

description:
  A made-up device used by scripts/overlays.sh to prove that the checks of
  binding documents and their examples can fail.

properties:
  compatible:
    const: prukit,selftest-$v

  reg:
    maxItems: 1

  prukit,widgets:
    \$ref: /schemas/types.yaml#/definitions/uint32
    description: Number of widgets.

required:
  - compatible
  - reg
  - prukit,widgets

additionalProperties: false

examples:
  - |
    widget@1000 {
        compatible = "prukit,selftest-$v";
        reg = <0x1000 0x10>;
$req
    };
EOF
}

VENDOR_LINE='  "^prukit,.*":'

# mk_additions SERIES DIR: our files for the kernel's bindings tree, at their
# relative paths: vendor-prefixes.yaml with prukit, our YAML, the fixtures.
mk_additions() {
	local s=$1 a=$2 kb=${KDIR[$1]}/Documentation/devicetree/bindings f rel
	rm -rf "$a"
	mkdir -p "$a"
	awk -v add="$VENDOR_LINE" '{ print }
		/^patternProperties:/ { print add
			print "    description: prukit out-of-tree PRU drivers (local, not upstream)" }' \
		"$kb/vendor-prefixes.yaml" >"$a/vendor-prefixes.yaml"
	grep -qxF "$VENDOR_LINE" "$a/vendor-prefixes.yaml" ||
		{ echo "could not add prukit to vendor-prefixes.yaml"; return 1; }
	for f in "${ours[@]}"; do
		rel=${f#"$BIND_SRC"/}
		if [ -e "$kb/$rel" ]; then
			echo "$rel has the path of a kernel binding"
			return 1
		fi
		mkdir -p "$(dirname "$a/$rel")"
		cp "$f" "$a/$rel"
	done
	write_fixture "$a/prukit-selftest" good
	write_fixture "$a/prukit-selftest" bad
}

# mk_bindings_tree SERIES: print the directory of the bindings tree (kernel
# files as symlinks plus the additions), cached by kernel and additions.
mk_bindings_tree() {
	local s=$1 a=$WORK/$1/additions key t
	mk_additions "$s" "$a" >&2 || return 1
	key=$(cd "$a" && find . -type f | LC_ALL=C sort |
		while IFS= read -r f; do printf '%s\n' "$f"; cat "$f"; done | sha)
	t=$CACHE/bindings/${KNAME[$s]}-$key
	if [ ! -e "$t/.complete" ]; then
		rm -rf "$CACHE/bindings/${KNAME[$s]}"-*
		mkdir -p "$CACHE/bindings"
		cp -rs "${KDIR[$s]}/Documentation/devicetree/bindings" "$t"
		rm -f "$t/vendor-prefixes.yaml" "$t"/processed-schema*
		cp -r "$a/." "$t/"
		touch "$t/.complete"
	fi
	echo "$t"
}

# mk_schema SERIES: print the cache directory holding processed-schema.json
# made from the bindings tree; keyed by the tree and dt-schema.
mk_schema() {
	local s=$1 d=${BTREE[$1]} dir
	dir=$CACHE/schema/$(basename "$d")-dtschema${DTS_VER[$s]}
	if [ ! -e "$dir/processed-schema.json" ]; then
		# drop the schemas of earlier versions of our additions
		rm -rf "$CACHE/schema/${KNAME[$s]}"-*-dtschema"${DTS_VER[$s]}"
		mkdir -p "$dir"
		find "$d" -name '*.yaml' | LC_ALL=C sort >"$dir/files"
		"${DTB_BIN[$s]}dt-mk-schema" -j "@$dir/files" >"$dir/tmp.json" 2>"$dir/mk-schema.log" ||
			return 1
		mv "$dir/tmp.json" "$dir/processed-schema.json"
	fi
	echo "$dir"
}

declare -A SCHEMA BTREE
for s in $SERIES; do
	if BTREE[$s]=$(mk_bindings_tree "$s" 2>"$WORK/bindings-$s.log"); then
		pass "bindings tree for linux-$s: kernel bindings + vendor prefix prukit +" \
			"${#ours[@]} of ours + 2 self-test fixtures"
	else
		fail "could not make the bindings tree for linux-$s:"
		show "$WORK/bindings-$s.log" 6
		BTREE[$s]=
	fi
done
pids=()
for s in $SERIES; do
	[ -n "${BTREE[$s]}" ] || continue
	( d=$(mk_schema "$s") && echo "$d" >"$WORK/schema-$s" ) &
	pids+=($!)
	[ "$JOBS" -gt 1 ] || wait "$!" || true
done
for p in "${pids[@]}"; do wait "$p" || true; done
for s in $SERIES; do
	SCHEMA[$s]=
	if [ ! -s "$WORK/schema-$s" ]; then
		fail "dt-mk-schema failed for the linux-$s bindings tree"
		continue
	fi
	d=$(cat "$WORK/schema-$s")
	SCHEMA[$s]=$d/processed-schema.json
	bad=0
	for f in "${ours[@]}" prukit-selftest/; do
		rel=${f#"$BIND_SRC"/}
		if grep -qF "${BTREE[$s]}/$rel" "$d/mk-schema.log"; then
			fail "dt-mk-schema ($s) complains about $rel:"
			grep -F "${BTREE[$s]}/$rel" "$d/mk-schema.log" | show /dev/stdin 6
			bad=1
		fi
	done
	[ $bad -eq 1 ] || pass "processed schema for the linux-$s bindings tree" \
		"(dt-schema ${DTS_VER[$s]}, ${d#"$PRUKIT_CACHE"/})"
done

# check_binding SERIES REL TAG: yamllint, dt-doc-validate, example compiled and
# checked with dt-validate; REL is relative to the bindings tree.  Returns
# non-zero on any problem; the reasons are in $WORK/bind/TAG.why, each block
# headed by its stage ("yamllint:", "dt-doc-validate:", "example:").
check_binding() {
	local s=$1 rel=$2 tag=$3 k=${KDIR[$1]} bt=${BTREE[$1]} d=$WORK/bind rc=0
	local y=$bt/$rel
	mkdir -p "$d"
	rm -f "$d/$tag".*
	if ! yamllint -f parsable -c "$k/Documentation/devicetree/bindings/.yamllint" "$y" \
		>"$d/$tag.lint" 2>&1 || grep -q '\[error\]' "$d/$tag.lint"; then
		{ echo "yamllint:"; cat "$d/$tag.lint"; } >>"$d/$tag.why"
		rc=1
	fi
	if ! "${DTB_BIN[$s]}dt-doc-validate" -u "$bt" "$y" >"$d/$tag.doc" 2>&1 ||
		[ -s "$d/$tag.doc" ]; then
		{ echo "dt-doc-validate:"; cat "$d/$tag.doc"; } >>"$d/$tag.why"
		rc=1
	fi
	if ! "${DTB_BIN[$s]}dt-extract-example" "$y" >"$d/$tag.example.dts" 2>"$d/$tag.ex"; then
		{ echo "example: dt-extract-example failed"; cat "$d/$tag.ex"; } >>"$d/$tag.why"
		return 1
	fi
	if ! cpp -nostdinc -undef -D__DTS__ -x assembler-with-cpp \
		-I "$k/scripts/dtc/include-prefixes" -o "$d/$tag.example.pre" \
		"$d/$tag.example.dts" 2>"$d/$tag.ex" ||
		! dtc -I dts -O dtb -Wno-avoid_unnecessary_addr_size -Wno-graph_child_address \
			-Wno-interrupt_provider -Wno-unique_unit_address \
			-o "$d/$tag.example.dtb" "$d/$tag.example.pre" 2>>"$d/$tag.ex" ||
		[ -s "$d/$tag.ex" ]; then
		{ echo "example: does not compile cleanly"; cat "$d/$tag.ex"; } >>"$d/$tag.why"
		return 1
	fi
	if ! "${DTB_BIN[$s]}dt-validate" -p "${SCHEMA[$s]}" "$d/$tag.example.dtb" \
		>"$d/$tag.val" 2>&1 || [ -s "$d/$tag.val" ]; then
		{ echo "example: dt-validate"; cat "$d/$tag.val"; } >>"$d/$tag.why"
		rc=1
	fi
	return $rc
}

if [ ${#ours[@]} -eq 0 ]; then
	msg "no binding YAML under ${BIND_SRC#"$PRUKIT_TOP"/} yet: nothing of ours to validate"
fi
for s in $SERIES; do
	[ -n "${SCHEMA[$s]}" ] || continue
	for f in "${ours[@]}"; do
		rel=${f#"$BIND_SRC"/}
		tag=$s-$(echo "$rel" | tr '/' '_')
		if check_binding "$s" "$rel" "$tag"; then
			pass "binding $rel: yamllint, dt-doc-validate, example (linux-$s," \
				"dt-schema ${DTS_VER[$s]})"
		else
			fail "binding $rel (linux-$s, dt-schema ${DTS_VER[$s]}):"
			show "$WORK/bind/$tag.why" 20
		fi
	done
	# Self-test: the good fixture passes every stage; the bad one passes the
	# document checks and fails only on its example, for the right reason.
	why=$WORK/bind/selftest-$s-good.why
	if check_binding "$s" prukit-selftest/prukit,selftest-good.yaml "selftest-$s-good"; then
		pass "binding self-test $s: a valid fixture binding passes every stage"
	else
		fail "binding self-test $s: the valid fixture binding is rejected:"
		show "$why" 12
	fi
	why=$WORK/bind/selftest-$s-bad.why
	if check_binding "$s" prukit-selftest/prukit,selftest-bad.yaml "selftest-$s-bad"; then
		fail "binding self-test $s: an example lacking a required property is accepted"
	elif ! grep -q '^yamllint:\|^dt-doc-validate:' "$why" &&
		grep -q "'prukit,widgets' is a required property" "$why"; then
		pass "binding self-test $s: an example lacking a required property is rejected"
	else
		fail "binding self-test $s: the bad fixture failed for another reason:"
		show "$why" 12
	fi
done

# ---------------------------------------------------------------- validation

# dt-validate flags for whole trees, as the kernel's dtbs_check uses them: -m
# also reports compatibles that no binding documents.
VALIDATE_FLAGS=-m

# validate SERIES SCHEMA DTB OUT: dt-validate DTB, cached; writes OUT with one
# line per message (continuation lines joined with \n, the file name removed),
# sorted; OUT.err if the validator itself failed.
validate() {
	local s=$1 schema=$2 dtb=$3 out=$4 key cached raw
	key=$(sha "$dtb")-$(sha "$schema")-${DTS_VER[$s]}$VALIDATE_FLAGS
	cached=$CACHE/validate/$key.msgs
	if [ ! -e "$cached" ]; then
		mkdir -p "$CACHE/validate"
		raw=$out.raw
		# shellcheck disable=SC2086
		if ! "${DTB_BIN[$s]}dt-validate" $VALIDATE_FLAGS -p "$schema" "$dtb" >"$raw" 2>&1 ||
			grep -q '^Traceback' "$raw"; then
			cp "$raw" "$out.err"
			return 1
		fi
		awk -v f="$dtb" '
			function flush() { if (rec != "") print rec; rec = "" }
			/^\t/ { rec = rec "\\n" $0; next }
			{ flush(); line = $0
			  # "FILE: msg", or "FILE:0:0: msg" for -m with dt-schema 2022.08
			  if (index(line, f) == 1) {
				  line = substr(line, length(f) + 1)
				  sub(/^(:[0-9]+)*: /, "", line)
			  }
			  rec = line }
			END { flush() }' "$raw" | LC_ALL=C sort >"$cached.tmp.$$"
		mv "$cached.tmp.$$" "$cached"
	fi
	cp "$cached" "$out"
}

# Run "$@" in the background, at most $JOBS at a time.
bg() {
	while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || true; done
	"$@" &
}

# Merged trees: every overlay on every base.
declare -A MERGED
for s in $SERIES; do
	for b in $BOARDS; do
		[ -n "${BASE[$s/$b]}" ] || continue
		for o in "${overlays[@]}"; do
			[ "${OVL_OK[$o]}" = 1 ] || continue
			for_board "$OVL_SRC/$o.dtso" "$b" || continue
			m=$WORK/$s/$b+$o.dtb
			if fdtoverlay -i "${BASE[$s/$b]}" -o "$m" "$WORK/$s/$o.dtbo" \
				>"$m.log" 2>&1; then
				MERGED[$s/$b/$o]=$m
			else
				MERGED[$s/$b/$o]=
				show "$m.log" 10 >"$m.why"
			fi
		done
	done
done

# Self-test overlay: a property no binding allows on a PRU core and a node
# whose compatible no binding documents; the diff must report both, or a clean
# diff proves nothing.
mkdir -p "$WORK/selftest"
cat >"$WORK/selftest/bogus.dtso" <<'EOF'
/dts-v1/;
/plugin/;
&pru0 {
	prukit-selftest-bogus = <1>;
};
&{/} {
	prukit-selftest {
		compatible = "prukit,selftest-undocumented";
	};
};
EOF
selftest_board=${BOARDS%% *}
for s in $SERIES; do
	st=$WORK/selftest/$s-$selftest_board+bogus.dtb
	if [ -n "${BASE[$s/$selftest_board]}" ] &&
		dtc -@ -I dts -O dtb -o "$WORK/selftest/bogus.dtbo" "$WORK/selftest/bogus.dtso" \
			2>/dev/null &&
		fdtoverlay -i "${BASE[$s/$selftest_board]}" -o "$st" "$WORK/selftest/bogus.dtbo"; then
		MERGED[$s/$selftest_board/selftest]=$st
	fi
done

# All dt-validate runs, at most $JOBS in parallel.
for s in $SERIES; do
	[ -n "${SCHEMA[$s]}" ] || continue
	for b in $BOARDS; do
		[ -n "${BASE[$s/$b]}" ] || continue
		bg validate "$s" "${SCHEMA[$s]}" "${BASE[$s/$b]}" "$WORK/$s/$b.msgs"
		for o in "${overlays[@]}" selftest; do
			m=${MERGED[$s/$b/$o]:-}
			[ -n "$m" ] || continue
			bg validate "$s" "${SCHEMA[$s]}" "$m" "$m.msgs"
		done
	done
done
wait

# new_msgs BASE_MSGS MERGED_MSGS OUT: messages only the merged tree has.
new_msgs() { LC_ALL=C comm -13 "$1" "$2" >"$3"; }

for s in $SERIES; do
	m=${MERGED[$s/$selftest_board/selftest]:-}
	b=$WORK/$s/$selftest_board.msgs
	if [ -z "$m" ] || [ ! -e "$m.msgs" ] || [ ! -e "$b" ]; then
		fail "self-test $s: the bogus-property overlay could not be applied or validated"
		continue
	fi
	new_msgs "$b" "$m.msgs" "$m.new"
	if grep -q 'prukit-selftest-bogus' "$m.new"; then
		pass "self-test $s: dt-validate diff reports a bogus property added by an overlay"
	else
		fail "self-test $s: a bogus property on pru0 went unreported by the dt-validate diff"
	fi
	if grep -q 'prukit,selftest-undocumented' "$m.new"; then
		pass "self-test $s: dt-validate diff reports an undocumented compatible"
	else
		fail "self-test $s: an undocumented compatible went unreported by the dt-validate diff"
	fi
	if grep -v 'prukit-selftest\|prukit,selftest' "$m.new" >"$m.other"; then
		fail "self-test $s: the diff also reports messages unrelated to the self-test:"
		show "$m.other" 6
	else
		pass "self-test $s: the diff reports nothing else ($(wc -l <"$m.new") new," \
			"$(wc -l <"$b") in the base tree)"
	fi
done

# The "vring" interrupts of the PRU nodes (TI's binding; rpmsg's PRU -> ARM
# event) are not in the mainline binding, whose PRU nodes have no interrupts.
# An overlay that sets them says so in "prukit-vring: LABEL EVENT CHANNEL
# HOST" lines; then exactly these three properties on exactly those nodes
# are accepted from dt-validate, and their values are checked.
VRING_PROPS="interrupts interrupt-names interrupt-parent"
vring_lines() { sed -n 's|^[[:space:]/*]*prukit-vring:[[:space:]]*||p' "$1"; }

# vring_allowed MERGED OVERLAY_SRC IN OUT: copy IN's messages to OUT except
# those about nothing but the vring properties of a node "prukit-vring:"
# names; prints how many were accepted.
vring_allowed() {
	local m=$1 src=$2 in=$3 out=$4 label nodes=
	while read -r label _; do
		nodes="$nodes $(fdtget -t s "$m" /__symbols__ "$label" 2>/dev/null)"
	done < <(vring_lines "$src")
	python3 - "$in" "$out" "$VRING_PROPS" $nodes <<'PY'
import re, sys
src, dst, props, nodes = sys.argv[1], sys.argv[2], set(sys.argv[3].split()), sys.argv[4:]
names = {n.rsplit("/", 1)[-1] for n in nodes if n}
kept, accepted = [], 0
for msg in open(src):
    first = msg.split("\\n", 1)[0]
    # "PATH: msg", or "PARENT: NODE: msg" (a parent's schema about a child)
    head, sep, _ = first.partition("'")
    node = head.rstrip().rstrip(":").split(": ")[-1] if sep else ""
    quoted = set(re.findall(r"'([^']+)'", first[len(head):]))
    about = quoted - {"pinctrl-[0-9]+"}
    if (node.rsplit("/", 1)[-1] in names and about and about <= props
            and ("were unexpected" in first or "do not match any of the regexes" in first)):
        accepted += 1
    else:
        kept.append(msg)
open(dst, "w").writelines(kept)
print(accepted)
PY
}

# vring_values DTB OVERLAY_SRC NAME: each "prukit-vring:" node has exactly
# the declared interrupt, named "vring", from the PRUSS's INTC.
vring_values() {
	local m=$1 src=$2 name=$3 label ev ch host path intc want got
	intc=$(fdtget -t s "$m" /__symbols__ pruss_intc 2>/dev/null) || intc=
	while read -r label ev ch host; do
		path=$(fdtget -t s "$m" /__symbols__ "$label" 2>/dev/null) || path=
		want="$ev $ch $host vring $(fdtget -t u "$m" "$intc" phandle 2>/dev/null || echo none)"
		got="$(fdtget -t u "$m" "$path" interrupts 2>/dev/null || echo none)"
		got="$got $(fdtget -t s "$m" "$path" interrupt-names 2>/dev/null || echo none)"
		got="$got $(fdtget -t u "$m" "$path" interrupt-parent 2>/dev/null || echo missing)"
		if [ -n "$path" ] && [ -n "$intc" ] && [ "$got" = "$want" ]; then
			pass "$name: $label vring interrupt: event $ev, channel $ch, host $host of pruss_intc"
		else
			fail "$name: $label ($path) interrupts, interrupt-names, interrupt-parent are" \
				"\"$got\", expected \"$want\" (pruss_intc's phandle last)"
		fi
	done < <(vring_lines "$src")
}

# check_merged SERIES BOARD OVERLAY: the checks of one overlay on one base
# tree; the SUMMARY text goes to $WORK/summary.SERIES.BOARD.OVERLAY.
check_merged() {
	local s=$1 b=$2 o=$3 m=${MERGED[$1/$2/$3]:-} bm=$WORK/$1/$2.msgs ok=1
	local name="$o on $s/$b" label prop want path got nbase nnew nexp=0 npins nvring
	if [ -z "$m" ]; then
		fail "$name: fdtoverlay could not apply it:"
		cat "$WORK/$s/$b+$o.dtb.why"
		echo "FAIL (fdtoverlay failed)" >"$WORK/summary.$s.$b.$o"
		return
	fi
	pass "$name: fdtoverlay applied it"
	if [ ! -e "$bm" ] || [ ! -e "$m.msgs" ]; then
		fail "$name: dt-validate did not run to completion"
		for f in "$bm.err" "$m.msgs.err"; do [ -e "$f" ] && show "$f" 8; done
		ok=0
	else
		new_msgs "$bm" "$m.msgs" "$m.new"
		nbase=$(wc -l <"$bm")
		if grep -q 'prukit-vring:' "$OVL_SRC/$o.dtso"; then
			nvring=$(vring_allowed "$m" "$OVL_SRC/$o.dtso" "$m.new" "$m.new.kept")
			mv "$m.new.kept" "$m.new"
			pass "$name: dt-validate: $nvring message(s) about the vring interrupts alone," \
				"accepted (prukit-vring:; not in the mainline binding)"
			vring_values "$m" "$OVL_SRC/$o.dtso" "$name"
		fi
		nnew=$(wc -l <"$m.new")
		if [ "$nnew" -eq 0 ]; then
			pass "$name: dt-validate finds nothing new ($nbase messages in the base tree alone)"
		else
			fail "$name: dt-validate reports $nnew message(s) the base tree does not have:"
			show "$m.new" 12
			ok=0
		fi
	fi
	while read -r label prop want; do
		nexp=$((nexp + 1))
		if ! path=$(fdtget -t s "$m" /__symbols__ "$label" 2>/dev/null); then
			fail "$name: label $label not in the merged tree's __symbols__"
			ok=0
			continue
		fi
		got=$(fdtget -t s "$m" "$path" "$prop" 2>/dev/null) || got="<missing>"
		if [ "$got" = "$want" ]; then
			pass "$name: $label ($path) $prop = \"$want\""
		else
			fail "$name: $label ($path) $prop is \"$got\", expected \"$want\""
			ok=0
		fi
	done < <(sed -n 's/.*prukit-expect:[[:space:]]*//p' "$OVL_SRC/$o.dtso")
	# the pin check on the merged tree (nothing to do for an overlay without groups)
	npins=0
	if grep -q '^group' "$WORK/pins/$o.blob" 2>/dev/null; then
		dt_table "$m" "$m.pins"
		pincheck "$OVL_SRC/$o.dtso" "$WORK/pins/$o.blob" "$m.pins" "$(board_column "$b")" \
			>"$m.pins.out"
		report_pins "$name" "$m.pins.out" || ok=0
		npins=$(grep -c '^PASS' "$m.pins.out" || true)
	fi
	if [ $ok -eq 1 ]; then
		echo "PASS (dt-schema ${DTS_VER[$s]}: $nbase base messages, 0 new;" \
			"$nexp fdtget assertions; $npins pin checks)" >"$WORK/summary.$s.$b.$o"
	else
		echo "FAIL" >"$WORK/summary.$s.$b.$o"
	fi
}

for s in $SERIES; do
	for b in $BOARDS; do
		for o in "${overlays[@]}"; do
			[ "${OVL_OK[$o]}" = 1 ] || { echo "FAIL (overlay did not build)" \
				>"$WORK/summary.$s.$b.$o"; continue; }
			if ! for_board "$OVL_SRC/$o.dtso" "$b"; then
				echo "SKIP (prukit-boards: $(decl_lines prukit-boards "$OVL_SRC/$o.dtso"))" \
					>"$WORK/summary.$s.$b.$o"
				continue
			fi
			if [ -z "${BASE[$s/$b]}" ] || [ -z "${SCHEMA[$s]}" ]; then
				echo "FAIL (no base tree or schema)" >"$WORK/summary.$s.$b.$o"
				continue
			fi
			check_merged "$s" "$b" "$o"
		done
	done
done

# ------------------------------------------------- vring base-tree fixtures

# The rpmsg overlays on the PRU-ICSS of BeagleBoard's TI trees, written from
# the facts (tests/overlays/bases/ti-pruss.dts.in): 5.10's has the vring
# interrupts, which the overlay must leave as they are; 6.1's and 6.6's lack
# them, and the overlay must add them.
mkdir -p "$WORK/vring"
vring_in=$FIXTURES/bases/ti-pruss.dts.in
for base in ti-5.10 ti-6.1; do
	d=$WORK/vring/$base
	if [ "$base" = ti-5.10 ]; then
		v0=$'\t\t\t\t\tinterrupt-parent = <\&pruss_intc>;\n\t\t\t\t\tinterrupts = <16 2 2>;\n\t\t\t\t\tinterrupt-names = "vring";'
		v1=${v0/16 2 2/18 3 3}
	else
		v0= v1=
	fi
	awk -v n="$base" -v v0="$v0" -v v1="$v1" '
		/^@VRING0@$/ { if (v0 != "") print v0; next }
		/^@VRING1@$/ { if (v1 != "") print v1; next }
		{ gsub(/@NAME@/, n); print }' "$vring_in" >"$d.dts"
	if ! dtc -q -@ -I dts -O dtb -o "$d.dtb" "$d.dts" 2>"$d.log"; then
		fail "vring fixture $base does not build:"
		show "$d.log" 5
		continue
	fi
	# the fixture itself: with the properties (5.10) or without (6.1)
	got=$(fdtget -t s "$d.dtb" /ocp/target-module@4a300000/pruss@0/pru@34000 interrupt-names \
		2>/dev/null || echo none)
	case $base/$got in
	ti-5.10/vring | ti-6.1/none) pass "vring fixture $base: pru0's interrupt-names is $got" ;;
	*) fail "vring fixture $base: pru0's interrupt-names is $got" ;;
	esac
	for o in "${overlays[@]}"; do
		grep -q 'prukit-vring:' "$OVL_SRC/$o.dtso" || continue
		blob=$WORK/vring/$o.dtbo
		[ -e "$blob" ] || "$DTSO_BUILD" "$OVL_SRC/$o.dtso" "$blob" >/dev/null 2>&1 ||
			{ fail "$o: does not build for the vring fixtures"; continue; }
		if fdtoverlay -i "$d.dtb" -o "$d+$o.dtb" "$blob" 2>"$d+$o.log"; then
			vring_values "$d+$o.dtb" "$OVL_SRC/$o.dtso" "$o on the $base fixture"
		else
			fail "$o on the $base fixture: fdtoverlay could not apply it:"
			show "$d+$o.log" 5
		fi
	done
done

# ... and the allowance takes nothing else: a message that also names another
# property, or names a node no "prukit-vring:" line declares, stays.
if [ -e "$WORK/vring/ti-6.1+PRUKIT-RPMSG-00A0.dtb" ]; then
	st=$WORK/vring/selftest
	{
		echo "pruss@0: pru@34000: 'interrupt-names', 'interrupts' do not match any of the regexes: 'pinctrl-[0-9]+'"
		echo "/x/pru@38000: Unevaluated properties are not allowed ('interrupts', 'prukit-selftest-bogus' were unexpected)"
		echo "/x/pru@3c000: Unevaluated properties are not allowed ('interrupts' were unexpected)"
		echo "/x/pru@34000: 'firmware-name' is a required property"
	} >"$st.in"
	n=$(vring_allowed "$WORK/vring/ti-6.1+PRUKIT-RPMSG-00A0.dtb" "$OVL_SRC/PRUKIT-RPMSG-00A0.dtso" \
		"$st.in" "$st.out")
	if [ "$n" = 1 ] && [ "$(wc -l <"$st.out")" -eq 3 ] && ! grep -q "pruss@0: pru@34000" "$st.out"; then
		pass "self-test: the vring allowance takes the one vring-only message of four"
	else
		fail "self-test: the vring allowance took $n of 4 messages; kept:"
		show "$st.out" 4
	fi
else
	fail "self-test: no merged vring fixture to test the allowance on"
fi

# ------------------------------------------------------- pin-check self-tests

# Every tests/overlays/*.dtso names in a "prukit-selftest: TAG" line the one
# reason the pin check must reject it for (or "pass": it must pass).  It is
# built, checked as a blob and on every base tree; the union of the reasons
# of all FAIL lines must be exactly TAG.  Every reason below must be proven
# by some fixture.
SELFTEST_TAGS="mode input twice unknown conflict"
mkdir -p "$WORK/fixtures"
proven=" "
for f in "$FIXTURES"/*.dtso; do
	[ -e "$f" ] || continue
	n=$(basename "$f" .dtso)
	d=$WORK/fixtures/$n
	want=$(decl_lines prukit-selftest "$f")
	if [ -z "$want" ]; then
		fail "self-test pins: ${f#"$PRUKIT_TOP"/} has no 'prukit-selftest:' line"
		continue
	fi
	if ! "$DTSO_BUILD" --kdir "${KDIR[$FIRST_SERIES]}" "$f" "$d.dtbo" 2>"$d.log"; then
		fail "self-test pins: ${f#"$PRUKIT_TOP"/} does not build:"
		show "$d.log" 10
		continue
	fi
	check_boards "$f" "self-test pins: ${f#"$PRUKIT_TOP"/}" || continue
	dt_table "$d.dtbo" "$d.blob"
	pincheck "$f" "$d.blob" >"$d.out"
	ntrees=0
	for s in $SERIES; do
		for b in $BOARDS; do
			[ -n "${BASE[$s/$b]}" ] || continue
			for_board "$f" "$b" || continue
			if ! fdtoverlay -i "${BASE[$s/$b]}" -o "$d.$s.$b.dtb" "$d.dtbo" >"$d.log" 2>&1; then
				printf 'FAIL\tapply\tfdtoverlay cannot apply it to %s\n' "$s/$b" >>"$d.out"
				continue
			fi
			dt_table "$d.$s.$b.dtb" "$d.$s.$b.pins"
			pincheck "$f" "$d.blob" "$d.$s.$b.pins" "$(board_column "$b")" | sed "s|\$|  [$s/$b]|" >>"$d.out"
			ntrees=$((ntrees + 1))
		done
	done
	# prukit-boards: checked on exactly the listed boards' trees of this run
	listed=$(decl_lines prukit-boards "$f")
	if [ -n "$listed" ]; then
		nwant=0
		for s in $SERIES; do
			for b in $BOARDS; do
				case " $listed " in *" $b "*) [ -z "${BASE[$s/$b]}" ] || nwant=$((nwant + 1)) ;; esac
			done
		done
		if [ "$ntrees" -ne "$nwant" ]; then
			fail "self-test pins: $n.dtso (prukit-boards: $listed) was checked on $ntrees" \
				"merged trees, not the $nwant of its boards"
			continue
		fi
	fi
	got=$(awk -F'\t' '$1 == "FAIL" { print $2 }' "$d.out" | sort -u | tr '\n' ' ')
	nwhy=$(grep -c '^FAIL' "$d.out" || true)
	why=$(awk -F'\t' '$1 == "FAIL" { print $3; exit }' "$d.out")
	if [ "$want" = pass ]; then
		if [ -z "$got" ]; then
			pass "self-test pins: $n.dtso (valid) passes on its blob and $ntrees merged" \
				"trees${listed:+ (prukit-boards: $listed; other boards skipped)}"
		else
			fail "self-test pins: $n.dtso (valid) is rejected (${got% }):"
			grep '^FAIL' "$d.out" | show /dev/stdin 8
		fi
	elif [ "$got" = "$want " ]; then
		pass "self-test pins: $n.dtso rejected for '$want' only ($nwhy time(s), blob and" \
			"$ntrees merged trees), e.g.: $why"
		proven="$proven$want "
	elif [ -z "$got" ]; then
		fail "self-test pins: $n.dtso is accepted; it must be rejected for '$want'"
	else
		fail "self-test pins: $n.dtso rejected for '${got% }', expected '$want' only:"
		grep '^FAIL' "$d.out" | show /dev/stdin 8
	fi
done
for t in $SELFTEST_TAGS; do
	case $proven in
	*" $t "*) ;;
	*) fail "self-test pins: no fixture in ${FIXTURES#"$PRUKIT_TOP"/} proves rejection for '$t'" ;;
	esac
done

# ------------------------------------------------------------------ summary

for o in "${overlays[@]}"; do
	for s in $SERIES; do
		for b in $BOARDS; do
			r=$(cat "$WORK/summary.$s.$b.$o" 2>/dev/null || echo "FAIL (not checked)")
			# every other FAIL was counted where it was found
			[ "$r" != "FAIL (not checked)" ] || fail "$o on $s/$b: not checked"
			printf 'SUMMARY: %s x linux-%s/%s: %s\n' "$o" "$s" "$b" "$r"
		done
	done
done
for s in $SERIES; do
	msg "linux-$s: ${KNAME[$s]}, dt-schema ${DTS_VER[$s]}${DTB_BIN[$s]:+ (${DTB_BIN[$s]})}"
done
msg "overlays in ${OUT#"$PRUKIT_TOP"/}: ${overlays[*]/%/.dtbo}"
printf '%d passed, %d failed\n' "$npass" "$nfail"
[ "$nfail" -eq 0 ]
