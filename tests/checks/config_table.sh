#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The configuration table (config/pree_config.json) and its copies: fails when a generated file
# (rtl/pree_unit_stages.vh, model/pree/pree_config.h, mk/config.mk) differs from what
# scripts/pree_config.py writes from the table (the diff is printed; `make config` rewrites
# them), or when the RTL disagrees with the table: every fp32 unit's latency measured in Icarus
# at every Stages value with InRegs 0 and 1 and at its defaults, a Stages value one outside each
# range refused, and pree_top's update window and radiance depth for each datapath and PipeFast
# (scripts/pree_config_rtl.py). About 20 CPU seconds.
# level: quick
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
python3 scripts/pree_config.py stale || fail "a generated file is stale; rerun: make config"
python3 scripts/pree_config_rtl.py "$TMP/rtl" || fail "the RTL disagrees with config/pree_config.json; rerun: python3 scripts/pree_config_rtl.py"
echo "ok: the generated files and the RTL agree with config/pree_config.json"
