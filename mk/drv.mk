# SPDX-License-Identifier: Apache-2.0
# (After mk/cosim_axi.mk, whose model objects it links.) pree_drv, the C driver of pree_axi
# (drv/pree_drv.h), and its back ends: the Verilated wrapper (drv/pree_be_verilated.c, for
# tests), a board's UIO / /dev/mem mapping with Xilinx AXI DMA engines (drv/pree_be_uio.c), and
# the UART link of the ULX3S board top (drv/pree_be_uart.c; mk/postroute.mk simulates it).
#
#   build/drv/libpree_drv.a   the driver and the board back ends (for a board's program): UIO / AXI
#                             DMA, and the UART link of pree_ulx3s (drv/pree_be_uart.c, a serial port)
#   build/drv/pree_probe      board bring-up through it: the build's registers, and a hit-point
#                             loopback through the DMA (drv/pree_probe.c; tests/checks/drv_board.sh)
#   build/drv/pree_drv_test   the driver on the Verilated pree_axi of build/pree-cosim-axi-p4
#                             against the C model (tests/checks/drv_verilated.sh)

DRV_DIR    := $(BUILD)/drv
DRV_CFLAGS := $(CFLAGS) -Idrv
DRV_TEST   := $(DRV_DIR)/pree_drv_test
DRV_LIB    := $(DRV_DIR)/libpree_drv.a
DRV_PROBE  := $(DRV_DIR)/pree_probe
# The Verilated back end's model: pree_axi with 4 PREUs, the paper datapath (mk/cosim_axi.mk).
DRV_VL_OBJS := $(DRV_DIR)/pree_be_verilated.o $(DRV_DIR)/pree_wqueue.o $(HOST_DIR)/cosim_axi_rtl_p4.o \
               $(call AXI_MDIR,4,p)/Vpree_axi_p4__ALL.a $(COSIM_VLIB)

TEST_PREREQS += $(DRV_LIB) $(DRV_PROBE) $(DRV_TEST)

$(DRV_DIR)/%.o: drv/%.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(DRV_CFLAGS) -c $< -o $@
$(DRV_DIR)/pree_be_verilated.o: drv/pree_be_verilated.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(DRV_CFLAGS) -Ihost -c $< -o $@
$(DRV_DIR)/pree_drv_test.o: tb/drv/pree_drv_test.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(DRV_CFLAGS) -Ihost -c $< -o $@
$(DRV_LIB): $(DRV_DIR)/pree_drv.o $(DRV_DIR)/pree_be_uio.o $(DRV_DIR)/pree_be_uart.o $(DRV_DIR)/pree_uart_tty.o \
           $(DRV_DIR)/pree_wqueue.o
	$(call say,AR,$@)rm -f $@ && ar rcs $@ $^
$(DRV_PROBE): $(DRV_DIR)/pree_probe.o $(DRV_LIB)
	$(call say,LINK,$@)$(CC) $(LDFLAGS) $^ -o $@
$(DRV_TEST): $(DRV_DIR)/pree_drv_test.o $(DRV_DIR)/pree_drv.o $(DRV_VL_OBJS) $(LIBPREE)
	$(call say,LINK,$@)$(CXX) $(LDFLAGS) $^ -o $@ $(LDLIBS) -lz -pthread
-include $(wildcard $(DRV_DIR)/*.d)
