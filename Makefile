# SPDX-License-Identifier: GPL-2.0-only
#
# prukit: BeagleBone PRU devices for Linux.  See README.md.
#
# The module list lives in Kbuild; this file drives kbuild and everything
# else.  Entry points (stable names):
#   make / make modules   modules against KDIR (default: the running kernel)
#   make install          modules, PRU firmware, overlays, udev rule, uapi headers,
#                         servers (beaglelogic-tcpd, prukit-pixeld) and their systemd
#                         units, prukit-pixeld's configuration (kept if there is one)
#   make kernels          cross-build for Debian armmp 5.10, 6.1, 6.12 (W=1, sparse),
#                         as Debian ships them and with the kernel's own PRU drivers,
#                         and for the kernels boards run: 5.10-ti, 6.12-ti [KVERS=...]
#   make firmware         PRU firmware (bootstraps pru-gcc if none on PATH)
#   make overlays         device-tree overlays (out/overlays/*.dtbo), build only;
#                         make check validates them (scripts/overlays.sh --check)
#   make tools            host tools (prusim)
#   make kunit            KUnit suites on UML with KASAN and lockdep
#   make vmtest           VM tests on 6.12-ti, 6.12, 6.1, 5.10-ti with the PRUs in lockstep
#                         with the guest's clock, and a few on 6.1 with them on their own
#                         thread [KVERS=...] [TESTS=...]: the kernel's own PRU drivers on
#                         the QEMU PRU-ICSS; any of 5.10 6.1 6.12 5.10-ti 6.12-ti
#                         (Documentation/kernels.rst), each also as SERIES@thread or
#                         SERIES@lockstep (Documentation/qemu-pruss.rst)
#   make vmdeb            [KVER=6.1]: make deb's packages on a Debian root in the VM,
#                         installed with apt (DKMS in the guest), used, removed, purged
#   make vmrun            KVER=6.1 SCRIPT=path [IN=dir] [OUT=dir]: one script in the VM
#   make demo             the emulated BeagleBone runs prukit's drivers and the Cookbook's
#                         NeoPixel example, and shows what the pins did [KVER=6.1, or
#                         any kernel vmtest takes: KVER=6.12-ti for TI's PRU drivers]
#   make bench            speed: the simulator on the host and in the VM, the layer's round
#                         trip, rpmsg round trips, cycles per message, the drivers' figures
#                         [PARTS="prusim rpmsg-fw ws281x beaglelogic hub75 pwm encoder vm stress"]
#                         [KVER=...: the VM parts on that kernel; default 6.1, stress 6.1 6.12]
#   make deb              Debian packages prukit-dkms, -firmware, -overlays, -tools
#                         (arch all) into out/deb/, for a board's apt
#   make check            everything CI runs; ends with "N passed, N failed"

PRUKIT_VERSION := $(shell sed -n 's/^PACKAGE_VERSION="\(.*\)"/\1/p' $(CURDIR)/dkms.conf)

KDIR ?= /lib/modules/$(shell uname -r)/build
DESTDIR ?=
FIRMWARE_DIR ?= /lib/firmware
UDEV_RULES_DIR ?= /etc/udev/rules.d
MODPROBE_DIR ?= /lib/modprobe.d
DEPMOD_DIR ?= /lib/depmod.d
INCLUDE_DIR ?= /usr/include
SBIN_DIR ?= /usr/sbin
SYSTEMD_UNIT_DIR ?= /lib/systemd/system
BIN_DIR ?= /usr/bin
TOOL_LIB_DIR ?= /usr/lib/prukit
DATA_DIR ?= /usr/share/prukit
SYSCONF_DIR ?= /etc

BUILD := $(CURDIR)/out
SCRIPTS := $(CURDIR)/scripts

.PHONY: all modules modules_install clean install firmware firmware_install FORCE \
	overlays overlays_install udev_install modprobe_install depmod_install headers_install server_install tool_install kernels tools kunit vmtest vmdeb vmrun checkpatch demo bench check version deb

all: modules

modules:
	$(MAKE) -C $(KDIR) M=$(CURDIR) modules

# Into updates/, which depmod searches first: prukit's rpmsg_pru replaces
# the one of TI's 5.10/6.1 kernels.  Builds what it installs (kbuild's
# modules_install only copies what a previous "make modules" left).
modules_install: modules
	$(MAKE) -C $(KDIR) M=$(CURDIR) INSTALL_MOD_DIR=updates \
		$(if $(DESTDIR),INSTALL_MOD_PATH=$(DESTDIR)) modules_install

clean:
	$(MAKE) -C $(KDIR) M=$(CURDIR) clean 2>/dev/null || true
	rm -rf $(BUILD)

version:
	@echo $(PRUKIT_VERSION)

# pru-gcc from PATH, or bootstrapped into the cache on first use.
firmware:
	bin=$$($(SCRIPTS)/pru-toolchain.sh) && \
		$(MAKE) -C firmware O=$(BUILD)/firmware CROSS_COMPILE=$$bin/pru-

# The firmware users run; test firmware (fw-test := y) stays out.
firmware_install: firmware
	install -d $(DESTDIR)$(FIRMWARE_DIR)/prukit
	install -m 0644 $$($(MAKE) -s -C firmware O=$(BUILD)/firmware list-install) \
		$(DESTDIR)$(FIRMWARE_DIR)/prukit/

# Build only (cpp, dtc and the kernel's dt-bindings headers); the validation
# against base trees and dt-schema is make check's.
overlays:
	$(SCRIPTS)/overlays.sh --build

# Builds what it installs, as firmware_install does.
overlays_install: overlays
	install -d $(DESTDIR)$(FIRMWARE_DIR)
	install -m 0644 $(BUILD)/overlays/*.dtbo $(DESTDIR)$(FIRMWARE_DIR)/

# One file, 60-prukit.rules: udev/60-prukit.rules (what every prukit device
# node shares) followed by each driver's drivers/<driver>/udev/*.rules, in
# the order of drivers/registry.  One file rather than one per driver, so
# that installing a newer prukit replaces the rules of a driver it renamed
# or dropped instead of leaving them behind.
include $(CURDIR)/drivers/registry.mk
UDEV_RULES := udev/60-prukit.rules \
	$(foreach d,$(prukit_drivers),$(sort $(wildcard drivers/$(d)/udev/*.rules)))

# Generated on every run (it takes no time): a rules file removed since the
# last run is gone from the result too, which modification times would miss.
$(BUILD)/udev/60-prukit.rules: FORCE
	@mkdir -p $(@D)
	@echo "  GEN     $@"
	@for f in $(UDEV_RULES); do \
		case $$f in \
		drivers/*) printf '\n# %s\n' "$$f"; \
			sed '/^# SPDX-License-Identifier:/d' "$$f" ;; \
		*) cat "$$f" ;; \
		esac || exit 1; \
	done >$@.tmp
	@mv $@.tmp $@

FORCE:

# depmod.d/prukit.conf: prukit's rpmsg_pru before TI's (see its comments);
# run depmod afterwards (DKMS runs it when it installs the modules)
depmod_install:
	install -D -m 0644 $(CURDIR)/depmod.d/prukit.conf $(DESTDIR)$(DEPMOD_DIR)/prukit.conf

# modprobe.d/prukit.conf: which module comes with which (see its comments)
modprobe_install:
	install -D -m 0644 $(CURDIR)/modprobe.d/prukit.conf $(DESTDIR)$(MODPROBE_DIR)/prukit.conf

udev_install: $(BUILD)/udev/60-prukit.rules
	install -D -m 0644 $< $(DESTDIR)$(UDEV_RULES_DIR)/60-prukit.rules

# The drivers' ioctl headers, for programs: #include <prukit/ws281x.h>
headers_install:
	install -d $(DESTDIR)$(INCLUDE_DIR)/prukit
	install -m 0644 $(CURDIR)/include/uapi/prukit/*.h $(DESTDIR)$(INCLUDE_DIR)/prukit/

# Daemons for the board, and their systemd units (not enabled: that is the
# user's choice).  drivers/beaglelogic/server: the BeagleLogic TCP server;
# tools/pixeld: E1.31, OPC and DDP onto the LED devices (its package,
# prukit_pixeld, in /usr/lib/prukit beside the prukit command's), with its
# configuration in /etc/prukit (a file already there is the user's: kept).
SERVERS := drivers/beaglelogic/server/beaglelogic-tcpd tools/pixeld/prukit-pixeld

server_install:
	install -d $(DESTDIR)$(SBIN_DIR) $(DESTDIR)$(SYSTEMD_UNIT_DIR)
	@for s in $(SERVERS); do \
		echo "  INSTALL $(SBIN_DIR)/$${s##*/}"; \
		sed 's|@VERSION@|$(PRUKIT_VERSION)|' $$s >$(DESTDIR)$(SBIN_DIR)/$${s##*/} && \
		chmod 0755 $(DESTDIR)$(SBIN_DIR)/$${s##*/} && \
		sed 's|@SBINDIR@|$(SBIN_DIR)|' $$s.service \
			>$(DESTDIR)$(SYSTEMD_UNIT_DIR)/$${s##*/}.service || exit 1; \
	done
	install -d $(DESTDIR)$(TOOL_LIB_DIR)/prukit_pixeld
	@for f in tools/pixeld/prukit_pixeld/*.py; do \
		sed 's|@VERSION@|$(PRUKIT_VERSION)|' $$f >$(DESTDIR)$(TOOL_LIB_DIR)/prukit_pixeld/$${f##*/} && \
		chmod 0644 $(DESTDIR)$(TOOL_LIB_DIR)/prukit_pixeld/$${f##*/} || exit 1; \
	done
	@if [ -e $(DESTDIR)$(SYSCONF_DIR)/prukit/pixeld.conf ]; then \
		echo "  KEEP    $(SYSCONF_DIR)/prukit/pixeld.conf"; \
	else \
		install -D -m 0644 tools/pixeld/pixeld.conf $(DESTDIR)$(SYSCONF_DIR)/prukit/pixeld.conf; \
	fi

# The prukit command (tools/prukit): /usr/bin/prukit, its Python package in
# /usr/lib/prukit, and the pin table it reads in /usr/share/prukit.
tool_install:
	install -d $(DESTDIR)$(BIN_DIR) $(DESTDIR)$(TOOL_LIB_DIR)/prukit_tool $(DESTDIR)$(DATA_DIR)
	install -m 0755 tools/prukit/prukit $(DESTDIR)$(BIN_DIR)/prukit
	@for f in tools/prukit/prukit_tool/*.py; do \
		sed 's|@VERSION@|$(PRUKIT_VERSION)|' $$f >$(DESTDIR)$(TOOL_LIB_DIR)/prukit_tool/$${f##*/} && \
		chmod 0644 $(DESTDIR)$(TOOL_LIB_DIR)/prukit_tool/$${f##*/} || exit 1; \
	done
	install -m 0644 sim/am335x-pins.tsv $(DESTDIR)$(DATA_DIR)/

install: modules_install firmware_install overlays_install udev_install headers_install \
	server_install tool_install modprobe_install depmod_install

kernels:
	$(SCRIPTS)/checkpatch.sh
	$(SCRIPTS)/kernels.sh $(or $(KVERS),5.10 6.1 6.12 5.10-ti 6.12-ti)

tools:
	$(MAKE) -C tools/prusim

kunit:
	$(SCRIPTS)/kunit.sh

vmtest:
	$(SCRIPTS)/vm.sh test "$(or $(KVERS),6.12-ti 6.12 6.1 5.10-ti 6.1@thread)" "$(TESTS)"

# The Debian packages in the VM: installed, used, removed, purged (6.1)
vmdeb:
	$(SCRIPTS)/vm.sh deb $(or $(KVER),6.1)

vmrun:
	@test -n "$(KVER)" -a -n "$(SCRIPT)" || \
		{ echo "usage: make vmrun KVER=6.1 SCRIPT=path [IN=dir] [OUT=dir] [OVERLAY='a.dtso b.dtso']"; exit 2; }
	PRUKIT_VM_OVERLAYS="$(abspath $(OVERLAY))" \
		$(SCRIPTS)/vm.sh run $(KVER) $(SCRIPT) "$(IN)" "$(or $(OUT),$(BUILD)/vmrun)"

checkpatch:
	$(SCRIPTS)/checkpatch.sh

demo:
	PRUKIT_VM_KVER="$(KVER)" $(SCRIPTS)/demo.sh

bench:
	PRUKIT_VM_KVER="$(KVER)" $(SCRIPTS)/bench.sh $(PARTS)

deb:
	$(SCRIPTS)/deb.sh

check:
	$(SCRIPTS)/check.sh
