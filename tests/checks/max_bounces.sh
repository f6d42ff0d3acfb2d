#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# pree render --max-bounces W (model/ppm/photon_pass.c; docs/photon_map.md, "Capping photon
# paths"): a cap the scene's paths never reach (W = 18 with max_depth 20) gives the bits of a render
# without it, for both estimators; W = 1 and 2 change the image, store fewer photons the smaller W
# is, and no traced path is longer than W + 1 segments; the statistics record W (0 without it); a
# checkpoint carries it (resume alone = one render; another W is a conflict); an absurd W is a
# one-line error with nothing written. --threads above the hardware's count warns once, and a
# count within it says nothing.
# level: quick
# cost: 8
source "$(dirname "$0")/../lib/check.sh"
cd "$TMP"
S=$ROOT/scenes
R=(--width 32 --height 24 --photons 20000 --quiet)
hashes() { echo "$(json "$1.json" image_hash)/$(json "$1.json" state_hash)"; }

for est in ppm pm; do
  run "$PREE" render "$S/cornell3" "${R[@]}" --estimator $est --threads 2 --out d$est.ppm --stats d$est.json
  expect_eq "$est: statistics' max_bounces without the option" "$(json d$est.json max_bounces)" 0
  run "$PREE" render "$S/cornell3" "${R[@]}" --estimator $est --threads 2 --max-bounces 18 --out w18$est.ppm --stats w18$est.json
  expect_eq "$est: --max-bounces 18 = no cap" "$(hashes w18$est)" "$(hashes d$est)"
  expect_eq "$est: statistics' max_bounces" "$(json w18$est.json max_bounces)" 18
  for w in 1 2; do
    run "$PREE" render "$S/cornell3" "${R[@]}" --estimator $est --threads 2 --max-bounces $w --out w$w$est.ppm --stats w$w$est.json
    [ "$(hashes w$w$est)" != "$(hashes d$est)" ] || fail "$est: --max-bounces $w gave the uncapped bits"
  done
  h1=$(json w1$est.json photon_hits) h2=$(json w2$est.json photon_hits) hd=$(json d$est.json photon_hits)
  [ "$h1" -lt "$h2" ] && [ "$h2" -lt "$hd" ] || fail "$est: photons stored W=1 $h1, W=2 $h2, uncapped $hd: not increasing"
  echo "ok: $est: photons stored W=1 $h1 < W=2 $h2 < uncapped $hd"
done
for w in 1 2; do
  expect_eq "longest photon path with --max-bounces $w" "$(json w${w}pm.json pm.path_segments_max)" $((w + 1))
done
[ "$(json dpm.json pm.path_segments_max)" -gt 3 ] || fail "uncapped longest path $(json dpm.json pm.path_segments_max) segments"

# A checkpoint keeps the cap: resume alone gives one render's bits; another cap is refused.
run "$PREE" render "$S/cornell3" "${R[@]}" --max-bounces 2 --photons 10000 --checkpoint c.ckp --out c.ppm
"$PREE" render --resume c.ckp --photons 20000 --out r.ppm --stats r.json 2>/dev/null || fail "resume failed"
expect_eq "resume of a --max-bounces 2 checkpoint = one render" "$(hashes r)" "$(hashes w2ppm)"
"$PREE" render --resume c.ckp --photons 20000 --max-bounces 3 --out r3.ppm 2>err.txt; rc=$?
expect_eq "resume with another cap: status" $rc 1
grep -q -- "--max-bounces 3 conflicts with the checkpoint's --max-bounces 2" err.txt || fail "$(cat err.txt)"

for bad in 0 -3 1001 two; do
  "$PREE" render "$S/cornell3" "${R[@]}" --max-bounces "$bad" --out bad.ppm 2>err.txt; rc=$?
  [ $rc -ne 0 ] && [ "$(wc -l < err.txt)" -eq 1 ] && [ ! -e bad.ppm ] \
    || fail "--max-bounces $bad: status $rc, $(wc -l < err.txt) lines, $(ls bad.ppm 2>/dev/null)"
  grep -q -- "--max-bounces" err.txt || fail "--max-bounces $bad: $(cat err.txt)"
  echo "ok: --max-bounces $bad: $(cat err.txt)"
done

# --threads: one warning above the hardware's threads (a resume, which parses its options twice,
# included), none within them; the bits do not change.
hw=$(python3 -c "import os; print(len(os.sched_getaffinity(0)))")   # what OpenMP counts
"$PREE" render "$S/cornell3" "${R[@]}" --threads $((hw + 1)) --out t.ppm --stats t.json 2>err.txt || fail "--threads $((hw + 1)) failed"
expect_eq "warnings for --threads $((hw + 1))" "$(grep -c "warning: --threads $((hw + 1)) is more than the $hw hardware threads" err.txt)/$(wc -l < err.txt)" 1/1
expect_eq "--threads $((hw + 1)): bits" "$(hashes t)" "$(hashes dppm)"
"$PREE" render --resume c.ckp --threads $((hw + 1)) --quiet --out r.ppm 2>err.txt || fail "resume with --threads $((hw + 1)) failed"
expect_eq "warnings for a resume with --threads $((hw + 1))" "$(grep -c 'warning: --threads' err.txt)" 1
"$PREE" render "$S/cornell3" "${R[@]}" --threads "$hw" --out t.ppm 2>err.txt || fail "--threads $hw failed"
expect_eq "stderr with --threads $hw" "$(cat err.txt)" ""
echo "max_bounces: ok"
