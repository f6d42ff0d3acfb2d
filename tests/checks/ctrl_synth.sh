#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Controllers synthesize (Yosys synth_xilinx) with no latch and no combinational loop, NumPreu 4;
# `make ctrl-synth` does 4/8/16.
set -u
cd "$(dirname "$0")/../.."
fail=0
for m in pree_aftso_hpuoc pree_adiso_rec; do
  if ! tb/ctrl/synth_ctrl.sh $m NumPreu=4; then echo "FAIL; rerun: tb/ctrl/synth_ctrl.sh $m NumPreu=4"; fail=1; fi
done
exit $fail
