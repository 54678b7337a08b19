#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# dtso-build.sh [--series S | --kdir DIR] SRC.dtso OUT.dtbo
#
# The one way prukit compiles a device-tree overlay source: the C
# preprocessor as Kbuild runs it for .dts files (cpp -nostdinc -undef
# -D__DTS__ -x assembler-with-cpp) with dt-bindings headers
# (#include <dt-bindings/pinctrl/am33xx.h> ...) and the directory of SRC on
# the include path, then dtc -@ (symbols, so that the result can be applied
# and can itself be referred to).  Any message of cpp or dtc - a warning
# included - is an error: it is printed and OUT is removed, so that no stale
# blob survives a failed build.  OUT is written (through a temporary file)
# only when everything succeeded.
#
# The headers are prukit's own by default: overlays/include/dt-bindings/
# (gpio, leds) and <dt-bindings/pinctrl/am33xx.h> generated from the pin
# table by scripts/pins-header.sh --dt, so that building an overlay needs
# no kernel source and no network (a board, a fresh machine).  An overlay
# that uses a macro they lack fails in dtc (a syntax error on the line that
# uses it); build it with a kernel's headers instead: --series S takes them from Debian's
# linux-source-S (5.10, 6.1, 6.12; fetched and extracted once into
# $PRUKIT_CACHE by scripts/linux-source.sh), --kdir DIR (or PRUKIT_DT_KDIR)
# from an extracted kernel tree.  Needs only cpp and device-tree-compiler,
# which it installs if they are missing.
#
# Used by scripts/overlays.sh (make overlays, make check) and scripts/vm.sh
# (make vmrun OVERLAY=my.dtso).  Exit status: 0 built, 1 the overlay does not
# build cleanly (reason printed), 2 usage or setup error.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

usage() {
	echo "usage: ${0##*/} [--series 5.10|6.1|6.12 | --kdir DIR] SRC.dtso OUT.dtbo" >&2
	exit 2
}
err() { printf 'dtso-build: %s\n' "$*" >&2; }

series=
kdir=${PRUKIT_DT_KDIR:-}
while [ $# -gt 0 ]; do
	case $1 in
	--series) [ $# -ge 2 ] || usage; series=$2; kdir=; shift 2 ;;
	--kdir) [ $# -ge 2 ] || usage; kdir=$2; shift 2 ;;
	-h | --help) usage ;;
	--) shift; break ;;
	-*) err "unknown option $1"; usage ;;
	*) break ;;
	esac
done
[ $# -eq 2 ] || usage
src=$1
out=$2

if [ ! -e "$src" ]; then
	err "$src: no such file"
	exit 2
fi
if [ ! -f "$src" ] || [ ! -r "$src" ]; then
	err "$src: not a readable file"
	exit 2
fi
case $src in
*.dtso | *.dts) ;;
*) err "$src: expected a .dtso overlay source"; exit 2 ;;
esac
outdir=$(dirname "$out")
if [ ! -d "$outdir" ]; then
	err "$out: directory $outdir does not exist"
	exit 2
fi

need_pkgs cpp device-tree-compiler
for t in cpp dtc; do
	command -v "$t" >/dev/null || { err "$t not found"; exit 2; }
done

tmp=$(mktemp -d "${TMPDIR:-/tmp}/dtso-build.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

if [ -n "$series" ]; then
	kdir=$("$PRUKIT_TOP/scripts/linux-source.sh" "$series" dt) ||
		{ err "could not get the linux-source-$series dt-bindings headers"; exit 2; }
fi
if [ -n "$kdir" ]; then
	if [ ! -d "$kdir/include/dt-bindings" ]; then
		err "$kdir/include/dt-bindings: no such directory (not a kernel source tree?)"
		exit 2
	fi
	incs=("-I" "$kdir/include")
	hdrs=${kdir%/}/include
else
	mkdir -p "$tmp/include/dt-bindings/pinctrl"
	"$PRUKIT_TOP/scripts/pins-header.sh" --dt >"$tmp/include/dt-bindings/pinctrl/am33xx.h" ||
		{ err "could not generate <dt-bindings/pinctrl/am33xx.h> from the pin table"; exit 2; }
	incs=("-I" "$tmp/include" "-I" "$PRUKIT_TOP/overlays/include")
	hdrs="prukit's (overlays/include, and am33xx.h from sim/am335x-pins.tsv; --series S for a kernel's)"
fi

# Relative paths in messages stay as the caller gave them.
if ! cpp -nostdinc -undef -D__DTS__ -x assembler-with-cpp "${incs[@]}" \
	-I "$(dirname "$src")" -o "$tmp/pre.dts" "$src" 2>"$tmp/cpp.log" || [ -s "$tmp/cpp.log" ]; then
	err "$src: the C preprocessor failed (headers: $hdrs):"
	sed 's/^/    /' "$tmp/cpp.log" >&2
	rm -f "$out"
	exit 1
fi
if ! dtc -@ -I dts -O dtb -o "$tmp/out.dtbo" "$tmp/pre.dts" 2>"$tmp/dtc.log" ||
	[ -s "$tmp/dtc.log" ]; then
	err "$src: dtc reported (any warning is an error; locations are in the .dtso):"
	# cpp's line markers make dtc name the .dtso; the rest names temp files
	sed -e "s|$tmp/pre.dts|$src (preprocessed)|g" -e "s|$tmp/out.dtbo|$out|g" \
		-e 's/^/    /' "$tmp/dtc.log" >&2
	rm -f "$out"
	exit 1
fi
cp "$tmp/out.dtbo" "$out.tmp.$$"
mv -f "$out.tmp.$$" "$out"
