#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every environment variable the engine, the co-simulation host and the driver read is named in
# one table (model/util/pree_env.h, pree_env.c) and documented (docs/engine.md, "Environment
# variables"): fails on a getenv() in model/, host/ or drv/ outside model/util/pree_env.c, on a
# name of the table that the header's comment or the docs do not list, and on a PREE_ name read
# by a check or script of the repository that the table does not hold. cli/cli_mpi.c reads only
# the MPI launchers' own variables. Under a second.
# level: quick
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
stray=$(grep -rn 'getenv *(' model host drv --include='*.c' --include='*.cpp' --include='*.h' | grep -v '^model/util/pree_env\.c:' || true)
[ -z "$stray" ] || fail "getenv outside model/util/pree_env.c (name the variable there): $stray"
names=$(sed -n 's/^ *\[PREE_ENV_[A-Z0-9_]*\] = "\(PREE_[A-Z0-9_]*\)",$/\1/p' model/util/pree_env.c)
[ "$(wc -w <<<"$names")" -ge 9 ] || fail "model/util/pree_env.c: fewer than 9 names read (the extraction is broken): $names"
for n in $names; do
  grep -q " \*   $n " model/util/pree_env.h || fail "$n: not described in model/util/pree_env.h's comment"
  grep -q "| \`$n\` |" docs/engine.md || fail "$n: not in docs/engine.md's table of environment variables"
done
# Variables the checks and scripts set for the engine, pree or pree cosim must be in the table.
used=$(grep -rhoE '\bPREE_(NO_AVX2|TRACER_[A-Z]+|GRID_[A-Z]+|NO_[A-Z]+|SCREEN_[A-Z]+|TEST_[A-Z_]+|OIIO_[A-Z]+)\b' \
         tests/checks scripts | grep -v '^PREE_TEST_\(JOBS\|TIMEOUT\|UNITS\|CHECKS\|XML\)$' | sort -u)
for n in $used; do grep -qx "$n" <<<"$names" || fail "$n: set by a check or script, but not in model/util/pree_env.c"; done
echo "ok: $(wc -w <<<"$names") environment variables, each in pree_env.h and docs/engine.md; no other getenv"
