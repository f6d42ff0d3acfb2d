#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# flip-reference.sh [VENV]: regenerate tests/data/flip/reference.txt, the figures that
# tests/checks/compare_flip.sh holds `pree compare --flip` to: the mean and the largest pixel of
# the LDR-FLIP map by NVIDIA's own implementation (pip flip-evaluator 1.7, pinned in
# scripts/install-deps.sh --flip; default VENV build/flip-venv) for the pairs of
# tests/data/flip/pairs.py and for smallppm's cornell3 image against a 96,000-photon render.
# Needs build/pree. Not part of the regression (it downloads the package once).
set -euo pipefail
cd "$(dirname "$0")/.."
venv=${1:-build/flip-venv}
scripts/install-deps.sh --flip "$venv"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python3 tests/data/flip/pairs.py "$tmp"
zcat tests/data/smallppm/cornell3_320x240_768k.ppm.gz >"$tmp/cornell3_a.ppm"
build/pree render scenes/cornell3 --width 320 --height 240 --photons 96000 --out "$tmp/cornell3_b.ppm" --quiet
"$venv/bin/python3" - "$tmp" >tests/data/flip/reference.txt <<'PY'
import sys, numpy as np, flip_evaluator as flip
d = sys.argv[1]
def load(p):   # an ASCII P3 file as display values in [0, 1]
    t = open(p).read().split(); w, h = int(t[1]), int(t[2])
    return np.array(t[4:4 + 3 * w * h], dtype=np.float32).reshape(h, w, 3) / 255
print("# LDR-FLIP by NVIDIA's flip-evaluator 1.7 (default 67.02 pixels per degree): pair, mean, largest pixel")
print("# written by scripts/flip-reference.sh; read by tests/checks/compare_flip.sh")
for k in ("noise", "edges", "colour", "cornell3"):
    m, mean, _ = flip.evaluate(load("%s/%s_a.ppm" % (d, k)), load("%s/%s_b.ppm" % (d, k)), "LDR", applyMagma=False)
    print("%s %.9g %.9g" % (k, mean, float(m.max())))
PY
cat tests/data/flip/reference.txt
