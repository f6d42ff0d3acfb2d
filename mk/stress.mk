# SPDX-License-Identifier: Apache-2.0
# make stress: the numerical stress suite of issue 10 (docs/numerics.md). Tables, CSVs and plots
# go to out/stress/; the plots are copied to docs/images/numerics-*.png.
#   stress-hitpoint  one hit point fed up to 1e9 (stable count: 2^32 + 1e6) accepted photons through
#                    both fp32 datapaths against double, long double and the closed form; sweeps of
#                    alpha, initial r2 and flux; non-finite inputs; N_emitted beyond 2^24 and 2^32
#   stress-rtl       one hit point fed 10 million accepted photons through each datapath's
#                    Verilated PREU, state written back every time, every word against the model
#                    (make sim-preu-chain; about 2 minutes a datapath)
#   stress-render    whole-render drift (fp32 paper/stable against double, 16x12, 1e6..1e8 photons,
#                    cornell3 and cornell-sphere) and scale invariance (scaled copies, 1e-4..1e6)
# The quick level runs inside make test: tests/checks/stress_quick.sh.
STRESS_DIR := $(OUT)/stress
STRESS_HP  := $(BUILD)/stress/stress_hitpoint
.PHONY: stress stress-hitpoint stress-rtl stress-render stress-plots

STRESS_HP_OBJS := $(patsubst tests/stress/%.c,$(BUILD)/stress/%.o,$(wildcard tests/stress/*.c))
$(BUILD)/stress/%.o: tests/stress/%.c $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(CFLAGS) -c $< -o $@
$(STRESS_HP): $(STRESS_HP_OBJS) $(LIBPREE)
	$(call say,LINK,$@)$(CC) $(LDFLAGS) $(STRESS_HP_OBJS) $(LIBPREE) -o $@ -lm

TEST_PREREQS += $(STRESS_HP)

stress: stress-hitpoint stress-rtl stress-render
stress-rtl:
	@mkdir -p $(STRESS_DIR)
	@$(MAKE) --no-print-directory sim-preu-chain | tee $(STRESS_DIR)/rtl-chain.txt
stress-hitpoint: $(DEPS_STAMP) $(STRESS_HP)
	@scripts/stress-hitpoint.sh $(STRESS_HP) $(STRESS_DIR)
stress-render: build
	@scripts/stress-render.sh $(BUILD)/pree $(STRESS_DIR)
# Redraw the plots from the CSVs of an earlier stress-hitpoint run.
stress-plots:
	@scripts/stress-plots.sh $(STRESS_DIR)

-include $(wildcard $(BUILD)/stress/*.d)
