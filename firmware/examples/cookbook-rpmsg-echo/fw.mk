# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# cookbook-rpmsg-echo: the support package's RPMsg echo example as the PRU
# Cookbook builds it, written against that API (<pru_rpmsg.h>), which
# prukit's lib/pru_rpmsg.c provides: every message comes back to its sender
# (/dev/rpmsg_pru30 on PRU0, /dev/rpmsg_pru31 on PRU1).
fw-srcs := echo.c
fw-lib-srcs := pru_rpmsg.c ocp_copy.S
fw-cores := 0 1
