#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
"""Statically trace a PRU firmware from its disassembly, counting cycles.

    pru-objdump -d fw.elf | pru-trace.py [--start SYM] [--r30 VALUE] [--max N]

Walks the program from SYM (default _start) through pru-objdump's output,
modelling the registers (value and which bits are known), 1 cycle per
instruction (taken branches too, LOOP iterations add none), until HALT.  It
prints one line per write to R30 and R31 and one for the halt:

    R30 <cycle> <value> <known-mask>     (hex, cycle = cycle the write issues)
    R31 <cycle> <value> <known-mask>
    HALT <cycle>

It refuses (exit 2) anything whose timing or effect it cannot know: a memory
load after the first R30 write (variable latency), a branch on an unknown
register, an instruction it does not model.  Good enough for straight-line
and __delay_cycles() style code such as firmware/hello; not a simulator.
"""

import argparse
import re
import sys

MASK32 = 0xFFFFFFFF
LINE = re.compile(r'^\s*([0-9a-f]+):\s+(?:[0-9a-f]{8}\s+)?([a-z]\S*)\s*(.*)$')
SYM = re.compile(r'^([0-9a-f]+) <([^>]+)>:$')
REG = re.compile(r'^r(\d+)(?:\.([bw])(\d))?$')
ALIASES = {'sp': 'r2', 'ra': 'r3.w2'}


class Unsupported(Exception):
    pass


def parse(lines):
    insns, syms = {}, {}
    for line in lines:
        line = line.rstrip('\n')
        m = SYM.match(line.strip())
        if m:
            syms[m.group(2)] = int(m.group(1), 16)
            continue
        m = LINE.match(line)
        if not m:
            continue
        addr = int(m.group(1), 16)
        ops = m.group(3).split('#')[0].strip()
        ops = [o.strip() for o in ops.split(',')] if ops else []
        insns[addr] = (m.group(2), ops, line.strip())
    return insns, syms


def field(name):
    """Register operand -> (regno, bit offset, width) or None."""
    name = ALIASES.get(name, name)
    m = REG.match(name)
    if not m:
        return None
    n = int(m.group(1))
    if m.group(2) is None:
        return n, 0, 32
    k = int(m.group(3))
    if m.group(2) == 'b':
        return n, 8 * k, 8
    return n, 8 * k, 16


class Machine:
    def __init__(self, r30):
        self.val = [0] * 32
        self.known = [0] * 32
        if r30 is not None:
            self.val[30], self.known[30] = r30 & MASK32, MASK32

    def read(self, op):
        f = field(op)
        if f is None:
            try:
                v = int(op, 0)
            except ValueError:
                raise Unsupported('operand %r' % op)
            return v & MASK32, MASK32
        n, off, w = f
        m = (1 << w) - 1
        return (self.val[n] >> off) & m, (self.known[n] >> off) & m

    def write(self, op, v, k):
        f = field(op)
        if f is None:
            raise Unsupported('destination %r' % op)
        n, off, w = f
        m = ((1 << w) - 1) << off
        self.val[n] = (self.val[n] & ~m) | ((v << off) & m)
        self.known[n] = (self.known[n] & ~m) | ((k << off) & m)
        return n

    def known_value(self, op, what):
        v, k = self.read(op)
        f = field(op)
        full = MASK32 if f is None else (1 << f[2]) - 1
        if k != full:
            raise Unsupported('%s depends on unknown register %s' % (what, op))
        return v


def target(ops0):
    return int(ops0.split()[0], 16)


def alu(mn, a, ak, b, bk):
    """Result value and known mask of a 32-bit ALU operation."""
    full = ak == MASK32 and bk == MASK32
    if mn == 'add':
        return (a + b) & MASK32, MASK32 if full else 0
    if mn == 'sub':
        return (a - b) & MASK32, MASK32 if full else 0
    if mn == 'and':
        zero = (~a & ak) | (~b & bk)
        return a & b, (ak & bk) | zero
    if mn == 'or':
        one = (a & ak) | (b & bk)
        return a | b, (ak & bk) | one
    if mn == 'xor':
        return a ^ b, ak & bk
    if mn in ('lsl', 'lsr'):
        if bk & 31 != 31:
            return 0, 0
        s = b & 31
        if mn == 'lsl':
            return (a << s) & MASK32, ((ak << s) | ((1 << s) - 1)) & MASK32
        return a >> s, (ak >> s) | (MASK32 & ~(MASK32 >> s))
    if mn in ('set', 'clr'):
        if bk & 31 != 31:
            return 0, 0
        bit = 1 << (b & 31)
        return ((a | bit) if mn == 'set' else (a & ~bit)) & MASK32, ak | bit
    raise Unsupported(mn)


def run(insns, pc, r30, max_cycles, out):
    m = Machine(r30)
    cycle = 0
    measuring = False
    loop = None         # (start, end, remaining)
    while True:
        if cycle > max_cycles:
            raise Unsupported('no HALT within %d cycles' % max_cycles)
        if pc not in insns:
            raise Unsupported('no instruction at 0x%08x' % pc)
        mn, ops, text = insns[pc]
        nxt = pc + 4
        dest = None
        try:
            if mn == 'halt':
                out.append('HALT %d' % cycle)
                return
            elif mn == 'nop':
                pass
            elif mn == 'ldi':
                v, k = m.read(ops[1])
                dest = m.write(ops[0], v, k)
            elif mn == 'mov':
                v, k = m.read(ops[1])
                dest = m.write(ops[0], v, k)
            elif mn in ('add', 'sub', 'and', 'or', 'xor', 'lsl', 'lsr', 'set', 'clr'):
                a, ak = m.read(ops[1])
                b, bk = m.read(ops[2])
                v, k = alu(mn, a, ak, b, bk)
                dest = m.write(ops[0], v, k)
            elif mn in ('qbeq', 'qbne'):
                a = m.known_value(ops[1], mn)
                b = m.known_value(ops[2], mn)
                if (a == b) == (mn == 'qbeq'):
                    nxt = target(ops[0])
            elif mn in ('qbbs', 'qbbc'):
                a, ak = m.read(ops[1])
                bit = 1 << m.known_value(ops[2], mn)
                if not ak & bit:
                    raise Unsupported('%s on unknown bit' % mn)
                if bool(a & bit) == (mn == 'qbbs'):
                    nxt = target(ops[0])
            elif mn in ('qba', 'jmp') and field(ops[0]) is None:
                nxt = target(ops[0])
            elif mn == 'jmp' or mn == 'ret':
                reg = ops[0] if mn == 'jmp' else 'r3.w2'
                nxt = (pc & ~0xFFFF) + 4 * m.known_value(reg, mn)
            elif mn == 'call' or mn == 'jal':
                link, dst = ('r3.w2', ops[0]) if mn == 'call' else (ops[0], ops[1])
                m.write(link, (nxt & 0xFFFF) // 4, 0xFFFF)
                if field(dst) is None:
                    nxt = target(dst)
                else:
                    nxt = (pc & ~0xFFFF) + 4 * m.known_value(dst, mn)
            elif mn == 'loop':
                end = target(ops[0])
                count = m.known_value(ops[1], mn)
                if count == 0:
                    nxt = end
                else:
                    loop = (nxt, end, count)
            elif mn in ('sbbo', 'sbco'):
                pass
            elif mn in ('lbbo', 'lbco'):
                if measuring:
                    raise Unsupported('memory load after the first R30 write')
                m.write(ops[0].split()[0], 0, 0)
                f = field(ops[0])
                # burst into following registers: forget them all
                nbytes = m.known_value(ops[3], mn) if len(ops) > 3 else 4
                n0 = f[0]
                for n in range(n0, min(32, n0 + 1 + nbytes // 4)):
                    m.known[n] = 0
            else:
                raise Unsupported('instruction %r' % mn)
        except Unsupported as e:
            raise Unsupported('0x%08x: %s: %s' % (pc, text, e))

        if dest in (30, 31):
            out.append('R%d %d 0x%08x 0x%08x' % (dest, cycle, m.val[dest], m.known[dest]))
            if dest == 30:
                measuring = True
        cycle += 1
        if loop is not None and nxt == loop[1]:
            start, end, left = loop
            if left > 1:
                loop = (start, end, left - 1)
                nxt = start
            else:
                loop = None
        pc = nxt


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--start', default='_start')
    ap.add_argument('--r30', type=lambda s: int(s, 0), default=None,
                    help='initial R30 (default: unknown)')
    ap.add_argument('--max', type=int, default=10_000_000)
    ap.add_argument('file', nargs='?', type=argparse.FileType('r'), default=sys.stdin)
    args = ap.parse_args()

    insns, syms = parse(args.file)
    if args.start not in syms:
        print('pru-trace: symbol %s not found' % args.start, file=sys.stderr)
        return 2
    out = []
    try:
        run(insns, syms[args.start], args.r30, args.max, out)
    except Unsupported as e:
        print('\n'.join(out))
        print('pru-trace: cannot follow: %s' % e, file=sys.stderr)
        return 2
    print('\n'.join(out))
    return 0


if __name__ == '__main__':
    sys.exit(main())
