#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The photon-map searches (docs/photon_map.md): the clustered search, the single-pass kd-tree
# search and the nanoflann oracle give the same radiance bits (--knn-bench 1 runs the three on the
# same trees in one process; their state hashes must agree) for k from 1 to 2000, sparse and dense
# shading points (the adaptive per-member scopes and the shared ones both taken), one and two
# threads, two scenes. The clustered search's prefilter: every path this processor has gives the
# same bits, reports itself and is the one that ran (the kernels count their own calls); the
# default is the widest /proc/cpuinfo lists; a path the processor lacks is a one-line error; the
# AVX-512 and AVX2 kernels' object code holds zmm and ymm instructions.
# cost: 20
. "$(dirname "$0")/../lib/check.sh"

bench() {  # bench NAME SCENE W H PHOTONS K THREADS: the three searches, stats in $TMP/NAME.json
  local name=$1 scene=$2 w=$3 h=$4 n=$5 k=$6 t=$7
  run "$PREE" render "$ROOT/scenes/$scene" --width "$w" --height "$h" --photons "$n" --estimator pm --k "$k" \
      --max-radius 4 --threads "$t" --knn-bench 1 --quiet --out "$TMP/$name.ppm" --stats "$TMP/$name.json"
  local c n_ d
  c=$(json "$TMP/$name.json" pm.bench.clustered.state_hash)
  n_=$(json "$TMP/$name.json" pm.bench.naive.state_hash)
  d=$(json "$TMP/$name.json" pm.bench.kdtree.state_hash)
  expect_eq "$name: clustered = oracle" "$c" "$n_"
  expect_eq "$name: kdtree = oracle" "$d" "$n_"
  expect_eq "$name: the image's state is theirs" "$(json "$TMP/$name.json" state_hash)" "$n_"
}

bench k1 cornell3 64 48 20000 1 1
bench k50-t1 cornell3 64 48 20000 50 1
bench k50-t2 cornell3 64 48 20000 50 2
bench k2000 cornell3 64 48 20000 2000 2
bench sparse cornell3 24 18 80000 200 1        # few shading points against many photons
bench dense cornell3 128 96 10000 50 2         # many shading points against few photons
bench teapot cornell-teapot 64 48 20000 200 2
[ "$(json "$TMP/sparse.json" pm.clusters_sparse)" -gt 0 ] || fail "sparse: no cluster took per-member scopes"
[ "$(json "$TMP/dense.json" pm.scope_photons)" -gt 0 ] || fail "dense: no shared scope"
[ "$(json "$TMP/k2000.json" pm.short_of_k)" -gt 0 ] || fail "k2000: no hit point short of k (the bound r0 untested)"
echo "ok: per-member scopes $(json "$TMP/sparse.json" pm.clusters_sparse), shared scope photons $(json "$TMP/dense.json" pm.scope_photons)"

# The prefilter paths.
flags=$(grep -m1 '^flags' /proc/cpuinfo)
has() { [[ " $flags " == *" $1 "* ]]; }
lacks() { case $1 in avx2) ! has avx2 ;; avx512) ! has avx512f ;; *) false ;; esac; }
widest=scalar; has avx2 && widest=avx2; has avx512f && widest=avx512
render() {  # render NAME ARGS...
  local name=$1; shift
  "$PREE" render "$ROOT/scenes/cornell3" --width 64 --height 48 --photons 20000 --estimator pm --k 50 --max-radius 4 \
      --threads 2 --quiet --out "$TMP/$name.ppm" --stats "$TMP/$name.json" "$@"
}
run render auto
expect_eq "the default path is the widest the processor has" "$(json "$TMP/auto.json" pm.kernel)" "$widest"
for p in scalar avx2 avx512; do
  if lacks $p; then
    if render "k-$p" --knn-kernel $p 2>"$TMP/err"; then fail "--knn-kernel $p accepted without the processor's $p"; fi
    [ "$(wc -l <"$TMP/err")" -eq 1 ] || fail "--knn-kernel $p: not one error line: $(cat "$TMP/err")"
    [ ! -e "$TMP/k-$p.ppm" ] || fail "--knn-kernel $p: an image was written"
    echo "ok: --knn-kernel $p refused: $(cat "$TMP/err")"
    continue
  fi
  run render "k-$p" --knn-kernel $p
  expect_eq "--knn-kernel $p reported" "$(json "$TMP/k-$p.json" pm.kernel)" $p
  expect_eq "--knn-kernel $p: the same bits" "$(json "$TMP/k-$p.json" state_hash)" "$(json "$TMP/auto.json" state_hash)"
  for q in scalar avx2 avx512; do
    calls=$(json "$TMP/k-$p.json" pm.kernel_calls.$q)
    if [ $q = $p ]; then [ "$calls" -gt 0 ] || fail "--knn-kernel $p: its kernel never ran"
    else expect_eq "--knn-kernel $p: $q kernel calls" "$calls" 0; fi
  done
done

# The vector kernels' object code.
obj="$(dirname "$PREE")/model/pm/knn_kernel.o"
[ -f "$obj" ] || fail "no $obj"
for fn in kernel_avx512:zmm kernel_avx2:ymm; do
  n=$(objdump -d --no-show-raw-insn --disassemble="${fn%:*}" "$obj" | grep -c "%${fn#*:}")
  [ "$n" -ge 10 ] || fail "${fn%:*}: $n instructions on ${fn#*:} registers"
  echo "ok: ${fn%:*}: $n instructions on ${fn#*:} registers"
done
