#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
"""Emit GNU as source with .word directives covering every PRU instruction
format, opcode, field select, burst length encoding and branch offset sign,
plus random words (undefined encodings included).  The prusim disassembler
must print each exactly as pru-objdump does."""

import random
import sys

# Keep all branch targets at non-negative addresses.
PAD_WORDS = 1024


def fmt1(sub, io, rd, rdsel, rs1, rs1sel, rs2_or_imm, rs2sel=0):
    w = sub << 25 | io << 24 | rs1sel << 13 | rs1 << 8 | rdsel << 5 | rd
    if io:
        w |= (rs2_or_imm & 0xff) << 16
    else:
        w |= rs2sel << 21 | rs2_or_imm << 16
    return w


def words():
    rnd = random.Random(20240601)
    regs = [0, 1, 2, 3, 4, 5, 17, 28, 29, 30, 31]
    out = []

    # Format 1: every sub-opcode, both operand kinds, every field select.
    for sub in range(16):
        for io in (0, 1):
            for sel in range(8):
                rd = regs[(sub + sel) % len(regs)]
                rs1 = regs[(sub + 3 * sel + 1) % len(regs)]
                op2 = (sel * 37 + sub) & 0xff if io else regs[(sel + 5) % len(regs)]
                out.append(fmt1(sub, io, rd, sel, rs1, (sel + 3) % 8, op2, (sel + 5) % 8))
            out.append(fmt1(sub, io, 0, 7, 0, 7, 0, 7))      # nop when OR, io=0
            out.append(fmt1(sub, io, 9, 4, 10, 6, 0, 7))     # mov when OR, io=1, imm 0
            out.append(fmt1(sub, io, 9, 4, 10, 6, 255, 7))
    # Format 2: every sub-opcode 0..15 with both operand kinds.
    for sub in range(16):
        for io in (0, 1):
            for k in range(6):
                w = 1 << 29 | sub << 25 | io << 24 | rnd.getrandbits(24)
                out.append(w)
    # JMP/JAL/call/ret forms.
    for io in (0, 1):
        for sel in range(8):
            for reg in (3, 4, 30):
                out.append(1 << 29 | 0 << 25 | io << 24 | sel << 21 | reg << 16 | rnd.getrandbits(16))
                out.append(1 << 29 | 1 << 25 | io << 24 | rnd.getrandbits(16) << 8 | sel << 5 | reg)
        out.append(1 << 29 | 0 << 25 | io << 24 | 6 << 21 | 3 << 16)
        out.append(1 << 29 | 1 << 25 | io << 24 | 0x1234 << 8 | 6 << 5 | 3)
        out.append(1 << 29 | 1 << 25 | io << 24 | 0xffff << 8 | 6 << 5 | 3)
    # LDI/LMBD with every destination select.
    for sel in range(8):
        out.append(1 << 29 | 2 << 25 | rnd.getrandbits(16) << 8 | sel << 5 | regs[sel])
        out.append(1 << 29 | 3 << 25 | 1 << 24 | 1 << 16 | sel << 13 | 7 << 8 | sel << 5 | 1)
        out.append(1 << 29 | 3 << 25 | sel << 21 | 31 << 16 | sel << 13 | 7 << 8 | sel << 5 | 1)
    # XFR: kinds 0..3, scan bit, devices, every rdb, length codes.
    for kind in range(4):
        for s in (0, 1):
            for wba in (0, 10, 11, 12, 14, 20, 253, 254, 255):
                for length in (0, 3, 7, 119, 123, 124, 125, 126, 127):
                    rdb = length & 3
                    out.append(1 << 29 | 7 << 25 | kind << 23 | wba << 15 | s << 14 |
                               length << 7 | rdb << 5 | (wba % 30))
    # LOOP/ILOOP with immediate and register counts, every end offset class.
    for il in (0, 1):
        for io in (0, 1):
            for off in (0, 1, 2, 127, 128, 255):
                for cnt in (0, 1, 0x7f, 0xff):
                    w = 1 << 29 | 8 << 25 | io << 24 | il << 15 | off
                    w |= cnt << 16 if io else (cnt & 7) << 21 | 5 << 16
                    out.append(w)
    # SLP, HALT.
    out += [1 << 29 | 15 << 25, 1 << 29 | 15 << 25 | 1 << 23, 1 << 29 | 5 << 25]
    # Format 4: every condition, offsets of both signs, operand kinds.
    offsets = (0, 1, 2, 255, 256, 511, -1, -2, -256, -511, -512)
    for cond in range(8):
        for off in offsets:
            for io in (0, 1):
                raw = off & 0x3ff
                w = 1 << 30 | cond << 27 | (raw >> 8) << 25 | io << 24 | (raw & 0xff)
                w |= (rnd.getrandbits(8) << 16) if io else (rnd.getrandbits(3) << 21 | 31 << 16)
                w |= rnd.getrandbits(3) << 13 | rnd.getrandbits(5) << 8
                out.append(w)
                out.append(w | 1 << 29)
    # Format 5: bit tests, including the wbs/wbc (offset 0) forms.
    for bits in range(4):
        for off in offsets:
            for io in (0, 1):
                raw = off & 0x3ff
                w = 6 << 29 | bits << 27 | (raw >> 8) << 25 | io << 24 | (raw & 0xff)
                w |= (rnd.getrandbits(5) << 16) if io else (rnd.getrandbits(3) << 21 | 31 << 16)
                w |= rnd.getrandbits(3) << 13 | 31 << 8
                out.append(w)
    # Format 6: LBBO/SBBO/LBCO/SBCO, every burst length code and rdb.
    for top in (4, 7):
        for ls in (0, 1):
            for length in range(128):
                for io in (0, 1):
                    w = top << 29 | ls << 28 | (length >> 4) << 25 | io << 24
                    w |= ((length >> 1) & 7) << 13 | (length & 1) << 7
                    w |= (length & 3) << 5 | rnd.getrandbits(5) | rnd.getrandbits(5) << 8
                    w |= (rnd.getrandbits(8) << 16) if io else (rnd.getrandbits(3) << 21 |
                                                                 rnd.getrandbits(5) << 16)
                    out.append(w)
    # The undefined top-level format 101, and random words of every kind.
    out += [5 << 29 | rnd.getrandbits(29) for _ in range(16)]
    out += [rnd.getrandbits(32) for _ in range(20000)]
    return out


def main():
    ws = words()
    print("\t.text")
    print(f"\t.rept {PAD_WORDS}\n\tnop\n\t.endr")
    for w in ws:
        print(f"\t.word 0x{w:08x}")
    print(f"\t.rept {PAD_WORDS}\n\tnop\n\t.endr")
    print(f"{len(ws)} instruction words", file=sys.stderr)


if __name__ == "__main__":
    main()
