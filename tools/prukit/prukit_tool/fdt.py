# SPDX-License-Identifier: GPL-2.0-only
"""A flattened device tree (.dtb/.dtbo) reader, and what an overlay needs.

The format is the devicetree specification's (v0.4, chapter 5): a header
of big-endian 32-bit words, a structure block of tokens and a strings
block of property names.  Only reading, only what prukit's command needs.
"""
import struct

FDT_MAGIC = 0xD00DFEED
FDT_BEGIN_NODE, FDT_END_NODE, FDT_PROP, FDT_NOP, FDT_END = 1, 2, 3, 4, 9


class Node:
    """One node: name, properties (name -> bytes), children (name -> Node)."""

    def __init__(self, name, parent=None):
        self.name = name
        self.parent = parent
        self.props = {}
        self.children = {}

    @property
    def path(self):
        if self.parent is None:
            return "/"
        up = self.parent.path
        return (up if up != "/" else "") + "/" + self.name

    def walk(self):
        yield self
        for c in self.children.values():
            yield from c.walk()

    def string(self, prop):
        """A string property's value, or None."""
        v = self.props.get(prop)
        return v.rstrip(b"\0").decode(errors="replace") if v is not None else None

    def strings(self, prop):
        v = self.props.get(prop)
        return [s.decode(errors="replace") for s in v.split(b"\0") if s] if v else []

    def cells(self, prop):
        v = self.props.get(prop, b"")
        return list(struct.unpack(">%dI" % (len(v) // 4), v[: len(v) // 4 * 4]))


def parse(blob):
    """The root Node of a flattened tree; ValueError if it is not one."""
    if len(blob) < 40:
        raise ValueError("too short for a device tree blob")
    magic, total, off_struct, off_strings = struct.unpack_from(">4I", blob, 0)
    if magic != FDT_MAGIC:
        raise ValueError("not a device tree blob (magic 0x%08x)" % magic)
    if total > len(blob):
        raise ValueError("truncated: header says %d bytes, file has %d" % (total, len(blob)))
    pos = off_struct
    root = None
    node = None

    def name_at(off):
        end = blob.index(b"\0", off_strings + off)
        return blob[off_strings + off:end].decode(errors="replace")

    while pos + 4 <= total:
        tok, = struct.unpack_from(">I", blob, pos)
        pos += 4
        if tok == FDT_BEGIN_NODE:
            end = blob.index(b"\0", pos)
            name = blob[pos:end].decode(errors="replace")
            pos = (end + 4) & ~3
            if node is None:
                node = root = Node("")
            else:
                child = Node(name, node)
                node.children[name] = child
                node = child
        elif tok == FDT_END_NODE:
            if node is None:
                raise ValueError("unbalanced nodes")
            node = node.parent
        elif tok == FDT_PROP:
            length, nameoff = struct.unpack_from(">II", blob, pos)
            pos += 8
            if node is None:
                raise ValueError("property outside a node")
            node.props[name_at(nameoff)] = blob[pos:pos + length]
            pos = (pos + length + 3) & ~3
        elif tok == FDT_NOP:
            continue
        elif tok == FDT_END:
            break
        else:
            raise ValueError("bad token %d at offset %d" % (tok, pos - 4))
    if root is None:
        raise ValueError("no root node")
    return root


def load(path):
    with open(path, "rb") as f:
        return parse(f.read())


class OverlayInfo:
    """What an overlay (.dtbo) takes: pads, PRU cores, devices, firmware.

    pads: {pad offset (0x800 + the pinctrl-single offset): mux mode};
    prus: the PRU cores ("pru0", "pru1") it refers to (targets and
    phandles alike, from __fixups__); compatibles: of the nodes it adds;
    firmware: the firmware-name values of its nodes.
    """

    def __init__(self, name, root):
        self.name = name
        fixups = root.children.get("__fixups__")
        labels = set(fixups.props) if fixups else set()
        self.prus = sorted(lab for lab in labels if lab in ("pru0", "pru1"))
        self.pads = {}
        self.compatibles = []
        self.firmware = []
        for n in root.walk():
            if "pinctrl-single,pins" in n.props:
                c = n.cells("pinctrl-single,pins")
                step = 3 if len(c) % 3 == 0 else 2
                for i in range(0, len(c) - step + 1, step):
                    mode = (c[i + 2] if step == 3 else c[i + 1]) & 7
                    self.pads[0x800 + c[i]] = mode
            for comp in n.strings("compatible"):
                if comp not in self.compatibles:
                    self.compatibles.append(comp)
            for fw in n.strings("firmware-name"):
                if fw not in self.firmware:
                    self.firmware.append(fw)
