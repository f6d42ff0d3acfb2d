# PREU (rtl/pree_preu.v): lint, Verilator bench scoreboarded against model/preu_fp32.c,
# self-checking Icarus bench over a C-generated vector file, Yosys synthesis.
#   make sim-preu        Verilator C++ bench (PREU_N ops) + the Verilog bench over PREU_IV_N vectors
#                        under Icarus and under Verilator --binary, both modes, and a run that
#                        breaks the mode-switch rule, which the RTL assertion must stop
#   make sim-preu-full   the thorough level: PREU_N_FULL Verilator ops over several seeds
#   make wave-preu       an FST waveform of a short Verilator run (PREU_N=200 recommended)
#   make lint-preu       verilator --lint-only -Wall, with and without PREE_ASSERT, TagW 1/8/32
#   make yosys-check-preu  Yosys structural checks: no latch, no combinational loop (seconds)
#   make synth-preu      the checks, then synth_xilinx (7-series, flattened, no I/O buffers):
#                        resource figures in build/preu/synth_xilinx_stat.txt (several minutes)

PREU_RTL    := rtl/pree_preu.v
PREU_UNITS  := rtl/pree_fp32_add.v rtl/pree_fp32_mul.v rtl/pree_fp32_sqr.v rtl/pree_fp32_div.v \
               rtl/pree_fp32_cmp.v $(filter-out rtl/pree_fp32_add.v rtl/pree_fp32_mul.v \
               rtl/pree_fp32_sqr.v rtl/pree_fp32_div.v rtl/pree_fp32_cmp.v,$(wildcard rtl/pree_fp32_*.v))
PREU_SRCS   := $(PREU_RTL) $(PREU_UNITS)
PREU_DIR    := $(BUILD)/preu
PREU_N      ?= 200000
PREU_N_FULL ?= 2000000
PREU_IV_N   ?= 4000
PREU_SEED   ?= 1
PREU_CFLAGS := -std=c11 -O2 -g $(FPFLAGS) -Wall -Wextra -Imodel -Itb/preu
PREU_C_OBJ  := $(PREU_DIR)/preu_fp32.o $(PREU_DIR)/preu_vec.o
PREU_BENCH  := $(PREU_DIR)/vl/preu_bench

.PHONY: sim-preu-badswitch wave-preu lint-preu sim-preu sim-preu-vl sim-preu-iv sim-preu-vlbin sim-preu-full synth-preu yosys-check-preu
LINT_TARGETS  += lint-preu
SIM_TARGETS   += sim-preu
SYNTH_TARGETS += synth-preu

$(PREU_DIR)/%.o: model/%.c model/preu_fp32.h model/fp32_ops.h | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(PREU_CFLAGS) -c $< -o $@
$(PREU_DIR)/%.o: tb/preu/%.c tb/preu/preu_vec.h model/preu_fp32.h model/fp32_ops.h | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(PREU_CFLAGS) -c $< -o $@

lint-preu: | $(DEPS_STAMP)
	verilator --lint-only -Wall -Irtl --top-module pree_preu $(PREU_SRCS)
	verilator --lint-only -Wall -Irtl -DPREE_ASSERT --top-module pree_preu $(PREU_SRCS)
	verilator --lint-only -Wall -Irtl -GTagW=1 --top-module pree_preu $(PREU_SRCS)
	verilator --lint-only -Wall -Irtl -GTagW=8 --top-module pree_preu $(PREU_SRCS)

# Verilator bench: the C model objects are linked into the harness; assertions on.
$(PREU_BENCH): $(PREU_SRCS) tb/preu/preu_bench.cpp tb/preu/preu_vec.h model/preu_fp32.h $(PREU_C_OBJ) | $(DEPS_STAMP)
	@mkdir -p $(@D)
	verilator --cc --exe --build -j 2 -O3 --trace-fst -Irtl -DPREE_ASSERT --top-module pree_preu \
	  -Mdir $(PREU_DIR)/vl -o preu_bench \
	  -CFLAGS "-O2 $(FPFLAGS) -I$(CURDIR)/model -I$(CURDIR)/tb/preu" \
	  $(PREU_SRCS) $(CURDIR)/tb/preu/preu_bench.cpp $(abspath $(PREU_C_OBJ)) >$(PREU_DIR)/vl-build.log 2>&1 \
	  || { tail -30 $(PREU_DIR)/vl-build.log; exit 1; }

sim-preu-vl: $(PREU_BENCH)
	$(PREU_BENCH) $(PREU_N) $(PREU_SEED)

# A waveform of a short run: build/preu/preu.fst (make wave-preu PREU_N=200).
wave-preu: $(PREU_BENCH)
	$(PREU_BENCH) $(PREU_N) $(PREU_SEED) +trace=$(PREU_DIR)/preu.fst
	@echo "waveform: $(PREU_DIR)/preu.fst"

# Icarus bench: vectors written by the C generator from the same sequence generator.
$(PREU_DIR)/preu_vecgen: $(PREU_DIR)/preu_vecgen.o $(PREU_C_OBJ)
	$(CC) $^ -o $@ -lm
$(PREU_DIR)/preu_vec_$(PREU_IV_N)_$(PREU_SEED).hex: $(PREU_DIR)/preu_vecgen
	$(PREU_DIR)/preu_vecgen $(PREU_IV_N) $(PREU_SEED) $@
$(PREU_DIR)/tb_preu_$(PREU_IV_N)_$(PREU_SEED).vvp: tb/preu/tb_preu.v $(PREU_SRCS) $(PREU_DIR)/preu_vec_$(PREU_IV_N)_$(PREU_SEED).hex
	iverilog -g2005 -DPREE_ASSERT -Irtl -s tb_preu -Ptb_preu.NOps=$(PREU_IV_N) \
	  -Ptb_preu.VecFile='"$(PREU_DIR)/preu_vec_$(PREU_IV_N)_$(PREU_SEED).hex"' -o $@ tb/preu/tb_preu.v $(PREU_SRCS)

sim-preu-iv: $(PREU_DIR)/tb_preu_$(PREU_IV_N)_$(PREU_SEED).vvp
	vvp -N $<

# The same self-checking Verilog bench and vector file under Verilator (--binary --timing): the
# two simulators must give the same verdict and the same cycle count.
$(PREU_DIR)/vlbin/tb_preu_$(PREU_IV_N)_$(PREU_SEED): tb/preu/tb_preu.v $(PREU_SRCS) $(PREU_DIR)/preu_vec_$(PREU_IV_N)_$(PREU_SEED).hex
	@mkdir -p $(@D)
	verilator --binary --timing -j 2 -Irtl -DPREE_ASSERT --top-module tb_preu -GNOps=$(PREU_IV_N) \
	  -GVecFile='"$(PREU_DIR)/preu_vec_$(PREU_IV_N)_$(PREU_SEED).hex"' -Mdir $(PREU_DIR)/vlbin \
	  -o tb_preu_$(PREU_IV_N)_$(PREU_SEED) tb/preu/tb_preu.v $(PREU_SRCS) >$(PREU_DIR)/vlbin-build.log 2>&1 \
	  || { tail -30 $(PREU_DIR)/vlbin-build.log; exit 1; }

sim-preu-vlbin: $(PREU_DIR)/vlbin/tb_preu_$(PREU_IV_N)_$(PREU_SEED)
	$<

# The mode-switch assertion must fire when the bench switches modes with operations in flight.
sim-preu-badswitch: $(PREU_DIR)/preu_vec_bad.hex tb/preu/tb_preu.v $(PREU_SRCS)
	iverilog -g2005 -DPREE_ASSERT -Irtl -s tb_preu -Ptb_preu.NOps=100 -Ptb_preu.BadSwitch=1 \
	  -Ptb_preu.VecFile='"$(PREU_DIR)/preu_vec_bad.hex"' -o $(PREU_DIR)/tb_preu_badswitch.vvp \
	  tb/preu/tb_preu.v $(PREU_SRCS)
	if vvp -N $(PREU_DIR)/tb_preu_badswitch.vvp >$(PREU_DIR)/badswitch.log 2>&1; then \
	  echo "sim-preu-badswitch: the run passed, but it switched modes while busy"; exit 1; fi
	grep -q 'mode_i changed while operations were in flight' $(PREU_DIR)/badswitch.log || \
	  { tail -5 $(PREU_DIR)/badswitch.log; echo "sim-preu-badswitch: failed, but not by the assertion"; exit 1; }
	@echo "sim-preu-badswitch: the mode-switch assertion fired as it must"
$(PREU_DIR)/preu_vec_bad.hex: $(PREU_DIR)/preu_vecgen
	$(PREU_DIR)/preu_vecgen 100 1 $@

sim-preu: sim-preu-vl sim-preu-iv sim-preu-vlbin sim-preu-badswitch

sim-preu-full: $(PREU_BENCH)
	for s in 1 2 3 4 5; do $(PREU_BENCH) $(PREU_N_FULL) $$s || exit 1; done

# Structural checks (quick, part of make test and make check through tests/checks/preu_quick.sh): no latches,
# no combinational loops. synth-preu adds the 7-series figures (several minutes).
yosys-check-preu: $(PREU_SRCS) tb/preu/preu_check.ys | $(DEPS_STAMP)
	@mkdir -p $(PREU_DIR)
	yosys -q -l $(PREU_DIR)/check.log -p 'read_verilog -Irtl $(PREU_SRCS); script tb/preu/preu_check.ys'

synth-preu: yosys-check-preu
	yosys -q -l $(PREU_DIR)/synth_xilinx.log -p 'read_verilog -Irtl $(PREU_SRCS); synth_xilinx -family xc7 -top pree_preu -flatten -noiopad; tee -o $(PREU_DIR)/synth_xilinx_stat.txt stat'
	@sed -n '/Number of cells/,$$p' $(PREU_DIR)/synth_xilinx_stat.txt
