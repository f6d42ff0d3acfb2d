# SPDX-License-Identifier: Apache-2.0
# make bench: speed, memory, and run time against error. Figures go to out/bench/.
# Engine speed per grid and thread count, every scene, and run time against error (a plot).
BENCH_DIR := $(OUT)/bench
.PHONY: bench bench-engine bench-scale bench-convergence bench-scenes bench-count bench-pm
# The RTL's own figures come from `make ctrl-util` (dispatcher utilization) and
# `make sim-full` (whole-frame co-simulation), which take longer.
bench: bench-engine bench-scale bench-count bench-scenes bench-convergence bench-pm
bench-scenes: build
	@scripts/bench-scenes.sh
bench-engine: build
	@scripts/bench-engine.sh $(BUILD)/pree $(BENCH_DIR)
# The three frame sizes of issue 15 (320x240/768k, 1600x1200/19.2M, 3840x2160/82.9M), re-filter on
# and off: wall, peak memory, grid entries, candidates (docs/engine_performance.md, "The engine at scale").
bench-scale: build
	@scripts/bench-scale.sh $(BUILD)/pree $(BENCH_DIR)
# Instruction counts per phase under callgrind: repeatable where seconds wander (about a minute).
bench-count: build
	@scripts/bench-count.sh $(BUILD)/pree $(BENCH_DIR)
bench-convergence: build
	@scripts/bench-convergence.sh $(BUILD)/pree $(BENCH_DIR)
# The photon-map estimator against PPM (bias against convergence), the clustered search's speedup,
# threads and task schedules, the photon-path cap (docs/photon_map.md).
bench-pm: build
	@scripts/bench-pm.sh $(BUILD)/pree $(BENCH_DIR)
