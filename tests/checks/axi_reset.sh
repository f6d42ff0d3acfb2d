#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# pree_axi at the end of a reset (tb/axi/axi_reset_tb.v, Icarus, the real pree_top with small
# memories): an AXI4-Lite write and read, a photon and a hit point, all offered at the first edge
# after ARESETn rises, while the wrapper's synchronised reset is still low; each must be taken
# once and answered (the formal job formal/axi found them taken and lost there; docs/formal.md).
# cost: 10
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
run iverilog -g2005 -Irtl -o "$TMP/reset.vvp" -s axi_reset_tb tb/axi/axi_reset_tb.v $(grep -v '^//' rtl/pree.f)
run vvp -N "$TMP/reset.vvp"
