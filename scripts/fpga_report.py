#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""fpga_report.py: one Markdown table row from a Yosys synth_ecp5 + nextpnr-ecp5 run.

Usage: fpga_report.py <config> <synth.json> <nextpnr report.json> <yosys stat.txt>
Prints
  | config | Fmax (MHz) | critical path | LUT4 | FF | CCU2C | MULT18 | EBR |
Fmax is nextpnr's achieved figure for the clock (register to register; the pins' paths are a
separate, unconstrained domain). The critical path is nextpnr's worst register-to-register path:
its start and end registers (the unit's seam, "u_seam<k>", or the wrapper's input / output
register, or inside pree_fpga_preu_wrap's PREU the register's instance path), its delay split into logic and routing, and its cells: LUT4 (and PFUMX / L6MUX21
wide-function muxes), CCU2C carry cells (each CCU2C holds two bits of a carry chain) and
MULT18X18D multipliers. Resources are Yosys's cell counts after synth_ecp5 (the wrapper's
input and output registers included in FF).
"""
import json
import re
import sys


def seam_of(cell):
    """The register a path starts or ends at, as the instance path inside the unit: nextpnr
    names a flip-flop after the net it drives, a seam's g_stage[r] register or data[r + 1]
    (data[0] is the seam's input, the previous seam's output), or the unit's s<k>_* wire
    (seam k's output); the wrapper's own registers are "input reg" and "output reg"."""
    name = re.sub(r"_TRELLIS_FF.*$", "", cell)
    for inst in ("u_preu.", "u_aftso."):               # the PREU's or the dispatcher's path
        if name.startswith(inst):
            return name[len(inst):]
    if cell.startswith("u_fold.g_fold[0].src_") and "_DI_" in cell:   # named after a chain of
        return "register"                              # cells from the fold's input: not recoverable
    if re.match(r"(in_q|mode_q|valid_q|stall_q)\b", name):
        return "input reg"
    if re.match(r"(out_q|g_fold)", name):
        return "output reg"
    name = re.sub(r"^(genblk\d+\.)*g_\w+\.g_(def|set)\.", "", name)
    if name.startswith("u_unit."):
        name = name[len("u_unit."):]
    else:
        return "output reg" if re.match(r"(y_q|valid_out_q)", name) else "input reg"
    m = re.match(r"(.*)\.g_reg\.(?:g_stage\[(\d+)\]\.\w+|data\[(\d+)\])$", name)
    if m:
        if m.group(3) == "0":
            return "reg into " + m.group(1)
        reg = int(m.group(2)) + 1 if m.group(2) is not None else int(m.group(3))
        return m.group(1) + (" (reg %d)" % reg if reg > 1 else "")
    name = re.sub(r"\.q_o$", "", name)                 # a seam's output port
    m = re.match(r"s(\d+)_\w+$", name)
    if m:
        return "u_seam" + m.group(1)
    if re.match(r"(y_o|valid_o)$", name):
        return "output of the last seam"
    if re.match(r"(a_i|b_i|t_i|sub_i|valid_i)$", name):
        return "input reg"
    return name


def main():
    if len(sys.argv) != 5:
        raise SystemExit("usage: fpga_report.py <config> <synth.json> <report.json> <stat.txt>")
    cfg, synth, report, stat = sys.argv[1:]
    mods = json.load(open(synth))["modules"]
    top = next(t for t in ("pree_fpga_preu_wrap", "pree_fpga_aftso_wrap", "pree_fpga_wrap") if t in mods)
    cells = mods[top]["cells"]
    types = {name: c["type"] for name, c in cells.items()}
    rep = json.load(open(report))

    clk = [k for k in rep["fmax"]][0]
    fmax = rep["fmax"][clk]["achieved"]
    paths = [p for p in rep["critical_paths"]
             if not p["from"].startswith("<async>") and not p["to"].startswith("<async>")]
    crit = "-"
    if paths:
        path = paths[0]["path"]
        logic = sum(e["delay"] for e in path if e["type"] in ("logic", "clk-to-q", "setup"))
        route = sum(e["delay"] for e in path if e["type"] == "routing")
        luts, muxes, mults, ccu = 0, 0, 0, set()
        for e in path:
            if e["type"] != "logic":
                continue
            name = e["from"]["cell"]
            base = name.split("$CCU2_COMB")[0]
            t = "CCU2C" if "$CCU2_COMB" in name else types.get(name, "?")
            if t == "CCU2C":
                ccu.add(base)
            elif t == "LUT4":
                luts += 1
            elif t in ("PFUMX", "L6MUX21"):
                muxes += 1
            elif t.startswith("MULT18"):
                mults += 1
        start, end = path[0]["from"]["cell"], path[-1]["to"]["cell"]
        parts = ["%d LUT4" % luts]
        if muxes:
            parts.append("%d PFUMX/L6MUX" % muxes)
        if ccu:
            parts.append("%d CCU2C" % len(ccu))
        if mults:
            parts.append("%d MULT18" % mults)
        crit = "%s -> %s: %.2f ns (%.2f logic, %.2f routing); %s" % (
            seam_of(start), seam_of(end), logic + route, logic, route, ", ".join(parts))

    count = {}
    for line in open(stat):
        m = re.match(r"^\s+(\d+)\s+(\S+)\s*$", line)
        if m:
            count[m.group(2)] = count.get(m.group(2), 0) + int(m.group(1))
    print("| %s | %.1f | %s | %d | %d | %d | %d | %d |" % (
        cfg, fmax, crit, count.get("LUT4", 0), count.get("TRELLIS_FF", 0), count.get("CCU2C", 0),
        count.get("MULT18X18D", 0), count.get("DP16KD", 0)))


if __name__ == "__main__":
    main()
