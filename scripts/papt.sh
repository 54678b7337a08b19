# SPDX-License-Identifier: GPL-2.0-only
#
# Private apt for packages of other suites and architectures (sourced after
# lib.sh).  It reads the Debian archive from the machine's own apt sources
# but keeps its sources, lists, cache and dpkg status under
# $PRUKIT_CACHE/apt: the machine's apt state is never touched.
#   papt_init        set up and refresh the lists (at most once a day)
#   papt ARGS...     apt-get with the private configuration
#   pcache ARGS...   apt-cache with the private configuration
#   papt_fetch DIR PKG...  download PKG... and extract them into DIR
# Sources: bullseye, bookworm and bookworm-backports binaries (amd64,
# armhf), and bookworm's source packages (scripts/qemu-build.sh).

PRUKIT_APT=$PRUKIT_CACHE/apt

# The Debian archive URI from the machine's apt sources (deb822 or one-line).
debian_mirror() {
	local m=${PRUKIT_DEBIAN_MIRROR:-}
	[ -n "$m" ] || m=$(awk '
		/^URIs:/ && $2 ~ /\/debian\/?$/ { print $2; exit }
		/^deb / { for (i = 2; i <= NF; i++)
				if ($i ~ /^[a-z]+:\/\// && $i ~ /\/debian\/?$/) { print $i; exit } }
		' /etc/apt/sources.list.d/*.sources /etc/apt/sources.list \
		  /etc/apt/sources.list.d/*.list 2>/dev/null | head -n 1)
	[ -n "$m" ] || die "no Debian archive found in the apt sources; set PRUKIT_DEBIAN_MIRROR"
	echo "$m"
}

papt_opts=(
	-o "Dir::Etc::SourceList=$PRUKIT_APT/etc/sources.list"
	-o "Dir::Etc::SourceParts=$PRUKIT_APT/etc/sources.list.d"
	-o "Dir::Etc::PreferencesParts=$PRUKIT_APT/etc/preferences.d"
	-o "Dir::State=$PRUKIT_APT"
	-o "Dir::State::Lists=$PRUKIT_APT/lists"
	-o "Dir::State::status=$PRUKIT_APT/status"
	-o "Dir::Cache=$PRUKIT_APT/cache"
	-o "APT::Architecture=amd64"
	-o "APT::Architectures::=amd64"
	-o "APT::Architectures::=armhf"
	-o "Debug::NoLocking=1"
	-o "Acquire::Languages=none"
)
papt() { apt-get "${papt_opts[@]}" "$@"; }
pcache() { apt-cache "${papt_opts[@]}" "$@"; }

papt_init() {
	local mirror keyring=/usr/share/keyrings/debian-archive-keyring.gpg
	need_pkgs apt dpkg debian-archive-keyring
	mirror=$(debian_mirror)
	mkdir -p "$PRUKIT_APT"/{lists/partial,cache/archives/partial,etc/preferences.d,etc/sources.list.d}
	[ -e "$PRUKIT_APT/status" ] || : >"$PRUKIT_APT/status"
	cat >"$PRUKIT_APT/etc/sources.list.new" <<EOT
deb [arch=amd64,armhf signed-by=$keyring] $mirror bullseye main
deb [arch=amd64,armhf signed-by=$keyring] $mirror bookworm main
deb [arch=amd64,armhf signed-by=$keyring] $mirror bookworm-backports main
deb-src [signed-by=$keyring] $mirror bookworm main
EOT
	if ! cmp -s "$PRUKIT_APT/etc/sources.list.new" "$PRUKIT_APT/etc/sources.list"; then
		mv "$PRUKIT_APT/etc/sources.list.new" "$PRUKIT_APT/etc/sources.list"
		rm -f "$PRUKIT_APT"/lists/*Packages* "$PRUKIT_APT"/lists/*Sources*
	else
		rm -f "$PRUKIT_APT/etc/sources.list.new"
	fi
	if [ -z "$(find "$PRUKIT_APT/lists" -maxdepth 1 -name '*Packages*' -mmin -1440 | head -n 1)" ]; then
		msg "updating the private apt lists (bullseye, bookworm, bookworm-backports; amd64, armhf; bookworm sources)"
		run_logged "$PRUKIT_APT/update.log" papt update
	fi
}

papt_fetch() {
	local dest=$1 deb dl
	shift
	dl=$(mktemp -d "$PRUKIT_CACHE/download.XXXXXX")
	(cd "$dl" && run_logged "$dl/download.log" papt download "$@") || { rm -rf "$dl"; return 1; }
	mkdir -p "$dest"
	for deb in "$dl"/*.deb; do
		dpkg-deb -x "$deb" "$dest"
	done
	rm -rf "$dl"
}
