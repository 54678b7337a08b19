# SPDX-License-Identifier: GPL-2.0-only
# Shared helpers for prukit's build and test scripts (sourced, not run).

PRUKIT_TOP=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
PRUKIT_CACHE=${PRUKIT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/prukit}
export PRUKIT_TOP PRUKIT_CACHE

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

ncpus() { getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1; }
