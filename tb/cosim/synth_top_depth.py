#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""synth_top_depth.py: logic depth of pree_top's own paths in a Yosys synth_xilinx netlist.

Usage: synth_top_depth.py [--inline SUB,...] NETLIST.json [MODULE]   (MODULE: default pree_top)
Prints a Markdown table: for each group of path endpoints in MODULE (a register, or an input
of a sub-module such as a PREU, a controller or a RAM bank), the most LUT levels and the most
cells (LUT + CARRY4 + MUXF7/8) on any path ending there, and where that path starts.

Method: MODULE is read with its hierarchy kept, so its paths are its own logic. A path starts
at a flip-flop output (FD*), an output of a sub-module instance (PREU, controller, RAM bank),
or a module input, and ends at a flip-flop input, a sub-module input or a module output.
--inline names sub-modules (by a part of the module name, e.g. pree_aftso_hpuoc) whose paths
join MODULE's: a path then runs through the instance's ports, from the registers on one side
to those on the other, as the two netlists were mapped (no logic optimised across the port).
Every combinational cell is traversed from each input bit to each output bit (conservative for
CARRY4: one level per CARRY4 of a chain). Endpoints are grouped by name with bit and generate
indices removed (g_hp[3].u_state.raddr_i[5] -> g_hp[*].u_state.raddr_i). These are logic
levels after mapping, not timing: no place and route is run. A synth_ecp5 netlist reads the same
way: TRELLIS_FF a register, LUT4 a LUT level, CCU2C, PFUMX and L6MUX21 cells without one.
"""
import json
import re
import sys
from collections import defaultdict

FF = re.compile(r"^(FD[A-Z]*(_1)?|TRELLIS_FF)$")
LUT = re.compile(r"^LUT[1-6]$")
WIRE = {"IBUF", "OBUF", "BUFG", "INV", "BUF"}
COMB = {"CARRY4", "MUXF7", "MUXF8", "CCU2C", "PFUMX", "L6MUX21"}


def weight(t):
    """(lut levels, cells) added by one combinational cell."""
    if LUT.match(t):
        return (1, 1)
    if t in COMB:
        return (0, 1)
    return (0, 0)


def group(name):
    """Endpoint group: bit and generate indices removed."""
    return re.sub(r"\[\d+\]", "[*]", name).replace("\\", "")


def build(mods, name, pfx, inline, g):
    """Adds module `name`'s cells to graph g, its bits keyed (pfx, bit). Instances of modules
    whose name contains a string of `inline` are entered (their paths join the caller's);
    others are boundaries. Returns the module's port bits: {port: [key, ...]}."""
    mod = mods[name]
    key = lambda b: (pfx, b)
    for n, info in mod["netnames"].items():
        hidden = info.get("hide_name", 0) or n.startswith("$")
        for i, b in enumerate(info["bits"]):
            if isinstance(b, str):
                continue
            label = pfx + (n if len(info["bits"]) == 1 else "%s[%d]" % (n, i))
            rank = (hidden, len(label))
            if key(b) not in g["bitname"] or rank < g["bitname"][key(b)][0]:
                g["bitname"][key(b)] = (rank, label)
    for cname, c in mod["cells"].items():
        t = c["type"]
        dirs = c.get("port_directions", {})
        conn = {p: [key(b) for b in bs if not isinstance(b, str)] for p, bs in c["connections"].items()}
        ins = [b for p, bs in conn.items() if dirs.get(p) == "input" for b in bs]
        outs = [b for p, bs in conn.items() if dirs.get(p) == "output" for b in bs]
        if LUT.match(t) or t in COMB or t in WIRE:
            for b in outs:
                g["driver"][b] = (t, ins)
        elif FF.match(t):
            for b in outs:
                g["start"].add(b)
            q = conn.get("Q", [])
            reg = group(g["bitname"][q[0]][1]) if q and q[0] in g["bitname"] else group(pfx + cname)
            for b in ins:
                g["ends"].append((reg, b))
        elif t in mods and any(m in t for m in inline):
            inner = build(mods, t, pfx + group(cname).split(".")[-1] + ".", inline, g)
            for p, bs in conn.items():
                for outer, innerb in zip(bs, inner.get(p, [])):
                    if dirs.get(p) == "input":
                        g["driver"][innerb] = ("BUF", [outer])
                    else:
                        g["driver"][outer] = ("BUF", [innerb])
        else:   # a sub-module or a RAM primitive: a boundary
            for b in outs:
                g["start"].add(b)
            inst = group(pfx + cname)
            for p, bs in conn.items():
                if dirs.get(p) == "input":
                    for b in bs:
                        g["ends"].append(("%s.%s" % (inst, p), b))
    return {p: [key(b) for b in info["bits"] if not isinstance(b, str)]
            for p, info in mod["ports"].items()}


def main():
    args = sys.argv[1:]
    inline = []
    if len(args) >= 2 and args[0] == "--inline":
        inline = args[1].split(",")
        args = args[2:]
    if len(args) not in (1, 2):
        raise SystemExit(__doc__)
    top = args[1] if len(args) == 2 else "pree_top"
    with open(args[0]) as f:
        mods = json.load(f)["modules"]

    g = {"driver": {}, "start": set(), "ends": [], "bitname": {}}
    ports = build(mods, top, "", inline, g)
    for p, info in mods[top]["ports"].items():
        for b in ports[p]:
            if info["direction"] == "input":
                g["start"].add(b)
            else:
                g["ends"].append((group(p), b))
    driver, start, ends, bitname = g["driver"], g["start"], g["ends"], g["bitname"]

    def nm(b):
        return bitname[b][1] if b in bitname else "net%s" % (b,)

    memo = {}

    def depth(b):
        """(lut levels, cells, start bit) of the deepest path arriving at bit b."""
        if b in memo:
            return memo[b]
        stack = [(b, False)]
        while stack:
            x, done = stack.pop()
            if x in memo:
                continue
            if x in start or x not in driver:
                memo[x] = (0, 0, x)
                continue
            t, ins = driver[x]
            if not done:
                stack.append((x, True))
                stack.extend((i, False) for i in ins if i not in memo)
                continue
            w = weight(t)
            best = (w[0], w[1], x)          # a cell without inputs (constant)
            for n, i in enumerate(ins):
                d = memo[i]
                cand = (d[0] + w[0], d[1] + w[1], d[2])
                if n == 0 or cand[:2] > best[:2]:
                    best = cand
            memo[x] = best
        return memo[b]

    worst = defaultdict(lambda: (-1, -1, None))
    for g, b in ends:
        d = depth(b)
        if d[:2] > worst[g][:2]:
            worst[g] = d
    rows = sorted(worst.items(), key=lambda kv: (-kv[1][0], -kv[1][1], kv[0]))
    print("| endpoint (register or sub-module input) | LUT levels | cells on path | deepest path starts at |")
    print("|---|---|---|---|")
    for g, (lut, cells, s) in rows:
        if lut <= 0:
            continue
        print("| %s | %d | %d | %s |" % (g, lut, cells, group(nm(s))))


if __name__ == "__main__":
    main()
