# SPDX-License-Identifier: Apache-2.0
# (After mk/fpga.mk, whose venv it uses.) The whole PREE placed and routed on the ULX3S's
# LFE5U-85F (docs/fpga_board.md): pree_axi behind the UART bridge of
# rtl/board/pree_ulx3s.v, pins in constraints/pree_ulx3s.lpf; scripts/fpga_pnr_top.sh runs each
# step (Yosys synth_ecp5 of pree_axi alone, then of the board top around it; nextpnr-ecp5 per
# seed; ecppack of the first seed's result), scripts/fpga_top_report.py writes the tables.
# Outside `make test`: hours of one core (docs/fpga_board.md).
#
#   make fpga-pnr-top                       everything: $(FPGA_TOP_DIR)/pree_ulx3s.bit,
#                                           $(FPGA_TOP_DIR)/report.md and the first seed's
#                                           floorplan, $(FPGA_TOP_DIR)/floorplan.png
#   FPGA_TOP_CONFIG=p1                      a named configuration (below; default d1, the deep
#                                           PREU), in $(BUILD)/fpga-top-<name>
#   FPGA_TOP_SEEDS="1 2 3"                  nextpnr's placer seeds, one run each (default 1); the
#                                           first one's routed design makes the bitstream
#   FPGA_TOP_PARAMS="NumPreu=2 PipeFast=1 ..."   pree_ulx3s's parameters in place of the named
#                                           configuration's
#   FPGA_PNR_OPTS="--placer heap ..."       nextpnr's placer and router options in place of the
#                                           named configuration's
#   FPGA_TOP_DIR=build/fpga-top-x           another folder (one per configuration)

# The named configurations (docs/fpga_board.md), each with a core clock below its routed Fmax:
# d1, one PREU with the deep stages (PipeFast 1), 1,024 hit points in 2 banks, 512 pixels in 2
# banks, 40 MHz (PLL 25 MHz x 8 / 5, CLKOP divider 15, VCO 600 MHz), placed by nextpnr's
# electrostatic placer (HeAP's placement does not route); p1, the same with the paper's stages,
# 20 MHz (x 4 / 5, divider 30), HeAP; p2, two paper PREUs, 4,096 hit points in 8 banks and as
# many pixels in 4, 100 MHz (does not route).
FPGA_TOP_CONFIG_d1 := NumPreu=1 HpAW=10 HpBankW=1 IdxAW=7 PxAW=9 PxBankW=1 CntW=16 Datapath=0 PipeFast=1 PllInDiv=5 PllFbDiv=8 PllOpDiv=15
FPGA_TOP_CONFIG_p1 := NumPreu=1 HpAW=10 HpBankW=1 IdxAW=7 PxAW=9 PxBankW=1 CntW=16 Datapath=0 PipeFast=0 PllInDiv=5 PllFbDiv=4 PllOpDiv=30
FPGA_TOP_CONFIG_p2 := NumPreu=2 HpAW=12 HpBankW=3 IdxAW=12 PxAW=12 PxBankW=2 CntW=16 Datapath=0 PipeFast=0
FPGA_TOP_PNR_HEAP  := --placer-heap-timingweight 25 --router router2
FPGA_TOP_PNR_d1    := --placer static --router router2
FPGA_TOP_CONFIG ?= d1
FPGA_TOP_DIR    ?= $(BUILD)/fpga-top-$(FPGA_TOP_CONFIG)
FPGA_TOP_SEEDS  ?= 1
FPGA_TOP_PARAMS ?= $(FPGA_TOP_CONFIG_$(FPGA_TOP_CONFIG))
FPGA_PNR_OPTS   ?= $(or $(FPGA_TOP_PNR_$(FPGA_TOP_CONFIG)),$(FPGA_TOP_PNR_HEAP))
FPGA_TOP_RUN     = PATH=$(abspath $(FPGA_VENV))/bin:$$PATH FPGA_TOP_PARAMS="$(FPGA_TOP_PARAMS)" \
                   FPGA_PNR_OPTS="$(FPGA_PNR_OPTS)" \
                   nice -n 10 scripts/fpga_pnr_top.sh
FPGA_TOP_BOARD  := rtl/pree_reset_sync.v $(wildcard rtl/board/*.v)
FPGA_TOP_FIRST   = $(firstword $(FPGA_TOP_SEEDS))

# The parameters are an input: a change rebuilds everything; nextpnr's options, the routes. Each
# is kept in a file rewritten only when it changes (fpga_top_keep TEXT,FILE), for the goals that
# build or simulate a configuration.
FPGA_TOP_PFILE  := $(FPGA_TOP_DIR)/params.txt
FPGA_TOP_OFILE  := $(FPGA_TOP_DIR)/pnr-opts.txt
fpga_top_keep    = { echo '$(1)' | cmp -s - $(2) || echo '$(1)' > $(2); }
ifneq ($(filter fpga-pnr-top sim-postroute% $(FPGA_TOP_DIR)/%,$(MAKECMDGOALS)),)
ifeq ($(strip $(FPGA_TOP_PARAMS)),)
$(error FPGA_TOP_CONFIG=$(FPGA_TOP_CONFIG): no such configuration (d1, p1, p2; or set FPGA_TOP_PARAMS))
endif
$(shell mkdir -p $(FPGA_TOP_DIR) && $(call fpga_top_keep,$(FPGA_TOP_PARAMS),$(FPGA_TOP_PFILE)) && \
        $(call fpga_top_keep,$(FPGA_PNR_OPTS),$(FPGA_TOP_OFILE)))
endif

.PHONY: fpga-pnr-top
fpga-pnr-top: $(FPGA_TOP_DIR)/report.md $(FPGA_TOP_DIR)/pree_ulx3s.bit $(FPGA_TOP_DIR)/floorplan.png
	@cat $(FPGA_TOP_DIR)/report.md

$(FPGA_TOP_DIR)/pree_axi.json: $(shell grep -v '^//' rtl/pree.f) $(wildcard rtl/*.vh) rtl/pree.f \
                               scripts/fpga_pnr_top.sh $(FPGA_TOP_PFILE) | $(FPGA_STAMP)
	$(FPGA_TOP_RUN) core $(FPGA_TOP_DIR)

$(FPGA_TOP_DIR)/pree_ulx3s.json: $(FPGA_TOP_DIR)/pree_axi.json $(FPGA_TOP_BOARD)
	$(FPGA_TOP_RUN) board $(FPGA_TOP_DIR)

# Each seed's run ends in seed<N>.result, routed or not (the report's rows); the bitstream and the
# floorplan need the first seed routed.
$(FPGA_TOP_DIR)/seed%.result: $(FPGA_TOP_DIR)/pree_ulx3s.json constraints/pree_ulx3s.lpf $(FPGA_TOP_OFILE)
	$(FPGA_TOP_RUN) pnr $(FPGA_TOP_DIR) $*
$(FPGA_TOP_DIR)/seed%.config: $(FPGA_TOP_DIR)/seed%.result
	@test -f $@ || { echo "fpga-pnr-top: seed $*: $$(cat $<) (log $(@D)/seed$*.log)" >&2; exit 1; }

$(FPGA_TOP_DIR)/pree_ulx3s.bit: $(FPGA_TOP_DIR)/seed$(FPGA_TOP_FIRST).config
	$(FPGA_TOP_RUN) pack $(FPGA_TOP_DIR) $(FPGA_TOP_FIRST)

$(FPGA_TOP_DIR)/floorplan.png: $(FPGA_TOP_DIR)/seed$(FPGA_TOP_FIRST).config scripts/fpga_floorplan.py
	python3 scripts/fpga_floorplan.py $(FPGA_TOP_DIR)/seed$(FPGA_TOP_FIRST).routed.json $@

$(FPGA_TOP_DIR)/report.md: $(foreach s,$(FPGA_TOP_SEEDS),$(FPGA_TOP_DIR)/seed$(s).result) scripts/fpga_top_report.py
	python3 scripts/fpga_top_report.py $(FPGA_TOP_DIR) $(FPGA_TOP_SEEDS) > $@.tmp && mv $@.tmp $@
