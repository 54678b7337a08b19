# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# rpmsg-echo: every rpmsg message comes back unchanged to its sender
# (/dev/rpmsg_pru30 on PRU0, /dev/rpmsg_pru31 on PRU1).
fw-srcs := rpmsg-echo.c
fw-lib-srcs := rpmsg.c ocp_copy.S
fw-cores := 0 1
fw-stack-size := 0x100
