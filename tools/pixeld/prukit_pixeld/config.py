# SPDX-License-Identifier: GPL-2.0-only
"""prukit-pixeld's configuration file: read and checked, every error named
with its line."""
from .outputs import FbOutput, FileOutput, Map, Ws281xOutput
from .protocols import DDP_PORT, E131_PORT, OPC_PORT


class ConfigError(Exception):
    """A configuration file's errors, each "FILE:LINE: what and why"."""


# -------------------------------------------------------------------------- config

SETTINGS = {
    "listen": str, "multicast-interface": str,
    "e131": "onoff", "opc": "onoff", "ddp": "onoff",
    "e131-port": "port", "opc-port": "port", "ddp-port": "port",
    "source-timeout": float, "frame-wait": float, "max-sources": int,
    "opc-max-clients": int, "stats-file": str, "sync-universes": "universes",
}
DEFAULTS = {
    "listen": "0.0.0.0", "multicast-interface": "0.0.0.0",
    "e131": True, "opc": True, "ddp": True,
    "e131-port": E131_PORT, "opc-port": OPC_PORT, "ddp-port": DDP_PORT,
    "source-timeout": 2.5, "frame-wait": 0.05, "max-sources": 8,
    "opc-max-clients": 16, "stats-file": "", "sync-universes": [],
}
MAP_KEYS = {
    "e131": {"universe", "channel", "pixels", "at", "layout", "format"},
    "opc": {"channel", "pixels", "at"},
    "ddp": {"offset", "pixels", "at", "format"},
}


class Config:
    def __init__(self, path):
        self.path = path
        self.settings = dict(DEFAULTS)
        self.outputs = {}
        self.maps = []
        errors = []
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                lines = f.read().splitlines()
        except OSError as e:
            raise ConfigError("%s: %s" % (path, e.strerror)) from e
        for no, text in enumerate(lines, 1):
            words = text.split("#", 1)[0].split()
            if not words:
                continue
            where = "%s:%d" % (path, no)
            try:
                self.line(where, words)
            except ValueError as e:
                errors.append("%s: %s" % (where, e))
        if not self.maps and not errors:
            errors.append("%s: no map line: nothing would be shown" % path)
        if errors:
            raise ConfigError("\n".join(errors))

    def line(self, where, words):
        key, args = words[0], words[1:]
        if key == "output":
            self.output(where, args)
        elif key == "map":
            self.map(where, args)
        elif key in SETTINGS:
            self.settings[key] = self.value(key, SETTINGS[key], args)
        else:
            raise ValueError("unknown keyword %r (settings: %s; output, map)"
                             % (key, ", ".join(SETTINGS)))

    @staticmethod
    def value(key, kind, args):
        if kind == "universes":
            return [universe(a) for a in args]
        if len(args) != 1:
            raise ValueError("%s takes one value" % key)
        v = args[0]
        if kind == "onoff":
            if v not in ("on", "off"):
                raise ValueError("%s is on or off, not %r" % (key, v))
            return v == "on"
        if kind == "port":
            return number(v, 1, 65535, key)
        if kind is int:
            return number(v, 1, 1000, key)
        if kind is float:
            try:
                f = float(v)
            except ValueError:
                f = -1
            if not 0 < f <= 60:
                raise ValueError("%s is seconds, more than 0 and at most 60, not %r" % (key, v))
            return f
        return v

    def output(self, where, args):
        if len(args) < 2:
            raise ValueError("output NAME TYPE ...: TYPE is ws281x [DEVICE], hub75, "
                             "fb DEVICE or file PATH PIXELS [rgbw] [append]")
        name, kind, rest = args[0], args[1], args[2:]
        if name in self.outputs:
            raise ValueError("output %s is defined twice" % name)
        if kind == "ws281x" and len(rest) <= 1:
            out = Ws281xOutput(name, rest[0] if rest else "/dev/ws281x0")
        elif kind == "hub75" and not rest:
            out = FbOutput(name, "the hub75 framebuffer", find_hub75=True)
        elif kind == "fb" and len(rest) == 1:
            out = FbOutput(name, rest[0])
        elif kind == "file" and 2 <= len(rest) <= 4 and \
                set(rest[2:]) <= {"rgb", "rgbw", "append"}:
            out = FileOutput(name, rest[0], number(rest[1], 1, 1 << 20, "PIXELS"),
                             4 if "rgbw" in rest[2:] else 3, "append" in rest[2:])
        else:
            raise ValueError("output %s: %r is not ws281x [DEVICE], hub75, fb DEVICE or "
                             "file PATH PIXELS [rgbw] [append]" % (name, " ".join(args[1:])))
        self.outputs[name] = out

    def map(self, where, args):
        if len(args) < 2:
            raise ValueError("map OUTPUT PROTOCOL [KEY VALUE]...: PROTOCOL is e131, opc or ddp")
        name, proto, rest = args[0], args[1], args[2:]
        if name not in self.outputs:
            raise ValueError("map: no output %r defined above" % name)
        if proto not in MAP_KEYS:
            raise ValueError("map: protocol %r is not e131, opc or ddp" % proto)
        if len(rest) % 2:
            raise ValueError("map %s %s: keys and values go in pairs (%s)"
                             % (name, proto, " ".join(rest)))
        try:
            kw = self.map_keys(proto, rest)
        except ValueError as e:
            raise ValueError("map %s %s: %s" % (name, proto, e)) from e
        out = self.outputs[name]
        if proto == "e131":
            kw.setdefault("universe", 1)
            kw.setdefault("channel", 1)
            kw.setdefault("layout", "contiguous")
        elif proto == "opc":
            kw.setdefault("channel", 1)
        else:
            kw.setdefault("offset", 0)
        nbpp = 3 if proto == "opc" else None
        if "format" in kw:
            nbpp = 4 if kw.pop("format") == "rgbw" else 3
        self.maps.append(Map(where, out, proto, nbpp, **kw))

    @staticmethod
    def map_keys(proto, rest):
        """The KEY VALUE pairs of a map line, checked."""
        kw = {}
        for k, v in zip(rest[::2], rest[1::2]):
            if k not in MAP_KEYS[proto]:
                raise ValueError("unknown key %r (%s)" % (k, ", ".join(sorted(MAP_KEYS[proto]))))
            if k in kw:
                raise ValueError("%s given twice" % k)
            if k == "universe":
                kw[k] = universe(v)
            elif k == "channel":
                kw[k] = number(v, 1, 512, k) if proto == "e131" else number(v, 1, 255, k)
            elif k == "pixels":
                kw[k] = number(v, 1, 1 << 20, k)
            elif k in ("at", "offset"):
                kw[k] = number(v, 0, 1 << 24, k)
            elif k == "layout":
                if v not in ("contiguous", "pixels"):
                    raise ValueError("layout is contiguous (pixels may straddle universes) "
                                     "or pixels (never split), not %r" % v)
                kw[k] = v
            elif k == "format":
                if v not in ("rgb", "rgbw"):
                    raise ValueError("format is rgb or rgbw, not %r" % v)
                kw[k] = v
        return kw


def number(v, lo, hi, what):
    try:
        n = int(v, 10)
    except ValueError:
        n = None
    if n is None or not lo <= n <= hi:
        raise ValueError("%s is a whole number from %d to %d, not %r" % (what, lo, hi, v))
    return n


def universe(v):
    return number(v, 1, 63999, "universe")
