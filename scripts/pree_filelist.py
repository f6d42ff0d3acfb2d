#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""pree_filelist.py: rtl/pree.f from FuseSoC's view of pree.core.

Usage: pree_filelist.py EDA_YML OUT
EDA_YML is the .eda.yml that `fusesoc run --setup` writes for a target of pree.core (mk/fusesoc.mk
sets up the lint target); its Verilog sources, in FuseSoC's order (the order of the core's rtl
fileset: leaves first), become OUT's lines, with the include files named in the header. OUT is
written whole or not at all. Needs PyYAML (FuseSoC's own dependency: run it with the hardware
tools' venv's python3).
"""
import os
import sys
import tempfile

import yaml

HEADER = """\
// pree.f: the PREE RTL in dependency order (leaves first), for Vivado (read_verilog -f / add_files),
// Verilator (-f), Icarus (-c) and Yosys (read_verilog of each line). Top for an FPGA build:
// pree_axi (docs/integration.md); pree_top for the bare engine. Paths relative to the repository.
// Generated from pree.core's rtl fileset by `make pree-f` (scripts/pree_filelist.py): edit the core.
// The include directory is rtl/: -Irtl for Verilator and Icarus, +incdir+rtl or Vivado's
// include_dirs elsewhere. Include files:
//   {includes}.
"""


def fail(msg):
    print(f"pree_filelist: {msg}", file=sys.stderr)
    sys.exit(1)


def main():
    if len(sys.argv) != 3:
        fail("usage: pree_filelist.py EDA_YML OUT")
    src, out = sys.argv[1], sys.argv[2]
    try:
        with open(src) as f:
            eda = yaml.safe_load(f)
    except (OSError, yaml.YAMLError) as e:
        fail(f"{src}: {e}")
    if not isinstance(eda, dict) or not isinstance(eda.get("files"), list):
        fail(f"{src}: no 'files' list (not an edalize .eda.yml)")
    sources, includes = [], []
    for f in eda["files"]:
        name = f.get("name", "")
        # FuseSoC names each file src/<core>/<path in the core's folder>.
        parts = name.split("/", 2)
        if len(parts) != 3 or parts[0] != "src":
            fail(f"{src}: file '{name}' is not under src/<core>/")
        path = parts[2]
        if not f.get("file_type", "").startswith("verilogSource"):
            continue
        (includes if f.get("is_include_file") else sources).append(path)
    if not sources:
        fail(f"{src}: no Verilog sources")
    text = HEADER.format(includes=", ".join(includes)) + "\n".join(sources) + "\n"
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(out)), prefix=".pree_f.")
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
