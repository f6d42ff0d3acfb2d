# (After mk/fpga.mk.) pree_axi's register map: one source, rtl/regs/pree_axi.rdl
# (SystemRDL, docs/integration.md "Register map").
#
#   make regs     regenerate from it, with PeakRDL (the hardware tools' venv: make fpga-deps, or
#                 FPGA_VENV=<venv>), the committed files scripts/regs_gen.sh lists: the C header
#                 drv/pree_axi_regs.h, the register numbers rtl/pree_axi_regs.vh that pree_axi.v
#                 includes, the check's table tb/regs/pree_axi_regs_table.h, and the table of
#                 docs/integration.md (tests/checks/regs_map.sh fails when one is stale)

TEST_PREREQS += $(FPGA_STAMP)

.PHONY: regs
regs: $(FPGA_STAMP)
	scripts/regs_gen.sh $(FPGA_VENV) .

