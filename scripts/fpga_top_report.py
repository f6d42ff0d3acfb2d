#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""fpga_top_report.py: the tables of `make fpga-pnr-top` (docs/fpga_board.md).

Usage: fpga_top_report.py <dir> <seed> [<seed> ...]
Reads <dir>/pree_ulx3s.json (the netlist nextpnr placed), <dir>/pree_ulx3s.stat.txt (Yosys's
cell counts), and per seed <dir>/seed<N>.report.json (nextpnr --report) and seed<N>.time (wall,
user and system seconds). Prints three Markdown tables: Fmax per seed with the critical path
(nextpnr's worst register-to-register path of the core clock: its start and end registers and
their RTL source lines, its delay split into logic and routing, its cells by type, each CCU2C
once) and nextpnr's run time; the placed design's use of every resource of the part (nextpnr,
first seed); Yosys's cell counts.
"""
import json
import re
import sys


def cell_types(netlist):
    """Each cell's type and its RTL source line (Yosys's src attribute, the first one)."""
    cells = json.load(open(netlist))["modules"]["pree_ulx3s"]["cells"]
    return ({name: c["type"] for name, c in cells.items()},
            {name: re.sub(r"\.\d+-\d+\.\d+$", "", c.get("attributes", {}).get("src", "?").split("|")[0])
             for name, c in cells.items()})


def reg_name(cell):
    """A flip-flop as nextpnr names it (after a net it drives), without the mapping suffix."""
    return re.sub(r"(_TRELLIS_FF|_MULT18X18D|_DP16KD).*$", "", cell)


def path_summary(path, types, srcs):
    """The path's registers with their RTL lines, its delay, its cells by type: nextpnr splits
    each CCU2C (two bits of a carry chain) into <name>$CCU2_COMB0/1, counted once here."""
    logic = sum(e["delay"] for e in path if e["type"] in ("logic", "clk-to-q", "setup"))
    route = sum(e["delay"] for e in path if e["type"] == "routing")
    cells = {}
    for e in path:
        if e["type"] == "logic":
            name = e["from"]["cell"]
            base = name.split("$CCU2_COMB")[0]
            cells[base] = "CCU2C" if "$CCU2_COMB" in name else types.get(name, "?")
    count = {}
    for t in cells.values():
        count[t] = count.get(t, 0) + 1
    start, end = path[0]["from"]["cell"], path[-1]["to"]["cell"]
    listed = ", ".join("%d %s" % (n, t) for t, n in sorted(count.items(), key=lambda x: -x[1]))
    return "%s (%s) -> %s (%s): %.2f ns (%.2f logic, %.2f routing); cells: %s" % (
        reg_name(start), srcs.get(start, "?"), reg_name(end), srcs.get(end, "?"),
        logic + route, logic, route, listed or "none")


def main():
    if len(sys.argv) < 3:
        raise SystemExit("usage: fpga_top_report.py <dir> <seed> [<seed> ...]")
    d, seeds = sys.argv[1], sys.argv[2:]
    types, srcs = cell_types(d + "/pree_ulx3s.json")
    print("| seed | Fmax (MHz) | target (MHz) | critical path (nextpnr, register to register) | nextpnr wall / CPU (s) |")
    print("|---|---|---|---|---|")
    first = None
    for s in seeds:
        rep = json.load(open("%s/seed%s.report.json" % (d, s)))
        first = first or rep
        wall, user, system = (float(x) for x in open("%s/seed%s.time" % (d, s)).read().split()[-3:])
        core = [k for k in rep["fmax"] if "clk" in k and "25mhz" not in k] or list(rep["fmax"])
        f = rep["fmax"][core[0]]
        paths = [p for p in rep["critical_paths"]
                 if not p["from"].startswith("<async>") and not p["to"].startswith("<async>")]
        crit = path_summary(paths[0]["path"], types, srcs) if paths else "-"
        print("| %s | %.1f | %g | %s | %.0f / %.0f |" % (s, f["achieved"], f["constraint"], crit,
                                                         wall, user + system))
    print()
    print("| resource (nextpnr) | used | available | use |")
    print("|---|---|---|---|")
    for bel, u in sorted(first["utilization"].items()):
        if u["available"]:
            print("| %s | %d | %d | %.1f%% |" % (bel, u["used"], u["available"],
                                                100.0 * u["used"] / u["available"]))
    print()
    print("| cell (Yosys) | count |")
    print("|---|---|")
    stat = open(d + "/pree_ulx3s.stat.txt").read()
    for m in re.finditer(r"^\s+(\d+)\s+([A-Z][A-Z0-9_]+)\s*$", stat, re.M):
        print("| %s | %s |" % (m.group(2), m.group(1)))


if __name__ == "__main__":
    main()
