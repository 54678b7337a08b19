# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# input-echo: copy the R31 inputs to the R30 outputs, forever (tests).
fw-srcs := input-echo.c
fw-cores := 0 1
fw-stack-size := 0x100
fw-test := y
