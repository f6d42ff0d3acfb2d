#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""fpga_top_report.py: the tables of `make fpga-pnr-top` (docs/fpga_board.md).

Usage: fpga_top_report.py <dir> <seed> [<seed> ...]
Reads <dir>/pree_ulx3s.json (the netlist nextpnr placed), <dir>/pree_ulx3s.stat.txt (Yosys's
cell counts), and per seed <dir>/seed<N>.result ("routed" or "not routed: <why>"),
seed<N>.log (nextpnr's), seed<N>.time (wall, user and system seconds) and, if routed,
seed<N>.report.json (nextpnr --report). Prints three Markdown tables: per seed the core clock's
Fmax estimated after placement and reached after routing, the critical path (nextpnr's worst
register-to-register path of the core clock: its start and end registers and their RTL source
lines, its delay split into logic and routing, its cells by type, each CCU2C once) or, for a seed
that did not route, why and how far the router came, and nextpnr's run time; the placed design's
use of every resource of the part (nextpnr, the first routed seed); Yosys's cell counts.
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


def placed_fmax(log):
    """The core clock's Fmax that nextpnr estimates after placement (its first report), or None."""
    m = re.search(r"Max frequency for clock '[^']*clk'[^:]*: ([\d.]+) MHz", log)
    return float(m.group(1)) if m else None


def router_progress(log):
    """How far the router came: router2's best pass (fewest overused wires) and its last one;
    router1's arcs still to route at its last progress line."""
    iters = [(int(i), int(o)) for i, o in re.findall(r"iter=(\d+) wires=\d+ overused=(\d+)", log)]
    if not iters:
        r1 = re.findall(r"^Info:\s+(\d+) \|\s+\d+\s+\d+ \|\s+-?\d+\s+-?\d+ \|\s+(\d+)\|", log, re.M)
        if r1:
            return "router1: %d arcs left to route after %d iterations" % (int(r1[-1][1]), int(r1[-1][0]))
        return "the router did not start"
    best = min(iters, key=lambda x: (x[1], x[0]))
    return "router2: %d overused wires at best (pass %d), %d at pass %d" % (
        best[1], best[0], iters[-1][1], iters[-1][0])


def main():
    if len(sys.argv) < 3:
        raise SystemExit("usage: fpga_top_report.py <dir> <seed> [<seed> ...]")
    d, seeds = sys.argv[1], sys.argv[2:]
    types, srcs = cell_types(d + "/pree_ulx3s.json")
    print("| seed | after placement (MHz) | Fmax after routing (MHz) | target (MHz) | "
          "critical path (nextpnr, register to register) | nextpnr wall / CPU (s) |")
    print("|---|---|---|---|---|---|")
    first = None
    for s in seeds:
        base = "%s/seed%s" % (d, s)
        result = open(base + ".result").read().strip()
        log = open(base + ".log", errors="replace").read()
        placed = placed_fmax(log)
        wall, user, system = (float(x) for x in open(base + ".time").read().split()[-3:])
        if result != "routed":
            print("| %s | %s | %s | - | %s; %s | %.0f / %.0f |" % (
                s, "%.2f" % placed if placed else "-", result.split(":")[0], result.split(": ", 1)[-1],
                router_progress(log), wall, user + system))
            continue
        rep = json.load(open(base + ".report.json"))
        first = first or rep
        core = [k for k in rep["fmax"] if "clk" in k and "25mhz" not in k] or list(rep["fmax"])
        f = rep["fmax"][core[0]]
        paths = [p for p in rep["critical_paths"]
                 if not p["from"].startswith("<async>") and not p["to"].startswith("<async>")]
        crit = path_summary(paths[0]["path"], types, srcs) if paths else "-"
        print("| %s | %s | **%.2f** | %g | %s | %.0f / %.0f |" % (
            s, "%.2f" % placed if placed else "-", f["achieved"], f["constraint"], crit, wall,
            user + system))
    if first is not None:
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
