#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# Yosys structural check of pree_top (NumPreu 4, small memories), both PREU datapaths, and NumPreu 1
# (its one-lane index fields; paper datapath, about 5 CPU s): no latch, no combinational loop, no
# multiple drivers. The full synth_xilinx run is `make synth-top`.
set -u
cd "$(dirname "$0")/../.."
srcs=$(grep -v '^//' rtl/pree.f | tr '\n' ' ')   # the RTL filelist
mkdir -p build/cosim
for pd in 4:0 4:1 1:0; do
  p=${pd%:*} d=${pd#*:}
  cmd="read_verilog -Irtl $srcs; chparam -set NumPreu $p -set HpAW 10 -set HpBankW 4 -set IdxAW 8 -set PxAW 8 -set PxBankW 2 -set Datapath $d pree_top; hierarchy -check -top pree_top; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr t:\$sr; check -assert"
  if ! yosys -q -l build/cosim/top_yosys.log -p "$cmd" >/dev/null; then
    echo "FAIL (log build/cosim/top_yosys.log); reproduce: yosys -p '$cmd'"; tail -15 build/cosim/top_yosys.log; exit 1
  fi
  echo "pree_top (NumPreu $p, datapath $d): no latch, no loop"
done
