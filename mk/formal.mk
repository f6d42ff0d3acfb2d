# SPDX-License-Identifier: Apache-2.0
# The formal suite: SymbiYosys jobs in
# formal/<job>/ (docs/formal.md), run through the pinned tools of `make fpga-deps` by
# scripts/formal-run.sh.
#
#   make formal         every job, prove and cover (the full level): one line per task
#   make formal-quick   the quick level only (the jobs in make test: tests/checks/formal_quick.sh)
#   make formal FORMAL_JOBS="axi aftso:prove"   some jobs or tasks only
#   make formal-mutants the mutants of formal/mutants_full.txt (their jobs take minutes: not in
#                       make test, which checks formal/mutants.txt)
# make test installs the tools (TEST_PREREQS) and runs formal_quick.sh and formal_mutants.sh.

FORMAL_JOBS  ?=
# The tools' venv and its stamp as mk/fpga.mk names them (that fragment, read after this one,
# installs it).
FORMAL_VENV  := $(if $(FPGA_VENV),$(FPGA_VENV),$(BUILD)/fpga-venv)
FORMAL_STAMP := $(FORMAL_VENV)/.deps-ok

TEST_PREREQS += $(FORMAL_STAMP)

.PHONY: formal formal-quick formal-mutants
formal: $(FORMAL_STAMP)
	@FPGA_VENV=$(FORMAL_VENV) nice -n 10 scripts/formal-run.sh full $(FORMAL_JOBS)

formal-quick: $(FORMAL_STAMP)
	@FPGA_VENV=$(FORMAL_VENV) nice -n 10 scripts/formal-run.sh quick

formal-mutants: $(FORMAL_STAMP)
	@FPGA_VENV=$(FORMAL_VENV) FORMAL_MUTANTS=formal/mutants_full.txt nice -n 10 bash tests/checks/formal_mutants.sh
