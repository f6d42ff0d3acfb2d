#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# README.md and docs/ speak of the product as it is now: the grep below (session, an issue number,
# "this machine", a local clone path) finds nothing but the product's own uses in ALLOW. Every
# repository path the README names exists (generated outputs under build/ and out/ excepted) and
# every `make TARGET` it names is a target the Makefile defines (read from make's database, not
# `make -n TARGET`, which runs the recipes of `run` and `stress` that call make themselves).
# cost: 1
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"

# Product uses of the words: the renderer's session state and a checkpoint/resume session.
ALLOW='render[_ ]session|checkpoint session|resumed session'
grep -rniIE 'session|issue [0-9]|this machine|clone /[a-z]' README.md docs/ \
  | grep -viE "$ALLOW" >"$TMP/hits"
[ -s "$TMP/hits" ] && fail "history or machine anecdote in the docs (rewrite as what is true now):
$(head -20 "$TMP/hits")"
echo "ok: README.md and docs/ name no session, issue, this machine or clone path"

# Paths: repository folders/files the README names (globs expanded; placeholders skipped).
python3 - README.md >"$TMP/paths" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
roots = r'(?:rtl|model|cli|host|drv|tb|tests|scripts|scenes|docs|constraints|formal|mk|\.ci)'
found = set(re.findall(r'(?<![\w/.-])(' + roots + r'/[\w.*/-]*[\w*])', text))
found = {p for p in found if not p.split('/')[-1].isupper()}   # "model/RTL contract" is prose
found |= set(re.findall(r'`(LICENSE|NOTICE|CITATION\.cff|CHANGELOG\.md|Makefile|[\w-]+\.core)`', text))
for p in sorted(found):
    print(p)
PY
[ -s "$TMP/paths" ] || fail "no path found in README.md (the extraction is broken)"
n=0
while read -r p; do
  case "$p" in *'<'*|*SCENE*|*FILE*|*IMAGE*) continue ;; esac
  compgen -G "$p" >/dev/null || fail "README.md names $p, which does not exist"
  n=$((n + 1))
done <"$TMP/paths"
echo "ok: the $n repository paths README.md names exist"

# Targets: every `make X` of the README is a rule of the Makefile's database.
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -pRrq -f Makefile : 2>/dev/null | sed -n 's/^\([A-Za-z0-9_.-]*\):.*/\1/p' | sort -u >"$TMP/targets"
grep -oE 'make [a-z][a-z0-9-]*' README.md | awk '{print $2}' | sort -u >"$TMP/named"
[ -s "$TMP/named" ] || fail "no make target found in README.md (the extraction is broken)"
missing=$(comm -23 "$TMP/named" "$TMP/targets")
[ -z "$missing" ] || fail "README.md names make targets the Makefile does not define: $missing"
echo "ok: the $(wc -l <"$TMP/named") make targets README.md names are defined"
