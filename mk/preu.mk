# SPDX-License-Identifier: Apache-2.0
# PREU (rtl/pree_preu.v), both datapaths and both pipeline configurations (PREU_CFGS: 0 paper,
# 1 stable, each with PipeFast 0; 0f, 1f the same with PipeFast 1, the deep plans): lint, Verilator bench
# scoreboarded against the C model (model/pree/preu_fp32.c, model/pree/preu_stable.c), self-checking
# Icarus bench over a C-generated vector file, Yosys synthesis.
#   make sim-preu        per configuration: Verilator C++ bench (PREU_N ops) + the Verilog bench over
#                        PREU_IV_N vectors under Icarus and under Verilator --binary, both modes;
#                        and a run that breaks the mode-switch rule, which the RTL assertion must stop
#   make sim-preu-full   the thorough level: PREU_N_FULL Verilator ops over several seeds, each datapath
#   make sim-preu-chain  one hit point fed PREU_CHAIN_N accepted photons (default 10 million)
#                        through each datapath's Verilated PREU, state written back each time,
#                        every word against the model; r2 and radiance against double per decade
#   make sim-preu-vl-dp1 one configuration's Verilator bench (dp0 paper, dp1 stable, dp0f/dp1f
#                        deep); sim-preu-vl: all four
#   make wave-preu       an FST waveform of a short Verilator run (PREU_N=200, PREU_WAVE_DP=0|1)
#   make lint-preu       verilator --lint-only -Wall, with and without PREE_ASSERT, TagW 1/8/32, all four
#   make yosys-check-preu  Yosys structural checks, all four: no latch, no combinational loop
#   make synth-preu      the checks, then synth_xilinx (7-series, flattened, no I/O buffers) per
#                        datapath: figures in build/preu/synth_xilinx_stat_dp{0,1}.txt (minutes)

PREU_RTL    := rtl/pree_preu.v rtl/pree_preu_lat.vh rtl/pree_preu_plan.vh rtl/pree_unit_stages.vh
PREU_UNITS  := $(wildcard rtl/pree_fp32_*.v) rtl/pree_wacc.v rtl/pree_u64_to_f32.v
PREU_SRCS   := rtl/pree_preu.v $(PREU_UNITS)
PREU_DIR    := $(BUILD)/preu
PREU_DPS    := 0 1
PREU_CFGS   ?= 0 1 0f 1f
override PREU_CFGS := $(subst _, ,$(PREU_CFGS))   # make PREU_CFGS=0f_1f: a subset
preu_dp      = $(subst f,,$(1))
preu_pf      = $(if $(findstring f,$(1)),1,0)
PREU_N      ?= 200000
PREU_N_FULL ?= 2000000
PREU_IV_N   ?= 4000
PREU_SEED   ?= 1
PREU_WAVE_DP ?= 0
PREU_CHAIN_N ?= 10000000
PREU_CFLAGS := -std=c11 -D_GNU_SOURCE -O2 -g $(FPFLAGS) -fexcess-precision=standard $(WARN) $(MODEL_INC) -Itb/preu
PREU_HDRS   := tb/preu/preu_vec.h $(addprefix model/pree/,preu_state.h preu_fp32.h preu_stable.h wide_acc.h fp32_ops.h)
PREU_C_OBJ  := $(PREU_DIR)/preu_fp32.o $(PREU_DIR)/preu_stable.o $(PREU_DIR)/preu_vec.o
preu_bench   = $(PREU_DIR)/vl_dp$(1)/preu_bench
preu_hex     = $(PREU_DIR)/preu_vec_dp$(1)_$(PREU_IV_N)_$(PREU_SEED).hex

.PHONY: sim-preu-chain sim-preu-badswitch wave-preu lint-preu sim-preu sim-preu-vl sim-preu-iv sim-preu-vlbin sim-preu-full synth-preu yosys-check-preu
LINT_TARGETS  += lint-preu
SIM_TARGETS   += sim-preu
# The four Verilator benches, shared by preu_quick, preu_sim, fail_trace and vharness_trace:
# built once, beforehand, as the checks may run at once.
TEST_PREREQS  += $(foreach cfg,0 1 0f 1f,$(call preu_bench,$(cfg)))
SYNTH_TARGETS += synth-preu

$(PREU_DIR)/%.o: model/pree/%.c $(PREU_HDRS) | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(PREU_CFLAGS) -c $< -o $@
$(PREU_DIR)/%.o: tb/preu/%.c $(PREU_HDRS) | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(PREU_CFLAGS) -c $< -o $@

lint-preu: | $(DEPS_STAMP)
	@for dp in $(PREU_DPS); do for pf in 0 1; do g="-GDatapath=$$dp -GPipeFast=$$pf"; \
	  for x in "" -DPREE_ASSERT -GTagW=1 -GTagW=8; do \
	    cmd="verilator --lint-only -Wall -Irtl $$g $$x --top-module pree_preu $(PREU_SRCS)"; \
	    $(call say_sh,LINT,pree_preu Datapath=$$dp PipeFast=$$pf $$x,$$cmd); $$cmd || exit 1; \
	done; done; done

# The Icarus vector generator (both datapaths).
$(PREU_DIR)/preu_vecgen: $(PREU_DIR)/preu_vecgen.o $(PREU_C_OBJ)
	$(call say,LINK,$@)$(CC) $^ -o $@ -lm
$(PREU_DIR)/preu_vec_bad.hex: $(PREU_DIR)/preu_vecgen
	$(call say,GEN,$@)$(PREU_DIR)/preu_vecgen 100 1 0 $@

# Per configuration $(1) (datapath, f: PipeFast 1): the Verilator bench (the C model objects are linked into the harness;
# assertions on), the Icarus vectors and simulation, and the same Verilog bench under Verilator
# --binary --timing (the two simulators must give the same verdict and cycle count).
define PREU_DP_RULES
$(call preu_bench,$(1)): $(PREU_SRCS) $(PREU_RTL) tb/preu/preu_bench.cpp $(VHARNESS) $(PREU_HDRS) $(PREU_C_OBJ) | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$(call say,VERILATE,$$@)verilator --cc --exe --build -j 2 -O3 $(VL_BENCH_OPT) --trace-fst -Irtl -DPREE_ASSERT --top-module pree_preu \
	  -GDatapath=$(call preu_dp,$(1)) -GPipeFast=$(call preu_pf,$(1)) -Mdir $(PREU_DIR)/vl_dp$(1) -o preu_bench \
	  -CFLAGS "-O2 $(FPFLAGS) -DPREU_DATAPATH=$(call preu_dp,$(1)) $(patsubst -I%,-I$(CURDIR)/%,$(MODEL_INC)) -I$(CURDIR)/tb/preu $(VHARNESS_INC)" \
	  $(PREU_SRCS) $(CURDIR)/tb/preu/preu_bench.cpp $(abspath $(PREU_C_OBJ)) >$(PREU_DIR)/vl-build-dp$(1).log 2>&1 \
	  || { tail -30 $(PREU_DIR)/vl-build-dp$(1).log; exit 1; }

.PHONY: sim-preu-vl-dp$(1) sim-preu-iv-dp$(1) sim-preu-vlbin-dp$(1)
sim-preu-vl-dp$(1): $(call preu_bench,$(1))
	$$< $(PREU_N) $(PREU_SEED)

$(PREU_DIR)/tb_preu_dp$(1)_$(PREU_IV_N)_$(PREU_SEED).vvp: tb/preu/tb_preu.v $(PREU_SRCS) $(PREU_RTL) $(call preu_hex,$(call preu_dp,$(1)))
	$$(call say,IVERILOG,$$@)iverilog -g2005 -DPREE_ASSERT -Irtl -s tb_preu -Ptb_preu.NOps=$(PREU_IV_N) -Ptb_preu.Datapath=$(call preu_dp,$(1)) \
	  -Ptb_preu.PipeFast=$(call preu_pf,$(1)) -Ptb_preu.VecFile='"$(call preu_hex,$(call preu_dp,$(1)))"' -o $$@ tb/preu/tb_preu.v $(PREU_SRCS)
sim-preu-iv-dp$(1): $(PREU_DIR)/tb_preu_dp$(1)_$(PREU_IV_N)_$(PREU_SEED).vvp
	vvp -N $$<

$(PREU_DIR)/vlbin_dp$(1)/tb_preu_$(PREU_IV_N)_$(PREU_SEED): tb/preu/tb_preu.v $(PREU_SRCS) $(PREU_RTL) $(call preu_hex,$(call preu_dp,$(1)))
	@mkdir -p $$(@D)
	$$(call say,VERILATE,$$@)verilator --binary --timing -j 2 $(VL_BENCH_OPT) -Irtl -DPREE_ASSERT --top-module tb_preu -GNOps=$(PREU_IV_N) \
	  -GDatapath=$(call preu_dp,$(1)) -GPipeFast=$(call preu_pf,$(1)) -GVecFile='"$(call preu_hex,$(call preu_dp,$(1)))"' -Mdir $(PREU_DIR)/vlbin_dp$(1) \
	  -o tb_preu_$(PREU_IV_N)_$(PREU_SEED) tb/preu/tb_preu.v $(PREU_SRCS) >$(PREU_DIR)/vlbin-build-dp$(1).log 2>&1 \
	  || { tail -30 $(PREU_DIR)/vlbin-build-dp$(1).log; exit 1; }
sim-preu-vlbin-dp$(1): $(PREU_DIR)/vlbin_dp$(1)/tb_preu_$(PREU_IV_N)_$(PREU_SEED)
	$$<
endef
$(foreach cfg,0 1 0f 1f,$(eval $(call PREU_DP_RULES,$(cfg))))
# The vectors depend on the datapath only (the model knows no pipeline).
$(foreach dp,$(PREU_DPS),$(eval $(call preu_hex,$(dp)): $(PREU_DIR)/preu_vecgen ; $(PREU_DIR)/preu_vecgen $(PREU_IV_N) $(PREU_SEED) $(dp) $$@))

sim-preu-vl: $(foreach cfg,$(PREU_CFGS),sim-preu-vl-dp$(cfg))
sim-preu-iv: $(foreach cfg,$(PREU_CFGS),sim-preu-iv-dp$(cfg))
sim-preu-vlbin: $(foreach cfg,$(PREU_CFGS),sim-preu-vlbin-dp$(cfg))

# A waveform of a short run: build/preu/preu.fst (make wave-preu PREU_N=200 PREU_WAVE_DP=1).
wave-preu: $(call preu_bench,$(PREU_WAVE_DP))
	$< $(PREU_N) $(PREU_SEED) +trace=$(PREU_DIR)/preu.fst
	@echo "waveform: $(PREU_DIR)/preu.fst"

# The mode-switch assertion must fire when the bench switches modes with operations in flight.
sim-preu-badswitch: $(PREU_DIR)/preu_vec_bad.hex tb/preu/tb_preu.v $(PREU_SRCS)
	$(call say,IVERILOG,$(PREU_DIR)/tb_preu_badswitch.vvp)iverilog -g2005 -DPREE_ASSERT -Irtl -s tb_preu -Ptb_preu.NOps=100 -Ptb_preu.BadSwitch=1 \
	  -Ptb_preu.VecFile='"$(PREU_DIR)/preu_vec_bad.hex"' -o $(PREU_DIR)/tb_preu_badswitch.vvp \
	  tb/preu/tb_preu.v $(PREU_SRCS)
	@if vvp -N $(PREU_DIR)/tb_preu_badswitch.vvp >$(PREU_DIR)/badswitch.log 2>&1; then \
	  echo "sim-preu-badswitch: the run passed, but it switched modes while busy"; exit 1; fi
	@grep -q 'mode_i changed while operations were in flight' $(PREU_DIR)/badswitch.log || \
	  { tail -5 $(PREU_DIR)/badswitch.log; echo "sim-preu-badswitch: failed, but not by the assertion"; exit 1; }
	@echo "sim-preu-badswitch: the mode-switch assertion fired as it must"

sim-preu: sim-preu-vl sim-preu-iv sim-preu-vlbin sim-preu-badswitch

sim-preu-full: $(foreach cfg,$(PREU_CFGS),$(call preu_bench,$(cfg)))
	for dp in $(PREU_CFGS); do for s in 1 2 3 4 5; do $(PREU_DIR)/vl_dp$$dp/preu_bench $(PREU_N_FULL) $$s || exit 1; done; done

sim-preu-chain: $(foreach dp,$(PREU_DPS),$(call preu_bench,$(dp)))
	for dp in $(PREU_DPS); do $(PREU_DIR)/vl_dp$$dp/preu_bench --chain $(PREU_CHAIN_N) || exit 1; done

# Structural checks (quick, part of make test and make check through tests/checks/preu_quick.sh): no latches,
# no combinational loops. synth-preu adds the 7-series figures (several minutes a datapath).
yosys-check-preu: $(PREU_SRCS) $(PREU_RTL) tb/preu/preu_check.ys | $(DEPS_STAMP)
	@mkdir -p $(PREU_DIR)
	@for dp in $(PREU_DPS); do for pf in 0 1; do \
	  cmd="yosys -q -l $(PREU_DIR)/check_dp$$dp-pf$$pf.log -p 'read_verilog -Irtl $(PREU_SRCS); chparam -set Datapath $$dp -set PipeFast $$pf pree_preu; script tb/preu/preu_check.ys'"; \
	  $(call say_sh,YOSYS,preu/check_dp$$dp-pf$$pf,$$cmd); eval "$$cmd" || exit 1; \
	done; done

synth-preu: yosys-check-preu
	@for dp in $(PREU_DPS); do \
	  cmd="yosys -q -l $(PREU_DIR)/synth_xilinx_dp$$dp.log -p 'read_verilog -Irtl $(PREU_SRCS); chparam -set Datapath $$dp pree_preu; synth_xilinx -family xc7 -top pree_preu -flatten -noiopad; tee -o $(PREU_DIR)/synth_xilinx_stat_dp$$dp.txt stat'"; \
	  $(call say_sh,SYNTH,preu/synth_xilinx_dp$$dp,$$cmd); eval "$$cmd" || exit 1; \
	  echo "== datapath $$dp"; sed -n '/Number of cells/,$$p' $(PREU_DIR)/synth_xilinx_stat_dp$$dp.txt; \
	done
