#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# Print the directory holding pru-gcc (the "bin" directory), building it first
# if needed.  A pru-gcc already on PATH (gcc-pru on a BeagleBone image) wins.
# Otherwise binutils, gcc (C only), newlib and libgcc for --target=pru are
# built from Debian's binutils-source, gcc-12-source and newlib-source into
# $PRUKIT_CACHE/pru-toolchain-<versions>, once (about 20 minutes on 2 cores).
set -euo pipefail
. "$(dirname "$0")/lib.sh"

if [ -z "${PRUKIT_BOOTSTRAP_PRU_GCC:-}" ] && command -v pru-gcc >/dev/null 2>&1; then
	dirname "$(command -v pru-gcc)"
	exit 0
fi

# Not on a board: building GCC there takes hours (and more memory than a
# 512 MB board has).  PRUKIT_HOST_MACHINE stands for uname -m (tests).
case ${PRUKIT_HOST_MACHINE:-$(uname -m)} in
arm* | aarch64)
	[ -n "${PRUKIT_BOOTSTRAP_PRU_GCC:-}" ] ||
		die "no pru-gcc on this ARM machine, and building one here takes hours: install BeagleBoard's gcc-pru (sudo apt install gcc-pru, from BeagleBoard's package repository, which their images use), or install the prebuilt firmware (the prukit-firmware package, built on a PC with make deb); PRUKIT_BOOTSTRAP_PRU_GCC=1 builds it here anyway"
	;;
esac

need_pkgs binutils-source gcc-12-source newlib-source build-essential \
	libgmp-dev libmpfr-dev libmpc-dev flex bison texinfo xz-utils patch

bu_tar=$(ls /usr/src/binutils/binutils-*.tar.xz)
gcc_tar=$(ls /usr/src/gcc-12/gcc-*-dfsg.tar.xz)
nl_tar=$(ls /usr/src/newlib/newlib-*.tar.xz)
bu_ver=$(basename "$bu_tar" .tar.xz)
gcc_ver=$(basename "$gcc_tar" -dfsg.tar.xz)
nl_ver=$(basename "$nl_tar" .tar.xz)

prefix=$PRUKIT_CACHE/pru-toolchain-$gcc_ver-$bu_ver-$nl_ver
# One bootstrap at a time: it rebuilds in one shared directory, so a second
# caller waits here for the first one and then finds the toolchain built.
mkdir -p "$PRUKIT_CACHE"
exec 9>"$PRUKIT_CACHE/pru-toolchain.lock"
flock 9
if [ -x "$prefix/bin/pru-gcc" ] && [ -e "$prefix/.complete" ]; then
	echo "$prefix/bin"
	exit 0
fi

build=$PRUKIT_CACHE/build/pru-toolchain
rm -rf "$build" "$prefix"
mkdir -p "$build"
jobs=$(ncpus)
export PATH=$prefix/bin:$PATH
# The tools themselves (not what they compile) are built without debug
# information and at -O1: the build is dominated by compiling gcc's own
# huge generated sources, and a cold make check must fit in its budget.
# What pru-gcc generates does not depend on how pru-gcc was compiled;
# libgcc and newlib keep their own target flags (-O2).
export CFLAGS="-O1 -g0" CXXFLAGS="-O1 -g0"
start=$(date +%s)
stage() { msg "pru toolchain: $* ($(( $(date +%s) - start )) s)"; }

stage "1/5 binutils ($bu_ver)"
tar -C "$build" -xJf "$bu_tar"
mkdir -p "$build/b-binutils"
(cd "$build/b-binutils" &&
	run_logged ../binutils-configure.log "../$bu_ver/configure" --target=pru \
		--prefix="$prefix" --disable-nls --disable-werror --disable-gdb \
		--disable-gdbserver --disable-sim --disable-gprofng &&
	run_logged ../binutils-build.log make -j"$jobs" &&
	run_logged ../binutils-install.log make install)

stage "2/5 gcc, C only ($gcc_ver)"
tar -C "$build" -xJf "$gcc_tar"
gsrc=$build/$gcc_ver
# Debian's DFSG tarball lacks the GFDL manuals; this patch lets the build run without them.
(cd "$gsrc" && run_logged ../gcc-patch.log patch -p2 -i /usr/src/gcc-12/patches/gcc-gfdl-build.diff)
mkdir -p "$build/b-gcc"
(cd "$build/b-gcc" &&
	run_logged ../gcc-configure.log "$gsrc/configure" --target=pru --prefix="$prefix" \
		--enable-languages=c --with-newlib --without-headers --disable-nls \
		--disable-libssp --disable-shared --disable-threads --disable-lto \
		--disable-plugin --disable-libcc1 --disable-libquadmath --disable-libgomp &&
	run_logged ../gcc-build.log make -j"$jobs" all-gcc &&
	run_logged ../gcc-install.log make install-gcc)

stage "3/5 newlib ($nl_ver)"
tar -C "$build" -xJf "$nl_tar"
mkdir -p "$build/b-newlib"
(cd "$build/b-newlib" &&
	run_logged ../newlib-configure.log ../newlib-salsa/configure --target=pru \
		--prefix="$prefix" --disable-nls &&
	run_logged ../newlib-build.log make -j"$jobs" &&
	run_logged ../newlib-install.log make install)

stage "4/5 libgcc"
(cd "$build/b-gcc" &&
	run_logged ../libgcc-build.log make -j"$jobs" all-target-libgcc &&
	run_logged ../libgcc-install.log make install-target-libgcc)

stage "5/5 smoke test"
printf 'int main(void) { return 0; }\n' >"$build/t.c"
run_logged "$build/smoke.log" "$prefix/bin/pru-gcc" -O2 -o "$build/t.elf" "$build/t.c"
touch "$prefix/.complete"
rm -rf "$build"
stage "done, installed in $prefix"
echo "$prefix/bin"
