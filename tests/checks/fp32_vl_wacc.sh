#!/usr/bin/env bash
# pree_wacc (the stable datapath's wide accumulator add), Verilator bench: the directed list plus
# FP32_QUICK (1 million) random operations with random valid gaps, bit for bit against wide_add()
# of model/pree/wide_acc.h. Fails on any mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-vl-wacc
