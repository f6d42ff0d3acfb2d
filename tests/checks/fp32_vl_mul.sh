#!/usr/bin/env bash
# pree_fp32_mul (multiplier), Verilator bench: the directed list plus FP32_QUICK (1 million) random
# operations with random valid gaps, bit for bit against model/pree/fp32_ops.h. Fails on any mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-vl-mul
