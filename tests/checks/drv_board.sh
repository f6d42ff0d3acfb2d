#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# pree_drv's board back end (drv/pree_be_uio.c) builds and links into build/drv/pree_probe, the
# bring-up program. It cannot run without a board (no UIO device, AXI DMA or u-dma-buf), so only
# its refusals are exercised: missing options (exit 2, usage), and a register block that does not
# exist (exit 1, one line naming the device).
# cost: 1
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
probe=build/drv/pree_probe
[ -x "$probe" ] || fail "$probe missing (make $probe)"
"$probe" --regs /dev/uio0 2>"$TMP/err"
rc=$?
[ $rc -eq 2 ] || fail "$probe without its DMA and buffer options: exit $rc, expected 2"
grep -q "are all needed" "$TMP/err" || fail "no usage line for missing options: $(cat "$TMP/err")"
echo "ok: missing options refused: $(cat "$TMP/err")"
"$probe" --regs "$TMP/no-uio" --dma-hp "$TMP/no-dma" --dma-ph "$TMP/no-dma" --dma-cand "$TMP/no-dma" \
  --dma-m "$TMP/no-dma" --buf "$TMP/no-buf" >"$TMP/out" 2>"$TMP/err"
rc=$?
[ $rc -eq 1 ] || fail "$probe on missing devices: exit $rc, expected 1"
[ "$(wc -l <"$TMP/err")" -eq 1 ] && grep -q "no-uio: No such file" "$TMP/err" \
  || fail "$probe on missing devices: not one line naming the device: $(cat "$TMP/err")"
[ ! -s "$TMP/out" ] || fail "$probe wrote output before failing: $(cat "$TMP/out")"
echo "ok: a missing register block refused: $(cat "$TMP/err")"
