# SPDX-License-Identifier: GPL-2.0-only
#
# The gate, included by every driver's Kbuild: out of tree there is no
# Kconfig, so drivers/<driver>/<driver>.ko is built (CONFIG_PRUKIT_<DRIVER>
# ?= m, upper case, a "prukit_" prefix dropped) wherever the kernel has every
# option its line in drivers/registry needs; dkms.conf lists the module
# under the same condition.  In a kernel tree (make kunit) Kconfig's value,
# when it sets one, stands (?=).  The options come from the kernel's
# include/config/auto.conf, which kbuild reads in every directory; the
# variable is set in the driver's own directory, so it reaches no other.
prukit-driver := $(notdir $(patsubst %/,%,$(src)))
prukit-config := CONFIG_PRUKIT_$(shell echo '$(patsubst prukit_%,%,$(prukit-driver))' | tr a-z A-Z)
include $(prukit_top)/drivers/registry.mk
prukit-needs := $(call prukit_needs_of,$(prukit-driver))
ifeq ($(strip $(foreach c,$(prukit-needs),$(if $($(c)),,$(c)))),)
$(prukit-config) ?= m
endif

# A driver written for an interface that some kernels with its options lack
# says so in its Kbuild, one line per symbol its kernel headers must
# declare ("# prukit-kernel-api: include/linux/counter.h devm_counter_alloc"):
# it is built only where the kernel's header has it.  dkms.conf reads the
# same lines.
# ($(src) is absolute in an external module build, relative to the source
# tree in a kernel tree's)
prukit-api-kbuild := $(firstword $(wildcard $(src)/Kbuild $(srctree)/$(src)/Kbuild))
prukit-api-lacks := $(if $(prukit-api-kbuild),$(shell \
	sed -n 's/^\# prukit-kernel-api: *//p' $(prukit-api-kbuild) | \
	while read -r h s; do grep -qsw "$$s" "$(srctree)/$$h" || echo "$$h"; done))
ifneq ($(strip $(prukit-api-lacks)),)
$(prukit-config) :=
endif
