# SPDX-License-Identifier: Apache-2.0
# The two PREE controllers: AFTSO-HpUOC (rtl/pree_aftso_hpuoc.v, hit-point update dispatch) and
# ADISO-REC (rtl/pree_adiso_rec.v, leaping addresses). C models, Verilator benches against them,
# Icarus benches over their vectors, lint, Yosys synthesis, utilization. docs/controllers.md.
#
#   make ctrl-sim        Verilator benches, NumPreu 4/8/16; Icarus benches, NumPreu 2/4/8/16
#                        (part of `make sim`)
#   make ctrl-sim-full   longer random runs and more seeds (a few minutes)
#   make ctrl-lint       verilator --lint-only -Wall, every configuration (part of `make lint`)
#   make ctrl-synth      synth_xilinx resource lines in build/ctrl/synth.txt (part of `make synth`)
#   make ctrl-util       PREU utilization table in build/ctrl/util.txt; NP_FILE=f adds a
#                        measured N^P distribution (one value per line) through model and RTL

CTRL_DIR      := $(BUILD)/ctrl
CTRL_PREUS    := 4 8 16
# The small PREU counts run in the Icarus benches only (no Verilated bench of their own), both
# controllers and EarlyReady = 1 (pree_top's).
CTRL_SMALL_PREUS := 1 2
CTRL_EARLY    := 0 1
CTRL_CFLAGS   := -std=c11 -O2 -g $(WARN) -Itb/ctrl -Imodel/pree
CTRL_HDR      := $(wildcard tb/ctrl/*.h) model/pree/aftso_rule.h
AFTSO_RTL     := rtl/pree_aftso_hpuoc.v
ADISO_RTL     := rtl/pree_adiso_rec.v
# Verilator: -O3 and the default output split favour simulation speed; VL_BENCH_OPT (Makefile) the build time;
# X values are randomised so that a missing reset shows up as a mismatch; PREE_ASSERT turns on
# the RTL's simulation-only invariant checks.
CTRL_VERILATE := verilator --cc --exe --build -O3 -j $(THREADS) $(VL_BENCH_OPT) --x-assign unique --x-initial unique +define+PREE_ASSERT

# AFTSO configurations pP_eE[_bB][_wW]: NumPreu P, EarlyReady E, BufDepth B (default 4),
# PhotonsPerCycle W (default 1). The regression runs EarlyReady = 1 (the default) for every
# NumPreu, the paper's back-pressure (EarlyReady = 0) for NumPreu = 4, and the wide intakes of
# pree_top's 8- and 16-PREU co-simulation builds (2 photons into 8 entries, 4 into 16);
# ctrl-sim-full adds the rest and an 8-entry buffer.
CTRL_AFTSO_CFGS     := p4_e0 p4_e1 p8_e1 p16_e1 p8_e1_b8_w2 p16_e1_b16_w4
CTRL_AFTSO_STD      := $(foreach p,$(CTRL_PREUS),$(foreach e,$(CTRL_EARLY),p$(p)_e$(e)))
CTRL_AFTSO_CFGS_ALL := $(CTRL_AFTSO_STD) p16_e1_b8 p8_e1_b8_w2 p16_e1_b16_w4 p4_e0_b4_w2
ctrl_cfg_word = $(patsubst $(2)%,%,$(filter $(2)%,$(subst _, ,$(1))))
ctrl_cfg_buf  = $(or $(call ctrl_cfg_word,$(1),b),4)
ctrl_cfg_ppc  = $(or $(call ctrl_cfg_word,$(1),w),1)
CTRL_AFTSO_BENCHES := $(foreach c,$(CTRL_AFTSO_CFGS),$(CTRL_DIR)/aftso_$(c)/aftso_bench)
CTRL_AFTSO_BENCHES_ALL := $(foreach c,$(CTRL_AFTSO_CFGS_ALL),$(CTRL_DIR)/aftso_$(c)/aftso_bench)
CTRL_ADISO_BENCHES := $(foreach p,$(CTRL_PREUS),$(CTRL_DIR)/adiso_p$(p)/adiso_bench)
CTRL_AFTSO_VVP     := $(foreach c,$(CTRL_SMALL_PREUS:%=p%_e1) $(CTRL_AFTSO_STD),$(CTRL_DIR)/icarus/aftso_$(c).vvp)
CTRL_ADISO_VVP     := $(foreach p,$(CTRL_SMALL_PREUS) $(CTRL_PREUS),$(CTRL_DIR)/icarus/adiso_p$(p).vvp)
CTRL_VECS          := $(CTRL_AFTSO_VVP:.vvp=.ncyc) $(CTRL_ADISO_VVP:.vvp=.ncyc)
CTRL_TOOLS         := $(CTRL_DIR)/aftso_util $(CTRL_DIR)/aftso_vecgen $(CTRL_DIR)/adiso_vecgen $(CTRL_DIR)/adiso_seq
CTRL_ALL           := $(CTRL_AFTSO_BENCHES) $(CTRL_ADISO_BENCHES) $(CTRL_AFTSO_VVP) $(CTRL_ADISO_VVP) \
                      $(CTRL_VECS) $(CTRL_TOOLS)

TEST_PREREQS  += $(CTRL_ALL)
SIM_TARGETS   += ctrl-sim
LINT_TARGETS  += ctrl-lint
SYNTH_TARGETS += ctrl-synth

.PHONY: ctrl-build ctrl-sim ctrl-sim-verilator ctrl-sim-icarus ctrl-sim-full ctrl-lint ctrl-synth ctrl-util
ctrl-build: $(CTRL_ALL) $(CTRL_AFTSO_BENCHES_ALL)

# Host C: the models and the tools around them.
$(CTRL_DIR)/%.o: tb/ctrl/%.c $(CTRL_HDR)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(CTRL_CFLAGS) -c $< -o $@

$(CTRL_DIR)/aftso_rule.o: model/pree/aftso_rule.c model/pree/aftso_rule.h
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(CTRL_CFLAGS) -c $< -o $@
CTRL_AFTSO_OBJ := $(CTRL_DIR)/aftso_model.o $(CTRL_DIR)/aftso_rule.o
$(CTRL_DIR)/aftso_util: $(CTRL_DIR)/aftso_util.o $(CTRL_AFTSO_OBJ)
	$(call say,LINK,$@)$(CC) $^ -o $@ -lm
$(CTRL_DIR)/aftso_vecgen: $(CTRL_DIR)/aftso_vecgen.o $(CTRL_AFTSO_OBJ)
	$(call say,LINK,$@)$(CC) $^ -o $@ -lm
$(CTRL_DIR)/adiso_vecgen: $(CTRL_DIR)/adiso_vecgen.o $(CTRL_DIR)/adiso_model.o
	$(call say,LINK,$@)$(CC) $^ -o $@ -lm
$(CTRL_DIR)/adiso_seq: $(CTRL_DIR)/adiso_seq.o $(CTRL_DIR)/adiso_model.o
	$(call say,LINK,$@)$(CC) $^ -o $@ -lm

# Verilator benches, one binary per configuration (the parameters are compile-time).
define CTRL_AFTSO_RULE
$(CTRL_DIR)/aftso_$(1)/aftso_bench: $(AFTSO_RTL) tb/ctrl/aftso_bench.cpp $(VHARNESS) $(CTRL_AFTSO_OBJ) $(CTRL_HDR)
	$$(call say,VERILATE,$$@)$(CTRL_VERILATE) -GNumPreu=$(2) -GEarlyReady=$(3) -GBufDepth=$(4) -GPhotonsPerCycle=$(5) \
	  -CFLAGS "-O2 -DNUM_PREU=$(2) -DEARLY_READY=$(3) -DBUF_DEPTH=$(4) -DPPC=$(5) -I$(abspath tb/ctrl) -I$(abspath model/pree) $(VHARNESS_INC)" \
	  --Mdir $$(@D) -o aftso_bench $(AFTSO_RTL) $(abspath tb/ctrl/aftso_bench.cpp) \
	  $(abspath $(CTRL_AFTSO_OBJ)) >$$(@D).log 2>&1 || { cat $$(@D).log; exit 1; }
endef
define CTRL_ADISO_RULE
$(CTRL_DIR)/adiso_p$(1)/adiso_bench: $(ADISO_RTL) tb/ctrl/adiso_bench.cpp $(VHARNESS) $(CTRL_DIR)/adiso_model.o $(CTRL_HDR)
	$$(call say,VERILATE,$$@)$(CTRL_VERILATE) -GNumPreu=$(1) -GPipeDepth=12 \
	  -CFLAGS "-O2 -DNUM_PREU=$(1) -DPIPE_DEPTH=12 -I$(abspath tb/ctrl) $(VHARNESS_INC)" \
	  --Mdir $$(@D) -o adiso_bench $(ADISO_RTL) $(abspath tb/ctrl/adiso_bench.cpp) \
	  $(abspath $(CTRL_DIR)/adiso_model.o) >$$(@D).log 2>&1 || { cat $$(@D).log; exit 1; }
endef
# Icarus benches and the C models' vectors for them (the .ncyc file holds the cycle count).
define CTRL_AFTSO_ICARUS_RULE
$(CTRL_DIR)/icarus/aftso_p$(1)_e$(2).vvp: tb/ctrl/aftso_tb.v tb/ctrl/vec_tb.vh $(AFTSO_RTL)
	@mkdir -p $$(@D)
	$$(call say,IVERILOG,$$@)iverilog -g2005 -Wall -DPREE_ASSERT -Itb/ctrl -P aftso_tb.NumPreu=$(1) -P aftso_tb.EarlyReady=$(2) -o $$@ $$(filter %.v,$$^)
$(CTRL_DIR)/icarus/aftso_p$(1)_e$(2).ncyc: $(CTRL_DIR)/aftso_vecgen
	@mkdir -p $$(@D)
	$$(call say,GEN,$$@)$$< --preu $(1) --early-ready $(2) --seed $(1)$(2)7 --cycles 3000 $$(@:.ncyc=.stim) $$(@:.ncyc=.exp) >$$@
endef
define CTRL_ADISO_ICARUS_RULE
$(CTRL_DIR)/icarus/adiso_p$(1).vvp: tb/ctrl/adiso_tb.v tb/ctrl/vec_tb.vh $(ADISO_RTL)
	@mkdir -p $$(@D)
	$$(call say,IVERILOG,$$@)iverilog -g2005 -Wall -Itb/ctrl -P adiso_tb.NumPreu=$(1) -P adiso_tb.PipeDepth=12 -o $$@ $$(filter %.v,$$^)
$(CTRL_DIR)/icarus/adiso_p$(1).ncyc: $(CTRL_DIR)/adiso_vecgen
	@mkdir -p $$(@D)
	$$(call say,GEN,$$@)$$< --preu $(1) --pipe 12 --seed $(1)3 $$(@:.ncyc=.stim) $$(@:.ncyc=.exp) >$$@
endef
$(foreach c,$(CTRL_AFTSO_CFGS_ALL),$(eval $(call CTRL_AFTSO_RULE,$(c),$(call ctrl_cfg_word,$(c),p),$(call ctrl_cfg_word,$(c),e),$(call ctrl_cfg_buf,$(c)),$(call ctrl_cfg_ppc,$(c)))))
$(foreach p,$(CTRL_PREUS),$(foreach e,$(CTRL_EARLY),$(eval $(call CTRL_AFTSO_ICARUS_RULE,$(p),$(e)))))
$(foreach p,$(CTRL_SMALL_PREUS),$(eval $(call CTRL_AFTSO_ICARUS_RULE,$(p),1)))
$(foreach p,$(CTRL_PREUS),$(eval $(call CTRL_ADISO_RULE,$(p))))
$(foreach p,$(CTRL_SMALL_PREUS) $(CTRL_PREUS),$(eval $(call CTRL_ADISO_ICARUS_RULE,$(p))))

# Simulation: every bench once (quick), then longer runs (full).
ctrl-sim: ctrl-sim-verilator ctrl-sim-icarus
ctrl-sim-verilator: $(CTRL_AFTSO_BENCHES) $(CTRL_ADISO_BENCHES)
	@set -e; for b in $(CTRL_AFTSO_BENCHES) $(CTRL_ADISO_BENCHES); do $$b | tail -1; done
ctrl-sim-icarus: $(CTRL_AFTSO_VVP) $(CTRL_ADISO_VVP) $(CTRL_VECS)
	@set -e; for v in $(CTRL_AFTSO_VVP) $(CTRL_ADISO_VVP); do \
	  vvp -N $$v +stim=$${v%.vvp}.stim +exp=$${v%.vvp}.exp +ncyc=$$(cat $${v%.vvp}.ncyc) | tail -1; done
ctrl-sim-full: $(CTRL_AFTSO_BENCHES_ALL) $(CTRL_ADISO_BENCHES)
	@set -e; for s in 11 12 13; do \
	  for b in $(CTRL_AFTSO_BENCHES_ALL); do $$b --seed $$s --scale 10 | tail -1; done; \
	  for b in $(CTRL_ADISO_BENCHES); do $$b --seed $$s --nmax 4096 --random 60 | tail -1; done; done

# Lint: both modules, every configuration the project builds, no waivers.
ctrl-lint:
	@set -e; for p in $(CTRL_PREUS); do \
	  for e in $(CTRL_EARLY); do verilator --lint-only -Wall -GNumPreu=$$p -GEarlyReady=$$e $(AFTSO_RTL); done; \
	  verilator --lint-only -Wall -GNumPreu=$$p $(ADISO_RTL); done
	@verilator --lint-only -Wall -GNumPreu=16 -GBufDepth=8 $(AFTSO_RTL)
	@verilator --lint-only -Wall -GNumPreu=4 -GBufDepth=2 $(AFTSO_RTL)
	@verilator --lint-only -Wall -GNumPreu=8 -GBufDepth=8 -GPhotonsPerCycle=2 $(AFTSO_RTL)
	@verilator --lint-only -Wall -GNumPreu=16 -GBufDepth=16 -GPhotonsPerCycle=4 $(AFTSO_RTL)
	@verilator --lint-only -Wall -GNumPreu=4 -GBufDepth=2 -GPhotonsPerCycle=2 -GEarlyReady=0 $(AFTSO_RTL)
	@verilator --lint-only -Wall +define+PREE_ASSERT $(AFTSO_RTL)
	@echo "ctrl-lint: pree_aftso_hpuoc and pree_adiso_rec clean for NumPreu $(CTRL_PREUS) (BufDepth 2, 4, 8, 16; PhotonsPerCycle 1, 2, 4)"

# Synthesis: one resource line per configuration; fails on a latch or a loop.
ctrl-synth:
	@mkdir -p $(CTRL_DIR)
	@set -e; { for p in $(CTRL_PREUS); do tb/ctrl/synth_ctrl.sh pree_aftso_hpuoc NumPreu=$$p; done; \
	  for p in $(CTRL_PREUS); do tb/ctrl/synth_ctrl.sh pree_adiso_rec NumPreu=$$p; done; } >$(CTRL_DIR)/synth.txt.tmp
	@mv $(CTRL_DIR)/synth.txt.tmp $(CTRL_DIR)/synth.txt && cat $(CTRL_DIR)/synth.txt

# Utilization: geometric N^P with mean 32 (cornell3: 78 M candidates / 2.45 M photon hits),
# 1 M photons back to back, for both EarlyReady settings; then the RTL on 20 k of them.
CTRL_UTIL_PHOTONS ?= 1000000
ctrl-util: $(CTRL_DIR)/aftso_util $(CTRL_AFTSO_BENCHES_ALL)
	@set -e; { for e in $(CTRL_EARLY); do for p in $(CTRL_PREUS); do \
	    $(CTRL_DIR)/aftso_util --preu $$p --early-ready $$e --geo 32 --photons $(CTRL_UTIL_PHOTONS); done; done; \
	  for p in $(CTRL_PREUS); do \
	    $(CTRL_DIR)/aftso_util --preu $$p --buf 8 --geo 32 --photons $(CTRL_UTIL_PHOTONS); done; \
	  $(CTRL_DIR)/aftso_util --geo 32 --photons 20000 --seed 5 --write-np $(CTRL_DIR)/np_geo32.txt >/dev/null; \
	  for c in $(CTRL_AFTSO_CFGS_ALL); do $(CTRL_DIR)/aftso_$$c/aftso_bench --np-file $(CTRL_DIR)/np_geo32.txt; done; \
	  if [ -n "$(NP_FILE)" ]; then for p in $(CTRL_PREUS); do \
	    $(CTRL_DIR)/aftso_util --preu $$p --np-file $(NP_FILE); \
	    $(CTRL_DIR)/aftso_p$${p}_e1/aftso_bench --np-file $(NP_FILE); done; fi; } >$(CTRL_DIR)/util.txt.tmp
	@mv $(CTRL_DIR)/util.txt.tmp $(CTRL_DIR)/util.txt && cat $(CTRL_DIR)/util.txt
