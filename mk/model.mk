# SPDX-License-Identifier: Apache-2.0
# The C reference engine: libpree.a from model/*/*.c (and the OpenImageIO module from
# model/image/image_io.cpp), the `pree` program's
# command line (cli/*.c), and the cmocka unit tests in tests/unit (one binary per test_*.c).

MODEL_C   := $(wildcard model/*/*.c)
# C++ only where a library demands it: nanoflann (model/pm/knn_naive.cpp); OpenImageIO's is the
# shared module below.
MODEL_CXX := $(filter-out model/image/image_io.cpp,$(wildcard model/*/*.cpp))
MODEL_OBJ := $(MODEL_C:%.c=$(BUILD)/%.o) $(MODEL_CXX:%.cpp=$(BUILD)/%.o)
CLI_OBJ   := $(patsubst %.c,$(BUILD)/%.o,$(wildcard cli/*.c))

# OpenImageIO (model/image/image_io.cpp) is a shared module that model/image/image.c loads on the first PNG
# or EXR read/write: loading libOpenImageIO costs ~0.3 s of CPU per process, which runs that only
# touch PPM files then skip.
OIIO_MODULE := $(BUILD)/libpree_oiio.so
$(BUILD)/model/image/image.o: CFLAGS += -DPREE_OIIO_MODULE=\"$(abspath $(OIIO_MODULE))\"
$(BUILD)/model/image/image.o: mk/model.mk
$(OIIO_MODULE): model/image/image_io.cpp model/image/image_io.h model/image/image.h $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CXX,$@)$(CXX) $(CXXFLAGS) -fPIC -shared $< -o $@ -lOpenImageIO -lOpenImageIO_Util
LIBPREE   := $(BUILD)/libpree.a
LDLIBS    += -lassimp -lpng -lz -ljansson

UNIT_SRC  := $(wildcard tests/unit/test_*.c)
UNIT_BIN  := $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)

TEST_PREREQS += $(BUILD)/pree $(UNIT_BIN)

$(BUILD)/%.o: %.c $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CC,$@)$(CC) $(CFLAGS) -c $< -o $@

$(BUILD)/%.o: %.cpp $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,CXX,$@)$(CXX) $(CXXFLAGS) -c $< -o $@

$(LIBPREE): $(MODEL_OBJ) | $(OIIO_MODULE)
	@mkdir -p $(@D)
	$(call say,AR,$@)rm -f $@ && ar rcs $@ $^


$(BUILD)/tests/%: tests/unit/%.c $(LIBPREE)
	@mkdir -p $(@D)
	$(call say,CC,$@.o)$(CC) $(CFLAGS) -Itests/unit -DSCENES_DIR=\"$(CURDIR)/scenes\" -c $< -o $@.o
	$(call say,LINK,$@)$(CXX) $(LDFLAGS) $@.o $(LIBPREE) -o $@ $(LDLIBS) -lcmocka

# The version `pree --version` and the EXR metadata give: git describe, baked in at build time.
# build/version.h is rewritten (at parse time) only when the description changes, so an unchanged
# tree rebuilds nothing.
PREE_VERSION := $(shell git describe --always --dirty --tags 2>/dev/null || echo unknown)
VERSION_H    := $(BUILD)/version.h
VERSION_LINE := \#define PREE_VERSION "$(PREE_VERSION)"
$(shell mkdir -p $(BUILD) && { echo '$(VERSION_LINE)' | cmp -s - $(VERSION_H) || echo '$(VERSION_LINE)' >$(VERSION_H); })
$(BUILD)/cli/cli_version.o: $(VERSION_H)
$(BUILD)/cli/cli_version.o: CFLAGS += -I$(BUILD)

# MPI (cli/cli_mpi.c, model/ppm/render_dist.c, docs/scale_out.md): with Open MPI's mpicc present
# (Debian libopenmpi-dev, scripts/install-deps.sh) the engine is built against it (every program
# that links libpree.a links libmpi), MPI=0 builds without. The
# choice is kept in build/mpi.flags (rewritten at parse time only when it changes) so that a tree
# built before the package came in is relinked with it.
MPI ?= $(if $(shell command -v mpicc 2>/dev/null),1,0)
ifeq ($(MPI),1)
MPI_CFLAGS  := -DPREE_MPI $(shell mpicc --showme:compile)
MPI_LDLIBS  := $(shell mpicc --showme:link)
endif
MPI_FLAGS := $(BUILD)/mpi.flags
MPI_LINE  := MPI=$(MPI) $(MPI_CFLAGS) $(MPI_LDLIBS)
$(shell { echo '$(MPI_LINE)' | cmp -s - $(MPI_FLAGS) || echo '$(MPI_LINE)' >$(MPI_FLAGS); })
$(BUILD)/cli/cli_mpi.o $(BUILD)/model/ppm/render_dist.o: CFLAGS += $(MPI_CFLAGS)
$(BUILD)/cli/cli_mpi.o $(BUILD)/model/ppm/render_dist.o: $(MPI_FLAGS)
LDLIBS += $(MPI_LDLIBS)
$(BUILD)/pree: $(MPI_FLAGS)

-include $(wildcard $(BUILD)/model/*/*.d $(BUILD)/cli/*.d $(BUILD)/tests/*.d)
