# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# hub75: the RGB LED matrix refresh, hub75-pru0.elf and hub75-pru1.elf (the
# same program; the overlay says which core drives the panel).
fw-srcs := hub75_main.c hub75_scan.S hub75_banks.S
fw-cores := 0 1
fw-stack-size := 0x100
