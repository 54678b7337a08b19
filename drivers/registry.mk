# SPDX-License-Identifier: GPL-2.0-only
#
# drivers/registry read by make, the one parser every makefile includes
# (Kbuild, drivers/gate.mk, Makefile, firmware/Makefile):
#   prukit_drivers            the drivers, in the registry's order
#   prukit_needs_of DRIVER    the kernel options its line needs, CONFIG_ prefixed
prukit_registry := $(dir $(abspath $(lastword $(MAKEFILE_LIST))))registry
prukit_drivers := $(shell awk '/^[a-z0-9_]+[ \t]/ { print $$1 }' $(prukit_registry))
prukit_needs_of = $(addprefix CONFIG_,$(subst $(comma), ,$(shell awk -v d='$(1)' \
	'$$1 == d { print $$2 }' $(prukit_registry))))
