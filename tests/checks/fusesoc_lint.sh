#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The FuseSoC core pree.core: `fusesoc run --target=lint` (Verilator --lint-only -Wall of
# pree_axi, the repository as the cores root, no network) passes; rtl/pree.f is what `make pree-f`
# generates from the core (the same files in FuseSoC's order); the core's parameters are exactly
# pree_axi's overridable ones (those not marked "do not override"), and so are those of the pnr
# target's top, tb/fpga/pree_fpga_axi_wrap.v, which is lint-clean too; the core's version is
# pree_axi's PREE_VERSION; every other target (sim_wrap, sim_icarus, sim_verilator, synth, pnr)
# sets up (`fusesoc run --setup`: its files exist, its flow and options are valid; nothing is
# built). FuseSoC from the hardware
# tools' venv (FPGA_VENV, default build/fpga-venv; make test installs it).
# cost: 20 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
venv=${FPGA_VENV:-${BUILD:-build}/fpga-venv}
[ -x "$venv/bin/fusesoc" ] || fail "no FuseSoC in $venv (make fpga-deps)"
out=${BUILD:-build}/fusesoc/check-lint
rm -rf "$out" "$out"-*
mkdir -p "${BUILD:-build}" && touch "${BUILD:-build}/FUSESOC_IGNORE"
run "$venv/bin/fusesoc" --cores-root . run --build-root "$out" --target=lint pree:pree:pree_axi
echo "ok: fusesoc run --target=lint of pree.core"
for t in sim_wrap sim_icarus sim_verilator synth pnr; do
  run "$venv/bin/fusesoc" --cores-root . run --setup --build-root "$out-$t" --target=$t pree:pree:pree_axi >/dev/null
done
echo "ok: the targets sim_wrap, sim_icarus, sim_verilator, synth and pnr set up"

eda=$(ls "$out"/*/lint/*.eda.yml) || fail "no .eda.yml under $out"
run "$venv/bin/python3" scripts/pree_filelist.py "$eda" "$TMP/pree.f"
diff rtl/pree.f "$TMP/pree.f" >"$TMP/f.diff" \
  || fail "rtl/pree.f is not pree.core's rtl fileset (edit pree.core, then make pree-f): $(grep '^[<>]' "$TMP/f.diff" | tr '\n' ' ')"
echo "ok: rtl/pree.f is generated from pree.core ($(grep -vc '^//' rtl/pree.f) files)"

params() {  # params MODULE FILE: the overridable parameters of the module's header, sorted
  sed -n "/^module $1 #(/,/^) (/p" "$2" | grep -v 'do not override' \
    | sed -n 's/^ *parameter *\([A-Za-z_][A-Za-z0-9_]*\).*/\1/p' | sort
}
rtl_params=$(params pree_axi rtl/pree_axi.v)
core_params=$("$venv/bin/python3" -c 'import sys, yaml
p = yaml.safe_load(open(sys.argv[1]))["parameters"]
print("\n".join(sorted(k for k, v in p.items() if v.get("paramtype") == "vlogparam")))' "$eda")
[ -n "$rtl_params" ] || fail "no parameters read from rtl/pree_axi.v's module header"
[ "$rtl_params" = "$core_params" ] \
  || fail "pree.core's lint target and pree_axi differ in parameters (< pree_axi.v, > pree.core): $(diff <(echo "$rtl_params") <(echo "$core_params") | grep '^[<>]' | tr '\n' ' ')"
echo "ok: pree.core exposes pree_axi's $(echo "$rtl_params" | wc -l) parameters"

wrap_params=$(params pree_fpga_axi_wrap tb/fpga/pree_fpga_axi_wrap.v)
[ "$rtl_params" = "$wrap_params" ] \
  || fail "tb/fpga/pree_fpga_axi_wrap.v and pree_axi differ in parameters (< pree_axi.v, > wrapper): $(diff <(echo "$rtl_params") <(echo "$wrap_params") | grep '^[<>]' | tr '\n' ' ')"
run verilator --lint-only -Wall -Irtl --top-module pree_fpga_axi_wrap -f rtl/pree.f tb/fpga/pree_fpga_fold.v tb/fpga/pree_fpga_axi_wrap.v
echo "ok: the pnr target's top passes pree_axi's parameters and is lint-clean"

v=$(sed -n "s/.*localparam \[31:0\] PREE_VERSION = 32'h\([0-9a-fA-F_]*\);.*/\1/p" rtl/pree_axi.v | tr -d _)
[ ${#v} = 8 ] || fail "no PREE_VERSION = 32'hXXXX_XXXX in rtl/pree_axi.v"
rtl_ver=$((16#${v:2:2})).$((16#${v:4:2})).$((16#${v:6:2}))
core_ver=$(sed -n 's/^name: .*:\([^:]*\)$/\1/p' pree.core)
expect_eq "pree.core's version (pree_axi's PREE_VERSION $rtl_ver)" "$core_ver" "$rtl_ver"
