# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# beaglelogic: the logic analyzer's firmware, beaglelogic-pru0.elf (the
# storer: blocks from the scratchpad to the capture buffers in DDR) and
# beaglelogic-pru1.elf (the sampler: R31 every 2 * divisor cycles).
fw-srcs := bl_main.c bl_sample.S bl_store.S
fw-cores := 0 1
fw-stack-size := 0x100
