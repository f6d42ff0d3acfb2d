#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# EXR metadata round trip through OpenImageIO's own reader (iinfo, Debian openimageio-tools): a
# render's EXR header carries pree:scene, size, photons, photon offset, precision, datapath, grid,
# alpha, version (the build's git describe, `pree --version`) and the image hash, each equal to
# the run's options and its statistics file; PNG output stays without them (its bytes unchanged).
# Usage: tests/checks/exr_metadata.sh
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
command -v iinfo >/dev/null || fail "iinfo missing (Debian openimageio-tools: scripts/install-deps.sh)"
[ -x "$PREE" ] || fail "$PREE not built (make build)"
run "$PREE" render scenes/cornell3 --width 40 --height 30 --photons 3000 --photon-offset 777 \
    --precision fp32 --datapath stable --grid smallppm --alpha 0.6 \
    --out "$TMP/m.exr" --out "$TMP/m.png" --stats "$TMP/m.json" --quiet
iinfo -v "$TMP/m.exr" >"$TMP/info" || fail "iinfo cannot read $TMP/m.exr"
sed 's/^/  | /' "$TMP/info"
meta() { sed -n "s/^ *pree:$1: \"\(.*\)\"$/\1/p" "$TMP/info"; }
version=$("$PREE" --version | sed -n '1s/^pree //p')
if git rev-parse --git-dir >/dev/null 2>&1; then
  case "$version" in ""|unknown) fail "pree --version is '$version' in a git tree";; esac
  git rev-parse -q --verify "${version%-dirty}^{commit}" >/dev/null 2>&1 || \
    git rev-parse -q --verify "$(echo "$version" | sed -n 's/.*-g\([0-9a-f]*\).*/\1/p')^{commit}" >/dev/null 2>&1 || \
    fail "pree --version '$version' names no commit of this repository"
  echo "ok: pree --version $version names a commit"
fi
expect_eq "pree:scene" "$(meta scene)" "scenes/cornell3"
expect_eq "pree:size" "$(meta size)" "40x30"
expect_eq "pree:photons" "$(meta photons)" "$(json "$TMP/m.json" photons_emitted)"
expect_eq "pree:photon_offset" "$(meta photon_offset)" "777"
expect_eq "pree:precision" "$(meta precision)" "fp32"
expect_eq "pree:datapath" "$(meta datapath)" "stable"
expect_eq "pree:grid" "$(meta grid)" "smallppm"
expect_eq "pree:alpha" "$(python3 -c "print(float(\"$(meta alpha)\"))")" "$(json "$TMP/m.json" alpha)"
expect_eq "pree:version" "$(meta version)" "$version"
expect_eq "pree:image_hash" "$(meta image_hash)" "$(json "$TMP/m.json" image_hash)"
expect_eq "photons in the statistics" "$(json "$TMP/m.json" photons_emitted)" "3000"
iinfo -v "$TMP/m.png" | grep -q 'pree:' && fail "the PNG carries pree: attributes"
echo "ok: the PNG has no pree: attributes"
# The double mode names no datapath.
run "$PREE" render scenes/cornell3 --width 16 --height 12 --photons 500 --out "$TMP/d.exr" --quiet
iinfo -v "$TMP/d.exr" >"$TMP/info"
expect_eq "double: pree:datapath" "$(meta datapath)" "none"
expect_eq "double: pree:precision" "$(meta precision)" "double"
echo "exr_metadata: ok"
