#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# Every tracked source file names its licence with an SPDX identifier in its header
# (scripts/spdx.py: which files are source, and each syntax's comment); the generated register
# files get it from scripts/regs_gen.sh.
# cost: 1 (one pass over the tracked files)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
out=$(python3 scripts/spdx.py --check) || fail "source files without an SPDX identifier (scripts/spdx.py --apply): $(echo "$out" | head -5 | tr '\n' ' ')"
echo "ok: $(git ls-files | wc -l) tracked files, every source file has its SPDX identifier"
