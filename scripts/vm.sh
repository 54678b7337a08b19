#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-only
#
# The prukit VM harness: boots Debian's own armmp kernels under QEMU (TCG,
# 2 CPUs) with a Debian armhf userland, prukit's modules for that kernel,
# its firmware, and the kernel's device tree of the board plus prukit's
# overlays: the board path - QEMU's vexpress-a15 with prukit's AM335x
# PRU-ICSS (pruss=on; qemu/am335x_pruss.c, built by scripts/qemu-build.sh),
# tests/vm/board/am335x-pruss.dtso, and the kernel's own PRU drivers pruss,
# irq_pruss_intc and pru_rproc (scripts/pru-kit.sh) under prukit's modules
# built as for a BeagleBone kernel (kernels.sh --board).
#
# The board is QEMU's vexpress-a15 rather than "virt": its RAM is at
# 0x80000000, where an AM335x has its DDR, so PRU firmware sees the ARM's
# buffers at the addresses it would on a BeagleBone.  That matters because
# virtio (rpmsg) puts CPU physical addresses into its descriptors, while on
# "virt" RAM at 0x40000000 would overlap what a PRU reaches at those
# addresses on an AM335x (GPIO banks at 0x44e07000, 0x4804c000, ...).
#
#   vm.sh run KVER SCRIPT [IN] [OUT]   (make vmrun)
#	Boot SERIES KVER (5.10, 6.1, 6.12, 5.10-ti, 6.12-ti: scripts/lib.sh
#	kernel_flavour), run SCRIPT as root in the guest
#	with /proc, /sys, /dev and debugfs mounted, prukit's modules loaded
#	and the host directory IN unpacked at /in (also the working directory);
#	copy the guest's /out to OUT; exit with the script's status.  With
#	PRUKIT_VM_OVERLAYS="a.dtso b.dtso" (make vmrun OVERLAY=...) those
#	overlays are built and applied after prukit's own.
#   vm.sh test [KVERS] [TESTS]         (make vmtest)
#	For each kernel (default: 6.12-ti 6.12 6.1 5.10-ti 6.1@thread, the
#	longest first; SERIES@thread and SERIES@lockstep are SERIES on that
#	clock whatever PRUKIT_VM_CLOCK says, SERIES@thread running
#	THREAD_TESTS), boot once and run the tests in tests/vm/cases and
#	drivers/<driver>/tests/vm/cases of drivers/registry's drivers (all,
#	or those named in TESTS), bring back
#	their logs and artifacts to out/vm/<kernel>/ and print "N passed, N
#	failed" per kernel and overall.  A test that leaves files for a
#	second boot (second_boot below) gets one, right after the first.
#	VM_JOBS kernels boot at once (default: one per host CPU).
#   vm.sh deb [KVER]                   (make vmdeb, default 6.1)
#	The Debian packages of make deb on a Debian root dpkg knows, booted
#	from a disk: installed with apt, DKMS building the modules in the
#	guest, the drivers run from the installed files, then removal and
#	purge (deb_test below; tests/vm/deb/guest).
#
# Either fails on any oops, BUG, WARN, lockdep report, hung task or
# poisoned page found written in the kernel log, on a register access the
# QEMU PRU-ICSS does not model (its log, -d unimp,guest_errors; the guest
# also fails the test that made it), and bounds every boot by a timeout
# (VM_TIMEOUT seconds).  PRUKIT_VM_APPEND adds to the guest kernel's
# command line (a debugging aid: e.g. "dyndbg=module prukit_pru +p").
# PRUKIT_VM_JITTER=SEED runs the simulated PRU-ICSS in slices of random
# length with random pauses (its jitter knob, Documentation/qemu-pruss.rst):
# the same seed, the same slices and pauses; "random" (the default) picks
# one; 0 is off.  Every boot prints its seed.  PRUKIT_VM_HOLD=taken (the
# default), serviced or none: how long an interrupt towards the ARM holds
# simulated time (until the ARM took its event, until it serviced it,
# never).  PRUKIT_VM_OCP_WRITE_DELAY=CYCLES (default 100): how long a PRU's
# store over the OCP master port takes to land in RAM (0: at once).
# PRUKIT_VM_DDR_JITTER=CYCLES (default 0): while the jitter seed is not 0,
# each DDR load or store of a PRU takes up to this many cycles longer.
# PRUKIT_VM_CLOCK=lockstep (the default) or thread: the simulated PRUs run
# in lockstep with the guest's virtual clock (QEMU's -icount shift=0: one
# ARM instruction a nanosecond, a PRU cycle every five; the vCPU and the
# PRUs take turns on one thread), so that a loaded host slows both alike,
# or on a thread of their own as fast as the host lets them, beside two
# vCPUs.  vm.sh deb always boots threaded (see deb_test).
# PRUKIT_QEMU=PATH boots another build of qemu-system-arm (one with
# pruss=on, e.g. to compare two builds' speed) instead of
# scripts/qemu-build.sh's.
set -euo pipefail
. "$(dirname "$0")/lib.sh"

need_pkgs device-tree-compiler cpio kmod tar sigrok-cli
. "$(dirname "$0")/papt.sh"

# One boot runs every VM test of a kernel: in lockstep about 15-19 minutes
# on the 2-core machine, two boots at a time, and a host whose CPUs are
# shared can take twice that (threaded boots, measured with 55% steal
# time: 6.12 took 749 s in its tests alone, about 8 minutes idle).  The
# bound is for a hung guest, not a slow one.
VM_TIMEOUT=${VM_TIMEOUT:-3600}
# What a threaded boot of make vmtest runs (SERIES@thread below), to keep
# the threaded clock that make bench and make vmdeb use working: the
# interrupts of a 10 us burst through the hold, and rpmsg.
THREAD_TESTS=${THREAD_TESTS:-10-boot 60-irq 65-pru-consumer 70-rpmsg-echo}
# A guest keeps about one host CPU busy, not two (a lockstep guest is one
# thread; a threaded 6.12 boot of every test used 1.1 CPUs on average), so vm.sh test
# boots as many kernels at once as the host has CPUs: on 2 CPUs, 5.10 and
# 6.1 together took 753 s where each alone takes about 700.
VM_JOBS=${VM_JOBS:-$(ncpus)}
VM_MEM=${VM_MEM:-1024}
VM_CPUS=${VM_CPUS:-2}
VMDIR=$PRUKIT_TOP/tests/vm
# The guest kernel's command line.  slub_debug=U has SLUB keep the call
# site of every live object in the caches the leak checks count
# (tests/vm/lib/leak.py), so a leak names where it was allocated, and what
# the kernel itself keeps on every probe (pinctrl-single's pin functions)
# is told from a driver's leak.  The call site is all they need: with
# stack_depot_disable=1 (5.12 on) SLUB keeps no whole stacks, whose pages
# the stack depot never gives back (a 6.1 run lost 40 KiB of free memory
# per display bind/unbind cycle to it).
# log_buf_len=1M: the tests and the splat check read the whole kernel log
# with dmesg, and some kernels keep little of it (5.10-ti's build: 16 KiB,
# which a boot of every test overflows; Debian's: 128 KiB).  printk.time=1:
# every kernel line carries its timestamp (5.10-ti's build has no
# PRINTK_TIME), which is how the splat check tells the kernel's lines from
# what the tests print on the same console.
cmdline="console=ttyAMA0 loglevel=5 panic=-1 rdinit=/init page_poison=1 log_buf_len=1M printk.time=1"
cmdline+=" slub_debug=U,kmalloc-*,kernfs_node_cache stack_depot_disable=1"
cmdline+=${PRUKIT_VM_APPEND:+ $PRUKIT_VM_APPEND}
# clock_args thread|lockstep - set machine and accel for a boot whose
# simulated PRUs run on their own thread, or in lockstep with the guest's
# virtual clock.  Lockstep boots one vCPU (an AM335x has one Cortex-A8):
# QEMU 7.2's -icount with two hangs the vexpress-a15's boot before its
# first console line (tried: shift 0 and auto, sleep on and off).
clock_args() {
	case $1 in
	thread)
		machine=(-smp "$VM_CPUS" -m "$VM_MEM" -nic none)
		accel=(-accel tcg,thread=multi)
		;;
	lockstep)
		machine=(-smp 1 -m "$VM_MEM" -nic none)
		accel=(-accel tcg,thread=single -icount shift=0,align=off,sleep=off)
		;;
	*) die "PRUKIT_VM_CLOCK=$1: thread or lockstep" ;;
	esac
}
clock_args "${PRUKIT_VM_CLOCK:-lockstep}"
jitter=${PRUKIT_VM_JITTER:-random}
if [ "$jitter" = random ]; then
	jitter=$(( (RANDOM << 15 | RANDOM) + 1 ))
fi
[[ "$jitter" =~ ^[0-9]{1,10}$ ]] && [ "$jitter" -le 4294967295 ] ||
	die "PRUKIT_VM_JITTER=$jitter: a seed from 0 (off) to 4294967295, or random"
case ${PRUKIT_VM_HOLD:-taken} in
serviced) hold_mode=0 ;;
taken) hold_mode=1 ;;
none) hold_mode=2 ;;
*) die "PRUKIT_VM_HOLD=$PRUKIT_VM_HOLD: serviced, taken or none" ;;
esac
ocp_write_delay=${PRUKIT_VM_OCP_WRITE_DELAY:-100}
[[ "$ocp_write_delay" =~ ^[0-9]{1,8}$ ]] && [ "$ocp_write_delay" -le 10000000 ] ||
	die "PRUKIT_VM_OCP_WRITE_DELAY=$ocp_write_delay: PRU cycles from 0 to 10000000"
ddr_jitter=${PRUKIT_VM_DDR_JITTER:-0}
[[ "$ddr_jitter" =~ ^[0-9]{1,5}$ ]] && [ "$ddr_jitter" -le 10000 ] ||
	die "PRUKIT_VM_DDR_JITTER=$ddr_jitter: PRU cycles from 0 to 10000"
# The board's sound device needs no host audio.
export QEMU_AUDIO_DRV=none

# Splats that fail a run wherever they appear in the kernel log.
# Guests boot with page_poison=1 (Debian's kernels have PAGE_POISONING):
# a write into a freed page is reported when the page is allocated again.
splat_re='Oops|BUG:|WARNING:|Unable to handle kernel|Kernel panic|INFO: task .* blocked|possible (recursive|circular) locking|UBSAN:|refcount_t:|list_(add|del) corruption|general protection|stack-protector|pagealloc: memory corruption|blocked for more than'

# The QEMU: Debian's 7.2 with prukit's PRU-ICSS (scripts/qemu-build.sh).
qemu=${PRUKIT_QEMU:-}
qemu_binary() {
	[ -n "$qemu" ] || qemu=$("$PRUKIT_TOP/scripts/qemu-build.sh") ||
		die "building qemu-system-arm failed"
}

# build_prukit SERIES - cross-build prukit's modules (as for a BeagleBone
# kernel, with the kernel's PRU drivers) and firmware for SERIES (no-ops
# when up to date) and set kver, kdir, kimage and tag (the name of its
# directories in out/kernels and out/vm: scripts/lib.sh kernel_tag).
# SERIES is one of Debian's (5.10, 6.1, 6.12) or a board's kernel (5.10-ti:
# BeagleBoard's whole; 6.12-ti: Debian's with TI's PRU drivers).
build_prukit() {
	local series=$1 line
	line=$("$PRUKIT_TOP/scripts/fetch-kernels.sh" --image "$series")
	read -r _ kver kdir _ kimage <<<"$line"
	tag=$(kernel_tag "$series" "$kver")
	"$PRUKIT_TOP/scripts/kernels.sh" --build-only --board "$series" >/dev/null ||
		die "building prukit for $series ($kver) failed (see out/kernels/$tag*/build.log)"
	make -s -C "$PRUKIT_TOP" firmware >/dev/null || die "make firmware failed"
	make -s -C "$PRUKIT_TOP" overlays >/dev/null || die "make overlays failed"
	# the tests' host halves decode the guest's pin traces with it
	make -s -C "$PRUKIT_TOP" tools >/dev/null || die "make tools (out/tools/prusim) failed"
	qemu_binary
}

# The device tree: the kernel's own vexpress-a15 tree, the simulated
# PRU-ICSS and board (tests/vm/board: the QEMU device's, with a BeagleBone
# tree's labels), the test-only nodes
# (tests/vm/overlays), then every overlay that "make overlays_install"
# ships for the Black, exactly those blobs, then the user's own overlays
# (make vmrun OVERLAY=...: space separated .dtso paths in
# $PRUKIT_VM_OVERLAYS).  QEMU adds its virtio-mmio nodes when it boots.
make_dtb() {
	local dir=$1 o name base board=$VMDIR/board/am335x-pruss.dtso
	mkdir -p "$dir"
	rm -f "$dir"/*.dtbo
	base=$(find "$kimage/usr/lib/linux-image-$kver" -name vexpress-v2p-ca15-tc1.dtb | head -n 1)
	[ -n "$base" ] || die "no vexpress-v2p-ca15-tc1.dtb in linux-image-$kver"
	local overlays=()
	"$PRUKIT_TOP/scripts/dtso-build.sh" "$board" "$dir/board.dtbo" ||
		die "cannot build overlay $board"
	overlays+=("$dir/board.dtbo")
	# Debian's dtbs carry no symbols: give the GIC its label, for the
	# board's interrupts (interrupt-parent = <&gic>).  BeagleBoard's trees
	# are built with dtc -@ (5.10-ti's has the label).
	cp "$base" "$dir/base.dtb"
	base=$dir/base.dtb
	fdtget -p "$base" /__symbols__ >/dev/null 2>&1 || fdtput -c "$base" /__symbols__
	[ "$(fdtget "$base" /__symbols__ gic 2>/dev/null)" = /interrupt-controller@2c001000 ] ||
		fdtput -t s "$base" /__symbols__ gic /interrupt-controller@2c001000
	for o in "$VMDIR"/overlays/*.dtso; do
		[ -e "$o" ] || continue
		# the package test's tree: the board and the package's overlays only
		[ -z "${VM_OVERLAY_DIR:-}" ] || continue
		name=$(basename "$o" .dtso)
		"$PRUKIT_TOP/scripts/dtso-build.sh" "$o" "$dir/$name.dtbo" ||
			die "cannot build overlay $o"
		overlays+=("$dir/$name.dtbo")
	done
	local src boards
	for o in "${VM_OVERLAY_DIR:-$PRUKIT_TOP/out/overlays}"/*.dtbo; do
		[ -e "$o" ] || die "no shipped overlays in ${VM_OVERLAY_DIR:-out/overlays} (make overlays)"
		# the simulated board is a Black: not the overlays made for
		# other boards only ("prukit-boards:" without am335x-boneblack)
		src=$PRUKIT_TOP/overlays/$(basename "$o" .dtbo).dtso
		boards=$(sed -n 's/^ \* prukit-boards://p' "$src" 2>/dev/null)
		[ -z "$boards" ] || [[ " $boards " == *" am335x-boneblack "* ]] || continue
		overlays+=("$o")
	done
	for o in ${PRUKIT_VM_OVERLAYS:-}; do
		name=user-$(basename "$o" .dtso)
		"$PRUKIT_TOP/scripts/dtso-build.sh" "$o" "$dir/$name.dtbo" ||
			die "cannot build overlay $o"
		overlays+=("$dir/$name.dtbo")
	done
	if ! fdtoverlay -i "$base" -o "$dir/merged.dtb" "${overlays[@]}" 2>"$dir/fdtoverlay.log"; then
		cat "$dir/fdtoverlay.log" >&2
		die "applying the overlays failed (a label the simulated board lacks?): ${overlays[*]##*/}"
	fi
	dtc -q -I dtb -O dtb -o "$dir/prukit.dtb" "$dir/merged.dtb"
	msg "device tree: ${overlays[*]##*/}"
}

# make_initrd DIR MODE SCRIPT_OR_TESTS - the userland plus an archive with
# the kernel's modules, its PRU drivers, prukit's modules and firmware, and
# the test harness.
make_initrd() {
	local dir=$1 mode=$2 arg=$3 stage=$1/stage rootfs m f d
	rootfs=$("$PRUKIT_TOP/scripts/vm-rootfs.sh")
	# deb and stage2 (deb_test, deb_root): the initramfs only finds the
	# Debian root on its disk; nothing of prukit's is in it
	local bare=0
	case $mode in deb | stage2) bare=1 ;; esac
	rm -rf "$stage"
	mkdir -p "$stage"/{prukit/tests,lib/firmware/prukit,lib/modules/"$kver"}

	local mods=$stage/lib/modules/$kver
	while read -r m; do
		case $m in '' | '#'*) continue ;; esac
		for f in "$kimage/lib/modules/$kver/kernel/$m".ko*; do
			[ -e "$f" ] || continue
			mkdir -p "$mods/kernel/$(dirname "$m")"
			cp "$f" "$mods/kernel/$(dirname "$m")/"
		done
	done <"$VMDIR/modules"
	cp "$kimage/lib/modules/$kver"/modules.{order,builtin,builtin.modinfo} "$mods/" 2>/dev/null || true
	mkdir -p "$mods/updates"
	# (a board's kernel, 5.10-ti, has its PRU drivers, rpmsg and counter in
	# its image: tests/vm/modules; no kit is built for it)
	for d in "$PRUKIT_TOP/out/kernels/$tag-board" "$PRUKIT_TOP/out/kernels/$tag-pru-kit" \
		"$PRUKIT_TOP/out/kernels/$tag-rpmsg-kit" "$PRUKIT_TOP/out/kernels/$tag-counter-kit"; do
		# bare: the kernel's PRU drivers (and rpmsg and counter), as a board's
		# kernel package has them, not prukit's modules - but PRCM's
		# stand-ins, which the board's tree needs (tests/kmod/prm_standin.c,
		# clkctrl_standin.c)
		if [ $bare = 1 ] && [ "$d" = "$PRUKIT_TOP/out/kernels/$tag-board" ]; then
			cp "$d/tests/kmod/prm_standin.ko" "$d/tests/kmod/clkctrl_standin.ko" \
				"$mods/updates/" ||
				die "no PRCM stand-ins for $kver (scripts/kernels.sh --board)"
			continue
		fi
		[ -d "$d" ] && find "$d" -name '*.ko' -exec cp -t "$mods/updates/" {} +
	done
	if [ $bare = 0 ] && [ ! -e "$mods/kernel/drivers/rpmsg/rpmsg_pru.ko" ]; then
		# A stand-in for TI's own rpmsg_pru where TI's kernels have it,
		# beside prukit's in updates/ (tests/vm/cases/71-rpmsg-ti-module);
		# 5.10-ti has TI's own (tests/vm/modules)
		mkdir -p "$mods/kernel/drivers/rpmsg"
		cp "$PRUKIT_TOP/out/kernels/$tag-board-ti/rpmsg_pru.ko" "$mods/kernel/drivers/rpmsg/" ||
			die "no stand-in for TI's rpmsg_pru (scripts/kernels.sh --board)"
	fi
	# as "make install" leaves a board: depmod with prukit's depmod.d
	[ $bare = 1 ] || make -s -C "$PRUKIT_TOP" depmod_install DESTDIR="$stage" >/dev/null ||
		die "make depmod_install failed"
	mkdir -p "$stage/lib/depmod.d"
	depmod -b "$stage" -C "$stage/lib/depmod.d" -e -E "$kdir/Module.symvers" "$kver" \
		2>"$dir/depmod.log"
	if grep -q 'needs unknown symbol' "$dir/depmod.log"; then
		cat "$dir/depmod.log" >&2
		die "modules for $kver have unresolved symbols"
	fi

	install -m 0755 "$VMDIR/init" "$stage/init"
	if [ $bare = 1 ]; then
		{
			echo "PRUKIT_MODE=$mode"
			echo "PRUKIT_MODULES='${PRUKIT_DEB_MODULES:-prm_standin clkctrl_standin pruss irq_pruss_intc pru_rproc}'"
			echo "PRUKIT_KVER='$kver'"
			echo "PRUKIT_SERIES='$series'"
		} >"$stage/prukit/config"
		[ "$mode" = deb ] && install -m 0755 "$arg" "$stage/prukit/script"
		(cd "$stage" && find . -print0 | cpio --null -o -H newc --quiet) >"$dir/prukit.cpio"
		cat_initrd "$rootfs" "$dir"
		return 0
	fi
	cp "$PRUKIT_TOP"/out/firmware/*.elf "$stage/lib/firmware/prukit/"
	# the shipped overlays' blobs, where make install and prukit-overlays put them
	# (the board's tree is merged here, make_dtb; the prukit command reads them)
	make -s -C "$PRUKIT_TOP" overlays_install DESTDIR="$stage" >/dev/null ||
		die "make overlays_install failed"
	install -m 0755 "$VMDIR/run-tests" "$stage/prukit/run-tests"
	# Every case, tests/vm/cases and the drivers' own, side by side.
	local all name path
	all=$(vm_cases) || die "VM test names must be unique"
	while read -r name path; do
		[ -z "$name" ] || install -m 0755 "$path" "$stage/prukit/tests/$name"
	done <<<"$all"
	[ -d "$VMDIR/lib" ] && cp -r "$VMDIR/lib" "$stage/prukit/lib"
	# and the drivers' guest libraries (drivers/<driver>/tests/vm/lib/*.py)
	local lib
	for lib in $(prukit_drivers | sed "s|.*|$PRUKIT_TOP/drivers/&/tests/vm/lib/*.py|"); do
		[ -e "$lib" ] || continue
		[ ! -e "$stage/prukit/lib/${lib##*/}" ] || die "guest library ${lib##*/} twice"
		install -m 0644 "$lib" "$stage/prukit/lib/"
	done
	# The udev rules and the servers, as make install puts them (udev runs
	# only when a test starts it: drivers/ws281x/tests/vm/cases/80-ws281x-cycles;
	# the servers too: drivers/beaglelogic/tests/vm/cases/82-beaglelogic)
	make -s -C "$PRUKIT_TOP" udev_install server_install tool_install modprobe_install \
		DESTDIR="$stage" >/dev/null ||
		die "make udev_install server_install tool_install modprobe_install failed"
	# Clients a user runs on the board, as shipped
	install -D -m 0755 "$PRUKIT_TOP/firmware/rpmsg-neopixel/rainbow.py" "$stage/prukit/bin/rainbow.py"
	# Senders for prukit-pixeld (tests/vm/cases/94-pixeld): PyPI's sacn, a
	# wheel the guest imports as it is, and ours for OPC and DDP
	install -m 0644 "$("$PRUKIT_TOP/scripts/sacn-wheel.sh")" "$stage/prukit/lib/" ||
		die "no sacn wheel (scripts/sacn-wheel.sh)"
	install -m 0644 "$PRUKIT_TOP/tools/pixeld/tests/pixel_send.py" "$stage/prukit/lib/"
	{
		echo "PRUKIT_MODE=$mode"
		echo "PRUKIT_MODULES='$PRUKIT_VM_MODULES'"
		[ "$mode" = test ] && echo "PRUKIT_TESTS='$arg'"
		echo "PRUKIT_KVER='$kver'"
		echo "PRUKIT_SERIES='$series'"
	} >"$stage/prukit/config"
	[ "$mode" = run ] && install -m 0755 "$arg" "$stage/prukit/script"

	(cd "$stage" && find . -print0 | cpio --null -o -H newc --quiet) >"$dir/prukit.cpio"
	cat_initrd "$rootfs" "$dir"
}

# cat_initrd ROOTFS DIR - DIR/initrd: the userland's cpio, then DIR/prukit.cpio.
# The kernel takes an uncompressed cpio after a compressed one only at a
# 4-byte aligned offset (init/initramfs.c); zeros in between are skipped.
# Without the padding a rootfs of the wrong length boots into "Initramfs
# unpacking failed: invalid magic".
cat_initrd() {
	local pad=$(( (4 - $(stat -c %s "$1") % 4) % 4 ))
	{ cat "$1"; head -c "$pad" /dev/zero; cat "$2/prukit.cpio"; } >"$2/initrd"
}

# boot DIR IN OUT - boot the prepared kernel; console to DIR/console.log,
# the QEMU PRU-ICSS's log of unmodelled accesses to DIR/qemu.log.
# Returns the guest's exit status (or 124 on timeout, 125 without one).
# Two disks carry the files: IN as a tar exactly its own size (busybox
# tar reads an archive to the end of its device, which on one 256 MiB disk
# for both directions cost the guest about 40 s per boot), and an empty
# 256 MiB one the guest writes /out onto.
boot() {
	local dir=$1 in=$2 out=$3 indisk=$1/in.tar outdisk=$1/out.img rc name
	local board=(-M vexpress-a15,pruss=on -d unimp,guest_errors -D "$dir/qemu.log"
		-global "am335x-pruss.jitter-seed=$jitter"
		-global "am335x-pruss.hold-mode=$hold_mode"
		-global "am335x-pruss.ocp-write-delay=$ocp_write_delay"
		-global "am335x-pruss.ddr-jitter=$ddr_jitter")
	name=${dir##*/}
	[ "$name" != boot2 ] || name="$(basename "$(dirname "$dir")") (second boot)"
	[ "$jitter" = 0 ] ||
		msg "$name: the PRU-ICSS's jitter seed: $jitter (again: PRUKIT_VM_JITTER=$jitter)"
	[ "${accel[2]:-}" != -icount ] ||
		msg "$name: the PRUs in lockstep with the guest's virtual clock (${accel[*]:2}, one vCPU)"
	rm -f "$dir/qemu.log"
	rm -f "$indisk" "$outdisk"
	if [ -n "$in" ]; then
		tar -cf "$indisk" -C "$in" .
	else
		tar -cf "$indisk" -T /dev/null
	fi
	truncate -s 256M "$outdisk"

	# errexit off for the pipeline, then back as the caller had it: a
	# plain "set -e" here would turn it on in callers that turned it off.
	local start=$(date +%s) errexit=${-//[^e]/}
	set +e
	timeout --foreground "$VM_TIMEOUT" "$qemu" "${board[@]}" "${machine[@]}" \
		"${accel[@]}" -nographic -no-reboot \
		-kernel "$kimage/boot/vmlinuz-$kver" -initrd "$dir/initrd" \
		-dtb "$dir/dtb/prukit.dtb" \
		-append "$cmdline" \
		-drive if=none,file="$indisk",format=raw,id=in,readonly=on \
		-device virtio-blk-device,drive=in,serial=prukit-in \
		-drive if=none,file="$outdisk",format=raw,id=out \
		-device virtio-blk-device,drive=out,serial=prukit-out \
		${VM_ROOTDISK:+-drive if=none,file="$VM_ROOTDISK",format=raw,id=root,snapshot=${VM_ROOTDISK_SNAPSHOT:-on}} \
		${VM_ROOTDISK:+-device virtio-blk-device,drive=root,serial=prukit-root} \
		</dev/null 2>&1 | tee "$dir/console.log" | sed -n '/^prukit-vm:/,$p'
	rc=${PIPESTATUS[0]}
	[ -z "$errexit" ] || set -e
	echo "$(( $(date +%s) - start ))" >"$dir/seconds"

	rm -rf "$out"
	mkdir -p "$out"
	tar -xf "$outdisk" -C "$out" 2>/dev/null || true
	rm -f "$indisk" "$outdisk"

	if [ "$rc" -eq 124 ]; then
		echo "FAIL: $kver: no result within ${VM_TIMEOUT} s"
		return 124
	fi
	rc=$(sed -n 's/^PRUKIT-VM-EXIT \([0-9]*\).*/\1/p' "$dir/console.log" | tail -n 1)
	if [ -z "$rc" ]; then
		echo "FAIL: $kver: the guest did not finish (see $dir/console.log)"
		return 125
	fi
	return "$rc"
}

# kernel_log_clean DIR OUT [WHICH] - fail on any splat in the console or
# dmesg, and on anything the QEMU PRU-ICSS logged (an access it does not
# model, a PRU the simulator stopped: DIR/qemu.log) but what a test said it
# makes on purpose (OUT/<test>/model-log-expected).  WHICH ("second boot: ")
# goes into the result's name.
kernel_log_clean() {
	local dir=$1 out=$2 which=${3:-} hits
	local log
	# Only what the kernel wrote: its lines carry a timestamp, on the
	# console from where it starts (a test's own output without a newline
	# may come first on the line).  What a test prints ("PASS: dmesg: no
	# Oops/BUG/WARNING") is not a splat.
	log=$(cat "$dir/console.log" "$out/dmesg.txt" 2>/dev/null | tr -d '\r' |
		grep -oE '\[ *[0-9]+\.[0-9]+\] .*' || true)
	hits=$(grep -E "$splat_re" <<<"$log" | sort -u || true)
	# 5.10 parses page_poison=1 by enabling a static key before
	# jump_label_init(), which WARNs at boot (later kernels enable it
	# after); poisoning works all the same.  That one splat, and only with
	# that backtrace, is not ours.
	# (Here-strings, not "printf | grep -q": with pipefail, grep -q leaving
	# early fails the pipeline.)
	if grep -q 'from \[<[0-9a-f]*>\] (early_page_poison_param' <<<"$log"; then
		hits=$(grep -v 'WARNING: CPU: 0 PID: 0 at kernel/jump_label.c:[0-9]* static_key_enable_cpuslocked' \
			<<<"$hits" || true)
	fi
	if [ -n "$hits" ]; then
		printf '%s\n' "$hits" | head -n 20
		echo "FAIL: $kver: ${which}kernel log clean (oops/BUG/WARN/lockdep/hung task/page corruption)"
		return 1
	fi
	# (QEMU's own boards log there too: vexpress probes devices it lacks)
	# The PRU-ICSS's blocks log "am335x-pruss: ..."; the rest of the L4
	# interconnects are QEMU's unimplemented devices "am335x.l4_*".
	hits=$(grep -E '^(am335x-pruss: |am335x\.l4_[a-z]+: unimplemented )' "$dir/qemu.log" 2>/dev/null || true)
	# A test that makes the model log on purpose (a PRU it stops) says so
	# in OUT/<test>/model-log-expected: "COUNT TEXT" per line, COUNT lines
	# with TEXT in them, exactly; those lines are its, the rest are not.
	local f n text got
	for f in "$out"/*/model-log-expected; do
		[ -e "$f" ] || continue
		while read -r n text; do
			got=$(grep -cF -- "$text" <<<"$hits" || true)
			if [ "$got" != "$n" ]; then
				echo "FAIL: $kver: ${which}kernel log clean, but the PRU-ICSS model logged \"$text\" $got time(s), $n expected (${f#"$out"/})"
				return 1
			fi
			hits=$(grep -vF -- "$text" <<<"$hits" || true)
		done <"$f"
	done
	if [ -n "$hits" ]; then
		sort <<<"$hits" | uniq -c | sort -rn | head -n 20
		echo "FAIL: $kver: ${which}kernel log clean, but the PRU-ICSS model logged $(wc -l <<<"$hits") line(s) ($dir/qemu.log)"
		return 1
	fi
	echo "PASS: $kver: ${which}kernel log clean (no oops, BUG, WARN, lockdep, hung task or page corruption)"
}

# second_boot DIR - boot the kernel of DIR again for the tests that left
# DIR/out/<test>/next-boot.tar: a tar of files (relative to /) that the
# guest's init lays over the root before any module loads, as a board's disk
# keeps what the first boot wrote; then only those tests run, with
# PRUKIT_BOOT=2 (tests/vm/init).  Console and artifacts in DIR/boot2/.
second_boot() {
	local dir=$1 b=$1/boot2 f t
	rm -rf "$b"
	for f in "$dir"/out/*/next-boot.tar; do
		[ -e "$f" ] || continue
		t=${f%/next-boot.tar}
		mkdir -p "$b/in/next-boot"
		cp "$f" "$b/in/next-boot/${t##*/}.tar"
	done
	[ -d "$b" ] || return 0
	ln -s ../initrd "$b/initrd"
	ln -s ../dtb "$b/dtb"
	boot "$b" "$b/in" "$b/out"
	kernel_log_clean "$b" "$b/out" "second boot: "
}

# Loaded in this order at boot (no udev loads them): PRCM's stand-in
# (without it ti-sysc defers the PRU-ICSS's target module for ever), the
# kernel's PRU drivers (modprobe.d/prukit.conf brings prukit_pru with
# pru_rproc), the rpmsg transport and rpmsg_pru and the simulator's test
# port.  Not the test consumer: it holds PRU0 as a prukit driver does,
# which locks PRU0's remoteproc sysfs files; the tests that use it load it
# (consumer_load).
PRUKIT_VM_MODULES=${PRUKIT_VM_MODULES:-prm_standin clkctrl_standin pruss irq_pruss_intc pru_rproc virtio_rpmsg_bus rpmsg_pru prusim_port}

# The package test's Debian root (deb_root): bookworm armhf, minbase, with
# what the packages need on a board and the kernel headers' dependencies.
DEB_ROOT_PKGS=busybox-static,apt,adduser,kmod,python3,dkms,gcc,make,linux-compiler-gcc-12-arm,libelf1,libssl3
DEB_ROOT_SIZE=3G

# The armhf ELF entry deb_root registers in binfmt_misc when none runs
# armhf programs yet: Debian's qemu-arm entry (qemu-user-static's
# /usr/lib/binfmt.d/qemu-arm.conf) under prukit's name.  F: the kernel
# opens the interpreter at registration, so it runs inside a chroot.
BINFMT_MISC=/proc/sys/fs/binfmt_misc
BINFMT_ARMHF=':prukit-armhf:M::\x7f\x45\x4c\x46\x01\x01\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\x02\x00\x28\x00:\xff\xff\xff\xff\xff\xff\xff\x00\xff\xff\xff\xff\xff\xff\xff\xff\xfe\xff\xff\xff:/usr/libexec/qemu-binfmt/arm-binfmt-P:OPF'

# stage2_host ROOT LOG - debootstrap's second stage in a chroot here, its
# armhf programs run by qemu-user (Debian's qemu-user-static) through
# binfmt_misc: about 2.5 minutes, against 7 in the VM.  Returns 2, before
# it touches ROOT, where it cannot run: not root, binfmt_misc neither
# mounted nor mountable, no entry registrable, or PRUKIT_DEB_STAGE2=vm.
# An entry it registered is removed afterwards (binfmt_misc is the
# kernel's, not this container's); one left by a killed run names only
# qemu-user-static's interpreter.
stage2_host() {
	local root=$1 log=$2 reg='' rc=0
	[ "${PRUKIT_DEB_STAGE2:-}" != vm ] && [ "$(id -u)" -eq 0 ] || return 2
	if [ ! -e "$BINFMT_MISC/register" ]; then
		mount -t binfmt_misc binfmt_misc "$BINFMT_MISC" 2>/dev/null || return 2
	fi
	need_pkgs qemu-user-static
	if ! chroot "$root" /bin/true 2>/dev/null; then
		[ ! -e "$BINFMT_MISC/prukit-armhf" ] || echo -1 >"$BINFMT_MISC/prukit-armhf"
		printf '%s\n' "$BINFMT_ARMHF" >"$BINFMT_MISC/register" 2>/dev/null || return 2
		reg=$BINFMT_MISC/prukit-armhf
		chroot "$root" /bin/true >"$log" 2>&1 || rc=1
	fi
	if [ $rc -eq 0 ]; then
		msg "second stage here, armhf under qemu-user (once)"
		chroot "$root" /debootstrap/debootstrap --second-stage >"$log" 2>&1 &&
			chroot "$root" apt-get clean >>"$log" 2>&1 || rc=1
	fi
	[ -z "$reg" ] || echo -1 >"$reg"
	# debootstrap unmounts the /proc and /sys it mounted; make sure, as
	# the tree is copied into an image and removed next
	! grep -q " $root/" /proc/self/mounts ||
		die "mounts left under $root after debootstrap's second stage: $(grep " $root/" /proc/self/mounts)"
	return $rc
}

# deb_root - print the path of a raw ext4 image holding a Debian root that
# dpkg knows: debootstrap's first stage (it only downloads and unpacks),
# then its second stage - every package's maintainer scripts - here under
# qemu-user (stage2_host) or, where that cannot run, in the VM on the
# kernel build_prukit set.  Cached in $PRUKIT_CACHE/vm by the package
# list; boots use it read-only (qemu's snapshot=on).
deb_root() {
	local key img tmp dir rc=0 t0
	key=$(echo "$DEB_ROOT_PKGS $DEB_ROOT_SIZE 1" | sha256sum | cut -c1-12)
	img=$PRUKIT_CACHE/vm/debroot-$key.img
	if [ ! -e "$img" ]; then
		need_pkgs debootstrap e2fsprogs
		mkdir -p "$PRUKIT_CACHE/vm"
		tmp=$(mktemp -d "$PRUKIT_CACHE/vm/debroot.XXXXXX")
		msg "building the package test's Debian root (bookworm armhf minbase: $DEB_ROOT_PKGS): first stage"
		run_logged "$tmp/first.log" debootstrap --foreign --arch=armhf --variant=minbase \
			--include="$DEB_ROOT_PKGS" bookworm "$tmp/root" "$(debian_mirror)"
		t0=$(date +%s)
		stage2_host "$tmp/root" "$tmp/second.log" || rc=$?
		if [ "$rc" -ne 0 ] && [ "$rc" -ne 2 ]; then
			tail -n 20 "$tmp/second.log" >&2 || true
			die "debootstrap's second stage failed under qemu-user; see $tmp/second.log"
		fi
		truncate -s "$DEB_ROOT_SIZE" "$tmp/root.img"
		mkfs.ext4 -q -F -L prukit-root -d "$tmp/root" "$tmp/root.img" ||
			die "mkfs.ext4 -d $tmp/root failed"
		rm -rf "$tmp/root"
		if [ "$rc" -eq 2 ]; then
			rc=0
			msg "no chroot with qemu-user here (root and binfmt_misc needed): the second stage runs in the VM"
			dir=$PRUKIT_TOP/out/vm/$tag/stage2
			rm -rf "$dir"
			mkdir -p "$dir"
			make_dtb "$dir/dtb"
			make_initrd "$dir" stage2 ""
			msg "second stage in the VM ($kver; several minutes, once)"
			VM_ROOTDISK=$tmp/root.img VM_ROOTDISK_SNAPSHOT=off boot "$dir" "" "$dir/out" >&2 || rc=$?
			if [ "$rc" -ne 0 ]; then
				tail -n 20 "$dir/out/stage2.log" >&2 || true
				rm -rf "$tmp"
				die "debootstrap's second stage failed in the VM (exit $rc); see $dir/console.log"
			fi
		fi
		mv "$tmp/root.img" "$img"
		rm -rf "$tmp"
		msg "package test root: $img (second stage $(( $(date +%s) - t0 )) s)"
	fi
	echo "$img"
}

# kernel_header_debs DIR - the armhf .debs of linux-headers-$kver, its
# -common package and linux-kbuild, into DIR (cached per kernel).
kernel_header_debs() {
	local d=$PRUKIT_CACHE/vm/headers-$kver pkgs deps x
	if [ ! -e "$d/.complete" ]; then
		papt_init
		pkgs=("linux-headers-$kver:armhf")
		deps=$(pcache show --no-all-versions "linux-headers-$kver:armhf" |
			sed -n 's/^Depends: //p' | tr ',' '\n' |
			sed -n 's/^ *\(linux-\(headers\|kbuild\)-[^ ]*\).*/\1/p')
		for x in $deps; do
			case $x in linux-kbuild-*) pkgs+=("$x:armhf") ;; *) pkgs+=("$x") ;; esac
		done
		rm -rf "$d"
		mkdir -p "$d"
		(cd "$d" && run_logged "$d/download.log" papt download "${pkgs[@]}") ||
			die "downloading ${pkgs[*]} failed"
		touch "$d/.complete"
	fi
	mkdir -p "$1"
	cp "$d"/*.deb "$1/"
}

# deb_test SERIES - prukit's Debian packages (make deb) installed, used,
# removed and purged on a Debian root dpkg knows, booted from its disk
# (tests/vm/deb/guest says what is checked).  The device tree takes the
# .dtbo files of the prukit-overlays package, as U-Boot would apply them.
deb_test() {
	local series=$1 dir rootimg rc=0
	build_prukit "$series"
	dir=$PRUKIT_TOP/out/vm/$tag/deb
	rm -rf "$dir"
	mkdir -p "$dir/in/debs" "$dir/ovl"
	# the packages of this tree, and the same under an older version for
	# the upgrade (0.1.0~old1 sorts before 0.1.0)
	# (into DIR, so that make deb's out/deb and its lintian.log stay as they were)
	PRUKIT_DEB_OUT=$dir/new "$PRUKIT_TOP/scripts/deb.sh" >"$dir/deb.log" 2>&1 ||
		{ tail -n 20 "$dir/deb.log"; die "make deb failed"; }
	PRUKIT_DEB_VERSION=$(make -s -C "$PRUKIT_TOP" version)~old1 PRUKIT_DEB_OUT=$dir/old \
		"$PRUKIT_TOP/scripts/deb.sh" >"$dir/deb-old.log" 2>&1 ||
		{ tail -n 20 "$dir/deb-old.log"; die "make deb of the older version failed"; }
	mkdir -p "$dir/in/debs/new" "$dir/in/debs/old"
	cp "$dir"/new/*.deb "$dir/in/debs/new/"
	cp "$dir"/old/*.deb "$dir/in/debs/old/"
	kernel_header_debs "$dir/in/headers"
	cp "$PRUKIT_TOP/tests/tool/uEnv-beagleboard.txt" "$dir/in/uEnv.txt"
	dpkg-deb -x "$dir"/new/prukit-overlays_*_all.deb "$dir/ovl"
	VM_OVERLAY_DIR=$dir/ovl/lib/firmware make_dtb "$dir/dtb"
	rootimg=$(deb_root)
	make_initrd "$dir" deb "$VMDIR/deb/guest"
	msg "package test: booting $kver from $rootimg"
	VM_ROOTDISK=$rootimg boot "$dir" "$dir/in" "$dir/out" || rc=$?
	kernel_log_clean "$dir" "$dir/out" || rc=1
	msg "package test: $kver, guest exit status $rc, $(cat "$dir/seconds") s"
	return "$rc"
}

cmd=${1:-}
shift || true
case $cmd in
deb)
	# Threaded whatever PRUKIT_VM_CLOCK says: DKMS builds every module in
	# the guest twice, on both vCPUs, and the test is of the packages,
	# not of the PRUs' timing (make vmtest's boots are lockstep).
	clock_args thread
	deb_test "${1:-6.1}"
	;;
run)
	series=${1:?usage: vm.sh run KVER SCRIPT [IN] [OUT]}
	script=${2:?usage: vm.sh run KVER SCRIPT [IN] [OUT]}
	in=${3:-}
	[ -z "$in" ] || in=$(cd "$in" && pwd)
	out=${4:-$PRUKIT_TOP/out/vmrun}
	[ -f "$script" ] || die "no such script: $script"
	build_prukit "$series"
	dir=$PRUKIT_TOP/out/vm/$tag/run
	mkdir -p "$dir"
	make_dtb "$dir/dtb"
	make_initrd "$dir" run "$(cd "$(dirname "$script")" && pwd)/$(basename "$script")"
	set +e
	boot "$dir" "$in" "$out" >&2
	rc=$?
	kernel_log_clean "$dir" "$out" >&2 || rc=1
	set -e
	msg "vmrun: $kver, script exit status $rc, $(cat "$dir/seconds") s; /out in $out"
	exit "$rc"
	;;
test)
	# SERIES@thread: that kernel booted with the PRUs on their own
	# thread (clock_args), running THREAD_TESTS (or the TESTS asked for);
	# SERIES@lockstep: in lockstep, running every test.  The longest
	# boots first, so that the last VM_JOBS end close together.
	kvers=${1:-6.12-ti 6.12 6.1 5.10-ti 6.1@thread}
	tests=${2:-}
	# tests/vm/cases and every driver's drivers/<driver>/tests/vm/cases
	# (scripts/lib.sh), all in the same boot.
	cases=$(vm_cases) || die "VM test names must be unique"
	for t in $tests $THREAD_TESTS; do
		awk -v t="$t" '$1 == t { f = 1 } END { exit !f }' <<<"$cases" || die "no VM test $t"
	done
	# A test that checks what only lockstep does says so in a line
	# "# prukit-vm: clock lockstep": a threaded boot runs it only if asked.
	all_tests= lockstep_only=
	while read -r t path; do
		if grep -q '^# prukit-vm: clock lockstep' "$path"; then
			lockstep_only+=" $t"
		else
			all_tests+=" $t"
		fi
	done <<<"$cases"
	[ -n "$all_tests" ] || die "no VM tests in tests/vm/cases or drivers/*/tests/vm/cases"
	# Every kernel's builds, device trees and initrds first, one at a time
	# (builds use every CPU), then the boots, VM_JOBS at once, each into
	# its directory's results; then, kernel by kernel, the host halves
	# and the results.
	declare -A kver_of kimage_of dir_of clock_of tests_of
	for series in $kvers; do
		clock=${PRUKIT_VM_CLOCK:-lockstep}
		case $series in
		*@thread | *@lockstep) clock=${series#*@} ;;
		*@*) die "$series: a kernel, a kernel@thread or a kernel@lockstep" ;;
		esac
		build_prukit "${series%@*}"
		kver_of[$series]=$kver
		kimage_of[$series]=$kimage
		dir=$PRUKIT_TOP/out/vm/$tag
		[ "$series" = "${series%@*}" ] || dir+=-$clock
		dir_of[$series]=$dir
		clock_of[$series]=$clock
		if [ -n "$tests" ]; then
			tests_of[$series]=$tests
		elif [ "${series%@thread}" != "$series" ]; then
			tests_of[$series]=$THREAD_TESTS
		elif [ "$clock" = lockstep ]; then
			tests_of[$series]="${all_tests# }$lockstep_only"
		else
			tests_of[$series]=${all_tests# }
		fi
		mkdir -p "$dir"
		make_dtb "$dir/dtb"
		make_initrd "$dir" test "${tests_of[$series]}"
	done
	running=0
	for series in $kvers; do
		if [ "$running" -ge "$VM_JOBS" ]; then
			wait -n || true
			running=$((running - 1))
		fi
		kver=${kver_of[$series]}
		kimage=${kimage_of[$series]}
		dir=${dir_of[$series]}
		msg "vmtest: booting $series ($kver)"
		rm -rf "$dir/results" "$dir/seconds" "$dir/boot2"
		(
			set +e
			clock_args "${clock_of[$series]}"
			boot "$dir" "" "$dir/out" >"$dir/results"
			kernel_log_clean "$dir" "$dir/out" >>"$dir/results"
			second_boot "$dir" >>"$dir/results"
			exit 0
		) &
		running=$((running + 1))
	done
	wait
	total_p=0
	total_f=0
	for series in $kvers; do
		kver=${kver_of[$series]}
		dir=${dir_of[$series]}
		label=$series
		res=$dir/results
		# kernel_log_clean's line comes last: without it the boot's
		# results are not all there.
		grep -qF ": $kver: kernel log clean" "$res" 2>/dev/null ||
			echo "FAIL: $kver: the boot left no complete results (see $dir/console.log)" >>"$res"
		[ ! -d "$dir/boot2" ] || grep -qF ": $kver: second boot: kernel log clean" "$res" ||
			echo "FAIL: $kver: the second boot left no complete results (see $dir/boot2/console.log)" >>"$res"
		# Host halves of tests, on what the guest brought back: each beside
		# its case's cases/ directory, in host/ (vm_host_half).
		for t in ${tests_of[$series]}; do
			host=$(awk -v t="$t" '$1 == t { print $2 }' <<<"$cases")
			[ -n "$host" ] || continue
			host=$(vm_host_half "$host")
			[ -x "$host" ] || continue
			if [ -d "$dir/out/$t" ]; then
				hrc=0
				"$host" "$dir/out/$t" >>"$res" 2>&1 || hrc=$?
				[ "$hrc" -eq 0 ] ||
					echo "FAIL: $t: host half exited with status $hrc" >>"$res"
			else
				echo "FAIL: $t: no artifacts came back for its host half" >>"$res"
			fi
		done
		grep -E '^(PASS|FAIL):' "$res" | sed "s|^\(PASS\|FAIL\): |\1: $label: |"
		p=$(grep -c '^PASS:' "$res" || true)
		f=$(grep -c '^FAIL:' "$res" || true)
		secs="$(cat "$dir/seconds" 2>/dev/null || echo '?') s (boot and tests)"
		[ ! -e "$dir/boot2/seconds" ] || secs="$secs + $(cat "$dir/boot2/seconds") s (second boot)"
		echo "$label ($kver): $p passed, $f failed, $secs"
		total_p=$((total_p + p))
		total_f=$((total_f + f))
	done
	echo "$total_p passed, $total_f failed"
	[ "$total_f" -eq 0 ]
	;;
log-check)
	# vm.sh log-check DIR OUT: the splat check alone, on a boot's
	# console.log and qemu.log in DIR and its dmesg.txt in OUT
	# (tests/harness/splat.sh)
	kver=log-check
	kernel_log_clean "${1:?usage: vm.sh log-check DIR OUT}" "${2:?usage: vm.sh log-check DIR OUT}"
	;;
*)
	die "usage: vm.sh run KVER SCRIPT [IN] [OUT] | vm.sh test [KVERS] [TESTS] | vm.sh deb [KVER] | vm.sh log-check DIR OUT"
	;;
esac
