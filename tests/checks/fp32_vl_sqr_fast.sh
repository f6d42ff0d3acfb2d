#!/usr/bin/env bash
# pree_fp32_sqr #(.PipeFast(1)) (the deep configuration, docs/fpga.md), Verilator bench: the directed
# list plus FP32_QUICK (1 million) random operations with random valid gaps, bit for bit against
# the C model, at the latency that mk/fp32.mk pins. Full level: its Verilator model is built on
# demand. Fails on any mismatch.
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-vl-sqr_fast
