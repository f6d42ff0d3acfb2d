#!/usr/bin/env python3
"""fp32_netlist_report.py: resources and logic depth per stage of a Yosys synth_xilinx netlist.

Usage: fp32_netlist_report.py <netlist.json> <top>
Prints one Markdown table row:
  | top | LUTs | FFs | DSP48E1 | CARRY4 | MUXF7/8 | LUT levels per stage | cell levels per stage |
where the per-stage figures are listed stage 1, 2, ... separated by " / " (stage 0 alone for a
combinational unit). A pipeline register that Yosys moved into a DSP48E1 (its P register) is
not in the FF column; the DSP column says how many DSPs use one.

Method: the flattened netlist is a graph of bit nets. A path starts at a primary input or a
flip-flop output (FD*) and ends at a flip-flop input or a primary output. Every combinational
cell is traversed from each input bit to each output bit (conservative for CARRY4: a carry
chain CI -> CO counts one level per CARRY4, the real critical path of a wide adder).
  lut_levels  = the most LUT1..LUT6 cells on any path ending in the stage (the usual "LUT levels");
  cell_levels = the most LUT, CARRY4, MUXF7/8 and DSP48E1 cells on any such path (what
                `ltp` would count between registers);
  dsp         = 1 when some path of the stage passes through a DSP48E1 (combinational multiply).
A DSP48E1 whose output register is used (PREG = 1) holds a pipeline register: its multiply
ends a path and its outputs start new ones.
The stage of an endpoint is read from the register name its flip-flop drives: s<k>_*_q and
g_stage[<k>].*_q are stage-k registers, valid_q[k] belongs to stage k+1; a primary output driven by logic (the
combinational comparator) is stage 0. IBUF/OBUF/BUFG cells count zero levels.
"""
import json
import re
import sys
from collections import defaultdict

FF = re.compile(r"^FD[A-Z]*(_1)?$")
LUT = re.compile(r"^LUT[1-6]$")
ZERO = {"IBUF", "OBUF", "BUFG", "INV"}   # counted as wires


def weight(cell_type):
    """(lut, carry, muxf, dsp) contributed by one cell."""
    if LUT.match(cell_type):
        return (1, 0, 0, 0)
    if cell_type == "CARRY4":
        return (0, 1, 0, 0)
    if cell_type in ("MUXF7", "MUXF8"):
        return (0, 0, 1, 0)
    if cell_type.startswith("DSP48"):
        return (0, 0, 0, 1)
    if cell_type in ZERO:
        return (0, 0, 0, 0)
    raise SystemExit("fp32_netlist_report: unknown cell type %s" % cell_type)


def stage_of(names):
    """Stage of a register from its name: s<k>_*_q, or g_stage[<k>].*_q in generate loops."""
    for n in names:
        m = re.match(r"^\\?s(\d+)_\w*_q$", n) or re.match(r"^\\?g_stage\[(\d+)\]\..*_q$", n)
        if m:
            return int(m.group(1))
    return None


def main():
    if len(sys.argv) != 3:
        raise SystemExit("usage: fp32_netlist_report.py <netlist.json> <top>")
    mod = json.load(open(sys.argv[1]))["modules"][sys.argv[2]]

    # Names of each bit (registers keep their RTL names on the flip-flop outputs).
    names = defaultdict(list)
    valid_bit = {}
    for name, net in mod["netnames"].items():
        for i, b in enumerate(net["bits"]):
            if isinstance(b, int):
                names[b].append(name)
                if name == "valid_q":
                    valid_bit[b] = i + 1

    # Combinational arcs and endpoints.
    fanin = defaultdict(list)    # output bit -> [(input bit, cell weight)]
    endpoints = []               # (bit, stage, weight of the ending cell)
    for cell in mod["cells"].values():
        t, conns, dirs = cell["type"], cell["connections"], cell["port_directions"]
        ins = [b for p, bs in conns.items() if dirs[p] == "input" for b in bs if isinstance(b, int)]
        outs = [b for p, bs in conns.items() if dirs[p] == "output" for b in bs if isinstance(b, int)]
        w = (0, 0, 0, 0) if FF.match(t) else weight(t)
        registered_dsp = t.startswith("DSP48") and int(cell["parameters"].get("PREG", "0"), 2) == 1
        if FF.match(t) or registered_dsp:
            # A DSP48E1 with PREG = 1 has absorbed a pipeline register: its multiply ends a
            # path (one DSP level) and its P outputs start new ones.
            q = conns["P" if registered_dsp else "Q"][0]
            st = valid_bit.get(q, stage_of(names[q]))
            if st is None:
                raise SystemExit("fp32_netlist_report: register output %s has no stage name" % names[q])
            for b in ins:
                endpoints.append((b, st, w))
            continue
        for o in outs:
            for i in ins:
                fanin[o].append((i, w))
    for name, port in mod["ports"].items():
        if port["direction"] == "output":
            for b in port["bits"]:
                if isinstance(b, int):
                    endpoints.append((b, 0, (0, 0, 0, 0)))

    # Longest paths, memoised: by LUT count (with its carry count) and by all counted cells.
    sys.setrecursionlimit(100000)
    memo = {}

    def depth(b):
        if b in memo:
            return memo[b]
        memo[b] = ((0, 0), 0, 0)           # cut any (unexpected) loop
        best_lut, best_all, dsp = (0, 0), 0, 0
        for i, w in fanin.get(b, []):
            (l, c), a, d = depth(i)
            best_lut = max(best_lut, (l + w[0], c + w[1]))
            best_all = max(best_all, a + sum(w))
            dsp = max(dsp, d + w[3])
        memo[b] = (best_lut, best_all, dsp)
        return memo[b]

    stages = {}
    for b, st, w in endpoints:
        (l, c), a, d = depth(b)
        l, c, a, d = l + w[0], c + w[1], a + sum(w), d + w[3]
        old = stages.get(st, ((0, 0), 0, 0))
        stages[st] = (max(old[0], (l, c)), max(old[1], a), max(old[2], d))
    rows = []
    for st in sorted(stages):
        (l, c), a, d = stages[st]
        if st == 0 and len(stages) > 1 and l == 0 and a == 0:
            continue                       # registered outputs: no logic after the last stage
        rows.append((l, a, c, d))

    count = defaultdict(int)
    preg = 0
    for cell in mod["cells"].values():
        t = cell["type"]
        kind = ("LUT" if LUT.match(t) else "FF" if FF.match(t) else "MUXF" if t.startswith("MUXF")
                else t)
        count[kind] += 1
        if t.startswith("DSP48") and int(cell["parameters"].get("PREG", "0"), 2) == 1:
            preg += 1
    dsp = "%d" % count["DSP48E1"] + (" (%d with P register)" % preg if preg else "")
    print("| %s | %d | %d | %s | %d | %d | %s | %s |" % (
        sys.argv[2], count["LUT"], count["FF"], dsp, count["CARRY4"], count["MUXF"],
        " / ".join("%d" % r[0] for r in rows),
        " / ".join("%d%s" % (r[1], " (DSP)" if r[3] else "") for r in rows)))


if __name__ == "__main__":
    main()
