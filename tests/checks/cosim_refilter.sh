#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# The host's re-filter with radii read back from the PREE (host/cosim_refilter.c): cornell3 64x48 /
# 128k photons (4 blocks of 32k, so the engine's schedule re-filters after blocks 1 and 2) through
# the Verilated pree_top with 4 PREUs, with --refilter and without (the default):
#   - both match the fp32 model word for word (hit points and image), and the scheduler's cycle
#     model predicts the RTL's stalls and every group's cycle across the read-back barriers;
#   - --refilter re-filters twice, reading every hit point back each time, and streams fewer
#     operations in fewer update cycles; the default reads nothing back;
#   - the two RTL images are the same bytes (dropping candidates that the read-back radii rule
#     out changes no result);
#   - --model-only --refilter re-filters as often and predicts the RTL run's operations and cycles.
# The AXI program (build/pree-cosim-axi-p4) at 32x24 / 100k photons: the same, its barriers
# being ends of AXI batches.
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
check_pair() {  # check_pair LABEL SCENE_OPTIONS...
  local label=$1; shift
  for mode in refilter none; do
    extra=""; [ $mode = refilter ] && extra="--refilter"
    run "$PREE" cosim scenes/cornell3 "$@" $extra --quiet --no-reference --stats "$TMP/$label-$mode.json" \
      --out "$TMP/$label-$mode.ppm"
  done
  python3 - "$TMP/$label-refilter.json" "$TMP/$label-none.json" "$label" <<'PY' || fail "$label: see above"
import sys
sys.path.insert(0, "tests/lib")
from cosim_report import load, words_match, model_predicts, finish
on, off, label = load(sys.argv[1]), load(sys.argv[2]), sys.argv[3]
bad = []
for d in (on, off):
    words_match(d, bad)
    if not d["axi"]:
        model_predicts(d, bad)
if on["host_refilters"] != 2 or on["refilter_hit_points_read"] != 2 * on["hit_points"]:
    bad.append("re-filters %d reading %d hit points, expected 2 reading 2 x %d"
               % (on["host_refilters"], on["refilter_hit_points_read"], on["hit_points"]))
if off["host_refilters"] != 0 or off["refilter_hit_points_read"] != 0:
    bad.append("without --refilter: hit points read back")
uo, uf = on["update"], off["update"]
if not (uo["operations"] < uf["operations"] and uo["cycles"] < uf["cycles"]):
    bad.append("re-filtered: %d operations in %d cycles, not fewer than %d in %d"
               % (uo["operations"], uo["cycles"], uf["operations"], uf["cycles"]))
print("%s: operations %d -> %d, update cycles %d -> %d, photon hits streamed %d -> %d"
      % (label, uf["operations"], uo["operations"], uf["cycles"], uo["cycles"],
         off["photon_hits_streamed"], on["photon_hits_streamed"]))
finish(bad)
PY
  cmp -s "$TMP/$label-refilter.ppm" "$TMP/$label-none.ppm" || fail "$label: the RTL images differ"
  echo "ok: $label: the same image with and without the re-filter"
}
check_pair pree_top --width 64 --height 48 --photons 128000 --preu 4
# --model-only --refilter (the radii from the model's words): the same re-filters, operations and
# predicted cycles as the RTL run's cycle model.
run "$PREE" cosim scenes/cornell3 --width 64 --height 48 --photons 128000 --preu 4 --refilter --model-only \
  --quiet --no-reference --stats "$TMP/model.json"
expect_eq "model-only re-filters" "$(json "$TMP/model.json" host_refilters)" 2
expect_eq "model-only operations" "$(json "$TMP/model.json" update.operations)" "$(json "$TMP/pree_top-refilter.json" update.operations)"
expect_eq "model-only cycles" "$(json "$TMP/model.json" update.cycles)" "$(json "$TMP/pree_top-refilter.json" schedule.model_cycles)"
[ -x build/pree-cosim-axi-p4 ] || fail "build/pree-cosim-axi-p4 missing (make build/pree-cosim-axi-p4)"
check_pair pree_axi --width 32 --height 24 --photons 100000 --preu 4 --axi
