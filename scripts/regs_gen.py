#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""regs_gen.py: pree_axi's register map (rtl/regs/pree_axi.rdl) into the files PeakRDL's own
exporters do not write: the register numbers pree_axi.v includes, the table the register-map
check compares the RTL with, and the Markdown table of docs/integration.md.

Usage: regs_gen.py <map.rdl> <registers.vh> <table.h> <table.md>
Runs under the hardware tools' venv (systemrdl-compiler, pinned with peakrdl in
scripts/install-deps.sh); scripts/regs_gen.sh runs it with PeakRDL's C-header exporter.
"""
import sys

from systemrdl import RDLCompileError, RDLCompiler
from systemrdl.node import RegfileNode, RegNode
from systemrdl.rdltypes import OnWriteType

HEAD = "generated from rtl/regs/pree_axi.rdl by scripts/regs_gen.py (make regs); do not edit"


def access(f):
    """A field's software access: RO, WO, RW or RW1C."""
    if f.get_property("onwrite") == OnWriteType.woclr:
        return "RW1C"
    return {(True, False): "RO", (False, True): "WO", (True, True): "RW"}[
        (f.is_sw_readable, f.is_sw_writable)]


def registers(top):
    """(name, offset, count, stride, description, reg node) in address order."""
    rows = []
    for n in top.children():
        if isinstance(n, RegNode):
            rows.append((n.inst_name, n.raw_address_offset, 1, 0, n.get_property("desc") or "", n))
        elif isinstance(n, RegfileNode):
            count = n.array_dimensions[0] if n.is_array else 1
            stride = n.array_stride if n.is_array else 0
            for i, r in enumerate(n.children()):
                head = (n.get_property("desc") or "") + " " if i == 0 else ""
                rows.append(("%s.%s" % (n.inst_name, r.inst_name),
                             n.raw_address_offset + r.raw_address_offset, count, stride,
                             head + (r.get_property("desc") or ""), r))
        else:
            raise SystemExit("regs_gen: %s: only registers and register files are supported" % n.inst_name)
    return rows


def verilog(rows):
    out = ["// pree_axi_regs.vh: register numbers (byte address / 4) of pree_axi's AXI4-Lite map,",
           "// included inside module pree_axi; " + HEAD + "."]
    regs = [r for r in rows if r[2] == 1]
    for i, (name, off, _, _, _, _) in enumerate(regs):
        lead = "localparam [9:0] " if i == 0 else "                 "
        end = ";" if i == len(regs) - 1 else ","
        out.append("%sR_%s = 10'h%03X%s" % (lead, name, off // 4, end))
    return "\n".join(out) + "\n"


def c_table(rows):
    out = ["/* pree_axi_regs_table.h: pree_axi's register map as a table (every register, its fields,",
           " * their software access and reset values), for the check that the RTL decodes exactly this",
           " * map (tb/regs/regs_check.c); " + HEAD + ". */",
           "#ifndef PREE_AXI_REGS_TABLE_H", "#define PREE_AXI_REGS_TABLE_H", "",
           "#include <stdint.h>", "",
           "enum { REG_RO, REG_WO, REG_RW, REG_RW1C };", "",
           "typedef struct {",
           "    const char *name;",
           "    unsigned lsb, width, access;   /* access: REG_* */",
           "    int has_reset;                 /* 0: the value is the build's (CONFIG0, CONFIG1) */",
           "    uint32_t reset;",
           "} reg_field_t;", "",
           "typedef struct {",
           "    const char *name;",
           "    uint32_t offset, count, stride;   /* count registers at offset + i * stride */",
           "    unsigned nfields;",
           "    reg_field_t field[8];",
           "} reg_desc_t;", "",
           "static const reg_desc_t reg_map[] = {"]
    codes = {"RO": "REG_RO", "WO": "REG_WO", "RW": "REG_RW", "RW1C": "REG_RW1C"}
    for name, off, count, stride, _, r in rows:
        fl = []
        for f in r.fields():
            if len(fl) == 8:
                raise SystemExit("regs_gen: %s: more than 8 fields" % name)
            rst = f.get_property("reset")
            fl.append('{"%s", %d, %d, %s, %d, 0x%Xu}' % (f.inst_name, f.lsb, f.width, codes[access(f)],
                                                        rst is not None, rst or 0))
        out.append('    {"%s", 0x%03Xu, %d, %d, %d, {%s}},' % (name, off, count, stride, len(fl), ", ".join(fl)))
    out += ["};", "", "#define REG_MAP_N (sizeof reg_map / sizeof reg_map[0])", "", "#endif", ""]
    return "\n".join(out)


def markdown(rows):
    out = ["| address | name | access | reset | fields |", "|---|---|---|---|---|"]
    for name, off, count, stride, desc, r in rows:
        fields = list(r.fields())
        acc = sorted({access(f) for f in fields})
        resets = [f.get_property("reset") for f in fields]
        reset = "-" if None in resets else "0x%08X" % sum(v << f.lsb for v, f in zip(resets, fields))
        addr = "0x%03X" % off if count == 1 else "0x%03X + %dk" % (off, stride)
        shown = name if count == 1 else name.replace(".", "[k].")
        if len(fields) == 1 and fields[0].inst_name == "VALUE":   # a plain number
            text = desc.strip() or fields[0].get_property("desc")
        else:
            text = "; ".join("%s %s: %s" % ("%d" % f.msb if f.width == 1 else "%d:%d" % (f.msb, f.lsb),
                                             f.inst_name, f.get_property("desc")) for f in fields)
            if desc.strip():
                text = desc.strip() + " " + text
        out.append("| %s | %s | %s | %s | %s |" % (addr, shown, "/".join(acc), reset, text))
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 5:
        raise SystemExit("usage: regs_gen.py <map.rdl> <registers.vh> <table.h> <table.md>")
    rdl, vh, table, md = sys.argv[1:]
    rdlc = RDLCompiler()
    try:
        rdlc.compile_file(rdl)
        top = rdlc.elaborate().top
    except RDLCompileError:
        raise SystemExit("regs_gen: %s does not compile (messages above)" % rdl)
    rows = registers(top)
    texts = {vh: verilog(rows), table: c_table(rows), md: markdown(rows)}
    for path, text in texts.items():
        with open(path, "w") as fh:
            fh.write(text)


if __name__ == "__main__":
    main()
