#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""fpga_floorplan.py: the floorplan of a routed `make fpga-pnr-top` design as a PNG.

Usage: fpga_floorplan.py <routed.json> <out.png>
Reads the design nextpnr-ecp5 wrote with --write (each cell's NEXTPNR_BEL, "X<x>/Y<y>/<bel>")
and draws the part's tile grid, one square per tile, coloured by the part of PREE that has the
most cells in it: each PREU, pree_top's own logic (controllers, memories, flow control), the AXI
wrapper, the board top (UART bridge, PLL, reset). Empty tiles are light grey. The legend is
printed on stdout (nextpnr's own --placed-svg draws every bel of the part: tens of megabytes).
"""
import json
import os
import re
import struct
import sys
import zlib

SCALE = 6          # pixels a tile
GRID = (127, 96)   # the LFE5U-85F's tile grid (nextpnr-ecp5 --85k), columns x rows
PARTS = [   # (name, colour, test on the cell's hierarchical name)
    ("PREU %d", None, re.compile(r"\.g_preu\[(\d+)\]\.")),
    ("pree_top's own logic", (70, 70, 70), re.compile(r"^u_link\.u_pree\.u_top\.")),
    ("AXI wrapper (pree_axi)", (230, 150, 0), re.compile(r"^u_link\.u_pree\.")),
    ("board top (UART bridge, PLL, reset)", (200, 0, 200), re.compile(r"")),
]
PREU_COLOURS = [(30, 100, 230), (0, 170, 80), (220, 40, 40), (0, 190, 200)]
EMPTY = (225, 225, 225)


def part_of(name):
    for label, colour, rx in PARTS:
        m = rx.search(name)
        if m:
            if colour is None:
                k = int(m.group(1))
                return label % k, PREU_COLOURS[k % len(PREU_COLOURS)]
            return label, colour
    raise AssertionError("unreachable")


def png(path, width, height, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    with open(path + ".tmp", "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main():
    if len(sys.argv) != 3:
        raise SystemExit("usage: fpga_floorplan.py <routed.json> <out.png>")
    src, out = sys.argv[1], sys.argv[2]
    try:
        mods = json.load(open(src))["modules"]
    except (OSError, ValueError, KeyError) as e:
        raise SystemExit("fpga_floorplan: %s: not a nextpnr JSON design (%s)" % (src, e))
    tiles, counts, colours = {}, {}, {}
    placed = 0
    for top in mods.values():
        for name, cell in top.get("cells", {}).items():
            bel = cell.get("attributes", {}).get("NEXTPNR_BEL")
            if not bel:
                continue
            m = re.match(r"X(\d+)/Y(\d+)/", bel)
            if not m:
                raise SystemExit("fpga_floorplan: %s: cell %s has bel '%s'" % (src, name, bel))
            label, colour = part_of(name)
            colours[label] = colour
            counts[label] = counts.get(label, 0) + 1
            t = tiles.setdefault((int(m.group(1)), int(m.group(2))), {})
            t[label] = t.get(label, 0) + 1
            placed += 1
    if not placed:
        raise SystemExit("fpga_floorplan: %s: no placed cell (NEXTPNR_BEL); write it with "
                         "nextpnr's --write after routing" % src)
    w, h = GRID
    off = [xy for xy in tiles if xy[0] >= w or xy[1] >= h]
    if off:
        raise SystemExit("fpga_floorplan: %s: tile X%d/Y%d outside the LFE5U-85F's %d x %d grid"
                         % (src, off[0][0], off[0][1], w, h))
    grid = [[EMPTY] * w for _ in range(h)]
    for (x, y), t in tiles.items():
        grid[y][x] = colours[max(t, key=t.get)]
    rows = []
    for y in range(h):
        line = []
        for x in range(w):
            line += list(grid[y][x]) * (SCALE - 1) + [255, 255, 255]
        rows += [line] * (SCALE - 1) + [[255] * (3 * SCALE * w)]
    png(out, SCALE * w, SCALE * h, rows)
    os.replace(out + ".tmp", out)
    print("%s: %d x %d tiles, %d placed cells" % (out, w, h, placed))
    for label in sorted(counts, key=lambda k: -counts[k]):
        print("  %-40s rgb%s %6d cells" % (label, colours[label], counts[label]))


if __name__ == "__main__":
    main()
