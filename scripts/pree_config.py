#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""pree_config.py: the generator of PREE's configuration copies from config/pree_config.json.

Usage:
  scripts/pree_config.py generate [DIR]   write the generated files under DIR (default: the
                                          repository), each only when its text changes
  scripts/pree_config.py stale            exit 1, with a diff, when a generated file in the
                                          repository differs from what the table gives
  scripts/pree_config.py cases            the fp32 bench checks, one "name level what" line each
                                          (tests/checks/fp32_unit.sh)

The generated files (never edit them; `make config` rewrites them):
  rtl/pree_unit_stages.vh   the PREU's unit kinds and each unit's default Stages (preu_stages),
                            included by rtl/pree_preu_plan.vh and tb/fp32/tb_fp32_pipe.v
  model/pree/pree_config.h  the same for C, the PREU's update window and radiance depth
  host/cosim_config.h       the co-simulation models' pree_top parameters (the engine, model/,
                            never names the co-simulation: tests/checks/engine_standalone.sh)
  mk/config.mk              the make variables: the fp32 bench configurations, every unit's Stages
                            range, the co-simulation models' parameters and the regression's models
Python 3 standard library only.
"""
import difflib
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TABLE = "config/pree_config.json"
SPDX = "SPDX-License-Identifier: Apache-2.0"
NOTE = "GENERATED from %s by scripts/pree_config.py (make config): do not edit." % TABLE


def load(root=ROOT):
    """The table, with each fp32 bench configuration's Stages and latency filled in."""
    with open(os.path.join(root, TABLE)) as f:
        t = json.load(f)
    for b in t["fp32_benches"]:
        u = t["units"][b["unit"]]
        if u["kind"] is None:
            b["latency"] = 0
        else:
            b["latency"] = b.get("stages", u["default_stages"][b["pipe_fast"]])
            lo, hi = u["stages"]
            if not lo <= b["latency"] <= hi:
                sys.exit("%s: fp32 bench %s: Stages %d outside %d .. %d" % (TABLE, b["name"], b["latency"], lo, hi))
    return t


def pipelined(t):
    """The units with a Stages parameter, in kind order: (name, unit)."""
    us = [(n, u) for n, u in t["units"].items() if u["kind"] is not None]
    return sorted(us, key=lambda nu: nu[1]["kind"])


def ternary(t, pf):
    """kind -> default Stages at PipeFast pf, as a chain of ?: on `kind`."""
    us = pipelined(t)
    expr = str(us[-1][1]["default_stages"][pf])
    for _, u in reversed(us[:-1]):
        expr = "(kind == %d) ? %d : %s" % (u["kind"], u["default_stages"][pf], expr)
    return expr


def gen_vh(t):
    us = pipelined(t)
    out = ["// " + SPDX, "// pree_unit_stages.vh: " + NOTE,
           "// The PREU's fp32 unit kinds and each unit's default Stages, included inside a module",
           "// (rtl/pree_preu_plan.vh, tb/fp32/tb_fp32_pipe.v). A unit's latency is Stages + InRegs.",
           "// kind  module            Stages  default (PipeFast 0 / 1)"]
    for n, u in us:
        out.append("//  %d    %-17s %2d .. %-2d %d / %d" % (u["kind"], u["module"], u["stages"][0], u["stages"][1],
                                                         u["default_stages"][0], u["default_stages"][1]))
    for n, u in us:
        out.append("localparam PREU_%s = %d;" % (n.upper(), u["kind"]))
    out += ["",
            "// A unit's stages: stages when set (non-zero), else the unit's own default for pipe_fast.",
            "function integer preu_stages;",
            "  input integer kind, pipe_fast, stages;",
            "  begin",
            "    if (stages != 0)         preu_stages = stages;",
            "    else if (pipe_fast == 0) preu_stages = %s;" % ternary(t, 0),
            "    else                     preu_stages = %s;" % ternary(t, 1),
            "  end",
            "endfunction", ""]
    return "\n".join(out)


def gen_h(t):
    p = t["preu"]
    top = t["top"]
    preus = sorted(int(n) for n in top["preus"])
    out = ["// " + SPDX, "/* pree_config.h: " + NOTE,
           " * The fp32 units' Stages (a unit's latency is Stages + InRegs), the PREU's latencies that",
           " * follow from them (the co-simulation models' parameters are in host/). */",
           "#ifndef PREE_CONFIG_H", "#define PREE_CONFIG_H", "",
           "/* Each unit's Stages range and its default Stages with PipeFast 0 and 1. */"]
    for n, u in pipelined(t):
        N = n.upper()
        out += ["#define PREE_%s_STAGES_MIN %d" % (N, u["stages"][0]),
                "#define PREE_%s_STAGES_MAX %d" % (N, u["stages"][1]),
                "#define PREE_%s_STAGES_PF0 %d" % (N, u["default_stages"][0]),
                "#define PREE_%s_STAGES_PF1 %d" % (N, u["default_stages"][1])]
    w = p["update_window"]
    out += ["",
            "/* pree_top's update hazard window (WIN_UPD: 1 + the PREU's update latency) for a datapath",
            " * (0 paper, 1 stable) and PipeFast, and its radiance depth (RAD_LAT: ADISO-REC's depth). */",
            "#define PREE_UPDATE_WINDOW(datapath, pipe_fast) \\",
            "    ((pipe_fast) ? ((datapath) ? %d : %d) : ((datapath) ? %d : %d))"
            % (w["stable"][1], w["paper"][1], w["stable"][0], w["paper"][0]),
            "#define PREE_RADIANCE_DEPTH(pipe_fast) ((pipe_fast) ? %d : %d)" % (p["radiance_depth"][1],
                                                                                p["radiance_depth"][0]),
            "", "#endif", ""]
    return "\n".join(out)


def gen_cosim_h(t):
    top = t["top"]
    preus = sorted(int(n) for n in top["preus"])
    out = ["// " + SPDX, "/* cosim_config.h: " + NOTE,
           " * The pree_top parameters of the co-simulation models (mk/config.mk passes the same). */",
           "#ifndef COSIM_CONFIG_H", "#define COSIM_CONFIG_H", ""]
    for k, v in top["widths"].items():
        out.append("#define COSIM_%s %d" % (k.upper(), v))
    for n in preus:
        c = top["preus"][str(n)]
        out += ["#define COSIM_HPB_%d %d" % (n, c["HpBankW"]),
                "#define COSIM_PXB_%d %d" % (n, c["PxBankW"]),
                "#define COSIM_PPC_%d %d" % (n, c["PhotonsPerCycle"])]
    out += ["/* X(n) for each PREU count n with a configuration above. */",
            "#define COSIM_PREU_COUNTS %s" % " ".join("X(%d)" % n for n in preus),
            "#define COSIM_MAX_PREU %d" % max(preus),
            "#define COSIM_MAX_PPC %d /* photon slots (PhotonsPerCycle) of the widest model */"
            % max(c["PhotonsPerCycle"] for c in top["preus"].values()),
            "", "#endif", ""]
    return "\n".join(out)


def gen_mk(t):
    top = t["top"]
    reg = top["regression"]
    b = t["fp32_benches"]
    names = lambda g: " ".join(x["name"] for x in b if x["group"] in g)
    out = ["# " + SPDX, "# config.mk: " + NOTE, "",
           "# Each unit's module and Stages range (a unit's latency is Stages + InRegs)."]
    for n, u in pipelined(t):
        out.append("FP32_STAGES_%s := %s" % (n, " ".join(str(s) for s in range(u["stages"][0], u["stages"][1] + 1))))
    for n, u in t["units"].items():
        out.append("FP32_TOP_%s := %s" % (n, u["module"]))
    out += ["FP32_PIPELINED := %s" % " ".join(n for n, _ in pipelined(t)),
            "",
            "# The fp32 bench configurations: <name> := <unit> <PipeFast> <Stages, or - for PipeFast's>",
            "# <latency> [ecp5]. FP32_UNITS: built for the regression; FP32_FAST: the units' PipeFast 1",
            "# forms; FP32_DEEP: built on demand."]
    for x in b:
        out.append("FP32_CFG_%s := %s %d %s %d%s" % (x["name"], x["unit"], x["pipe_fast"],
                                                   x.get("stages", "-"), x["latency"], " ecp5" if x.get("ecp5") else ""))
    out += ["FP32_UNITS := " + names(["units"]),
            "FP32_FAST := " + names(["fast"]),
            "FP32_DEEP := " + names(["fast", "deep"]),
            "",
            "# The co-simulation models' pree_top parameters: widths, and per PREU count its banks and",
            "# photons a cycle; the PREU counts with models; the regression's models (paper, stable and",
            "# PipeFast 1 counts, further tags, and the AXI wrapper's)."]
    out.append("COSIM_WIDTH_PARAMS := " + " ".join("-G%s=%d" % kv for kv in top["widths"].items()))
    preus = sorted(int(n) for n in top["preus"])
    for n in preus:
        c = top["preus"][str(n)]
        out += ["COSIM_HPB_%d := %d" % (n, c["HpBankW"]), "COSIM_PXB_%d := %d" % (n, c["PxBankW"]),
                "COSIM_PPC_%d := %d" % (n, c["PhotonsPerCycle"])]
    words = lambda l: " ".join(str(v) for v in l)
    out += ["COSIM_ALL_PREUS := " + words(preus),
            "COSIM_DATAPATHS := " + words(top["datapaths"]),
            "COSIM_PREUS := " + words(reg["paper"]),
            "COSIM_STABLE_PREUS ?= " + words(reg["stable"]),
            "COSIM_FAST_PREUS ?= " + words(reg["fast"]),
            "COSIM_EXTRA_TAGS := " + words(reg["extra"]),
            "AXI_REGRESSION_TAGS := " + words(reg["axi"]),
            "AXI_QUICK_TAGS := " + words(reg["axi_quick"]), ""]
    return "\n".join(out).replace(" \n", "\n")


OUTPUTS = {"rtl/pree_unit_stages.vh": gen_vh, "model/pree/pree_config.h": gen_h, "host/cosim_config.h": gen_cosim_h, "mk/config.mk": gen_mk}


def generate(root, t):
    for path, gen in OUTPUTS.items():
        text = gen(t)
        full = os.path.join(root, path)
        try:
            with open(full) as f:
                if f.read() == text:
                    continue
        except OSError:
            pass
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full + ".tmp", "w") as f:
            f.write(text)
        os.replace(full + ".tmp", full)
        print("GEN %s" % path)


def stale(t):
    bad = 0
    for path, gen in OUTPUTS.items():
        want = gen(t)
        try:
            with open(os.path.join(ROOT, path)) as f:
                have = f.read()
        except OSError:
            have = ""
        if have != want:
            bad += 1
            print("%s: stale (differs from what %s gives; run make config):" % (path, TABLE))
            sys.stdout.writelines(difflib.unified_diff(have.splitlines(True), want.splitlines(True),
                                                       path, path + " (from the table)"))
        else:
            print("ok: %s matches %s" % (path, TABLE))
    return bad


def main(argv):
    if len(argv) < 2 or argv[1] not in ("generate", "stale", "cases"):
        sys.exit(__doc__.split("\n\n")[1])
    t = load()
    if argv[1] == "generate":
        generate(argv[2] if len(argv) > 2 else ROOT, t)
    elif argv[1] == "stale":
        return 1 if stale(t) else 0
    else:
        for x in t["fp32_benches"]:
            u = t["units"][x["unit"]]
            params = ["PipeFast %d" % x["pipe_fast"]] if u["kind"] is not None else []
            params += ["Stages %d" % x["stages"]] if "stages" in x else []
            what = "%s%s, latency %d%s" % (u["module"], " #(%s)" % ", ".join(params) if params else "",
                                          x["latency"], ", ECP5 MULT18X18D products" if x.get("ecp5") else "")
            for sim in ("vl", "iv"):
                print("fp32_%s_%s %s %s, %s" % (sim, x["name"], "quick" if sim in x["quick"] else "full", what,
                                               "Verilator" if sim == "vl" else "Icarus"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
