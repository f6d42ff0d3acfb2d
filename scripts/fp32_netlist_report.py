#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""fp32_netlist_report.py: resources and logic depth per stage of a Yosys synth_xilinx netlist.

Usage: fp32_netlist_report.py <netlist.json> <top> [--max]
With --max (for a design with feedback, whose registers have no stage number, like the PREU):
  | top | LUTs | FFs | DSP48E1 | CARRY4 | MUXF7/8 | most LUT levels | most cell levels | where |
the largest LUT and cell levels over every path between registers, and the register (or
output) that ends a path with the most LUT levels. Otherwise prints one Markdown table row:
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
The stage of a register is its depth in registers from the primary inputs: 1 + the largest
stage among the registers (or inputs, stage 0) that reach its D, CE or reset pins through
combinational logic. Every unit is a feed-forward pipeline whose data registers load on the
valid bit of the stage before, so this is the stage number of the RTL whatever the register
names (the seams of pree_fp32_pipe). A DSP48E1 with internal registers counts them: its P
output lies AREG (BREG) + MREG + PREG stages after its A (B) inputs (CREG + PREG after C, PREG
after PCIN); a path into such a DSP ends at its first register (with one DSP level when that
register follows the multiplier), and each later internal register closes a stage of one DSP
level. A primary output driven by logic (the combinational comparator) is stage 0.
IBUF/OBUF/BUFG cells count zero levels.
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


def main():
    if len(sys.argv) not in (3, 4) or (len(sys.argv) == 4 and sys.argv[3] != "--max"):
        raise SystemExit("usage: fp32_netlist_report.py <netlist.json> <top> [--max]")
    most = len(sys.argv) == 4
    mod = json.load(open(sys.argv[1]))["modules"][sys.argv[2]]

    # Combinational arcs, register inputs and register outputs.
    fanin = defaultdict(list)    # output bit -> [(input bit, cell weight)]
    regs = []                    # (name, {port group: (latency, first_after_mul, [in bits])}, [out bits])
    start_weight = {}            # register output bit -> depth it starts with (DSP post-adder)
    for cname, cell in mod["cells"].items():
        t, conns, dirs = cell["type"], cell["connections"], cell["port_directions"]
        ins = [b for p, bs in conns.items() if dirs[p] == "input" for b in bs if isinstance(b, int)]
        outs = [b for p, bs in conns.items() if dirs[p] == "output" for b in bs if isinstance(b, int)]
        if FF.match(t):
            d_ins = [b for p, bs in conns.items() if dirs[p] == "input" and p != "C"
                     for b in bs if isinstance(b, int)]
            regs.append((cname, {"D": (1, False, d_ins)}, conns["Q"]))
            continue
        if t.startswith("DSP48"):
            prm = {k: int(v, 2) if set(v) <= {"0", "1"} else 0 for k, v in cell["parameters"].items()}
            areg, breg = prm.get("AREG", 0), prm.get("BREG", 0)
            mreg, preg, creg = prm.get("MREG", 0), prm.get("PREG", 0), prm.get("CREG", 0)
            lat_ab = max(areg, breg) + mreg + preg
            if lat_ab + creg + preg > 0:
                groups = {}
                for p, bs in conns.items():
                    if dirs[p] != "input" or p in ("CLK",):
                        continue
                    bits = [b for b in bs if isinstance(b, int)]
                    if p in ("A", "D", "ACIN"):
                        groups.setdefault("A", (areg + mreg + preg, areg == 0, []))[2].extend(bits)
                    elif p in ("B", "BCIN"):
                        groups.setdefault("B", (breg + mreg + preg, breg == 0, []))[2].extend(bits)
                    elif p == "C":
                        groups.setdefault("C", (creg + preg, creg == 0, []))[2].extend(bits)
                    elif p in ("PCIN",):
                        groups.setdefault("PCIN", (preg, True, []))[2].extend(bits)
                    else:                              # clock enables, resets, modes
                        groups.setdefault("CTRL", (1, False, []))[2].extend(bits)
                out = [b for p, bs in conns.items() if dirs[p] == "output" for b in bs
                       if isinstance(b, int)]
                regs.append((cname, groups, out))
                if preg == 0:                          # P comes from the post-adder: one level
                    for b in out:
                        start_weight[b] = ((0, 0), 1, 1)
                continue
        w = weight(t)
        for o in outs:
            for i in ins:
                fanin[o].append((i, w))

    # Stage of every register output bit: its depth in registers from the inputs.
    sys.setrecursionlimit(100000)
    reg_of_out = {}
    for r in regs:
        for b in r[2]:
            if isinstance(b, int):
                reg_of_out[b] = r
    src_memo, reg_memo = {}, {}

    def src_stage(b):
        """Largest stage among the register outputs and inputs reaching bit b (inputs: 0)."""
        if b in src_memo:
            return src_memo[b]
        src_memo[b] = 0
        if b in reg_of_out:
            st = reg_stage(reg_of_out[b])
        else:
            st = max([src_stage(i) for i, _ in fanin.get(b, [])] or [0])
        src_memo[b] = st
        return st

    def reg_stage(r):
        """Stage of a register's outputs (for a DSP, its last internal register)."""
        if r[0] in reg_memo:
            return reg_memo[r[0]]
        reg_memo[r[0]] = 0
        st = 0
        for lat, _, bits in r[1].values():
            if lat:
                st = max(st, max([src_stage(b) for b in bits] or [0]) + lat)
        reg_memo[r[0]] = st
        return st

    # Endpoints: (bit, stage, weight of the ending cell); internal DSP stages as their own rows.
    endpoints = []
    dsp_inner = []                                    # (stage, weight)
    end_name = {}                                     # endpoint bit -> the register it enters
    for r in regs:
        for lat, after_mul, bits in r[1].values():
            if not lat:
                continue
            first = 0 if most else max([src_stage(b) for b in bits] or [0]) + 1
            w = (0, 0, 0, 1) if after_mul else (0, 0, 0, 0)
            for b in bits:
                endpoints.append((b, first, w))
                end_name.setdefault(b, r[2])
            for k in range(2, lat + 1):
                dsp_inner.append((first + k - 1, (0, 0, 0, 1)))
    for name, port in mod["ports"].items():
        if port["direction"] == "output":
            for b in port["bits"]:
                if isinstance(b, int):
                    endpoints.append((b, 0, (0, 0, 0, 0)))

    # Longest paths, memoised: by LUT count (with its carry count) and by all counted cells.
    memo = {}

    def depth(b):
        if b in memo:
            return memo[b]
        memo[b] = ((0, 0), 0, 0)           # cut any (unexpected) loop
        best_lut, best_all, dsp = start_weight.get(b, ((0, 0), 0, 0))
        if b not in reg_of_out:
            for i, w in fanin.get(b, []):
                (l, c), a, d = depth(i)
                best_lut = max(best_lut, (l + w[0], c + w[1]))
                best_all = max(best_all, a + sum(w))
                dsp = max(dsp, d + w[3])
        memo[b] = (best_lut, best_all, dsp)
        return memo[b]

    if most:
        worst = (-1, 0, "")
        cells_most = 0
        for b, _, w in endpoints:
            (l, c), a, d = depth(b)
            cells_most = max(cells_most, a + sum(w))
            if l + w[0] > worst[0]:
                worst = (l + w[0], c + w[1], end_name.get(b, "an output"))
        net_of = {}                                   # bit -> a readable net name
        for name, net in mod["netnames"].items():
            if not name.startswith("$"):
                for k, b in enumerate(net["bits"]):
                    if isinstance(b, int) and b not in net_of:
                        net_of[b] = "%s[%d]" % (name, k) if len(net["bits"]) > 1 else name
        where = worst[2] if isinstance(worst[2], str) else \
            next((net_of[b] for b in worst[2] if b in net_of), "a register")
        count = defaultdict(int)
        for cell in mod["cells"].values():
            t = cell["type"]
            count["LUT" if LUT.match(t) else "FF" if FF.match(t) else "MUXF" if t.startswith("MUXF") else t] += 1
        print("| %s | %d | %d | %d | %d | %d | %d | %d | %s |" % (
            sys.argv[2], count["LUT"], count["FF"], count["DSP48E1"], count["CARRY4"], count["MUXF"],
            worst[0], cells_most, where))
        return

    stages = {}
    for b, st, w in endpoints:
        (l, c), a, d = depth(b)
        l, c, a, d = l + w[0], c + w[1], a + sum(w), d + w[3]
        old = stages.get(st, ((0, 0), 0, 0))
        stages[st] = (max(old[0], (l, c)), max(old[1], a), max(old[2], d))
    for st, w in dsp_inner:
        old = stages.get(st, ((0, 0), 0, 0))
        stages[st] = (old[0], max(old[1], 1), max(old[2], 1))
    rows = []
    for st in sorted(stages):
        (l, c), a, d = stages[st]
        if st == 0 and len(stages) > 1 and l == 0 and a == 0:
            continue                       # registered outputs: no logic after the last stage
        rows.append((l, a, c, d))

    count = defaultdict(int)
    dspregs = defaultdict(int)       # DSPs using their A/B, M and P registers
    for cell in mod["cells"].values():
        t = cell["type"]
        kind = ("LUT" if LUT.match(t) else "FF" if FF.match(t) else "MUXF" if t.startswith("MUXF")
                else t)
        count[kind] += 1
        if t.startswith("DSP48"):
            prm = cell["parameters"]
            reg = lambda k: int(prm.get(k, "0"), 2) if set(prm.get(k, "0")) <= {"0", "1"} else 0
            if reg("AREG") or reg("BREG"):
                dspregs["A/B"] += 1
            if reg("MREG"):
                dspregs["M"] += 1
            if reg("PREG"):
                dspregs["P"] += 1
    used = [("%d with %s register" % (dspregs[k], k)) for k in ("A/B", "M", "P") if dspregs[k]]
    dsp = "%d" % count["DSP48E1"] + (" (%s)" % ", ".join(used) if used else "")
    print("| %s | %d | %d | %s | %d | %d | %s | %s |" % (
        sys.argv[2], count["LUT"], count["FF"], dsp, count["CARRY4"], count["MUXF"],
        " / ".join("%d" % r[0] for r in rows),
        " / ".join("%d%s" % (r[1], " (DSP)" if r[3] else "") for r in rows)))


if __name__ == "__main__":
    main()
