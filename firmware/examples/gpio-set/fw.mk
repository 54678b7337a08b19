# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# gpio-set: the Cookbook's blink on a GPIO line Linux made an output; ten
# pulses on gpio1_28 (P9_12) with stores only, then halt (see gpio-set.c).
fw-srcs := gpio-set.c
fw-cores := 0
fw-stack-size := 0x100
