# SPDX-License-Identifier: Apache-2.0
# (After mk/cosim.mk, whose variables it uses.) The AXI4 wrapper (rtl/pree_axi.v) and the FPGA integration kit: docs/integration.md.
#
#   make lint-axi      verilator --lint-only -Wall of pree_axi through rtl/pree.f, NumPreu 4, 8, 16,
#                      both datapaths (in `make lint`)
#   make synth-axi     Yosys synth_xilinx of pree_axi: the wrapper's own logic (pree_top a black box)
#                      for 4, 8, 16 PREUs (4: 20 CPU seconds), the whole design for
#                      SYNTH_AXI_PREUS (default 4; the reduced flow, synth_axi.sh --fast) into the
#                      table of docs/integration_resources.md (scripts/fpga_doc.py, markers synth-axi)
#   make synth-axi-full  the whole pree_axi through synth_xilinx with the full ABC script, the fit
#                      table's memory sizes, LUT levels (tb/axi/synth_axi_full.sh), into the table of
#                      docs/integration_resources.md (markers synth-axi-full). SYNTH_AXI_FULL_RUNS:
#                      <mode>_pf<PipeFast>_p<NumPreu>, mode hier (PREU, RAM banks and controllers
#                      kept as modules), fine (pree_top's parts kept as well: the 16-PREU runs,
#                      ABC's calls smaller) or flat; each run's files in
#                      $(AXI_DIR)/full-synth.
#                      Outside `make test`: minutes of one core a run (the table's CPU column)
#   make fit-table     the block RAM / URAM fit table of docs/integration_resources.md (scripts/pree_fit.py)
#   build/pree-cosim-axi-<d><n>[f]  `pree cosim --axi [--pipe-fast]`: the co-simulation through
#                      pree_axi (d: p paper, s stable; n PREUs; f: PipeFast 1), built only when
#                      asked (the regression builds axi-p4: tests/checks/axi_cosim.sh)
#   build/axi/quick/pree-cosim-axi-<d><n>[f]  the same program built with g++ -O0 (the same
#                      cycles, a slower simulation, a build many times cheaper); the regression
#                      builds p8 and p16f (AXI_QUICK_TAGS: tests/checks/axi_cosim_wide.sh)
#   make sim-axi-wide  the wrapper with 8 PREUs (two photons a beat) against the model
#                      (tb/axi/axi_cosim_wide.sh; its model takes about 15 minutes to build, so it
#                      is outside `make test`)
#   make sim-axi-full  the whole-frame rows through the wrapper beside pree_top alone
#                      (tb/axi/axi_cosim_full.sh): AXI_FULL_TAGS (default p4 p8 p16 p4f p8f p16f
#                      s4 s4f), AXI_FULL_OPTS (default the whole frame, cornell3 320x240 / 768k
#                      photons), --gap AXI_FULL_GAP (0.3); the table in build/axi/full/table.md.
#                      AXI_FULL_QUICK=1: the quick builds of both sides (g++ -O0, the same cycles;
#                      build/cosim/quick/pree-cosim-<tag> for pree_top alone, mk/cosim.mk);
#                      AXI_FULL_GAP_TAGS: the tags that also run with --gap (default all).
#                      Outside `make test`: its 16 models take hours to build here
# The Verilated pree_axi models use the co-simulation's parameters and banks (mk/cosim.mk).

AXI_DIR    := $(BUILD)/axi
AXI_DRV_OBJS := $(BUILD)/drv/pree_drv.o $(BUILD)/drv/pree_be_verilated.o $(BUILD)/drv/pree_wqueue.o
AXI_RTL    := $(shell grep -v '^//' rtl/pree.f)
AXI_MDIR    = $(AXI_DIR)/vl$(3)_$(call cosim_tag,$(1),$(2))_h$(COSIM_HPB_$(1))_x$(COSIM_PXB_$(1))_w$(COSIM_PPC_$(1))
# The quick builds (flavour q): the same models compiled with g++ -O0, for short co-simulations
# in `make test` (the C++ of a model compiles many times faster; the RTL's cycles are the same,
# the simulation slower). axi_prog FLAVOUR TAG: the program's path.
axi_prog    = $(if $(1),$(AXI_DIR)/quick,$(BUILD))/pree-cosim-axi-$(2)
SYNTH_AXI_PREUS ?= 4
SYNTH_AXI_FULL_RUNS ?= hier_pf0_p4 hier_pf0_p8 fine_pf0_p16 hier_pf1_p4 hier_pf1_p8 fine_pf1_p16 hier_pf1_p1 flat_pf1_p1

TEST_PREREQS  += $(AXI_REGRESSION_TAGS:%=$(BUILD)/pree-cosim-axi-%) $(foreach t,$(AXI_QUICK_TAGS),$(call axi_prog,q,$(t)))
AXI_FULL_TAGS ?= p4 p8 p16 p4f p8f p16f s4 s4f
LINT_TARGETS  += lint-axi

.PHONY: lint-axi synth-axi synth-axi-full fit-table sim-axi-wide sim-axi-full
sim-axi-wide: $(BUILD)/pree-cosim-axi-p8 $(BUILD)/pree
	@bash tb/axi/axi_cosim_wide.sh
AXI_FULL_PROGS = $(foreach t,$(AXI_FULL_TAGS),$(if $(AXI_FULL_QUICK),$(AXI_DIR)/quick/pree-cosim-axi-$(t) $(COSIM_DIR)/quick/pree-cosim-$(t),$(BUILD)/pree-cosim-axi-$(t) $(BUILD)/pree-cosim-$(t)))
sim-axi-full: $(BUILD)/pree $(AXI_FULL_PROGS)
	@AXI_FULL_OPTS="$(AXI_FULL_OPTS)" AXI_FULL_QUICK="$(AXI_FULL_QUICK)" $(if $(AXI_FULL_GAP_TAGS),AXI_FULL_GAP_TAGS="$(AXI_FULL_GAP_TAGS)") bash tb/axi/axi_cosim_full.sh $(AXI_DIR)/full $(AXI_FULL_TAGS)

# The wrapper's models take the co-simulation's pree_top parameters (PipeFast included: d = pf,
# sf; PhotonsPerCycle NumPreu / 4, photon slots a beat). $(1): PREU count, $(2): p, s, pf or sf,
# $(3): the flavour (empty, or q: g++ -O0); the tag (p4, s8f, ...) names the model directory,
# its class and its program (build/pree-cosim-axi-p4f: `pree cosim --axi --pipe-fast`;
# build/axi/quick/pree-cosim-axi-p8 the quick build).
define AXI_VL_RULE
$(call AXI_MDIR,$(1),$(2),$(3))/Vpree_axi_$(call cosim_tag,$(1),$(2))__ALL.a: $(AXI_RTL) $(wildcard rtl/*.vh) rtl/pree.f tb/cosim/pree_top.vlt | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$(call say,VERILATE,$$(@D))verilator --cc --build -j $(THREADS) -O3 --x-assign fast --x-initial fast --trace-fst \
	  -Irtl --top-module pree_axi --prefix Vpree_axi_$(call cosim_tag,$(1),$(2)) --Mdir $$(@D) tb/cosim/pree_top.vlt \
	  $(call COSIM_GPARAMS,$(1),$(2)) -MAKEFLAGS "$(if $(3),OPT_FAST=-O0 OPT_SLOW=-O0,OPT_FAST=-O2 OPT_SLOW=-O1)" \
	  -f rtl/pree.f >$$(@D).log 2>&1 || { tail -30 $$(@D).log; exit 1; }
$(HOST_DIR)/cosim_axi_rtl$(3)_$(call cosim_tag,$(1),$(2)).o: host/cosim_axi_rtl.cpp $(call AXI_MDIR,$(1),$(2),$(3))/Vpree_axi_$(call cosim_tag,$(1),$(2))__ALL.a
	@mkdir -p $$(@D)
	$$(call say,CXX,$$@)$(CXX) $(COSIM_RTL_FLAGS) -Idrv -isystem $(call AXI_MDIR,$(1),$(2),$(3)) -DAXI_MODEL=Vpree_axi_$(call cosim_tag,$(1),$(2)) \
	  -DAXI_MODEL_H='"Vpree_axi_$(call cosim_tag,$(1),$(2)).h"' -DAXI_NP=$(1) -DAXI_DP=$(if $(findstring s,$(2)),1,0) \
	  -DAXI_PF=$(if $(findstring f,$(2)),1,0) -DAXI_HPB=$(COSIM_HPB_$(1)) -DAXI_PPC=$(COSIM_PPC_$(1)) -c $$< -o $$@
$(call axi_prog,$(3),$(call cosim_tag,$(1),$(2))): $(HOST_DIR)/cosim_main_axi.o $(COSIM_MAIN_OBJS) $(HOST_DIR)/cosim_axi.o $(filter-out %/cosim_drv.o,$(HOST_OBJS)) \
                          $(AXI_DRV_OBJS) \
                          $(HOST_DIR)/cosim_axi_rtl$(3)_$(call cosim_tag,$(1),$(2)).o $(BUILD)/cli/cli_options.o $(BUILD)/cli/cli_mpi.o $(LIBPREE) \
                          $(call AXI_MDIR,$(1),$(2),$(3))/Vpree_axi_$(call cosim_tag,$(1),$(2))__ALL.a $(COSIM_VLIB)
	@mkdir -p $$(@D)
	$$(call say,LINK,$$@)$(CXX) $(LDFLAGS) $$^ -o $$@ $(LDLIBS) -lz -pthread
endef
$(foreach p,$(COSIM_ALL_PREUS),$(foreach d,p s pf sf,$(eval $(call AXI_VL_RULE,$(p),$(d),))))
$(foreach p,$(COSIM_ALL_PREUS),$(foreach d,p s pf sf,$(eval $(call AXI_VL_RULE,$(p),$(d),q))))

# `pree cosim --axi` drives the wrapper through pree_drv on the Verilated back end (mk/drv.mk
# builds these objects).
$(HOST_DIR)/cosim_axi.o: host/cosim_axi.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(COSIM_CFLAGS) -Idrv -c $< -o $@

$(HOST_DIR)/cosim_main_axi.o: host/cosim_main.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(COSIM_CFLAGS) -DCOSIM_DRV_AXI=1 -c $< -o $@

lint-axi: | $(DEPS_STAMP)
	@bash tests/checks/axi_lint.sh

synth-axi: | $(DEPS_STAMP)
	@set -e; for p in 4 8 16; do tb/axi/synth_axi.sh --own $$p $(AXI_DIR)/synth; done
	@set -e; for p in $(SYNTH_AXI_PREUS); do tb/axi/synth_axi.sh --fast $$p $(AXI_DIR)/synth; done
	@{ echo '| design | LUT | FF | CARRY4 | DSP48E1 | RAMB36E1 | RAMB18E1 | LUTRAM |'; \
	  echo '|---|---|---|---|---|---|---|---|'; \
	  cat $(foreach p,4 8 16,$(AXI_DIR)/synth/own_p$(p).md) $(foreach p,$(SYNTH_AXI_PREUS),$(AXI_DIR)/synth/fast_p$(p).md); } \
	  > $(AXI_DIR)/synth/resources.md
	python3 scripts/fpga_doc.py docs/integration_resources.md synth-axi $(AXI_DIR)/synth/resources.md

# One run a file: <mode>_pf<PipeFast>_p<NumPreu>.md (tb/axi/synth_axi_full.sh), remade when the
# RTL or the script changes.
$(AXI_DIR)/full-synth/%.md: tb/axi/synth_axi_full.sh tb/cosim/synth_top_depth.py $(AXI_RTL) | $(DEPS_STAMP)
	nice -n 10 tb/axi/synth_axi_full.sh $(if $(filter flat_%,$*),--flat)$(if $(filter fine_%,$*),--fine) \
	  $(patsubst pf%,%,$(word 2,$(subst _, ,$*))) $(patsubst p%,%,$(word 3,$(subst _, ,$*))) $(@D)
synth-axi-full: $(SYNTH_AXI_FULL_RUNS:%=$(AXI_DIR)/full-synth/%.md)
	@{ echo '| PREUs | PREU | synthesis | LUT | FF | CARRY4 | MUXF7/8 | DSP48E1 | RAMB36E1 | RAMB18E1 | LUTRAM | LUT levels within a PREU | LUT levels elsewhere | CPU s |'; \
	  echo '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|'; \
	  cat $^; } > $(AXI_DIR)/full-synth/resources.md
	python3 scripts/fpga_doc.py docs/integration_resources.md synth-axi-full $(AXI_DIR)/full-synth/resources.md

fit-table:
	python3 scripts/pree_fit.py
