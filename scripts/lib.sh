# SPDX-License-Identifier: GPL-2.0-only
# Shared helpers for prukit's build and test scripts (sourced, not run).

PRUKIT_TOP=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
PRUKIT_CACHE=${PRUKIT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/prukit}
export PRUKIT_TOP PRUKIT_CACHE
# The scripts are make's entry points (make vmrun KVER=6.1 SCRIPT=x OUT=dir):
# the variables given on make's command line travel in MAKEFLAGS and would
# override those of every make a script runs (firmware/Makefile's and
# tools/prusim/Makefile's OUT: the firmware built into the vmrun output).
# A script's makes get only what it passes them.
unset MAKEFLAGS MAKEOVERRIDES MFLAGS

msg() { printf '[prukit] %s\n' "$*" >&2; }
die() { printf '[prukit] error: %s\n' "$*" >&2; exit 1; }

# Run a long step quietly, keeping its log; show the tail of the log on failure.
run_logged() {
	local log
	log=$(realpath -m "$1")
	shift
	if ! "$@" >"$log" 2>&1; then
		tail -n 40 "$log" >&2
		die "'$*' failed, full log in $log"
	fi
}

# need_pkgs PKG... - install the Debian packages that are missing, saying so.
need_pkgs() {
	local missing=() p
	for p in "$@"; do
		dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' ||
			missing+=("$p")
	done
	[ ${#missing[@]} -eq 0 ] && return 0
	msg "installing Debian packages: ${missing[*]}"
	local sudo=
	[ "$(id -u)" -ne 0 ] && sudo=sudo
	mkdir -p "$PRUKIT_CACHE"
	# Another install may hold apt's locks for a while: wait for it.
	local lock=(-o DPkg::Lock::Timeout=600)
	run_logged "$PRUKIT_CACHE/apt-update.log" $sudo apt-get "${lock[@]}" update
	run_logged "$PRUKIT_CACHE/apt-install.log" $sudo env DEBIAN_FRONTEND=noninteractive \
		apt-get "${lock[@]}" install -y --no-install-recommends "${missing[@]}"
}

# The kernels prukit builds for and boots, by name (SERIES):
#   5.10 6.1 6.12  Debian's armmp kernels, with the kernel's own (mainline)
#                  PRU drivers built beside them from Debian's linux-source
#                  for the board path (scripts/pru-kit.sh);
#   5.10-ti        BeagleBoard's TI kernel 5.10.168-ti-r71, whole (its PRU
#                  drivers, TI's rpmsg_pru, PREEMPT, HZ=250), built for the
#                  VM's machine: shared/ti-kernel/ beside the checkout;
#   6.12-ti        Debian's 6.12 with TI's 6.x pru_rproc and pruss_intc
#                  (shared/ti-kernel/ti-6.x-pru-drivers) and Debian's pruss.
# kernel_flavour SERIES - debian, ti-kernel or ti-drivers; fails on an
# unknown name.
PRUKIT_SERIES_ALL="5.10 6.1 6.12 5.10-ti 6.12-ti"
kernel_flavour() {
	case $1 in
	5.10 | 6.1 | 6.12) echo debian ;;
	5.10-ti) echo ti-kernel ;;
	6.12-ti) echo ti-drivers ;;
	*) die "unknown kernel '$1' (one of: $PRUKIT_SERIES_ALL)" ;;
	esac
}

# kernel_tag SERIES RELEASE - what names a flavour's build and VM
# directories (out/kernels/TAG-board, out/vm/TAG): the release, and for
# Debian's kernel with TI's PRU drivers the release with "-tipru" (it
# shares Debian's release).
kernel_tag() {
	case $(kernel_flavour "$1") in
	ti-drivers) echo "$2-tipru" ;;
	*) echo "$2" ;;
	esac
}

# ti_material - shared/ti-kernel: test material beside the checkout (CI
# lays shared/ beside its clone), or under $PRUKIT_SHARED.
ti_material() {
	realpath -m "${PRUKIT_SHARED:-$PRUKIT_TOP/../shared}/ti-kernel"
}

ncpus() { getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1; }

# prukit_drivers [TOP] - the drivers, one name per line, in the order of
# TOP/drivers/registry (TOP: PRUKIT_TOP), whose lines are what every list of
# drivers is derived from.
prukit_drivers() {
	awk '/^[a-z0-9_]+[ \t]/ { print $1 }' "${1:-$PRUKIT_TOP}/drivers/registry"
}

# vm_cases [TOP] - the VM test cases, one "NAME PATH" line each, sorted by
# name: the executable files in TOP/tests/vm/cases and in each driver's
# TOP/drivers/<driver>/tests/vm/cases (TOP: PRUKIT_TOP; the drivers of
# TOP/drivers/registry).  The guest runs them all in one boot, by name,
# from one directory (/prukit/tests), so two cases with one name are an
# error: both are named on stderr, none is listed.
vm_cases() {
	local top=${1:-$PRUKIT_TOP} d drivers dirs
	drivers=$(prukit_drivers "$top") || return 1
	dirs=("$top/tests/vm/cases")
	for d in $drivers; do dirs+=("$top/drivers/$d/tests/vm/cases"); done
	for d in "${dirs[@]}"; do
		[ -d "$d" ] || continue
		# Executables only: not __pycache__, data files and the like.
		find "$d" -maxdepth 1 -type f -perm -u+x -printf '%f %p\n'
	done | LC_ALL=C sort -k1,1 | awk '
		{ n[$1]++; path[$1] = path[$1] " " $2; line[NR] = $0; name[NR] = $1 }
		END {
			for (k in n) if (n[k] > 1) { print "two VM tests named " k ":" path[k] > "/dev/stderr"; bad = 1 }
			if (bad) exit 1
			for (i = 1; i <= NR; i++) print line[i]
		}'
}

# vm_host_half CASE_PATH - where the host half of a VM test case is (it may
# not exist): beside its cases/ directory, in host/ under the same name.
vm_host_half() {
	local p=$1
	echo "${p%/cases/*}/host/${p##*/}"
}

# driver_checks [TOP] - each driver's own make check step, one "NAME MIN
# PATH" line each: TOP/drivers/<driver>/tests/check.sh (the drivers of
# TOP/drivers/registry), with MIN (the fewest PASS:/FAIL: lines it must
# print, as step() takes it) from its line "# prukit-check-min: N", or
# "none" when it declares none.
driver_checks() {
	local top=${1:-$PRUKIT_TOP} f d min drivers
	drivers=$(prukit_drivers "$top") || return 1
	for d in $drivers; do
		f=$top/drivers/$d/tests/check.sh
		[ -f "$f" ] || continue
		min=$(sed -n 's/^# prukit-check-min: *\([0-9][0-9]*\) *$/\1/p' "$f" | head -n 1)
		echo "$d ${min:-none} $f"
	done
}

# prusim_and_images DIR IMAGE... - the prusim host tool (make tools:
# out/tools/prusim) and the PRU firmware images named (ws281x-pru0.elf ...)
# built into DIR/fw, a directory of their own: nothing else in out/ moves.
# The images' build log is DIR/fw.log.  On failure: the log's tail and a
# FAIL: line, return 1.
prusim_and_images() {
	local dir=$1 bin
	shift
	if ! make -s -C "$PRUKIT_TOP" tools >"$dir/tools.log" 2>&1; then
		tail -n 20 "$dir/tools.log"
		echo "FAIL: make tools (out/tools/prusim)"
		return 1
	fi
	bin=$("$PRUKIT_TOP/scripts/pru-toolchain.sh") || {
		echo "FAIL: scripts/pru-toolchain.sh"
		return 1
	}
	if ! make -s --no-print-directory -C "$PRUKIT_TOP/firmware" CROSS_COMPILE="$bin/pru-" \
		O="$dir/fw" "${@/#/$dir/fw/}" >"$dir/fw.log" 2>&1; then
		tail -n 20 "$dir/fw.log"
		echo "FAIL: building $*"
		return 1
	fi
}

# callgrind_ir FN OUT CMD... - the instructions function FN executes while
# CMD runs under valgrind's callgrind (only FN and what it calls are
# counted), printed on stdout; CMD's output and callgrind's go to OUT.log,
# OUT.valgrind.log and OUT.callgrind.  On failure: the logs and a FAIL:
# line, return 1.  The benches' exact count of the ARM's work (host builds).
callgrind_ir() {
	local fn=$1 out=$2 ir
	shift 2
	command -v valgrind >/dev/null || need_pkgs valgrind
	if ! valgrind --tool=callgrind --collect-atstart=no --toggle-collect="$fn" \
		--callgrind-out-file="$out.callgrind" "$@" >"$out.log" 2>"$out.valgrind.log"; then
		cat "$out.log" "$out.valgrind.log"
		echo "FAIL: $* under callgrind"
		return 1
	fi
	ir=$(sed -n 's/^summary: *\([0-9]*\)$/\1/p' "$out.callgrind")
	[ -n "$ir" ] || { echo "FAIL: no callgrind summary for $fn"; return 1; }
	echo "$ir"
}

# dkms_source DIR - what DKMS builds prukit from, as the prukit-dkms package
# and a release hold it: the top Kbuild, Makefile and dkms.conf, include/,
# the registry, and each registered driver's Kbuild, sources and headers
# (its KUnit suite, tests, firmware, udev rules and servers left out).  Only
# files git tracks.
dkms_source() {
	local dir=$1 d
	mkdir -p "$dir"
	(
		cd "$PRUKIT_TOP" || exit 1
		{
			git ls-files -- Kbuild Makefile dkms.conf include \
				drivers/registry drivers/registry.mk drivers/gate.mk
			for d in $(prukit_drivers); do
				git ls-files -- "drivers/$d/Kbuild" "drivers/$d/*.c" "drivers/$d/*.h" |
					grep -v -e '/[^/]*/[^/]*/' -e '_kunit\.c$'
			done
		} | xargs cp --parents -t "$dir"
	)
}

# copy_checkout DIR - copy the files a clone of the tree has (tracked and
# untracked-but-not-ignored, with uncommitted edits; no out/) into DIR: the
# harness's fresh trees (tests/harness/discovery.sh, fresh-clone.sh).
copy_checkout() {
	mkdir -p "$1"
	(cd "$PRUKIT_TOP" && git ls-files -z --cached --others --exclude-standard |
		while IFS= read -r -d '' f; do [ -e "$f" ] && printf '%s\0' "$f"; done |
		xargs -0 cp --parents -t "$1") && [ ! -e "$1/out" ]
}
