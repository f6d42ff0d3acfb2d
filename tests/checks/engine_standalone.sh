#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
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

# A header of host/ or tb/ reaches model/ only by a path naming the folder (the dry run below
# proves that no include path leads there).
reached=$(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]*/)?(host|tb)/' model/ || true)
[ -z "$reached" ] || fail "model/ includes a header of host/ or tb/:"$'\n'"$reached"
echo "ok: model/ includes no header of host/ or tb/"

make -n BUILD="$TMP/build" "$TMP/build/pree" >"$TMP/dry.txt" 2>&1 || fail "make -n BUILD=$TMP/build $TMP/build/pree: $(tail -3 "$TMP/dry.txt")"
compiled=$(grep -oE ' -c [^ ]+' "$TMP/dry.txt" | awk '{print $2}')
[ "$(printf '%s\n' "$compiled" | grep -c .)" -gt 20 ] || fail "the dry run compiles too few files to be build/pree's: $(head -5 "$TMP/dry.txt")"
strays=$(printf '%s\n' "$compiled" | grep -vE '^(cli|model)/' || true)
[ -z "$strays" ] || fail "build/pree compiles sources outside cli/ and model/:"$'\n'"$strays"
grep -qiE 'verilat|obj_dir' "$TMP/dry.txt" && fail "building build/pree runs Verilator: $(grep -iE 'verilat|obj_dir' "$TMP/dry.txt" | head -3)"
grep -qE -- '-I *([^ ]*/)?(host|tb)(/|[[:space:]]|$)' "$TMP/dry.txt" && fail "build/pree's flags reach into host/ or tb/: $(grep -oE -- '-I *([^ ]*/)?(host|tb)(/[^ ]*)?' "$TMP/dry.txt" | sort -u | head -3)"
echo "ok: build/pree compiles $(printf '%s\n' "$compiled" | wc -l) files of cli/ and model/ and runs no Verilator"
