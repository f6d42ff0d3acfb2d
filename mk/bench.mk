# make bench: speed, memory, and run time against error. Figures go to out/bench/.
# Fragments of other areas add their own benchmark targets to BENCH_TARGETS.
BENCH_DIR := $(OUT)/bench
.PHONY: bench bench-engine bench-convergence
bench: bench-engine bench-convergence $(BENCH_TARGETS)
bench-engine: build
	@scripts/bench-engine.sh $(BUILD)/pree $(BENCH_DIR)
bench-convergence: build
	@scripts/bench-convergence.sh $(BUILD)/pree $(BENCH_DIR)
