#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""postroute_sdf.py: nextpnr-ecp5's SDF (--sdf) made into what Icarus Verilog 11's $sdf_annotate
applies, with the routed netlist it belongs to (docs/fpga_board.md, "Timing-annotated run").

Icarus 11 applies an SDF IOPATH to the matching specify path of a cell (tb/postroute/ models)
and nothing else: it ignores INTERCONNECT (with a warning under -sdf-warn), every timing check
(SETUPHOLD and the others) and the TIMESCALE (the numbers are taken in the annotated module's
time unit); it finds a cell by its instance name, which nextpnr's flattened names (dots,
brackets, "$") and Yosys's renaming of "$" names do not give. So this script rewrites both:
  - an IOPATH of zero delay is left out (the models' paths are zero; nextpnr's names for the
    write port's zero paths of TRELLIS_RAMW are not the model's wiring);
  - every cell is renamed c<N> (the JSON and the SDF; <out.sdf>.names lists the old names);
  - a wire's delay to a cell input that has IOPATHs and no timing check is added to each IOPATH
    from that input (the larger of its rise and fall delays, to both of the path's);
  - a wire's delay to any other input (a flip-flop's, an EBR's, a pin's), or to an input that
    shares its net with another input of the cell (Icarus merges those and finds the IOPATHs of
    one name only), goes into a ROUTE_DELAY cell (tb/postroute/ecp5_route_delay.v) put in front of that input, whose IOPATH A Z it is;
    a data input's setup time (SETUPHOLD, SETUP, RECOVERY: the largest of its checks) is added
    to it, so that data arriving after (edge - setup) is sampled at the next edge, as the
    silicon would fail it; hold and width checks are dropped (counted);
  - the delays are written in picoseconds (min:typ:max triples kept, TIMESCALE 1ps);
  - the cells go into submodules of 256 (instances g<K>, SDF instances g<K>/c<N>): Icarus looks
    an SDF instance up by a linear search of its scope, minutes for 60,000 cells in one.
The counts of each are printed. A cell, pin or triple the netlist does not have is an error.

usage: postroute_sdf.py <sim.json> <routed.sdf> <out.json> <out.sdf>
  <sim.json>: scripts/postroute_netlist.py's output; <routed.sdf>: nextpnr's SDF of the same run.
"""
import json
import os
import re
import sys

TOKEN = re.compile(r'\(|\)|"[^"]*"|(?:\\.|[^\s()"\\])+')
UNIT_PS = {"1ps": 1, "10ps": 10, "100ps": 100, "1ns": 1000, "10ns": 10000, "100ns": 100000}
SETUP_CHECKS = ("SETUPHOLD", "SETUP", "RECOVERY")
DELAY_CELL = "ROUTE_DELAY"
GROUP = 256   # cells a submodule (group_cells)


class SdfError(Exception):
    pass


def parse(text):
    """The SDF as nested lists of tokens."""
    stack, cur = [], []
    for tok in TOKEN.findall(text):
        if tok == "(":
            stack.append(cur)
            cur = []
        elif tok == ")":
            if not stack:
                raise SdfError("unbalanced ')'")
            done, cur = cur, stack.pop()
            cur.append(done)
        else:
            cur.append(tok)
    if stack or len(cur) != 1:
        raise SdfError("unbalanced '('")
    return cur[0]


def unescape(name):
    return re.sub(r"\\(.)", r"\1", name)


def split_pin(ref):
    """inst/pin (the divider '/', escaped where part of a name) -> (inst, pin), unescaped."""
    m = re.match(r"^((?:\\.|[^/\\])*)/((?:\\.|[^/\\])+)$", ref)
    if not m:
        raise SdfError(f"'{ref}' is not instance/pin")
    return unescape(m.group(1)), unescape(m.group(2))


def triple(item, scale):
    """['min:typ:max'] (or one value) -> [min, typ, max] in ps."""
    if not isinstance(item, list) or len(item) != 1:
        raise SdfError(f"a delay value {item!r} is not (min:typ:max)")
    parts = item[0].split(":")
    if len(parts) == 1:
        parts = parts * 3
    try:
        return [round(float(p) * scale) for p in parts]
    except ValueError:
        raise SdfError(f"a delay value {item[0]!r} is not a number") from None


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def vmax(a, b):
    return [max(x, y) for x, y in zip(a, b)]


def port_name(spec):
    """An IOPATH or check port: PIN or (posedge PIN) -> (edge or None, PIN)."""
    if isinstance(spec, list):
        return spec[0], unescape(spec[1])
    return None, unescape(spec)


def read_sdf(path):
    """-> scale, {inst: (celltype, [(edge, in, out, rise, fall)], {pin: setup}, checks dropped)},
    [(src inst, src pin, dst inst, dst pin, delay)]"""
    with open(path) as f:
        sdf = parse(f.read())
    if not sdf or sdf[0] != "DELAYFILE":
        raise SdfError("not an SDF DELAYFILE")
    scale = 1
    cells, wires = {}, []
    for item in sdf[1:]:
        if item[0] == "TIMESCALE":
            unit = "".join(item[1:])
            if unit not in UNIT_PS:
                raise SdfError(f"TIMESCALE {unit} not handled")
            scale = UNIT_PS[unit]
        if item[0] != "CELL":
            continue
        ctype = inst = None
        paths, setup, dropped = [], {}, 0
        for sub in item[1:]:
            if sub[0] == "CELLTYPE":
                ctype = sub[1].strip('"')
            elif sub[0] == "INSTANCE":
                inst = unescape(sub[1]) if len(sub) > 1 else ""
            elif sub[0] == "DELAY":
                for kind in sub[1:]:
                    if kind[0] != "ABSOLUTE":
                        raise SdfError(f"cell {inst}: DELAY {kind[0]} not handled")
                    for d in kind[1:]:
                        if d[0] == "IOPATH":
                            edge, pin_in = port_name(d[1])
                            vals = [triple(v, scale) for v in d[3:]]
                            if any(vals[0]) or any(vals[-1]):   # zero: the model's default
                                paths.append((edge, pin_in, unescape(d[2]), vals[0], vals[-1]))
                        elif d[0] == "INTERCONNECT":
                            vals = [triple(v, scale) for v in d[3:]]
                            wires.append(split_pin(d[1]) + split_pin(d[2]) + (vmax(vals[0], vals[-1]),))
                        else:
                            raise SdfError(f"cell {inst}: {d[0]} not handled")
            elif sub[0] == "TIMINGCHECK":
                for c in sub[1:]:
                    if c[0] in SETUP_CHECKS:
                        _, pin = port_name(c[1])
                        s = triple(c[3], scale)
                        setup[pin] = vmax(setup.get(pin, [0, 0, 0]), s)
                        if c[0] == "SETUPHOLD" and any(triple(c[4], scale)):
                            dropped += 1   # its hold time
                    else:
                        dropped += 1
        if inst is None or ctype is None:
            raise SdfError("a CELL without CELLTYPE or INSTANCE")
        if inst in cells:
            raise SdfError(f"cell {inst} appears twice")
        cells[inst] = (ctype, paths, setup, dropped)
    return scale, cells, wires


def fmt(v):
    return "(%d:%d:%d)" % tuple(v)


def group_cells(design, top, cells):
    """Puts the cells into GROUP-cell submodules g<K> (modules pree_sdf_g<K>) of the top module:
    Icarus finds each SDF instance by a linear search of its scope, which over 60,000 cells of
    one scope takes minutes; two levels take a second. -> {cell: its group's instance name}"""
    order = sorted(cells)
    group = {c: f"g{i // GROUP}" for i, c in enumerate(order)}
    driver, users = {}, {}
    for c, cell in cells.items():
        for port, bits in cell["connections"].items():
            for b in bits:
                if isinstance(b, int):
                    if cell["port_directions"].get(port) == "output":
                        driver[b] = group[c]
                    else:
                        users.setdefault(b, set()).add(group[c])
    for port in top["ports"].values():
        for b in port["bits"]:
            if isinstance(b, int):
                users.setdefault(b, set()).add("" if port["direction"] == "output" else None)
    top_cells = {}
    for k in range(0, len(order), GROUP):
        g = group[order[k]]
        members = {c: cells[c] for c in order[k:k + GROUP]}
        bits = sorted({b for cell in members.values() for bits in cell["connections"].values()
                       for b in bits if isinstance(b, int)})
        ports = {}
        for b in bits:
            if driver.get(b) == g:
                if users.get(b, set()) - {g}:
                    ports[f"n{b}"] = {"direction": "output", "bits": [b]}
            else:
                ports[f"n{b}"] = {"direction": "input", "bits": [b]}
        design["modules"][f"pree_sdf_{g}"] = {
            "attributes": {}, "ports": ports, "cells": members,
            "netnames": {f"n{b}": {"hide_name": 0, "bits": [b], "attributes": {}} for b in bits}}
        top_cells[g] = {"hide_name": 0, "type": f"pree_sdf_{g}", "parameters": {}, "attributes": {},
                        "port_directions": {p: v["direction"] for p, v in ports.items()},
                        "connections": {p: v["bits"] for p, v in ports.items()}}
    top["cells"] = top_cells
    return group


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: postroute_sdf.py <sim.json> <routed.sdf> <out.json> <out.sdf>")
    src_json, src_sdf, dst_json, dst_sdf = sys.argv[1:]
    try:
        with open(src_json) as f:
            design = json.load(f)
        (top,) = design["modules"].values()
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"{src_json}: not a netlist of scripts/postroute_netlist.py ({e})")
    try:
        _, sdf_cells, wires = read_sdf(src_sdf)
    except (OSError, SdfError) as e:
        sys.exit(f"{src_sdf}: {e}")
    cells = top["cells"]
    for inst, (ctype, _, _, _) in sdf_cells.items():
        if inst and (inst not in cells or cells[inst]["type"] != ctype):
            sys.exit(f"{src_sdf}: cell {inst} ({ctype}) is not in {src_json}")

    n = {"iopath": 0, "wire_zero": 0, "shared_net": 0, "wire_folded": 0, "wire_cell": 0, "setup_cell": 0,
         "checks_dropped": sum(c[3] for c in sdf_cells.values())}
    # The delay before each cell input: the wire's, and (data inputs) the setup time.
    pin_delay = {}
    for _, _, inst, pin, d in wires:
        if inst not in cells or pin not in cells[inst]["connections"]:
            sys.exit(f"{src_sdf}: INTERCONNECT to {inst}/{pin}: no such cell input in {src_json}")
        if any(d):
            pin_delay[(inst, pin)] = vmax(pin_delay.get((inst, pin), [0, 0, 0]), d)
        else:
            n["wire_zero"] += 1
    paths = {inst: list(c[1]) for inst, c in sdf_cells.items() if inst}
    # Inputs of one cell on one net: Icarus merges them and finds the IOPATHs of only one of
    # their names, so each gets a delay cell (one of zero delay where the wire has none).
    cell_delay = {}
    for inst in paths:
        on_net = {}
        for pin, conn in cells[inst]["connections"].items():
            if cells[inst]["port_directions"].get(pin) == "input" and conn and not isinstance(conn[0], str):
                on_net.setdefault(conn[0], []).append(pin)
        for pins in on_net.values():
            if len(pins) > 1:
                for pin in pins:
                    cell_delay[(inst, pin)] = pin_delay.get((inst, pin), [0, 0, 0])
                    n["shared_net"] += 1
    for (inst, pin), d in pin_delay.items():
        ps = paths.get(inst, [])
        checked = pin in sdf_cells.get(inst, (None, [], {}, 0))[2]
        if (inst, pin) in cell_delay:
            continue
        if not checked and any(p[1] == pin for p in ps):
            paths[inst] = [(e, i, o, add(r, d), add(f, d)) if i == pin else (e, i, o, r, f)
                           for e, i, o, r, f in ps]
            n["wire_folded"] += 1
        else:
            cell_delay[(inst, pin)] = d
    for inst, (_, _, setup, _) in sdf_cells.items():
        for pin, s in setup.items():
            conn = cells[inst]["connections"].get(pin, [])
            if any(s) and conn and not isinstance(conn[0], str):   # a constant needs no setup
                if (inst, pin) not in cell_delay:
                    n["setup_cell"] += 1
                cell_delay[(inst, pin)] = add(cell_delay.get((inst, pin), [0, 0, 0]), s)

    # Rename the cells, put the delay cells in, group them, write both.
    names = {old: f"c{i}" for i, old in enumerate(sorted(cells))}
    next_bit = 1 + max(b for net in top["netnames"].values() for b in net["bits"] if isinstance(b, int))
    new_cells = {names[k]: v for k, v in cells.items()}
    entries = []   # (cell, CELLTYPE, its IOPATH lines)
    for inst, (ctype, _, _, _) in sdf_cells.items():
        ps = paths.get(inst, [])
        if inst and ps:
            entries.append((names[inst], ctype, [f"({e} {i})" if e else i for e, i, _, _, _ in ps], ps))
    for k, ((inst, pin), d) in enumerate(sorted(cell_delay.items())):
        conn = cells[inst]["connections"][pin]
        if len(conn) != 1:
            sys.exit(f"{src_json}: cell {inst} pin {pin} is not one bit")
        name = f"d{k}"
        new_cells[name] = {"hide_name": 0, "type": DELAY_CELL, "parameters": {}, "attributes": {},
                           "port_directions": {"A": "input", "Z": "output"},
                           "connections": {"A": list(conn), "Z": [next_bit]}}
        cells[inst]["connections"][pin] = [next_bit]
        next_bit += 1
        if any(d):
            entries.append((name, DELAY_CELL, ["A"], [(None, "A", "Z", d, d)]))
        n["wire_cell"] += 1
    n["setup_only_cells"] = n.pop("setup_cell")
    group = group_cells(design, top, new_cells)
    out = []
    for name, ctype, srcs, ps in sorted(entries, key=lambda e: e[0]):
        out.append(f'  (CELL (CELLTYPE "{ctype}") (INSTANCE {group[name]}/{name})\n    (DELAY (ABSOLUTE\n')
        for src, (_, _, o, r, f) in zip(srcs, ps):
            out.append(f"      (IOPATH {src} {o} {fmt(r)} {fmt(f)})\n")
            n["iopath"] += 1
        out.append("    )))\n")

    for path, write in ((dst_json, lambda f: json.dump(design, f)),
                        (dst_sdf, lambda f: f.write('(DELAYFILE\n  (SDFVERSION "3.0")\n  (DESIGN "top")\n'
                                                    '  (DIVIDER /)\n  (TIMESCALE 1ps)\n'
                                                    + "".join(out) + ")\n")),
                        (dst_sdf + ".names", lambda f: f.write("".join(f"{v}\t{k}\n" for k, v in names.items())))):
        with open(path + ".tmp", "w") as f:
            write(f)
        os.replace(path + ".tmp", path)
    print(f"postroute_sdf: {len(wires)} INTERCONNECT: {n['wire_zero']} zero, {n['wire_folded']} added to "
          f"their cell's IOPATHs, {n['wire_cell']} {DELAY_CELL} cells ({n['setup_only_cells']} of them "
          f"for a setup time alone, {n['shared_net']} for inputs that share a net); {n['iopath']} IOPATH written; {n['checks_dropped']} hold/width "
          f"checks (or hold parts of SETUPHOLD) dropped")


if __name__ == "__main__":
    main()
