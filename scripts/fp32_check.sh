#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# fp32_check.sh: run one make target of mk/fp32.mk as a regression check (tests/checks/fp32_*.sh).
# Usage: scripts/fp32_check.sh <target> [VAR=value ...]
# Exit 0 when the target succeeds; otherwise the last lines of its output and the exact
# command that reproduces the failure, and exit 1.
set -u
cd "$(dirname "$0")/.."
cmd=(make --no-print-directory "$@")
log=$(mktemp)
if "${cmd[@]}" >"$log" 2>&1; then
  grep -E "checked|vectors|^\||^verilator --lint" "$log" || true
  rm -f "$log"
  exit 0
fi
tail -40 "$log"
rm -f "$log"
echo "FAILED: reproduce with: ${cmd[*]}"
exit 1
