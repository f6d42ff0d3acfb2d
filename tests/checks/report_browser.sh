#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# make report in a real browser: the page (scripts/report/build.py) for a small make-run.sh output
# and for the repository's own out/ (what `make report` shows) is opened in headless Chromium
# (Debian chromium): its script must mark every image loaded (body data-images="ok", as many as
# the page holds), and the screenshot must not be blank (tests/lib/png_stats.py: many colours,
# a good part not background). The out/ page's screenshot is kept as out/report/screenshot.png.
# A copy with one broken image must be caught.
# Usage: tests/checks/report_browser.sh
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
command -v chromium >/dev/null || fail "chromium missing (scripts/install-deps.sh)"
[ -x "$PREE" ] || fail "$PREE not built (make build)"
chrome() { timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$TMP/profile" \
             --virtual-time-budget=15000 "$@" 2>>"$TMP/chromium.log"; }

# page FILE.html SHOT.png: every image loaded, the screenshot not blank.
page() {
  local html=$1 shot=$2 want got
  want=$(grep -o '<img ' "$html" | wc -l)
  chrome --dump-dom "file://$html" >"$TMP/dom.html" || fail "chromium --dump-dom $html failed: $(tail -3 "$TMP/chromium.log")"
  got=$(sed -n 's/.*<body[^>]* data-images="\([^"]*\)".*/\1/p' "$TMP/dom.html" | head -1)
  expect_eq "images loaded in $(basename "$(dirname "$(dirname "$html")")")/report" "$got" "ok"
  expect_eq "images counted by the page" "$(sed -n 's/.*data-image-count="\([0-9]*\)".*/\1/p' "$TMP/dom.html" | head -1)" "$want"
  [ "$want" -ge "${3:-1}" ] || fail "the page holds $want images, expected at least ${3:-1}"
  chrome --window-size=1280,2400 --screenshot="$shot" "file://$html" >/dev/null || fail "chromium --screenshot failed"
  read -r w h colours busy < <(python3 tests/lib/png_stats.py "$shot")
  echo "screenshot $shot: ${w}x$h, $colours colours, $busy not background"
  [ "$colours" -gt 500 ] && python3 -c "import sys; sys.exit(0 if float('$busy') > 0.05 else 1)" \
    || fail "the screenshot looks blank ($colours colours, $busy not background)"
}

# 1. A small run's output: images, maps and figures present.
mkdir -p "$TMP/bin" && cp "$PREE" "$TMP/bin/pree"
PREE_RUN_SIZE="--width 48 --height 36 --photons 5000" scripts/make-run.sh "$TMP/bin/pree" "$TMP/out" >"$TMP/run.log" 2>&1 \
  || { tail "$TMP/run.log"; fail "make-run.sh failed"; }
run python3 scripts/report/build.py "$ROOT" "$TMP/out" "$ROOT/build"
for s in "fp32 (paper) vs double" "Difference maps" "PREU utilization" "Synthesis and timing" "Regression"; do
  grep -q "$s" "$TMP/out/report/index.html" || fail "the page has no '$s'"
done
grep -q 'not run' "$TMP/out/report/index.html" && echo "ok: sections without a source say 'not run'"
page "$TMP/out/report/index.html" "$TMP/shot.png" 12

# 2. The check must see a broken image.
sed '0,/src="data:image\/png;base64,[A-Za-z0-9+\/]\{20\}/s//src="data:image\/png;base64,AAAA/' \
  "$TMP/out/report/index.html" >"$TMP/out/report/broken.html"
chrome --dump-dom "file://$TMP/out/report/broken.html" >"$TMP/dom.html"
grep -q 'data-images="broken: ' "$TMP/dom.html" || fail "a broken image was not reported"
echo "ok: a broken image is reported ($(grep -o 'data-images="broken: [^"]*"' "$TMP/dom.html"))"

# 3. The repository's own page (make report), its screenshot kept beside it.
run python3 scripts/report/build.py "$ROOT" "$ROOT/out" "$ROOT/build"
page "$ROOT/out/report/index.html" "$ROOT/out/report/screenshot.png" 3
echo "report_browser: ok (screenshot out/report/screenshot.png)"
