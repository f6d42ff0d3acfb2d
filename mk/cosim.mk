# SPDX-License-Identifier: Apache-2.0
# The PREE top (rtl/pree_top.v), its benches (tb/cosim/) and the co-simulation host (host/):
# docs/pree_top.md, docs/cosim.md.
#
#   make sim-top       Verilator bench of pree_top against the C model (adversarial traces),
#                      lint, and `pree cosim` of cornell3 at 64x48 / 20k photons (part of `make sim`)
#   make sim-full      cornell3 320x240 / 768k photons whole-frame co-simulation for the PREU
#                      counts in SIM_FULL_PREUS (default 4 8 16) and, with the stable datapath,
#                      in SIM_FULL_STABLE_PREUS (default 4); figures in
#                      $(COSIM_DIR)/full_{p,s}*.json, a utilization line per run
#   make wave TEST=t   an FST of one test (picoseconds, 8 ns a cycle) and a GTKWave save file that
#                      opens on the first photon with markers on the first hazard stall and bank
#                      conflicts (scripts/wave-view.py, which also lists their cycles); t = cosim (cornell3 32x24,
#                      2k photons) or one of the bench scenarios: random, one, dense, mixed
#   make lint-top      verilator --lint-only -Wall for NumPreu 1, 2, 4, 8, 16, both datapaths, PipeFast 0 and 1,
#                      PhotonsPerCycle 1 and NumPreu / 4
#   make synth-top     Yosys synth_xilinx of pree_top, NumPreu 4 (small memories): resource table; SYNTH_TOP_PIPEFAST=1: the deep PREUs
#
# `pree cosim` runs build/pree-cosim-<d><n>[f] (d: p paper, s stable; n PREUs; f: PipeFast = 1,
# `--pipe-fast`), one program per Verilated model, each built only when asked (make
# build/pree-cosim-s8, build/pree-cosim-p4f); build/pree itself needs no Verilator. The regression
# uses the paper datapath with NumPreu 4, 8, 16 (COSIM_PREUS) and the stable one with
# COSIM_STABLE_PREUS (default 4); the PipeFast = 1 models of both datapaths for the counts in
# COSIM_FAST_PREUS (default none; the regression builds build/pree-cosim-p4f for its deep
# co-simulation, whose reference image adds in the order of ADISO-REC's depth 64) are built when
# asked; the top bench links those models.
# Verilator: -O3, OPT_FAST=-O2 (the manual's advice for speed), FST tracing compiled in but
# only switched on by --trace; X assignments resolved the fast way (no random X).

COSIM_DIR    := $(BUILD)/cosim
COSIM_RTL    := $(shell grep -v '^//' rtl/pree.f)   # the RTL filelist (pree_top and its wrappers)
COSIM_INCS   := $(wildcard rtl/*.vh)   # the RTL's include files
VERILATOR_ROOT_DIR := $(shell verilator --getenv VERILATOR_ROOT 2>/dev/null)
# The models' parameters come from the configuration table (config/pree_config.json, through
# mk/config.mk): widths (COSIM_WIDTH_PARAMS) and, per PREU count, COSIM_HPB_n, COSIM_PXB_n,
# COSIM_PPC_n. Banks: hit points 2^(log2 NumPreu + 4) (hashed; few conflicts once the host orders
# candidates), pixels 2^(log2 NumPreu + 2). The model directory names carry them (and a version
# of the bank hash), so a change never reuses a stale model. Photons AFTSO-HpUOC takes per cycle
# (PhotonsPerCycle): NumPreu / 4, so that the intake offers 4 x NumPreu / 4 = NumPreu operations
# a cycle already at 4 hit points a photon (cornell3 averages 5.33 with the default skips; one
# photon a cycle capped 8 PREUs at 66.6%). The regression's models: COSIM_PREUS (paper),
# COSIM_STABLE_PREUS, COSIM_FAST_PREUS (both overridable) and COSIM_EXTRA_TAGS.
# $(1): PREU count, $(2): p (paper) or s (stable), with f for PipeFast = 1 (pf, sf); the model's
# tag (p4, s4, p4f, ...) names its directory, its class and its program.
cosim_tag     = $(subst f,,$(2))$(1)$(findstring f,$(2))
COSIM_MDIR    = $(COSIM_DIR)/vl2$(3)_$(call cosim_tag,$(1),$(2))_h$(COSIM_HPB_$(1))_x$(COSIM_PXB_$(1))_w$(COSIM_PPC_$(1))
COSIM_GPARAMS = -GNumPreu=$(1) $(COSIM_WIDTH_PARAMS) \
                -GHpBankW=$(COSIM_HPB_$(1)) -GPxBankW=$(COSIM_PXB_$(1)) -GPhotonsPerCycle=$(COSIM_PPC_$(1)) \
                -GDatapath=$(if $(findstring s,$(2)),1,0) -GPipeFast=$(if $(findstring f,$(2)),1,0)
COSIM_MODELS := $(foreach p,$(COSIM_PREUS),$(p):p) $(foreach p,$(COSIM_STABLE_PREUS),$(p):s) \
                $(foreach p,$(COSIM_FAST_PREUS),$(p):pf $(p):sf)
cosim_n = $(word 1,$(subst :, ,$(1)))
cosim_d = $(word 2,$(subst :, ,$(1)))
cosim_mtag = $(call cosim_tag,$(call cosim_n,$(1)),$(call cosim_d,$(1)))
COSIM_VLIB   := $(COSIM_DIR)/vlrt/libverilated.a
COSIM_VLRT   := verilated verilated_fst_c verilated_threads
COSIM_VLRT_FLAGS := -std=c++17 -O2 -isystem $(VERILATOR_ROOT_DIR)/include -isystem $(VERILATOR_ROOT_DIR)/include/vltstd \
                -DVM_COVERAGE=0 -DVM_SC=0 -DVM_TRACE=1 -DVM_TRACE_FST=1 -DVM_TRACE_VCD=0 -faligned-new
HOST_DIR     := $(BUILD)/host
HOST_OBJS    := $(HOST_DIR)/cosim_drv.o $(HOST_DIR)/cosim_reorder.o $(HOST_DIR)/cosim_report.o $(HOST_DIR)/cosim_sched.o $(HOST_DIR)/cosim_shadow.o
# The programs' own (pree cosim's command line, comparisons, outputs and the board of PREEs).
COSIM_MAIN_OBJS := $(foreach m,args compare dist layout outputs refilter,$(HOST_DIR)/cosim_$(m).o)
COSIM_BENCH  := $(COSIM_DIR)/top_bench
COSIM_CFLAGS := $(CFLAGS) -Ihost -Icli -Itb/lib
COSIM_PROGS  := $(foreach m,$(COSIM_MODELS),$(BUILD)/pree-cosim-$(call cosim_mtag,$(m)))
# host/cosim_rtl.cpp with the models $(1) (N:d words): their headers (with the pree_top scope's,
# which holds the public WIN_UPD), and COSIM_MODELS, the list the host instantiates its template
# from, X(class, PREU count, datapath, PipeFast) each.
cosim_cls    = Vpree_top_$(call cosim_mtag,$(1))
cosim_models = $(foreach m,$(1),-isystem $(call COSIM_MDIR,$(call cosim_n,$(m)),$(call cosim_d,$(m)),$(2)) \
                 -include $(call cosim_cls,$(m)).h -include $(call cosim_cls,$(m))_pree_top.h) \
               '-DCOSIM_MODELS=$(foreach m,$(1),X($(call cosim_cls,$(m)),$(call cosim_n,$(m)),$(if $(findstring s,$(call cosim_d,$(m))),1,0),$(if $(findstring f,$(call cosim_d,$(m))),1,0)))'

TEST_PREREQS  += $(COSIM_BENCH) $(COSIM_PROGS) $(COSIM_EXTRA_TAGS:%=$(BUILD)/pree-cosim-%)   # p4f: tests/checks/cosim_deep.sh
SIM_TARGETS   += sim-top
LINT_TARGETS  += lint-top
SYNTH_TARGETS += synth-top

.PHONY: sim-top sim-full lint-top synth-top wave

# One Verilated model per PREU count and datapath; $(3): the flavour, empty or q (the quick build:
# its C++ compiled with g++ -O0, the same cycles, a slower simulation, a build many times
# cheaper; build/cosim/quick/pree-cosim-<tag>, for make sim-axi-full AXI_FULL_QUICK=1).
define COSIM_VL_RULE
$(call COSIM_MDIR,$(1),$(2),$(3))/Vpree_top_$(call cosim_tag,$(1),$(2))__ALL.a: $(COSIM_RTL) $(COSIM_INCS) tb/cosim/pree_top.vlt | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$(call say,VERILATE,$$(@D))verilator --cc --build -j $(THREADS) -O3 --x-assign fast --x-initial fast --trace-fst \
	  -Irtl --top-module pree_top --prefix Vpree_top_$(call cosim_tag,$(1),$(2)) --Mdir $$(@D) tb/cosim/pree_top.vlt \
	  $(call COSIM_GPARAMS,$(1),$(2)) -MAKEFLAGS "$(if $(3),OPT_FAST=-O0 OPT_SLOW=-O0,OPT_FAST=-O2 OPT_SLOW=-O1)" \
	  $(COSIM_RTL) >$$(@D).log 2>&1 || { tail -30 $$(@D).log; exit 1; }
endef
$(foreach m,$(COSIM_MODELS),$(eval $(call COSIM_VL_RULE,$(call cosim_n,$(m)),$(call cosim_d,$(m)))))
# The Verilator run-time library, once for all models (tracing compiled in).
$(COSIM_DIR)/vlrt/%.o: $(VERILATOR_ROOT_DIR)/include/%.cpp | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CXX,$@)$(CXX) $(COSIM_VLRT_FLAGS) -c $< -o $@
$(COSIM_VLIB): $(COSIM_VLRT:%=$(COSIM_DIR)/vlrt/%.o)
	$(call say,AR,$@)rm -f $@ && ar rcs $@ $^

# The C interface to the models: one object per model for its program, one with every model of
# the regression for the top bench (COSIM_BENCH_MODELS: those and the PipeFast 1 model with 4 PREUs,
# built for tests/checks/cosim_deep.sh anyway, for the bench's deep-pipeline traces).
COSIM_RTL_FLAGS = $(COSIM_VLRT_FLAGS) -g $(WARN) -MMD -MP $(MODEL_INC) -Ihost $(VHARNESS_INC)
define COSIM_PROG_RULE
$(HOST_DIR)/cosim_rtl$(3)_$(call cosim_tag,$(1),$(2)).o: host/cosim_rtl.cpp $(call COSIM_MDIR,$(1),$(2),$(3))/Vpree_top_$(call cosim_tag,$(1),$(2))__ALL.a
	@mkdir -p $$(@D)
	$$(call say,CXX,$$@)$(CXX) $(COSIM_RTL_FLAGS) $(call cosim_models,$(1):$(2),$(3)) -c $$< -o $$@
$(if $(3),$(COSIM_DIR)/quick,$(BUILD))/pree-cosim-$(call cosim_tag,$(1),$(2)): $(HOST_DIR)/cosim_main.o $(COSIM_MAIN_OBJS) $(HOST_OBJS) $(HOST_DIR)/cosim_rtl$(3)_$(call cosim_tag,$(1),$(2)).o \
                          $(BUILD)/cli/cli_options.o $(BUILD)/cli/cli_mpi.o $(LIBPREE) $(call COSIM_MDIR,$(1),$(2),$(3))/Vpree_top_$(call cosim_tag,$(1),$(2))__ALL.a $(COSIM_VLIB)
	@mkdir -p $$(@D)
	$$(call say,LINK,$$@)$(CXX) $(LDFLAGS) $$^ -o $$@ $(LDLIBS) -lz -pthread
endef
$(foreach p,$(COSIM_ALL_PREUS),$(foreach d,$(COSIM_DATAPATHS) $(COSIM_DATAPATHS:%=%f),$(eval $(call COSIM_PROG_RULE,$(p),$(d)))))
$(foreach p,$(COSIM_ALL_PREUS),$(foreach d,$(COSIM_DATAPATHS) $(COSIM_DATAPATHS:%=%f),$(if $(filter $(p):$(d),$(COSIM_MODELS)),,$(eval $(call COSIM_VL_RULE,$(p),$(d))))))
$(foreach p,$(COSIM_ALL_PREUS),$(foreach d,$(COSIM_DATAPATHS) $(COSIM_DATAPATHS:%=%f),$(eval $(call COSIM_PROG_RULE,$(p),$(d),q))$(eval $(call COSIM_VL_RULE,$(p),$(d),q))))

COSIM_BENCH_MODELS := $(COSIM_MODELS) $(if $(filter 4:pf,$(COSIM_MODELS)),,4:pf)
COSIM_BENCH_LIBS   := $(foreach m,$(COSIM_BENCH_MODELS),$(call COSIM_MDIR,$(call cosim_n,$(m)),$(call cosim_d,$(m)))/Vpree_top_$(call cosim_mtag,$(m))__ALL.a)
$(HOST_DIR)/cosim_rtl_all.o: host/cosim_rtl.cpp $(COSIM_BENCH_LIBS)
	@mkdir -p $(@D)
	$(call say,CXX,$@)$(CXX) $(COSIM_RTL_FLAGS) $(call cosim_models,$(COSIM_BENCH_MODELS)) -c $< -o $@
$(HOST_DIR)/%.o: host/%.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(COSIM_CFLAGS) -c $< -o $@
$(COSIM_DIR)/%.o: tb/cosim/%.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(COSIM_CFLAGS) -c $< -o $@

$(COSIM_BENCH): $(COSIM_DIR)/top_bench.o $(COSIM_DIR)/top_bench_abank.o $(HOST_DIR)/cosim_rtl_all.o $(HOST_OBJS) $(LIBPREE) $(COSIM_VLIB)
	$(call say,LINK,$@)$(CXX) $(LDFLAGS) $^ $(COSIM_BENCH_LIBS) $(COSIM_VLIB) $(LIBPREE) -o $@ $(LDLIBS) -lz -pthread
-include $(wildcard $(HOST_DIR)/*.d $(COSIM_DIR)/*.d)

# Simulation: the bench's traces, then the reduced co-simulation.
COSIM_SMALL := scenes/cornell3 --width 64 --height 48 --photons 20000 --quiet
sim-top: $(COSIM_BENCH) $(BUILD)/pree $(COSIM_PROGS)
	@set -e; for p in $(COSIM_PREUS); do \
	  for s in random one dense mixed abank; do $(COSIM_BENCH) --preu $$p --scenario $$s --photons 600 | tail -1; done; \
	  $(COSIM_BENCH) --preu $$p --scenario random --hp 150 --photons 400 --gap 0.3 | tail -1; \
	  $(COSIM_BENCH) --preu $$p --scenario mixed --no-reorder --photons 400 | tail -1; done
	@set -e; for p in $(COSIM_STABLE_PREUS); do \
	  for s in random one dense mixed abank; do $(COSIM_BENCH) --preu $$p --datapath 1 --scenario $$s --photons 600 | tail -1; done; \
	  $(COSIM_BENCH) --preu $$p --datapath 1 --alpha 0.3 --scenario mixed --hp 150 --photons 400 --gap 0.3 | tail -1; done
	@set -e; for p in $(COSIM_PREUS); do \
	  $(BUILD)/pree cosim $(COSIM_SMALL) --preu $$p --stats $(COSIM_DIR)/small_p$$p.json --out $(COSIM_DIR)/small_p$$p.png; \
	  grep -E '"(hp|image)_words_differing"|preu_utilization|"ssim' $(COSIM_DIR)/small_p$$p.json; done
	@set -e; for p in $(COSIM_STABLE_PREUS); do \
	  $(BUILD)/pree cosim $(COSIM_SMALL) --preu $$p --datapath stable --stats $(COSIM_DIR)/small_s$$p.json --out $(COSIM_DIR)/small_s$$p.png; \
	  grep -E '"(hp|image)_words_differing"|preu_utilization|"ssim' $(COSIM_DIR)/small_s$$p.json; done

# Whole frame: cornell3 320x240, 768k photons; the paper datapath with SIM_FULL_PREUS PREUs, the
# stable one with SIM_FULL_STABLE_PREUS (models built for COSIM_STABLE_PREUS). Each run prints
# its update-pass utilization and stall causes; the report beside it holds the scheduler's
# cycle-model prediction (the 16-PREU whole frame: about 200 CPU seconds of RTL).
SIM_FULL_PREUS ?= 4 8 16
SIM_FULL_STABLE_PREUS ?= 4
SIM_FULL_SUMMARY = python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); u=d["update"]; \
  print("%s: %d PREUs, %d photons a cycle: %d cycles, utilization %.4f%%, stalls %s" % (sys.argv[1], d["preu"], \
  d["photons_per_cycle"], u["cycles"], 100 * u["preu_utilization"], u["short_cycles_by_cause"]))'
sim-full: $(BUILD)/pree $(foreach p,$(SIM_FULL_PREUS),$(BUILD)/pree-cosim-p$(p)) $(foreach p,$(SIM_FULL_STABLE_PREUS),$(BUILD)/pree-cosim-s$(p))
	@set -e; for m in $(SIM_FULL_PREUS:%=%:paper) $(SIM_FULL_STABLE_PREUS:%=%:stable); do \
	  p=$${m%%:*}; d=$${m##*:}; tag=$${d:0:1}$$p; \
	  echo "$(BUILD)/pree cosim scenes/cornell3 --preu $$p --datapath $$d --out $(COSIM_DIR)/full_$$tag.png --stats $(COSIM_DIR)/full_$$tag.json"; \
	  /usr/bin/time -f "wall %e s" $(BUILD)/pree cosim scenes/cornell3 --preu $$p --datapath $$d --quiet \
	    --out $(COSIM_DIR)/full_$$tag.png --stats $(COSIM_DIR)/full_$$tag.json; cat $(COSIM_DIR)/full_$$tag.json; \
	  $(SIM_FULL_SUMMARY) $(COSIM_DIR)/full_$$tag.json; done

# Waveforms: TEST=cosim or a bench scenario; opens with tb/cosim/pree_top.gtkw.
TEST ?= mixed
wave: $(COSIM_BENCH) $(BUILD)/pree $(BUILD)/pree-cosim-p4
	@mkdir -p $(COSIM_DIR)
	@if [ "$(TEST)" = cosim ]; then \
	  $(BUILD)/pree cosim scenes/cornell3 --width 32 --height 24 --photons 2000 --quiet --no-reference \
	    --trace $(COSIM_DIR)/wave_cosim.fst; \
	else $(COSIM_BENCH) --scenario $(TEST) --photons 40 --hp 120 --trace $(COSIM_DIR)/wave_$(TEST).fst; fi
	@python3 scripts/wave-view.py $(abspath $(COSIM_DIR))/wave_$(TEST).fst tb/cosim/pree_top.gtkw $(COSIM_DIR)/wave_$(TEST).gtkw
	@echo "gtkwave $(COSIM_DIR)/wave_$(TEST).gtkw"

lint-top: | $(DEPS_STAMP)
	@set -e; for f in 0 1; do for d in 0 1; do for p in $(COSIM_ALL_PREUS); do \
	  ws=1; if [ $$p -gt 4 ]; then ws="1 $$((p / 4))"; fi; for w in $$ws; do \
	  echo "verilator --lint-only -Wall -Irtl --top-module pree_top -GNumPreu=$$p -GDatapath=$$d -GPipeFast=$$f -GPhotonsPerCycle=$$w $(COSIM_RTL)"; \
	  verilator --lint-only -Wall -Irtl --top-module pree_top -GNumPreu=$$p -GDatapath=$$d -GPipeFast=$$f -GPhotonsPerCycle=$$w $(COSIM_RTL); done; done; done; done

# SYNTH_TOP_PIPEFAST=1: the deep PREUs (into $(COSIM_DIR)/synth_pf1).
SYNTH_TOP_PIPEFAST ?= 0
synth-top: | $(DEPS_STAMP)
	@mkdir -p $(COSIM_DIR)
	tb/cosim/synth_top.sh $(COSIM_DIR)/synth$(if $(filter 1,$(SYNTH_TOP_PIPEFAST)),_pf1) $(SYNTH_TOP_PIPEFAST)
