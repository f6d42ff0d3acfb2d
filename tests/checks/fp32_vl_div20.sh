#!/usr/bin/env bash
# pree_fp32_div #(.Stages(20)) (latency 20), Verilator bench: the directed list plus FP32_QUICK (1 million) random operations with random valid gaps,
# bit for bit against model/pree/fp32_ops.h. Full level. Fails on any mismatch.
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-vl-div20
