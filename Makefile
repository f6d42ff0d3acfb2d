# SPDX-License-Identifier: Apache-2.0
# PREE: progressive radiance estimation engine: RTL, C reference model, co-simulation.
# The front door. `make run` and `make test` do everything on a fresh Debian bookworm machine.
# Fragments in mk/ add the RTL, simulation and synthesis targets; each owns one area.

.DELETE_ON_ERROR:
.SUFFIXES:
SHELL := /bin/bash

BUILD   ?= build
OUT     ?= out
THREADS ?= 2
# The C++ optimisation of the unit-bench models (PREU, controllers, fp32 units): -O1 on the code
# that runs every cycle and -O0 on the rest compiles in about a third of the CPU time of
# Verilator's default -Os, and the benches run as fast (the deep stable PREU bench: 129 -> 43 CPU s
# to build, 3.9 s for 50,000 operations either way).
VL_BENCH_OPT := -MAKEFLAGS "OPT_FAST=-O1 OPT_SLOW=-O0 OPT_GLOBAL=-O0"

# Compiler flags. -ffp-contract=off and no fast-math are part of the bit-exactness contract:
# the fp32 model must round every operation exactly once, as the RTL does.
CC      := gcc
CXX     := g++
FPFLAGS := -ffp-contract=off -fno-fast-math
WARN    := -Wall -Wextra -Wshadow
ifeq ($(WERROR),1)
WARN    += -Werror
endif
OPT     ?= -O2
# The engine's folders (model/*/: docs in the README's layout table); every target includes them all.
MODEL_DIRS := $(sort $(dir $(wildcard model/*/*.h)))
MODEL_INC  := $(patsubst %/,-I%,$(MODEL_DIRS))
SANFLAGS :=
ifdef SANITIZER
SANFLAGS := -fsanitize=$(SANITIZER) -fno-omit-frame-pointer
OPT      := -O1
endif
CFLAGS   := -std=c11 -D_GNU_SOURCE $(OPT) -g $(FPFLAGS) -fexcess-precision=standard $(WARN) -fopenmp -MMD -MP $(SANFLAGS) $(MODEL_INC)
CXXFLAGS := -std=c++17 $(OPT) -g $(FPFLAGS) $(WARN) -fopenmp -MMD -MP $(SANFLAGS) $(MODEL_INC)
LDLIBS   := -lembree3 -lm
LDFLAGS  := -fopenmp $(SANFLAGS)

# Quiet builds: one short line a step (CC model/ppm/grid.o, LINK build/pree, VERILATE
# build/cosim/vl2_p4_h6_x4_w1); V=1 prints the full commands instead. A recipe line starts with
# $(call say,TAG,WHAT) and then its command; inside a shell loop, $(call say_sh,TAG,WHAT,COMMAND)
# is the shell command that prints the same line (WHAT and COMMAND may name shell variables).
V ?= 0
ifeq ($(V),1)
say =
say_sh = echo "$(3)"
else
say = @printf '  %-9s %s\n' '$(1)' '$(patsubst $(BUILD)/%,%,$(2))';
say_sh = printf '  %-9s %s\n' '$(1)' "$(2)"
endif

.PHONY: all deps build run test test-prereqs check bench clean help lint synth sim report
all: build

help:
	@echo "make run     install what is missing, build, render the default scene (SCENE=path for another)"
	@echo "make test    the full regression (ends with 'N passed, N failed')"
	@echo "make check   the quick regression for iteration"
	@echo "make bench   speed, memory and run-time-against-error figures"
	@echo "make config  write the configuration table's Verilog, C and make copies"
	@echo "make report  one HTML page of the last run, bench, co-simulations, synthesis and test: out/report/"

# Install every Debian package the project needs (quiet when all are present).
DEPS_STAMP := $(BUILD)/.deps-ok
deps: $(DEPS_STAMP)
$(DEPS_STAMP): scripts/install-deps.sh
	@scripts/install-deps.sh
	@mkdir -p $(@D) && touch $@

# The Verilator harness of every bench and of the co-simulation host (C++, header-only).
VHARNESS     := tb/lib/vharness.h
VHARNESS_INC := -I$(CURDIR)/tb/lib

# Each fragment owns one area and appends to TEST_PREREQS, LINT_TARGETS, SYNTH_TARGETS,
# SIM_TARGETS; its regression checks live in tests/checks/*.sh.
# mk/config.mk comes first: the configuration table's make variables, which the others read.
include mk/config.mk mk/model.mk
include $(sort $(filter-out mk/config.mk mk/model.mk,$(wildcard mk/*.mk)))

# The configuration table (config/pree_config.json) writes its copies: rtl/pree_unit_stages.vh,
# model/pree/pree_config.h, mk/config.mk (scripts/pree_config.py; tests/checks/config_table.sh
# fails when one is stale or the RTL disagrees with the table).
.PHONY: config
config:
	@python3 scripts/pree_config.py generate

# The pree program: the command line (cli/) over the engine (libpree.a); no Verilator. Its
# `cosim` command runs the co-simulation programs of mk/cosim.mk.
$(BUILD)/pree: $(CLI_OBJ) $(LIBPREE)
	$(call say,LINK,$@)$(CXX) $(LDFLAGS) $(filter %.o %.a,$^) -o $@ $(LDLIBS)

build: $(DEPS_STAMP) $(BUILD)/pree

# Builds run JOBS-parallel (default: all cores); the Verilated models dominate.
JOBS ?= $(shell nproc)
PARALLEL := -j$(JOBS)

# The clock for the time to the first image starts after the packages are in, before the build.
# SCENE=path renders another scene through the same comparison; SIZE="--width W --height H
# --photons N" (any render options) is given to every render of it.
SCENE ?= scenes/cornell3
SIZE  ?=
run: $(DEPS_STAMP)
	@export PREE_RUN_START=$$(date +%s.%N) PREE_RUN_SCENE='$(SCENE)' PREE_RUN_SIZE="$${PREE_RUN_SIZE:-$(SIZE)}"; \
	  $(MAKE) --no-print-directory $(PARALLEL) $(BUILD)/pree && \
	  scripts/make-run.sh $(BUILD)/pree $(OUT) "$(MAKE) --no-print-directory $(PARALLEL) $(BUILD)/pree-cosim-p4"

# One self-contained page from what make run, make bench, make sim(-full), make fpga-timing and
# make test wrote (scripts/report/build.py); tests/checks/report_browser.sh opens it in Chromium.
report:
	@python3 scripts/report/build.py $(CURDIR) $(OUT) $(BUILD)

test-prereqs: $(DEPS_STAMP) $(TEST_PREREQS)

test: $(DEPS_STAMP)
	@$(MAKE) --no-print-directory $(PARALLEL) test-prereqs
	@scripts/run-tests.sh full

check: $(DEPS_STAMP)
	@$(MAKE) --no-print-directory $(PARALLEL) test-prereqs
	@scripts/run-tests.sh quick

lint: $(DEPS_STAMP) $(LINT_TARGETS)
synth: $(DEPS_STAMP) $(SYNTH_TARGETS)
sim: $(DEPS_STAMP) $(SIM_TARGETS)

clean:
	rm -rf $(BUILD) $(OUT)
