#!/usr/bin/env python3
"""synth_top_depth.py: logic depth of pree_top's own paths in a Yosys synth_xilinx netlist.

Usage: synth_top_depth.py NETLIST.json [MODULE]   (MODULE: default pree_top)
Prints a Markdown table: for each group of path endpoints in MODULE (a register, or an input
of a sub-module such as a PREU, a controller or a RAM bank), the most LUT levels and the most
cells (LUT + CARRY4 + MUXF7/8) on any path ending there, and where that path starts.

Method: MODULE is read with its hierarchy kept, so its paths are its own logic. A path starts
at a flip-flop output (FD*), an output of a sub-module instance (PREU, controller, RAM bank),
or a module input, and ends at a flip-flop input, a sub-module input or a module output.
Every combinational cell is traversed from each input bit to each output bit (conservative for
CARRY4: one level per CARRY4 of a chain). Endpoints are grouped by name with bit and generate
indices removed (g_hp[3].u_state.raddr_i[5] -> g_hp[*].u_state.raddr_i). These are logic
levels after mapping, not timing: no place and route is run.
"""
import json
import re
import sys
from collections import defaultdict

FF = re.compile(r"^FD[A-Z]*(_1)?$")
LUT = re.compile(r"^LUT[1-6]$")
WIRE = {"IBUF", "OBUF", "BUFG", "INV", "BUF"}
COMB = {"CARRY4", "MUXF7", "MUXF8"}


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


def main():
    if len(sys.argv) not in (2, 3):
        raise SystemExit(__doc__)
    top = sys.argv[2] if len(sys.argv) == 3 else "pree_top"
    with open(sys.argv[1]) as f:
        mod = json.load(f)["modules"][top]

    # A readable name per bit (prefer public names, then the shortest).
    bitname = {}
    for n, info in mod["netnames"].items():
        hidden = info.get("hide_name", 0) or n.startswith("$")
        for i, b in enumerate(info["bits"]):
            if isinstance(b, str):
                continue
            label = n if len(info["bits"]) == 1 else "%s[%d]" % (n, i)
            key = (hidden, len(label))
            if b not in bitname or key < bitname[b][0]:
                bitname[b] = (key, label)

    def nm(b):
        return bitname[b][1] if b in bitname else "net%s" % b

    driver = {}        # bit -> (cell type, input bits) for combinational cells
    start = set()      # bits at which paths start
    ends = []          # (group name, bit)
    for p, info in mod["ports"].items():
        for b in info["bits"]:
            if isinstance(b, str):
                continue
            if info["direction"] == "input":
                start.add(b)
            else:
                ends.append((group(p), b))
    for cname, c in mod["cells"].items():
        t = c["type"]
        dirs = c.get("port_directions", {})
        ins = [b for p, bs in c["connections"].items() if dirs.get(p) == "input" for b in bs
               if not isinstance(b, str)]
        outs = [b for p, bs in c["connections"].items() if dirs.get(p) == "output" for b in bs
                if not isinstance(b, str)]
        if LUT.match(t) or t in COMB or t in WIRE:
            for b in outs:
                driver[b] = (t, ins)
        elif FF.match(t):
            for b in outs:
                start.add(b)
            q = [b for b in c["connections"].get("Q", []) if not isinstance(b, str)]
            reg = group(nm(q[0])) if q else group(cname)
            for b in ins:
                ends.append((reg, b))
        else:   # a sub-module or a RAM primitive: a boundary
            for b in outs:
                start.add(b)
            inst = group(cname)
            for p, bs in c["connections"].items():
                if dirs.get(p) == "input":
                    for b in bs:
                        if not isinstance(b, str):
                            ends.append(("%s.%s" % (inst, p), b))

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
