#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The stress suite's render script (scripts/stress-render.sh, make stress-render) still runs at its
# reduced size (16x12, 1e5 photons; scales 1e-4, 1, 1e6, 2^10) and says what it should: every drift and
# scale row, the stable datapath's drift from double below 1e-6 and below the paper datapath's on
# both scenes, and each scale-1 copy identical to itself. (The scale rows' figures are the host's
# limits, reported in docs/numerics_renders.md, not judged here.)
# Usage: tests/checks/stress_render_script.sh   (PREE=path/to/pree to test another build)
# cost: 36 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
run scripts/stress-render.sh "$PREE" "$TMP/sr" --quick
d="$TMP/sr/render-drift.md"; s="$TMP/sr/render-scale.md"
expect_eq "drift rows" "$(grep -cE '^\| (cornell3|cornell-sphere) \| 100000 \| (double|fp32-paper|fp32-stable) \|' "$d")" 6
expect_eq "scale rows" "$(grep -cE '^\| (cornell3|cornell-sphere) \| (1e-4|1|1e6|2\^10) \| (double|fp32-paper|fp32-stable) \|' "$s")" 24
for sc in cornell3 cornell-sphere; do
  p=$(awk -F'|' -v s=" $sc " '$2 == s && $4 == " fp32-paper " { print $8 + 0 }' "$d")
  t=$(awk -F'|' -v s=" $sc " '$2 == s && $4 == " fp32-stable " { print $8 + 0 }' "$d")
  awk -v p="$p" -v t="$t" 'BEGIN { exit !(t < 1e-6 && t < p) }' \
    || fail "$sc: stable drift $t should be < 1e-6 and < paper's $p; reproduce: scripts/stress-render.sh $PREE /tmp/sr --quick"
  echo "ok: $sc drift at 1e5 photons: stable $t < paper $p"
  z=$(awk -F'|' -v s=" $sc " '$2 == s && $3 == " 1 " && $8 + 0 != 0' "$s" | wc -l)
  expect_eq "$sc scale-1 rows identical to themselves" "$z" 0
done
