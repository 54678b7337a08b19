# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# gpio-pulse: the Cookbook's way to a GPIO line from a PRU; ten pulses on
# gpio1_28 (P9_12) over the OCP master port, then halt (see gpio-pulse.c).
fw-srcs := gpio-pulse.c
fw-cores := 0
fw-stack-size := 0x100
