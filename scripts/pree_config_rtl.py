#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""pree_config_rtl.py: measure the RTL against the configuration table (config/pree_config.json).

Usage: scripts/pree_config_rtl.py [WORKDIR]

Writes one Icarus testbench that instantiates every pipelined fp32 unit at every Stages value
of its range with InRegs 0 and 1, and at its default for PipeFast 0 and 1, sends one operation
into each and counts the cycles to its valid_o; and one that elaborates pree_top for each
datapath and PipeFast and prints its update window (WIN_UPD) and radiance depth (RAD_LAT).
Every measured latency must equal the table's (Stages + InRegs; the defaults; the windows and
depths), and a Stages value one outside each unit's range must fail elaboration with the
unit's own range error (the missing module <module>_stages_is_<lo>_to_<hi>). Prints one line per disagreement and exits 1 on any. Python 3 standard
library, Icarus Verilog 11.
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pree_config  # noqa: E402

ROOT = pree_config.ROOT
# The operand ports of each unit beside clk_i, rst_ni, valid_i, valid_o and y_o.
PORTS = {"add": ".a_i(32'd0), .b_i(32'd0), .sub_i(1'b0)", "mul": ".a_i(32'd0), .b_i(32'd0)",
         "sqr": ".a_i(32'd0)", "div": ".a_i(32'd0), .b_i(32'd0)", "u2f": ".a_i(64'd0)",
         "wacc": ".a_i(64'd0), .t_i(32'd0)"}
MAX_WAIT = 80   # cycles the bench waits for a valid_o (above the deepest unit's 32)


def unit_cases(t):
    """(unit, module, parameter text, expected latency, label) for every instance."""
    cases = []
    for n, u in pree_config.pipelined(t):
        lo, hi = u["stages"]
        for s in range(lo, hi + 1):
            for ir in t["preu"]["in_regs"]:
                cases.append((n, u["module"], ".Stages(%d), .InRegs(%d)" % (s, ir), s + ir,
                              "%s Stages %d InRegs %d" % (n, s, ir)))
        for pf in (0, 1):
            cases.append((n, u["module"], ".PipeFast(%d)" % pf, u["default_stages"][pf],
                          "%s default at PipeFast %d" % (n, pf)))
    return cases


def unit_bench(cases):
    out = ["`timescale 1ns/1ps", "module config_unit_tb;",
           "  reg clk = 1'b0, rst_n = 1'b0, v = 1'b0;",
           "  wire [%d:0] vo;" % (len(cases) - 1),
           "  integer lat [0:%d];" % (len(cases) - 1),
           "  integer i, k;",
           "  always #5 clk = ~clk;"]
    for i, (n, mod, par, _, _) in enumerate(cases):
        out.append("  %s #(%s) u%d (.clk_i(clk), .rst_ni(rst_n), .valid_i(v), %s, .valid_o(vo[%d]), .y_o());"
                   % (mod, par, i, PORTS[n], i))
    out += ["  task sample; input integer cyc; begin",
            "    for (i = 0; i < %d; i = i + 1) if (vo[i] === 1'b1 && lat[i] < 0) lat[i] = cyc;" % len(cases),
            "  end endtask",
            "  initial begin",
            "    for (i = 0; i < %d; i = i + 1) lat[i] = -1;" % len(cases),
            "    repeat (3) @(negedge clk);",
            "    rst_n = 1'b1;",
            "    @(negedge clk) v = 1'b1;   // one operation, taken at the next rising edge",
            "    #1 sample(0);",
            "    for (k = 1; k <= %d; k = k + 1) begin" % MAX_WAIT,
            "      @(negedge clk) v = 1'b0;",
            "      #1 sample(k);",
            "    end",
            "    for (i = 0; i < %d; i = i + 1) $display(\"lat %%0d %%0d\", i, lat[i]);" % len(cases),
            "    $finish;",
            "  end", "endmodule", ""]
    return "\n".join(out)


def top_bench(t):
    out = ["module config_top_tb;"]
    combos = [(d, pf) for d in (0, 1) for pf in (0, 1)]
    for d, pf in combos:
        out.append("  pree_top #(.NumPreu(4), .HpAW(10), .HpBankW(3), .IdxAW(7), .PxAW(9), .PxBankW(2), "
                   ".Datapath(%d), .PipeFast(%d)) t%d%d ();" % (d, pf, d, pf))
    out.append("  initial begin")
    for d, pf in combos:
        out.append("    $display(\"top %d %d %%0d %%0d\", t%d%d.WIN_UPD, t%d%d.RAD_LAT);" % (d, pf, d, pf, d, pf))
    out += ["    $finish;", "  end", "endmodule", ""]
    return "\n".join(out)


def run(cmd, cwd=ROOT):
    r = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return r.returncode, r.stdout


def iverilog(tb, out, extra):
    return run(["iverilog", "-g2005", "-Irtl", "-y", "rtl", "-o", out, tb] + extra)


def main(argv):
    t = pree_config.load()
    work = argv[1] if len(argv) > 1 else tempfile.mkdtemp(prefix="pree-config-")
    os.makedirs(work, exist_ok=True)
    bad = []

    cases = unit_cases(t)
    tb = os.path.join(work, "config_unit_tb.v")
    with open(tb, "w") as f:
        f.write(unit_bench(cases))
    rc, log = iverilog(tb, os.path.join(work, "unit.vvp"), [])
    if rc == 0:
        rc, log = run(["vvp", "-N", os.path.join(work, "unit.vvp")])
    if rc != 0:
        sys.exit("pree_config_rtl: the unit bench failed (%s):\n%s" % (tb, log[-3000:]))
    got = {int(w[1]): int(w[2]) for w in (ln.split() for ln in log.splitlines()) if w[:1] == ["lat"]}
    for i, (_, _, _, want, label) in enumerate(cases):
        if got.get(i) != want:
            bad.append("%s: latency %s in the RTL, %d in the table" % (label, got.get(i), want))
    print("units: %d instances measured (every Stages value with InRegs 0 and 1, the defaults)" % len(cases))

    # One Stages value outside each range: the unit must refuse it at elaboration, with the module
    # that names its range (<module>_stages_is_<lo>_to_<hi>, which does not exist).
    for n, u in pree_config.pipelined(t):
        refusal = "%s_stages_is_%d_to_%d" % (u["module"], u["stages"][0], u["stages"][1])
        for s in (u["stages"][0] - 1, u["stages"][1] + 1):
            one = os.path.join(work, "range_%s_%d.v" % (n, s))
            with open(one, "w") as f:
                f.write(unit_bench([(n, u["module"], ".Stages(%d)" % s, 0, "")]))
            rc, log = iverilog(one, one + "vp", [])
            if rc == 0 or refusal not in log:
                bad.append("%s Stages %d: not refused as %s" % (n, s, refusal))
    print("units: Stages one outside each range refused")

    tb = os.path.join(work, "config_top_tb.v")
    with open(tb, "w") as f:
        f.write(top_bench(t))
    files = [ln.strip() for ln in open(os.path.join(ROOT, "rtl/pree.f")) if ln.strip() and not ln.startswith("//")]
    rc, log = run(["iverilog", "-g2005", "-Irtl", "-o", os.path.join(work, "top.vvp"), tb] + files)
    if rc == 0:
        rc, log = run(["vvp", "-N", os.path.join(work, "top.vvp")])
    if rc != 0:
        sys.exit("pree_config_rtl: the pree_top elaboration failed (%s):\n%s" % (tb, log[-3000:]))
    p = t["preu"]
    for w in (ln.split() for ln in log.splitlines()):
        if w[:1] != ["top"]:
            continue
        d, pf, win, rad = (int(x) for x in w[1:5])
        want_win = p["update_window"]["stable" if d else "paper"][pf]
        if win != want_win:
            bad.append("pree_top Datapath %d PipeFast %d: WIN_UPD %d, table %d" % (d, pf, win, want_win))
        if rad != p["radiance_depth"][pf]:
            bad.append("pree_top PipeFast %d: RAD_LAT %d, table %d" % (pf, rad, p["radiance_depth"][pf]))
        print("pree_top Datapath %d PipeFast %d: WIN_UPD %d, RAD_LAT %d" % (d, pf, win, rad))
    for b in bad:
        print("MISMATCH: " + b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
