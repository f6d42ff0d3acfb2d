#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""postroute_netlist.py: nextpnr-ecp5's routed design (--write JSON) made ready for simulation
with the cell models of tb/postroute/ (docs/fpga_board.md, "Post-route simulation").

nextpnr leaves a cell input unconnected where the silicon's default level drives it (a pin tied
to a constant that needed no route). Each such input is tied here to that level:
  TRELLIS_COMB A..D high (a carry's unrouted LUT input is tied high; a logic LUT's INITVAL no
    longer depends on it), the rest low; DP16KD CLK/CE/OCE/WE/RST/CS high (the CIB's default;
    an "INV" mux turns that into low), the rest low (their constant is the cell's <pin>MUX);
  TRELLIS_FF LSR inactive (low with LSRMUX "LSR"), CE high; DCCA CE high; any other input low;
  MULT18X18D's cascade inputs SRIA / SRIB stay unconnected (the model has no cascade: SOURCEA
  and SOURCEB must be low).
A TRELLIS_IO's pad B becomes PAD_IN on an input pin, PAD_OUT on an output pin (the model's pad
is one-way: the simulators take no bidirectional pad on a top port).
TRELLIS_COMB also gets OFXMUX from its placement: "F5" on a slice's first LUT (OFX = M ? F1 : F),
"F6" on its second (OFX = M ? FXB : FXA). Cell types outside the models' list are an error.

usage: postroute_netlist.py <routed.json> <out.json>
"""
import json
import sys

MODELLED = {"TRELLIS_COMB", "TRELLIS_RAMW", "TRELLIS_FF", "DP16KD", "MULT18X18D", "DCCA",
            "EHXPLLL", "TRELLIS_IO"}
DP_HIGH = ("CLKA", "CLKB", "CEA", "CEB", "OCEA", "OCEB", "WEA", "WEB", "RSTA", "RSTB",
           "CSA0", "CSA1", "CSA2", "CSB0", "CSB1", "CSB2")
# The ports of the cells whose JSON may omit unconnected ones (nextpnr writes only those it has).
COMB_IN = "A B C D M F1 FCI FXA FXB DI0 DI1 WD WAD0 WAD1 WAD2 WAD3 WRE WCK".split()
FF_IN = "CLK LSR CE DI M".split()


def default_level(ctype, port, params):
    if ctype == "TRELLIS_COMB":
        return "1" if port in ("A", "B", "C", "D") else "0"
    if ctype == "DP16KD":
        return "1" if port in DP_HIGH else "0"
    if ctype == "TRELLIS_FF":
        if port == "LSR":
            return "1" if params.get("LSRMUX", "LSR").strip() == "INV" else "0"
        return "1" if port == "CE" else "0"
    if ctype == "DCCA":
        return "1" if port == "CE" else "0"
    return "0"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: postroute_netlist.py <routed.json> <out.json>")
    src, dst = sys.argv[1], sys.argv[2]
    try:
        with open(src) as f:
            design = json.load(f)
        top = design["modules"]["top"] if "top" in design["modules"] else None
        if top is None:
            (top,) = design["modules"].values()
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"{src}: not a routed nextpnr design ({e})")
    for name, cell in top["cells"].items():
        ctype = cell["type"]
        if ctype not in MODELLED:
            sys.exit(f"{src}: cell {name}: type {ctype} has no simulation model (tb/postroute/)")
        dirs, conns, params = cell["port_directions"], cell["connections"], cell["parameters"]
        extra = COMB_IN if ctype == "TRELLIS_COMB" else FF_IN if ctype == "TRELLIS_FF" else []
        for port in extra:
            dirs.setdefault(port, "input")
        for port, d in dirs.items():
            if ctype == "MULT18X18D" and port.startswith(("SRIA", "SRIB")):
                continue
            if d == "input" and not conns.get(port):
                conns[port] = [default_level(ctype, port, params)]
        if ctype == "TRELLIS_IO":
            d = params.get("DIR", "INPUT").strip()
            if d not in ("INPUT", "OUTPUT"):
                sys.exit(f"{src}: cell {name}: a {d} pin has no simulation model")
            pad = "PAD_IN" if d == "INPUT" else "PAD_OUT"
            conns[pad] = conns.pop("B")
            del dirs["B"]
            dirs[pad] = "input" if d == "INPUT" else "output"
        if ctype == "TRELLIS_COMB":
            for port in ("F", "FCO", "OFX"):
                dirs.setdefault(port, "output")
                conns.setdefault(port, [])
            bel = cell["attributes"].get("NEXTPNR_BEL", "")
            k = bel.rsplit(".", 1)[-1]
            if k not in ("K0", "K1"):
                sys.exit(f"{src}: cell {name}: TRELLIS_COMB placed at '{bel}', not a slice's K0/K1")
            uses_f1 = conns["F1"] not in (["0"], ["1"])
            uses_fx = conns["FXA"] not in (["0"], ["1"]) or conns["FXB"] not in (["0"], ["1"])
            if (k == "K0" and uses_fx) or (k == "K1" and uses_f1):
                sys.exit(f"{src}: cell {name}: OFX inputs do not match its place {bel}")
            params["OFXMUX"] = "F5" if k == "K0" else "F6"
    tmp = dst + ".tmp"
    with open(tmp, "w") as f:
        json.dump(design, f)
    import os
    os.replace(tmp, dst)


if __name__ == "__main__":
    main()
