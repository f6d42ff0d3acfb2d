# SPDX-License-Identifier: Apache-2.0
# (After mk/drv.mk and mk/fpga.mk.) pree_axi's register map: one source, rtl/regs/pree_axi.rdl
# (SystemRDL, docs/integration.md "Register map").
#
#   make regs     regenerate from it, with PeakRDL (the hardware tools' venv: make fpga-deps, or
#                 FPGA_VENV=<venv>), the committed files scripts/regs_gen.sh lists: the C header
#                 drv/pree_axi_regs.h, the register numbers rtl/pree_axi_regs.vh that pree_axi.v
#                 includes, the check's table tb/regs/pree_axi_regs_table.h, and the table of
#                 docs/integration.md
#   build/regs/regs_check   the RTL against the map through AXI4-Lite (tests/checks/regs_map.sh,
#                 which also fails when a generated file is stale)

REGS_DIR   := $(BUILD)/regs
REGS_CHECK := $(REGS_DIR)/regs_check

TEST_PREREQS += $(FPGA_STAMP) $(REGS_CHECK)

.PHONY: regs
regs: $(FPGA_STAMP)
	scripts/regs_gen.sh $(FPGA_VENV) .

# The parameters of the model it runs (mk/cosim_axi.mk's pree_axi with 4 PREUs, paper datapath).
$(REGS_DIR)/regs_check.o: tb/regs/regs_check.c tb/regs/pree_axi_regs_table.h | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(DRV_CFLAGS) -Itb/regs \
	  '-DREGS_GPARAMS="$(strip $(filter-out -GPipeFast=% -GPhotonsPerCycle=%,$(call COSIM_GPARAMS,4,p)))"' -c $< -o $@
$(REGS_CHECK): $(REGS_DIR)/regs_check.o $(DRV_VL_OBJS)
	$(call say,LINK,$@)$(CXX) $(LDFLAGS) $^ -o $@ $(LDLIBS) -lz -pthread
-include $(wildcard $(REGS_DIR)/*.d)
