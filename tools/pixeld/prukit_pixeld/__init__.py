# SPDX-License-Identifier: GPL-2.0-only
"""prukit-pixeld: pixels from the network onto prukit's LED devices.

Receives E1.31 (sACN, ANSI E1.31-2018) on UDP port 5568, Open Pixel
Control on TCP and UDP port 7890 and DDP on UDP port 4048, and writes whole
frames to the ws281x driver's /dev/ws281xN (48 NeoPixel strings) and to the
hub75 driver's /dev/fbN (a HUB75 matrix), as the configuration file maps
network channels onto their pixels (Documentation/pixeld.rst, and the
comments of the installed configuration file).

A frame is written only when it is complete: every universe an output's
E1.31 maps name with one sequence number (or the universes of a
synchronized frame, at the sync packet), one OPC message, a DDP packet
with the push flag; each output at most once per turn of the event loop.
Gamma and brightness are left to the drivers (the ws281x driver's
brightness and lut, the hub75 driver's levels and backlight): the daemon
copies the bytes.

Malformed, late, unmapped and surplus input is dropped and counted, never
kept: the state is bounded by the configuration (the universes it maps,
max-sources per universe, opc-max-clients connections of at most one OPC
message each, 8 sync groups joined as data names them).

The parts, each usable and tested on its own:
  protocols  the wire formats: parse_e131(), parse_opc(), parse_ddp()
  merge      source merging and frames: Pixeld (feed_e131/feed_opc/feed_ddp,
             tick, flush_ready)
  outputs    the devices (ws281x, framebuffer, file) and the maps
  config     the configuration file (Config, ConfigError)
  server     the sockets, multicast groups, signals and main()
  common     the log and the counters"""

VERSION = "@VERSION@"
