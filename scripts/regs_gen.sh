#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# regs_gen.sh: every file generated from pree_axi's register map (rtl/regs/pree_axi.rdl), written
# under DEST (the repository root for `make regs`; a scratch copy for tests/checks/regs_map.sh):
#   drv/pree_axi_regs.h               C header: the register block as a struct, field masks, resets
#                                     (PeakRDL's c-header exporter)
#   rtl/pree_axi_regs.vh              the register numbers pree_axi.v includes
#   tb/regs/pree_axi_regs_table.h     the map as a table for the RTL check (tb/regs/regs_check.c)
#   docs/integration.md               its register table, between the markers regs-map
#                                     (DEST/docs/integration.md must exist)
# Usage: regs_gen.sh VENV DEST   (VENV: the hardware tools' venv, make fpga-deps)
set -euo pipefail
venv=${1:?usage: regs_gen.sh VENV DEST}
dest=${2:?usage: regs_gen.sh VENV DEST}
cd "$(dirname "$0")/.."
rdl=rtl/regs/pree_axi.rdl
[ -x "$venv/bin/peakrdl" ] || { echo "regs_gen: no PeakRDL in $venv (make fpga-deps)" >&2; exit 1; }
mkdir -p "$dest/drv" "$dest/rtl" "$dest/tb/regs"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/regs_gen.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
"$venv/bin/peakrdl" c-header --type-style hier "$rdl" -o "$tmp/pree_axi_regs.h"
"$venv/bin/python" scripts/regs_gen.py "$rdl" "$tmp/pree_axi_regs.vh" "$tmp/pree_axi_regs_table.h" "$tmp/table.md"
python3 scripts/fpga_doc.py "$dest/docs/integration.md" regs-map "$tmp/table.md"
for f in pree_axi_regs.h pree_axi_regs.vh pree_axi_regs_table.h; do   # the licence line first
  { echo "// SPDX-License-Identifier: Apache-2.0"; cat "$tmp/$f"; } > "$tmp/$f.spdx"
  mv "$tmp/$f.spdx" "$tmp/$f"
done
mv "$tmp/pree_axi_regs.h" "$dest/drv/pree_axi_regs.h"
mv "$tmp/pree_axi_regs.vh" "$dest/rtl/pree_axi_regs.vh"
mv "$tmp/pree_axi_regs_table.h" "$dest/tb/regs/pree_axi_regs_table.h"
