#!/usr/bin/env bash
# The engine stands alone: nothing in model/ names the co-simulation or includes a header of
# host/ or tb/, and building build/pree from nothing (make's dry run into an empty build folder)
# compiles only cli/ and model/ sources, with no include path into host/ or tb/, and runs no
# Verilator. The co-simulation is a program of its own (build/pree-cosim-pN).
# level: quick
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"

named=$(grep -rIn -i 'cosim' model/ || true)
[ -z "$named" ] || fail "model/ names the co-simulation:"$'\n'"$named"
echo "ok: no 'cosim' in model/"

# Headers that live in host/ or tb/, and any model/ file that includes one of them.
outside=$(find host tb -name '*.h' -printf '%f\n' | sort -u)
[ -n "$outside" ] || fail "no headers found under host/ and tb/: the check would prove nothing"
included=$(grep -rhoE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"[^"]+"' model/ | sed 's/.*"\(.*\)"/\1/' |
  xargs -rn1 basename | sort -u)
both=$(comm -12 <(printf '%s\n' "$outside") <(printf '%s\n' "$included") || true)
# A header of the same name under model/ is the engine's own.
for h in $both; do
  [ -n "$(find model -name "$h")" ] || fail "model/ includes $h, a header of host/ or tb/"
done
echo "ok: model/ includes no header of host/ or tb/ ($(printf '%s\n' "$included" | wc -l) headers included)"

make -n BUILD="$TMP/build" "$TMP/build/pree" >"$TMP/dry.txt" 2>&1 || fail "make -n BUILD=$TMP/build $TMP/build/pree: $(tail -3 "$TMP/dry.txt")"
compiled=$(grep -oE ' -c [^ ]+' "$TMP/dry.txt" | awk '{print $2}')
[ "$(printf '%s\n' "$compiled" | grep -c .)" -gt 20 ] || fail "the dry run compiles too few files to be build/pree's: $(head -5 "$TMP/dry.txt")"
strays=$(printf '%s\n' "$compiled" | grep -vE '^(cli|model)/' || true)
[ -z "$strays" ] || fail "build/pree compiles sources outside cli/ and model/:"$'\n'"$strays"
grep -qiE 'verilat|obj_dir' "$TMP/dry.txt" && fail "building build/pree runs Verilator: $(grep -iE 'verilat|obj_dir' "$TMP/dry.txt" | head -3)"
grep -qE -- '-I *(\./)?(host|tb)(/|[[:space:]])' "$TMP/dry.txt" && fail "build/pree's flags reach into host/ or tb/: $(grep -oE -- '-I *(\./)?(host|tb)[^ ]*' "$TMP/dry.txt" | sort -u | head -3)"
echo "ok: build/pree compiles $(printf '%s\n' "$compiled" | wc -l) files of cli/ and model/ and runs no Verilator"
