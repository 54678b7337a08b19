#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# overlays.sh - build prukit's device-tree overlays and prove them against real
# base trees (called by "make overlays").
#
#  1. overlays/*.dtso: cpp (kernel dt-bindings headers) + dtc -@, any cpp or
#     dtc warning is an error; result in out/overlays/*.dtbo.  Built against
#     every kernel series below; the blobs must be identical.
#  2. Documentation/devicetree/bindings/**/*.yaml (N >= 0): yamllint,
#     dt-doc-validate, and the examples compiled and checked with dt-validate,
#     once per kernel series with that kernel's bindings.
#  3. am335x-boneblack and am335x-pocketbeagle built with -@ from Debian's
#     linux-source 6.1 and 6.12; every overlay applied with fdtoverlay; the
#     merged tree checked with dt-validate against the kernel's bindings plus
#     ours; it must not add any message to those of the base tree alone; the
#     "prukit-expect:" lines of each overlay are asserted with fdtget.
#  4. Self-tests that prove steps 2 and 3 can fail.
#
# Prints PASS:/FAIL: lines and a SUMMARY: line per overlay x base tree; exits
# non-zero if anything failed.  Processed schemas, base dtbs and dt-validate
# results are cached under $PRUKIT_CACHE/dt keyed by their inputs.
#
# Environment: PRUKIT_DT_SERIES (default "6.1 6.12"), PRUKIT_DT_BOARDS
# (default "am335x-boneblack am335x-pocketbeagle"), PRUKIT_JOBS (1 or 2).
set -euo pipefail
. "$(dirname "$0")/lib.sh"

SERIES=${PRUKIT_DT_SERIES:-"6.1 6.12"}
BOARDS=${PRUKIT_DT_BOARDS:-"am335x-boneblack am335x-pocketbeagle"}
JOBS=${PRUKIT_JOBS:-2}
[ "$JOBS" -ge 1 ] 2>/dev/null || JOBS=1
[ "$JOBS" -le 2 ] || JOBS=2

# dtschema from PyPI, used only when Debian's dt-schema is older than a kernel's
# DT_SCHEMA_MIN_VERSION (6.12 needs 2023.9, bookworm has 2022.08).  Exact pins,
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
BIND_SRC=$PRUKIT_TOP/Documentation/devicetree/bindings
OUT=$PRUKIT_TOP/out/overlays
WORK=$OUT/check
CACHE=$PRUKIT_CACHE/dt

nfail=0
npass=0
pass() { printf 'PASS: %s\n' "$*"; npass=$((npass + 1)); }
fail() { printf 'FAIL: %s\n' "$*"; nfail=$((nfail + 1)); }
# Show the first lines of a message file, indented and cut to 200 columns.
show() { sed -n "1,${2:-12}p" "$1" | cut -c1-200 | sed 's/^/    /'; }

sha() { sha256sum "$@" | cut -c1-16; }

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

# Pick the dt-schema tools for one kernel tree: Debian's if new enough.
# Sets DTBIN (directory of the tools, or empty for PATH) and DTVER.
pick_dtschema() {
	local k=$1 min deb
	min=$(sed -n 's/^DT_SCHEMA_MIN_VERSION = //p' "$k/Documentation/devicetree/bindings/Makefile")
	deb=$(dt-doc-validate --version)
	if [ -n "$min" ] && ! printf '%s\n%s\n' "$min" "$deb" | sort -Vc 2>/dev/null; then
		DTBIN=$(dtschema_venv) || die "could not install dtschema $DTSCHEMA_PIP_VERSION"
		DTBIN=$DTBIN/
		DTVER=$DTSCHEMA_PIP_VERSION
		printf '%s\n%s\n' "$min" "$DTVER" | sort -Vc 2>/dev/null ||
			die "kernel $k needs dtschema >= $min, pinned $DTVER is older"
	else
		DTBIN=
		DTVER=$deb
	fi
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

# compile_dtso SRC KDIR OUT: cpp + dtc -@; fails (and shows why) on any warning.
compile_dtso() {
	local src=$1 k=$2 out=$3 log=$3.log
	: >"$log"
	if ! cpp -nostdinc -undef -D__DTS__ -x assembler-with-cpp -I "$k/include" \
		-I "$(dirname "$src")" -o "$out.pre" "$src" 2>>"$log"; then
		return 1
	fi
	dtc -@ -I dts -O dtb -o "$out" "$out.pre" 2>>"$log" || return 1
	[ ! -s "$log" ]
}

overlays=()
for src in "$OVL_SRC"/*.dtso; do
	[ -e "$src" ] || continue
	overlays+=("$(basename "$src" .dtso)")
done
[ ${#overlays[@]} -gt 0 ] || fail "overlays: no overlays/*.dtso found"

declare -A OVL_OK
for o in "${overlays[@]}"; do
	src=$OVL_SRC/$o.dtso
	OVL_OK[$o]=1
	first=
	for s in $SERIES; do
		mkdir -p "$WORK/$s"
		if compile_dtso "$src" "${KDIR[$s]}" "$WORK/$s/$o.dtbo"; then
			pass "build $o.dtbo with linux-$s dt-bindings (cpp + dtc -@, no warnings)"
		else
			fail "build $o.dtbo with linux-$s dt-bindings: cpp/dtc reported:"
			show "$WORK/$s/$o.dtbo.log" 20
			OVL_OK[$o]=0
			continue
		fi
		if [ -z "$first" ]; then
			first=$s
			cp "$WORK/$s/$o.dtbo" "$OUT/$o.dtbo"
		elif cmp -s "$WORK/$first/$o.dtbo" "$WORK/$s/$o.dtbo"; then
			pass "$o.dtbo identical whether built with linux-$first or linux-$s headers"
		else
			fail "$o.dtbo differs between linux-$first and linux-$s dt-bindings headers"
			OVL_OK[$o]=0
		fi
	done
	if ! grep -q 'prukit-expect:' "$src"; then
		fail "$o: no 'prukit-expect:' lines in $o.dtso, nothing to assert in merged trees"
		OVL_OK[$o]=0
	fi
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

# check_merged SERIES BOARD OVERLAY: the checks of one overlay on one base
# tree; the SUMMARY text goes to $WORK/summary.SERIES.BOARD.OVERLAY.
check_merged() {
	local s=$1 b=$2 o=$3 m=${MERGED[$1/$2/$3]:-} bm=$WORK/$1/$2.msgs ok=1
	local name="$o on $s/$b" label prop want path got nbase nnew nexp=0
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
	if [ $ok -eq 1 ]; then
		echo "PASS (dt-schema ${DTS_VER[$s]}: $nbase base messages, 0 new;" \
			"$nexp fdtget assertions)" >"$WORK/summary.$s.$b.$o"
	else
		echo "FAIL" >"$WORK/summary.$s.$b.$o"
	fi
}

for s in $SERIES; do
	for b in $BOARDS; do
		for o in "${overlays[@]}"; do
			[ "${OVL_OK[$o]}" = 1 ] || { echo "FAIL (overlay did not build)" \
				>"$WORK/summary.$s.$b.$o"; continue; }
			if [ -z "${BASE[$s/$b]}" ] || [ -z "${SCHEMA[$s]}" ]; then
				echo "FAIL (no base tree or schema)" >"$WORK/summary.$s.$b.$o"
				continue
			fi
			check_merged "$s" "$b" "$o"
		done
	done
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
