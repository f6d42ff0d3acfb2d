# SPDX-License-Identifier: Apache-2.0
# (After mk/fpga.mk, whose venv it uses.) The timing diagrams of docs/integration.md: WaveDrom
# sources docs/wave/*.json rendered to the SVGs beside them (committed, so that the docs show
# them) by the wavedrom package of the hardware tools' venv (`make fpga-deps`). Their port rows
# are checked against pree_axi by tests/checks/integration_doc.sh (tb/axi/axi_wave_tb.v,
# scripts/wave_check.py).
#
#   make docs-waves   render every docs/wave/*.json whose SVG is missing or older

WAVE_SVG := $(patsubst %.json,%.svg,$(wildcard docs/wave/*.json))

.PHONY: docs-waves
docs-waves: $(WAVE_SVG)

docs/wave/%.svg: docs/wave/%.json | $(FPGA_STAMP)
	$(call say,WAVEDROM,$@)$(abspath $(FPGA_VENV))/bin/wavedrompy --input $< --svg $@.tmp
	@mv $@.tmp $@
