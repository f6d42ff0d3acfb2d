#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every vector level of the update's screening and the sphere tests that this processor has,
# forced with --simd (scalar, avx2, avx512; auto), gives the same image, state and update counts
# in double and fp32, on cornell3 (spheres) and cornell-water (a mesh with glass); the stats name
# the level that ran; an unknown level is a one-line error that writes nothing. The vector paths'
# object code holds their instructions (objdump): 512-bit registers in the AVX-512 prefilter,
# 256-bit gathers in the AVX2 prefilter and screening.
# level: quick
# cost: 10 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
levels="scalar"
grep -qw avx2 /proc/cpuinfo && levels="$levels avx2"
grep -qw avx512f /proc/cpuinfo && levels="$levels avx512"
echo "levels on this processor: $levels"
hashes() { echo "$(json "$1" image_hash)/$(json "$1" state_hash)/$(json "$1" hpuo_candidates)/$(json "$1" skip_candidates_outside_radius)/$(json "$1" hpuo_normal_passed)/$(json "$1" hpuo_accepted)"; }
for scene in cornell3 cornell-water; do
  for prec in double fp32; do
    ref=
    for lv in $levels auto; do
      run "$PREE" render "$ROOT/scenes/$scene" --width 96 --height 72 --photons 60000 --precision $prec \
          --threads 2 --simd $lv --out "$TMP/$lv.ppm" --stats "$TMP/$lv.json" --quiet
      [ $lv = auto ] || expect_eq "$scene $prec --simd $lv: the level run" "$(json "$TMP/$lv.json" simd)" $lv
      if [ -z "$ref" ]; then ref=$(hashes "$TMP/$lv.json"); continue; fi
      expect_eq "$scene $prec --simd $lv = scalar" "$(hashes "$TMP/$lv.json")" "$ref"
    done
  done
done
# An unknown level: one line on stderr, exit 2, no image.
if "$PREE" render "$ROOT/scenes/cornell3" --simd sse9 --out "$TMP/bad.ppm" 2>"$TMP/err"; then fail "--simd sse9 accepted"; fi
[ "$(wc -l <"$TMP/err")" = 1 ] || fail "--simd sse9: not one line: $(cat "$TMP/err")"
[ ! -e "$TMP/bad.ppm" ] || fail "--simd sse9 wrote an image"
echo "ok: --simd sse9 refused: $(cat "$TMP/err")"
# The object code of the vector paths.
body() { objdump -d --no-show-raw-insn "$1" | awk -v f="<$2>:" '$2 == f {on = 1; next} on && /^$/ {exit} on'; }
obj=${PREE_BUILD:-$ROOT/build}/model/ppm
[ -f "$obj/update_prefilter.o" ] || fail "no $obj/update_prefilter.o (build the engine first)"
n512=$(body "$obj/update_prefilter.o" near_avx512 | grep -c 'zmm')
n256=$(body "$obj/update_prefilter.o" near_avx2 | grep -c 'vgatherdps.*ymm')
nscr=$(body "$obj/update_batch.o" screen_avx2 | grep -c 'vgatherdpd.*ymm')
echo "near_avx512: $n512 zmm instructions; near_avx2: $n256 ymm gathers; screen_avx2: $nscr ymm gathers"
[ "$n512" -ge 10 ] || fail "near_avx512 holds $n512 instructions on zmm registers"
[ "$(body "$obj/update_prefilter.o" near_avx512 | grep -c 'vpcompressd')" -ge 1 ] || fail "near_avx512 has no vpcompressd"
[ "$n256" -ge 3 ] || fail "near_avx2 holds $n256 256-bit gathers"
[ "$nscr" -ge 3 ] || fail "screen_avx2 holds $nscr 256-bit gathers"
echo "PASS"
