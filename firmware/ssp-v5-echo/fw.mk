# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# ssp-v5-echo: the Cookbook-style echo (examples/cookbook-rpmsg-echo/echo.c,
# unchanged) built as the PRU Software Support Package's releases for TI's
# 4.x kernels built it: the interrupt routing in a type 5 resource of the
# resource table (this folder's resource_table_0.h and _1.h) and no
# .pru_irq_map; the channel announced with the 72-byte name service message
# (lib/pru_rpmsg.c with PRUKIT_SSP_NS_DESC).  Test firmware, for
# tests/vm/cases/74-rpmsg-ssp-v5: prukit_pru makes such firmware run.
fw-srcs := ssp-v5-echo.c
fw-lib-srcs := pru_rpmsg.c ocp_copy.S
fw-cores := 0 1
fw-test := y
# this folder's resource tables before firmware/include's, for echo.c's "..."
fw-cflags := -iquote $(FWDIR)/ssp-v5-echo -DPRUKIT_SSP_NS_DESC
