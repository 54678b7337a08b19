# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
# pru_encoder: the quadrature encoder driver's firmware, pru_encoder-pru0.elf:
# decodes A/B (x4) and an index from PRU0 R31 bits 14..16 (the sampling loop
# is pru_encoder_loop.S), polls its control block (pru_encoder_proto.h),
# strobes an event on overflow, underflow, index, reversal, skipped state.
fw-srcs := pru_encoder.c pru_encoder_loop.S
fw-cores := 0
fw-stack-size := 0x100
