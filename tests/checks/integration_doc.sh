#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# docs/integration.md against the product: its instantiation example (the ```verilog block) is
# lint-clean with pree_axi (verilator --lint-only -Wall through rtl/pree.f); every timing diagram
# it shows exists, and each docs/wave/*.json renders (wavedrom, the hardware tools' venv:
# FPGA_VENV, default build/fpga-venv) to exactly the SVG committed beside it (`make docs-waves`);
# every row of the diagrams that is a port of pree_axi is what pree_axi does under the diagram's
# stimulus (tb/axi/axi_wave_tb.v under Icarus, scripts/wave_check.py).
# cost: 20 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
doc=docs/integration.md
awk '/^```verilog$/ { f = 1; n++; next } /^```$/ { f = 0 } f && n == 1' "$doc" > "$TMP/pree_example.v"
grep -q '^module pree_example' "$TMP/pree_example.v" || fail "$doc: no \`\`\`verilog block with module pree_example"
run verilator --lint-only -Wall -Irtl --top-module pree_example -f rtl/pree.f "$TMP/pree_example.v"
echo "ok: $doc's instantiation example is lint-clean"

venv=${FPGA_VENV:-${BUILD:-build}/fpga-venv}
[ -x "$venv/bin/wavedrompy" ] || fail "no wavedrompy in $venv (make fpga-deps)"
refs=$(grep -o '(wave/[a-z_]*\.svg)' "$doc" | tr -d '()' | sort -u)
[ -n "$refs" ] || fail "$doc shows no docs/wave diagram"
for r in $refs; do
  [ -f "docs/${r%.svg}.json" ] || fail "$doc shows $r, but docs/${r%.svg}.json does not exist"
done
n=0
for src in docs/wave/*.json; do
  svg=${src%.json}.svg
  run "$venv/bin/wavedrompy" --input "$src" --svg "$TMP/out.svg" >/dev/null
  cmp -s "$TMP/out.svg" "$svg" || fail "$svg is not $src rendered (make docs-waves)"
  n=$((n + 1))
done
echo "ok: $n diagrams, each SVG its source's rendering; $(echo "$refs" | wc -l) shown in $doc"

# The diagrams against the RTL: tb/axi/axi_wave_tb.v replays each one's stimulus on pree_axi
# under Icarus and scripts/wave_check.py compares every port row, cycle by cycle.
run iverilog -g2005 -Irtl -o "$TMP/wave.vvp" -s axi_wave_tb -c rtl/pree.f tb/axi/axi_wave_tb.v
vvp -N "$TMP/wave.vvp" > "$TMP/wave.out" 2>&1 || fail "tb/axi/axi_wave_tb.v failed: $(tail -3 "$TMP/wave.out" | tr '\n' ' ')"
grep -q '^DONE' "$TMP/wave.out" || fail "tb/axi/axi_wave_tb.v did not finish: $(tail -3 "$TMP/wave.out" | tr '\n' ' ')"
python3 scripts/wave_check.py "$TMP/wave.out" docs/wave || fail "docs/wave diagrams differ from pree_axi (rerun: vvp -N on tb/axi/axi_wave_tb.v, then scripts/wave_check.py OUT docs/wave)"
echo "ok: the diagrams' port rows are pree_axi's, cycle by cycle"
