#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The committed teapot mesh is what scripts/teapot-tessellate.py makes from Newell's patch data
# (same OBJ text), with the expected counts (32 patches x 81 vertices; 4,032 triangles).
# level: quick
set -u
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cmd="python3 scripts/teapot-tessellate.py scenes/data/teapot/teapot_newell_306v_32p.txt $tmp/teapot.obj"
if ! $cmd 2>"$tmp/log"; then echo "FAIL: $(cat "$tmp/log")"; echo "reproduce: $cmd"; exit 1; fi
if ! cmp -s "$tmp/teapot.obj" <(gzip -dc scenes/data/teapot/teapot.obj.gz); then
  echo "FAIL: scenes/data/teapot/teapot.obj.gz differs from the script's output"
  echo "reproduce: $cmd && gzip -dc scenes/data/teapot/teapot.obj.gz | diff - $tmp/teapot.obj | head"
  exit 1
fi
v=$(grep -c '^v ' "$tmp/teapot.obj"); f=$(grep -c '^f ' "$tmp/teapot.obj")
if [ "$v" -ne 2592 ] || [ "$f" -ne 4032 ]; then
  echo "FAIL: $v vertices, $f triangles (expected 2592, 4032)"; echo "reproduce: $cmd"; exit 1
fi
echo "ok: teapot.obj.gz reproduced ($v vertices, $f triangles)"
