#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The fp32 benches can fail: each mutant below breaks one rule of the binary32 units (tie
# rounding, signed zero, NaN priority, latency, -0 == +0) or of the stable datapath's wide
# accumulator (truncation, saturation, exponent field, -0 dropped) and count conversion (sticky
# bit, shift amount) in a copy of rtl/, and both the Verilator bench and the Icarus testbench of
# the affected unit must then report mismatches and exit non-zero. A mutant that passes either
# fails this check.
# cost: 93 (its seconds in a serial run; the runner starts costly checks first)
set -u
cd "$(dirname "$0")/../.."
make --no-print-directory -s build/fp32/fp32_gen.o build/fp32/fp32_vecgen >/dev/null \
  || { echo "FAILED: make build/fp32/fp32_gen.o build/fp32/fp32_vecgen"; exit 1; }
work=build/fp32/mutants
rm -rf "$work"; mkdir -p "$work"
fail=0

# unit @ file @ sed expression @ what it breaks
mutants=(
  "mul@pree_fp32_round.v@s/wire inc   = guard \& (rest | lsb);/wire inc   = guard;/@ties away from zero"
  "add@pree_fp32_add.v@s/{s1_special, sign_l, sign_l \& sign_s}/{s1_special, sign_l, sign_l}/@x - x = -0 for negative x"
  "div@pree_fp32_special.v@s/assign y_o       = nan_a_i   ?/assign y_o       = (nan_a_i \&\& !nan_b_i) ?/@NaN priority a before b"
  "sqr@pree_fp32_sqr.v@s/.RegsOut (seam_regs(6))/.RegsOut (seam_regs(6) - 1)/@latency 1 instead of 2"
  "cmp@pree_fp32_cmp.v@s/wire eq_num    = both_zero | /wire eq_num    = /@-0 == +0"
  "wacc@pree_wacc.v@s/carry ? sum\[56:1\] : sum\[55:0\];/carry ? sum[56:1] + {55'd0, sum[0]} : sum[55:0];/@carry normalisation rounds instead of truncating"
  "wacc@pree_wacc.v@s/wire        sat   = carry \& s4_exp_top;/wire        sat   = 1'b0;/@no saturation to WIDE_MAX"
  "wacc@pree_wacc.v@s/{man_s\[55\] ? exp_s : 8'd0, man_s}/{exp_s, man_s}/@e field kept when bit 55 is 0"
  "wacc@pree_wacc.v@s/(inf_a | sign_t)/(inf_a | (sign_t \&\& t0[30:0] != 31'd0))/@t = -0 added as +0"
  "u2f@pree_u64_to_f32.v@s/(norm\[36:0\] != 37'd0)/(norm[35:0] != 36'd0)/@sticky bit misses one bit"
  "u2f@pree_u64_to_f32.v@s/s2_a << {s2_lz\[5:3\], 3'd0}/s2_a << {1'b0, s2_lz[4:3], 3'd0}/@shift ignores lz bit 5"
)

# The module of a unit: pree_fp32_<unit> unless named here (as in mk/fp32.mk).
top_of() {
  case $1 in wacc) echo pree_wacc ;; u2f) echo pree_u64_to_f32 ;; *) echo "pree_fp32_$1" ;; esac
}

i=0
for m in "${mutants[@]}"; do
  IFS='@' read -r unit file expr what <<<"$m"
  i=$((i + 1)); dir=$work/m$i
  mkdir -p "$dir/rtl"; cp rtl/pree_fp32_*.v rtl/pree_wacc.v rtl/pree_u64_to_f32.v "$dir/rtl/"
  sed -i "$expr" "$dir/rtl/$file"
  if cmp -s "rtl/$file" "$dir/rtl/$file"; then
    echo "mutant $i ($what): the edit did not apply to rtl/$file"; fail=1; continue
  fi
  U=$(echo "$unit" | tr a-z A-Z); top=$(top_of "$unit")
  build=(verilator --cc --exe --build -O0 -j 1 -MAKEFLAGS "OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0" -Mdir "$dir/vl" --top-module "$top"
         -y "$dir/rtl" "$dir/rtl/$top.v" "$PWD/tb/fp32/fp32_bench.cpp" "$PWD/build/fp32/fp32_gen.o"
         -CFLAGS "-O0 -DFP32_UNIT_$U -I$PWD/tb/fp32 -I$PWD/model -I$PWD/tb/lib" -o bench)
  if ! "${build[@]}" >"$dir/build.log" 2>&1; then
    echo "mutant $i ($what): build failed, see $dir/build.log"; fail=1; continue
  fi
  if "$dir/vl/bench" 100000 1 >"$dir/run.log" 2>&1; then
    echo "mutant $i ($what) in $unit: NOT detected; reproduce: ${build[*]} && $dir/vl/bench 100000 1"
    fail=1
  else
    echo "mutant $i ($what) in $unit: Verilator detected: $(tail -2 "$dir/run.log" | head -1)"
  fi
  tb=tb/fp32/tb_fp32_pipe.v; def=-DUNIT_$U
  if [ "$unit" = cmp ]; then tb=tb/fp32/tb_fp32_cmp.v; def=; fi
  iv=(iverilog -g2005 $def -I rtl -o "$dir/tb.vvp" -y "$dir/rtl" "$tb" "$dir/rtl/$top.v")
  if ! build/fp32/fp32_vecgen "$unit" 5000 1 "$dir/vec.txt" >/dev/null || ! "${iv[@]}" >"$dir/iv.log" 2>&1; then
    echo "mutant $i ($what): Icarus build failed, see $dir/iv.log"; fail=1; continue
  fi
  if vvp -N "$dir/tb.vvp" +vec="$dir/vec.txt" >"$dir/iv_run.log" 2>&1; then
    echo "mutant $i ($what) in $unit: NOT detected by Icarus; reproduce: ${iv[*]} && vvp -N $dir/tb.vvp +vec=$dir/vec.txt"
    fail=1
  else
    echo "mutant $i ($what) in $unit: Icarus detected: $(grep -m1 -E 'mismatches|FATAL' "$dir/iv_run.log")"
  fi
done
[ $fail -eq 0 ] || echo "FAILED: reproduce with: bash tests/checks/fp32_mutants.sh"
exit $fail
