# SPDX-License-Identifier: Apache-2.0
# The IEEE-754 binary32 units (rtl/pree_fp32_*.v) and the stable datapath's wide accumulator
# (rtl/pree_wacc.v, unit "wacc") and count conversion (rtl/pree_u64_to_f32.v, unit "u2f"):
# Verilator benches, Icarus testbenches over vector files, lint and Yosys synthesis.
# Documented in docs/fp32_units.md and docs/fp32_verification.md.
#
#   make sim-fp32          quick level: Verilator (directed + FP32_QUICK random per unit) and
#                          Icarus (directed + FP32_IV_QUICK random per unit); part of `make sim`
#   make sim-fp32-full     thorough level: FP32_FULL random per unit in Verilator (>= 10 million)
#                          and FP32_IV_FULL per unit in Icarus, and the squarer's exhaustive
#                          significand sweep (sim-fp32-sweep-sqr)
#   make sim-fp32-vl-<u>, sim-fp32-iv-<u>   one configuration (u = a name of FP32_UNITS or
#                          FP32_DEEP)
#   make sim-fp32-deep     the deep and other-Stages configurations (FP32_DEEP), both simulators
#   make sim-fp32-stages   Icarus, every unit at every supported Stages value (quick counts)
#   make lint-fp32         verilator --lint-only -Wall on every unit and configuration
#   make synth-fp32        yosys synth_xilinx per configuration (FP32_UNITS and the PipeFast = 1
#                          ones), latch and loop checks, resource table in
#                          $(BUILD)/fp32/synth/resources.md
# The bench configurations, each unit's module and its Stages range come from the configuration
# table (config/pree_config.json, through mk/config.mk): FP32_UNITS (the units at their defaults
# and "div8", the divider with Stages = 8), built for the regression; FP32_DEEP (docs/fpga.md:
# <unit>_fast = the unit with PipeFast = 1, its deep stage plan; div2, div12, div20 = the divider
# with Stages 2, 12, 20; <unit>_ecp5: built with PREE_ECP5_DSP, the products in ECP5 MULT18X18D
# primitives with their own registers (rtl/pree_fp32_dsp_mul.v, the FPGA timing flow's form),
# simulated by tb/fpga/MULT18X18D.v), whose Verilator models are built on demand (not in
# TEST_PREREQS), so that the quick regression stays fast. Each goes through the same benches at
# the latency its table row gives.

FP32_DIR      := $(BUILD)/fp32
FP32_RTL      := $(wildcard rtl/pree_fp32_*.v) rtl/pree_wacc.v rtl/pree_u64_to_f32.v
fp32_top       = $(FP32_TOP_$(1))
FP32_QUICK    ?= 1000000
FP32_FULL     ?= 10000000
FP32_IV_QUICK ?= 20000
FP32_IV_FULL  ?= 200000
FP32_SEED     ?= 1
FP32_CFLAGS   := -std=c11 -D_GNU_SOURCE -O2 $(FPFLAGS) -fexcess-precision=standard $(WARN) $(MODEL_INC) -Itb/fp32
FP32_GEN_DEPS := tb/fp32/fp32_gen.h tb/fp32/fp32_gen_cases.h model/pree/fp32_ops.h model/pree/wide_acc.h

FP32_VL_BIN := $(foreach u,$(FP32_UNITS),$(FP32_DIR)/vl_$(u)/fp32_bench_$(u))
FP32_IV_SIM := $(foreach u,$(FP32_UNITS),$(FP32_DIR)/tb_fp32_$(u).vvp)

TEST_PREREQS  += $(FP32_VL_BIN) $(FP32_IV_SIM) $(FP32_DIR)/fp32_vecgen
LINT_TARGETS  += lint-fp32
SYNTH_TARGETS += synth-fp32
SIM_TARGETS   += sim-fp32

.PHONY: sim-fp32 sim-fp32-full lint-fp32 synth-fp32

# The case generator (shared by both simulators) and the Icarus vector writer: C11, with the
# bit-exactness flags of the model, since the reference is host float arithmetic.
# fp32_gen.o: the binary32 units' cases (fp32_gen.c) and the stable datapath's (fp32_gen_wide.c)
# in one relocatable object, which every bench links.
$(FP32_DIR)/fp32_gen_%.o: tb/fp32/fp32_gen_%.c $(FP32_GEN_DEPS) | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(FP32_CFLAGS) -c $< -o $@

$(FP32_DIR)/fp32_gen_b32.o: tb/fp32/fp32_gen.c $(FP32_GEN_DEPS) | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(FP32_CFLAGS) -c $< -o $@

$(FP32_DIR)/fp32_gen.o: $(FP32_DIR)/fp32_gen_b32.o $(FP32_DIR)/fp32_gen_wide.o
	$(call say,LD,$@)$(LD) -r $^ -o $@

$(FP32_DIR)/fp32_vecgen: tb/fp32/fp32_vecgen.c $(FP32_DIR)/fp32_gen.o $(FP32_GEN_DEPS)
	$(call say,LINK,$@)$(CC) $(FP32_CFLAGS) $< $(FP32_DIR)/fp32_gen.o -o $@ -lm

# Per configuration $(1): the RTL unit $(2), Verilator -G/-D flags $(3), Icarus -D flags $(4).
# Verilator bench (one harness, unit chosen by -DFP32_UNIT_*), Icarus simulation, quick and
# full runs. --x-assign/--x-initial unique: no reliance on X or initial values.
define FP32_UNIT_RULES
$(FP32_DIR)/vl_$(1)/fp32_bench_$(1): $(FP32_RTL) tb/fpga/MULT18X18D.v tb/fp32/fp32_bench.cpp $(VHARNESS) $(FP32_DIR)/fp32_gen.o $(FP32_GEN_DEPS)
	@mkdir -p $$(@D)
	$$(call say,VERILATE,$$@)verilator --cc --exe --build -O3 -j 1 $(VL_BENCH_OPT) --x-assign unique --x-initial unique $(3) \
	  -Mdir $(FP32_DIR)/vl_$(1) --top-module $(call fp32_top,$(2)) -y rtl rtl/$(call fp32_top,$(2)).v \
	  $(abspath tb/fp32/fp32_bench.cpp) $(abspath $(FP32_DIR)/fp32_gen.o) \
	  -CFLAGS "-O2 -DFP32_UNIT_$(shell echo $(2) | tr a-z A-Z) $(4) -I$(abspath tb/fp32) -I$(abspath model) $(VHARNESS_INC)" \
	  -o fp32_bench_$(1) > $(FP32_DIR)/vl_$(1).build.log 2>&1 \
	  || { tail -30 $(FP32_DIR)/vl_$(1).build.log; exit 1; }

$(FP32_DIR)/tb_fp32_$(1).vvp: $(FP32_RTL) tb/fpga/MULT18X18D.v tb/fp32/tb_fp32_pipe.v tb/fp32/tb_fp32_cmp.v | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$(call say,IVERILOG,$$@)iverilog -g2005 -Wall -Irtl $(if $(filter cmp,$(2)),,-DUNIT_$(shell echo $(2) | tr a-z A-Z)) $(5) \
	  -o $$@ -y rtl $(if $(filter cmp,$(2)),tb/fp32/tb_fp32_cmp.v,tb/fp32/tb_fp32_pipe.v) \
	  rtl/$(call fp32_top,$(2)).v

.PHONY: sim-fp32-vl-$(1) sim-fp32-iv-$(1) sim-fp32-full-vl-$(1) sim-fp32-full-iv-$(1)
sim-fp32-vl-$(1): $(FP32_DIR)/vl_$(1)/fp32_bench_$(1)
	$$< $(FP32_QUICK) $(FP32_SEED)

sim-fp32-full-vl-$(1): $(FP32_DIR)/vl_$(1)/fp32_bench_$(1)
	$$< $(FP32_FULL) $(FP32_SEED)

sim-fp32-iv-$(1): $(FP32_DIR)/tb_fp32_$(1).vvp $(FP32_DIR)/fp32_vecgen
	$(FP32_DIR)/fp32_vecgen $(2) $(FP32_IV_QUICK) $(FP32_SEED) $(FP32_DIR)/vec_$(1)_quick.txt
	vvp -N $(FP32_DIR)/tb_fp32_$(1).vvp +vec=$(FP32_DIR)/vec_$(1)_quick.txt +seed=$(FP32_SEED)

sim-fp32-full-iv-$(1): $(FP32_DIR)/tb_fp32_$(1).vvp $(FP32_DIR)/fp32_vecgen
	$(FP32_DIR)/fp32_vecgen $(2) $(FP32_IV_FULL) $(FP32_SEED) $(FP32_DIR)/vec_$(1)_full.txt
	vvp -N $(FP32_DIR)/tb_fp32_$(1).vvp +vec=$(FP32_DIR)/vec_$(1)_full.txt +seed=$(FP32_SEED)
endef
# A configuration $(1) from its FP32_CFG_ line: words 1 unit, 2 PipeFast, 3 Stages, 4 latency.
fp32_cfg        = $(word $(2),$(FP32_CFG_$(1)))
fp32_cfg_stages = $(if $(filter -,$(call fp32_cfg,$(1),3)),,$(call fp32_cfg,$(1),3))
fp32_cfg_ecp5   = $(if $(filter ecp5,$(call fp32_cfg,$(1),5)),-DPREE_ECP5_DSP -y tb/fpga)
fp32_cfg_params = $(if $(filter cmp,$(call fp32_cfg,$(1),1)),,-GPipeFast=$(call fp32_cfg,$(1),2) $(if $(call fp32_cfg_stages,$(1)),-GStages=$(call fp32_cfg_stages,$(1))))
fp32_cfg_vl     = $(call fp32_cfg_params,$(1)) $(call fp32_cfg_ecp5,$(1))
fp32_cfg_iv     = -DUNIT_PIPEFAST=$(call fp32_cfg,$(1),2) $(if $(call fp32_cfg_stages,$(1)),-DUNIT_STAGES=$(call fp32_cfg_stages,$(1))) -DUNIT_LATENCY=$(call fp32_cfg,$(1),4) $(call fp32_cfg_ecp5,$(1))
$(foreach c,$(FP32_UNITS) $(FP32_DEEP),$(eval $(call FP32_UNIT_RULES,$(c),$(call fp32_cfg,$(c),1),$(call fp32_cfg_vl,$(c)),-DFP32_LATENCY=$(call fp32_cfg,$(c),4),$(call fp32_cfg_iv,$(c)))))

sim-fp32: $(foreach u,$(FP32_UNITS),sim-fp32-vl-$(u) sim-fp32-iv-$(u))
sim-fp32-full: $(foreach u,$(FP32_UNITS),sim-fp32-full-vl-$(u) sim-fp32-full-iv-$(u)) sim-fp32-sweep-sqr

.PHONY: sim-fp32-deep sim-fp32-full-deep sim-fp32-stages
sim-fp32-deep: $(foreach u,$(FP32_DEEP),sim-fp32-vl-$(u) sim-fp32-iv-$(u))
sim-fp32-full-deep: $(foreach u,$(FP32_DEEP),sim-fp32-full-vl-$(u) sim-fp32-full-iv-$(u))

# Every supported Stages value of every unit, Icarus (compiles in about a second), directed
# list plus FP32_STAGES_N random vectors each: the stage plans between the named configurations.
# (FP32_STAGES_<unit>: the table's range, mk/config.mk.)
FP32_STAGES_N ?= 5000
sim-fp32-stages: $(FP32_DIR)/fp32_vecgen | $(DEPS_STAMP)
	@set -e; mkdir -p $(FP32_DIR)/stages; \
	$(foreach u,$(FP32_PIPELINED), \
	  $(FP32_DIR)/fp32_vecgen $(u) $(FP32_STAGES_N) $(FP32_SEED) $(FP32_DIR)/stages/vec_$(u).txt; \
	  for s in $(FP32_STAGES_$(u)); do \
	    cmd="iverilog -g2005 -Wall -Irtl -DUNIT_$(shell echo $(u) | tr a-z A-Z) -DUNIT_STAGES=$$s -DUNIT_LATENCY=$$s -o $(FP32_DIR)/stages/$(u)$$s.vvp -y rtl tb/fp32/tb_fp32_pipe.v rtl/$(call fp32_top,$(u)).v"; \
	    $$cmd; \
	    vvp -N $(FP32_DIR)/stages/$(u)$$s.vvp +vec=$(FP32_DIR)/stages/vec_$(u).txt +seed=$(FP32_SEED) \
	      || { echo "sim-fp32-stages: $(u) Stages=$$s failed; rerun: $$cmd && vvp -N $(FP32_DIR)/stages/$(u)$$s.vvp +vec=$(FP32_DIR)/stages/vec_$(u).txt"; exit 1; }; \
	  done;) true

# The squarer has one operand: every significand at six exponents (50 million cases).
.PHONY: sim-fp32-sweep-sqr
sim-fp32-sweep-sqr: $(FP32_DIR)/vl_sqr/fp32_bench_sqr
	$< 0 $(FP32_SEED) sweep

# Lint: every unit as a top, with the helpers it instantiates, at its default, at PipeFast = 1
# and at the ends of its Stages range; the divider also at Stages 8, 12 and 20; the multiplier and
# squarer also as the ECP5 timing flow builds them (PREE_ECP5_DSP); warnings are errors.
FP32_LINT_CFGS := $(foreach u,add mul sqr wacc u2f,"$(call fp32_top,$(u)) -GPipeFast=1" \
                    "$(call fp32_top,$(u)) -GStages=1" \
                    "$(call fp32_top,$(u)) -GStages=$(lastword $(FP32_STAGES_$(u)))") \
                  "pree_fp32_div -GPipeFast=1" $(foreach s,2 8 12 20,"pree_fp32_div -GStages=$(s)") \
                  $(foreach u,mul sqr,"pree_fp32_$(u) -GPipeFast=1 -DPREE_ECP5_DSP -y tb/fpga")
lint-fp32: | $(DEPS_STAMP)
	@set -e; for u in $(foreach u,add mul sqr div cmp wacc u2f,$(call fp32_top,$(u))) \
	    $(FP32_LINT_CFGS); do \
	  set -- $$u; top=$$1; shift; \
	  echo "verilator --lint-only -Wall $$* -y rtl --top-module $$top rtl/$$top.v"; \
	  verilator --lint-only -Wall $$* -y rtl --top-module $$top rtl/$$top.v; \
	done

# Synthesis: one Yosys run per unit (scripts/fp32_synth.sh), then the resource/depth table.
synth-fp32: | $(DEPS_STAMP)
	@set -e; mkdir -p $(FP32_DIR)/synth; \
	{ echo "| unit | LUTs | FFs | DSP48E1 | CARRY4 | MUXF7/8 | LUT levels per stage | cells on longest path per stage |"; \
	  echo "|---|---|---|---|---|---|---|---|"; } > $(FP32_DIR)/synth/resources.md.tmp; \
	for u in $(FP32_UNITS) $(FP32_FAST); do \
	  $(call say_sh,SYNTH,fp32/synth/$$u,scripts/fp32_synth.sh $$u $(FP32_DIR)/synth); \
	  scripts/fp32_synth.sh $$u $(FP32_DIR)/synth >/dev/null || { echo "synth-fp32: $$u failed; rerun: scripts/fp32_synth.sh $$u $(FP32_DIR)/synth"; exit 1; }; \
	  cat $(FP32_DIR)/synth/$$u.row >> $(FP32_DIR)/synth/resources.md.tmp; \
	done; \
	mv $(FP32_DIR)/synth/resources.md.tmp $(FP32_DIR)/synth/resources.md; \
	cat $(FP32_DIR)/synth/resources.md
