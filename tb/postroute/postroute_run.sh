#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# postroute_run.sh: one post-route co-simulation run (mk/postroute.mk, docs/fpga_board.md):
# <program> (build/postroute/pree-cosim-uart-*) with pree cosim's options through the AXI host,
# its report and the board's cycles in <program>.run.txt, its wall and CPU seconds in
# <program>.run.time. The exit status is the program's: non-zero on any differing word.
#   postroute_run.sh <program> <pree cosim options...>
set -uo pipefail
prog=${1:?usage: postroute_run.sh <program> <pree cosim options...>}
shift
[ -x "$prog" ] || { echo "postroute_run: $prog: no such program (make it first)" >&2; exit 2; }
/usr/bin/time -f "wall %e s, CPU %U + %S s, peak %M KB" -o "$prog.run.time" \
  "$prog" --axi "$@" > "$prog.run.txt" 2>&1
rc=$?
cat "$prog.run.txt" "$prog.run.time"
exit $rc
