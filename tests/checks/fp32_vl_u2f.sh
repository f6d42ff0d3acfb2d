#!/usr/bin/env bash
# pree_u64_to_f32 (unsigned 64-bit integer to binary32, round to nearest even), Verilator bench:
# the directed list plus FP32_QUICK (1 million) random operations with random valid gaps, bit for
# bit against u64_to_f32() of model/pree/wide_acc.h. Fails on any mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-vl-u2f
