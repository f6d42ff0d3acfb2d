#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/make-run.sh end to end at a small size without the co-simulation: the double render is
# written first (and its time recorded), then the fp32 renders, their comparison JSON (with FLIP
# and the map scales) and the four difference maps, and the closing summary names the images,
# the report and the figures, read back from those JSON files.
# Usage: tests/checks/make_run_small.sh
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x "$PREE" ] || fail "$PREE not built (make build)"
mkdir -p "$TMP/bin" && cp "$PREE" "$TMP/bin/pree"   # alone: no co-simulation program beside it
PREE_RUN_SIZE="--width 48 --height 36 --photons 5000" scripts/make-run.sh "$TMP/bin/pree" "$TMP/out" >"$TMP/log" 2>&1 \
  || { tail -20 "$TMP/log"; fail "make-run.sh exited non-zero"; }
sed 's/^/  | /' "$TMP/log" | grep -v 'photons [0-9]*/'
for f in cornell3-double.png cornell3-double.exr cornell3-fp32.exr cornell3-fp32-stable.exr first-image-seconds.txt \
         cornell3-fp32-vs-double.json cornell3-fp32-stable-vs-double.json; do
  [ -s "$TMP/out/$f" ] || fail "no $f"
done
for m in "" -abs -ssim -flip; do [ -s "$TMP/out/cornell3-fp32-vs-double-diff$m.png" ] || fail "no diff map '$m'"; done
[ "$(head -1 "$TMP/out/first-image-seconds.txt" | tr -d '0-9')" = "" ] || fail "first-image-seconds.txt is not a number"
grep -n '^== ' "$TMP/log" | head -3 | grep -q 'first image' || fail "the first image is not announced right after the double render"
expect_eq "fp32 vs double JSON: flip present" "$(json "$TMP/out/cornell3-fp32-vs-double.json" flip | grep -c '^[0-9.e-]*$')" "1"
want=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print("SSIM %.7f, PSNR %.2f dB" % (d["ssim"], float(d["psnr_db"])))' \
  "$TMP/out/cornell3-fp32-vs-double.json")
grep -q "^fp32 (paper) vs double: $want" "$TMP/log" || fail "the summary does not give fp32's figures ($want)"
grep -q "^report .*report/index.html" "$TMP/log" || fail "the summary does not name the report"
grep -q "^RTL *not run" "$TMP/log" || fail "the summary does not say the RTL was not run"
echo "make_run_small: ok"
