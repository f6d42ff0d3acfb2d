# SPDX-License-Identifier: Apache-2.0
# Icarus bench of the PREE top (rtl/pree_top.v): tb/cosim/top_tb.v plays the host protocol over
# vectors from tb/cosim/top_vecgen.c (the fp32 model of libpree) and compares every hit-point
# and pixel word. Small memories so that Icarus runs it in seconds; docs/cosim.md,
# "Icarus bench".
#
#   make sim-top-icarus          every run below (part of `make sim`), then the mutants
#   make sim-top-icarus-mutants  copies of pree_top.v with one stall rule (hazard, duplicate,
#                                bank conflict, radiance window) broken each: the bench must fail
#                                each with mismatches
# Products in $(BUILD)/top_icarus: top_vecgen, one .vvp per configuration, vectors per run.

TOPIV_DIR  := $(BUILD)/top_icarus
TOPIV_RTL  := $(shell grep -v '^//' rtl/pree.f)
TOPIV_CFLAGS := -std=c11 -O2 -g $(FPFLAGS) -fexcess-precision=standard $(WARN) $(MODEL_INC)
TOPIV_IVERILOG := iverilog -g2005 -Wall -DPREE_ASSERT -Irtl -s top_tb

# Configurations: pree_top parameters (bench side) and the matching vecgen geometry.
# HpAW/IdxAW/PxAW as the vectors were written; HpBankW/PxBankW are the bench's choice.
TOPIV_CFGS := p1 p2 p4 p8 p16
TOPIV_GEOM_p1  := --preu 1 --hp-aw 10 --idx-aw 7 --px-aw 9
TOPIV_GEOM_p2  := --preu 2 --hp-aw 10 --idx-aw 7 --px-aw 9
TOPIV_GEOM_p4  := --preu 4 --hp-aw 10 --idx-aw 7 --px-aw 9
TOPIV_GEOM_p8  := --preu 8 --hp-aw 11 --idx-aw 8 --px-aw 10
TOPIV_GEOM_p16 := --preu 16 --hp-aw 11 --idx-aw 8 --px-aw 10
TOPIV_PAR_p1   := -P top_tb.NumPreu=1 -P top_tb.HpAW=10 -P top_tb.HpBankW=1 -P top_tb.IdxAW=7 -P top_tb.PxAW=9 -P top_tb.PxBankW=1
TOPIV_PAR_p2   := -P top_tb.NumPreu=2 -P top_tb.HpAW=10 -P top_tb.HpBankW=2 -P top_tb.IdxAW=7 -P top_tb.PxAW=9 -P top_tb.PxBankW=1
TOPIV_PAR_p4   := -P top_tb.NumPreu=4 -P top_tb.HpAW=10 -P top_tb.HpBankW=3 -P top_tb.IdxAW=7 -P top_tb.PxAW=9 -P top_tb.PxBankW=2
TOPIV_PAR_p8   := -P top_tb.NumPreu=8 -P top_tb.HpAW=11 -P top_tb.HpBankW=4 -P top_tb.IdxAW=8 -P top_tb.PxAW=10 -P top_tb.PxBankW=3
TOPIV_PAR_p16  := -P top_tb.NumPreu=16 -P top_tb.HpAW=11 -P top_tb.HpBankW=5 -P top_tb.IdxAW=8 -P top_tb.PxAW=10 -P top_tb.PxBankW=4

# Runs: configuration, vecgen scenario arguments, bench plusargs (gap percent, seed).
TOPIV_RUNS := p1_mixed p2_mixed p4_random p4_one p4_dense p4_mixed p4_abank p8_random p8_dense p16_random
TOPIV_CFG_p1_mixed   := p1
TOPIV_ARG_p1_mixed   := --scenario mixed --photons 16 --hp 120 --seed 11
TOPIV_PLUS_p1_mixed  := +gap=20 +seed=11
TOPIV_CFG_p2_mixed   := p2
TOPIV_ARG_p2_mixed   := --scenario mixed --photons 24 --hp 120 --place random --seed 10
TOPIV_PLUS_p2_mixed  := +gap=20 +seed=10
TOPIV_CFG_p4_random  := p4
TOPIV_ARG_p4_random  := --scenario random --photons 30 --hp 200 --seed 1
TOPIV_PLUS_p4_random := +gap=20 +seed=1
TOPIV_CFG_p4_one     := p4
TOPIV_ARG_p4_one     := --scenario one --photons 100 --hp 100 --seed 2
TOPIV_PLUS_p4_one    := +gap=0 +seed=2
TOPIV_CFG_p4_dense   := p4
TOPIV_ARG_p4_dense   := --scenario dense --photons 16 --hp 240 --seed 3
TOPIV_PLUS_p4_dense  := +gap=10 +seed=3
TOPIV_CFG_p4_mixed   := p4
TOPIV_ARG_p4_mixed   := --scenario mixed --photons 24 --hp 120 --seed 4
TOPIV_PLUS_p4_mixed  := +gap=40 +seed=4
TOPIV_CFG_p4_abank   := p4
TOPIV_ARG_p4_abank   := --scenario random --photons 30 --hp 200 --place random --seed 5
TOPIV_PLUS_p4_abank  := +gap=0 +seed=5
TOPIV_CFG_p8_random  := p8
TOPIV_ARG_p8_random  := --scenario random --photons 16 --hp 200 --seed 6
TOPIV_PLUS_p8_random := +gap=20 +seed=6
TOPIV_CFG_p8_dense   := p8
TOPIV_ARG_p8_dense   := --scenario dense --photons 8 --hp 240 --seed 7
TOPIV_PLUS_p8_dense  := +gap=10 +seed=7
TOPIV_CFG_p16_random := p16
TOPIV_ARG_p16_random := --scenario random --photons 10 --hp 160 --seed 8
TOPIV_PLUS_p16_random := +gap=20 +seed=8

# Mutants: name, the file edited (TOPIV_FILE_, default rtl/pree_top.v), sed expression, the run
# that must catch it.
TOPIV_MUTANTS := nohaz nodup noaconf nobconf winrad
TOPIV_FILE_nohaz  := rtl/pree_top_issue.v
TOPIV_SED_nohaz   := s/haz_o\[l\] = 1'b1;/haz_o[l] = 1'b0;/
TOPIV_RUN_nohaz   := p4_one
TOPIV_FILE_nodup  := rtl/pree_top_issue.v
TOPIV_SED_nodup   := s/dup_o\[l\] = 1'b1;/dup_o[l] = 1'b0;/
TOPIV_RUN_nodup   := p4_one
TOPIV_FILE_noaconf := rtl/pree_top_read.v
TOPIV_SED_noaconf := s/conf\[l\] = 1'b1;/conf[l] = 1'b0;/
TOPIV_RUN_noaconf := p4_abank
TOPIV_FILE_nobconf := rtl/pree_top_issue.v
TOPIV_SED_nobconf := s/bcf\[l\] = 1'b1;/bcf[l] = 1'b0;/
TOPIV_RUN_nobconf := p4_random
TOPIV_SED_winrad  := s/WIN_RAD \/\*verilator public\*\/ = LAT_ADD + 1;/WIN_RAD \/*verilator public*\/ = LAT_ADD;/
TOPIV_RUN_winrad  := p4_dense

TOPIV_VVPS    := $(TOPIV_CFGS:%=$(TOPIV_DIR)/top_tb_%.vvp)
TOPIV_VECS    := $(TOPIV_RUNS:%=$(TOPIV_DIR)/%.meta)
TOPIV_MUTVVPS := $(TOPIV_MUTANTS:%=$(TOPIV_DIR)/mut_%.vvp)

TEST_PREREQS += $(TOPIV_DIR)/top_vecgen $(TOPIV_VVPS) $(TOPIV_VECS) $(TOPIV_MUTVVPS)
SIM_TARGETS  += sim-top-icarus

.PHONY: sim-top-icarus sim-top-icarus-runs sim-top-icarus-mutants

# The vector writer: the fp32 PREU model and the radiance order of libpree's objects.
$(TOPIV_DIR)/top_vecgen: tb/cosim/top_vecgen.c tb/cosim/bench_draw.h $(BUILD)/model/pree/preu_fp32.o $(BUILD)/model/pree/adiso_order.o
	@mkdir -p $(@D)
	$(call say,LINK,$@)$(CC) $(TOPIV_CFLAGS) $(filter-out %.h,$^) -o $@ -lm

define TOPIV_CFG_RULE
$(TOPIV_DIR)/top_tb_$(1).vvp: tb/cosim/top_tb.v $(TOPIV_RTL) $(wildcard rtl/*.vh) mk/top_icarus.mk | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$(call say,IVERILOG,$$@)$(TOPIV_IVERILOG) $(TOPIV_PAR_$(1)) -o $$@ tb/cosim/top_tb.v $(TOPIV_RTL)
endef
define TOPIV_RUN_RULE
$(TOPIV_DIR)/$(1).meta: $(TOPIV_DIR)/top_vecgen mk/top_icarus.mk
	$$(call say,GEN,$$@)$(TOPIV_DIR)/top_vecgen $(TOPIV_GEOM_$(TOPIV_CFG_$(1))) $(TOPIV_ARG_$(1)) $(TOPIV_DIR)/$(1) >$(TOPIV_DIR)/$(1).vecgen.txt
endef
# A mutant: one RTL file with one edit (the rule fails when the edit no longer applies).
topiv_mfile = $(or $(TOPIV_FILE_$(1)),rtl/pree_top.v)
define TOPIV_MUT_RULE
$(TOPIV_DIR)/mut_$(1).vvp: tb/cosim/top_tb.v $(TOPIV_RTL) $(wildcard rtl/*.vh) mk/top_icarus.mk | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$(call say,SED,$(TOPIV_DIR)/mut_$(1)_$(notdir $(call topiv_mfile,$(1))))sed "$(TOPIV_SED_$(1))" $(call topiv_mfile,$(1)) >$(TOPIV_DIR)/mut_$(1)_$(notdir $(call topiv_mfile,$(1)))
	@if cmp -s $(call topiv_mfile,$(1)) $(TOPIV_DIR)/mut_$(1)_$(notdir $(call topiv_mfile,$(1))); then \
	  echo "mutant $(1): the edit '$(TOPIV_SED_$(1))' no longer applies to $(call topiv_mfile,$(1))"; exit 1; fi
	$$(call say,IVERILOG,$$@)$(TOPIV_IVERILOG) $(TOPIV_PAR_$(TOPIV_CFG_$(TOPIV_RUN_$(1)))) -o $$@ tb/cosim/top_tb.v \
	  $(TOPIV_DIR)/mut_$(1)_$(notdir $(call topiv_mfile,$(1))) $(filter-out $(call topiv_mfile,$(1)),$(TOPIV_RTL))
endef
$(foreach c,$(TOPIV_CFGS),$(eval $(call TOPIV_CFG_RULE,$(c))))
$(foreach r,$(TOPIV_RUNS),$(eval $(call TOPIV_RUN_RULE,$(r))))
$(foreach m,$(TOPIV_MUTANTS),$(eval $(call TOPIV_MUT_RULE,$(m))))

sim-top-icarus: sim-top-icarus-runs sim-top-icarus-mutants

# Every run; all of them even after a failure, then the verdict.
sim-top-icarus-runs: $(TOPIV_VVPS) $(TOPIV_VECS)
	@fail=0; \
	$(foreach r,$(TOPIV_RUNS),\
	  if vvp -N $(TOPIV_DIR)/top_tb_$(TOPIV_CFG_$(r)).vvp +vec=$(TOPIV_DIR)/$(r) $(TOPIV_PLUS_$(r)) \
	       >$(TOPIV_DIR)/$(r).log 2>&1 && tail -1 $(TOPIV_DIR)/$(r).log | grep -q '^top_tb: PASS$$'; then \
	    echo "$(r): $$(tail -2 $(TOPIV_DIR)/$(r).log | head -1)"; \
	  else tail -15 $(TOPIV_DIR)/$(r).log; \
	    echo "$(r): FAIL; reproduce: vvp -N $(TOPIV_DIR)/top_tb_$(TOPIV_CFG_$(r)).vvp +vec=$(TOPIV_DIR)/$(r) $(TOPIV_PLUS_$(r))"; \
	    fail=1; fi;) \
	exit $$fail

# Each mutant must fail its run with hit-point or pixel mismatches, or by the memories' contract
# check (pree_ram_banks under PREE_ASSERT: two reads or two writes of one bank in a cycle, which a
# removed conflict rule lets through); not by a time-out or another assertion.
sim-top-icarus-mutants: $(TOPIV_MUTVVPS) $(TOPIV_VECS)
	@fail=0; \
	$(foreach m,$(TOPIV_MUTANTS),\
	  if vvp -N $(TOPIV_DIR)/mut_$(m).vvp +vec=$(TOPIV_DIR)/$(TOPIV_RUN_$(m)) $(TOPIV_PLUS_$(TOPIV_RUN_$(m))) \
	       >$(TOPIV_DIR)/mut_$(m).log 2>&1; then \
	    echo "mutant $(m): NOT detected by run $(TOPIV_RUN_$(m)) (log $(TOPIV_DIR)/mut_$(m).log)"; fail=1; \
	  elif grep -q '^MISMATCH' $(TOPIV_DIR)/mut_$(m).log && grep -q 'top_tb: FAIL' $(TOPIV_DIR)/mut_$(m).log; then \
	    echo "mutant $(m): detected by run $(TOPIV_RUN_$(m)): $$(grep -c '^MISMATCH' $(TOPIV_DIR)/mut_$(m).log) mismatch lines, first: $$(grep -m1 '^MISMATCH' $(TOPIV_DIR)/mut_$(m).log)"; \
	  elif grep -q 'FATAL: .*pree_ram_banks .* in one cycle' $(TOPIV_DIR)/mut_$(m).log; then \
	    echo "mutant $(m): detected by run $(TOPIV_RUN_$(m)): $$(grep -m1 -o 'pree_ram_banks .* in one cycle' $(TOPIV_DIR)/mut_$(m).log)"; \
	  else tail -5 $(TOPIV_DIR)/mut_$(m).log; \
	    echo "mutant $(m): failed, but not by a mismatch (log $(TOPIV_DIR)/mut_$(m).log)"; fail=1; fi;) \
	exit $$fail
