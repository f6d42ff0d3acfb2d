# The C reference engine: libpree.a from model/*/*.c (and the OpenImageIO module from
# model/image/image_io.cpp), the `pree` program's
# command line (cli/*.c), and the cmocka unit tests in tests/unit (one binary per test_*.c).

MODEL_C   := $(wildcard model/*/*.c)
MODEL_OBJ := $(MODEL_C:%.c=$(BUILD)/%.o)
CLI_OBJ   := $(patsubst %.c,$(BUILD)/%.o,$(wildcard cli/*.c))

# OpenImageIO (model/image/image_io.cpp) is a shared module that model/image/image.c loads on the first PNG
# or EXR read/write: loading libOpenImageIO costs ~0.3 s of CPU per process, which runs that only
# touch PPM files then skip.
OIIO_MODULE := $(BUILD)/libpree_oiio.so
$(BUILD)/model/image/image.o: CFLAGS += -DPREE_OIIO_MODULE=\"$(abspath $(OIIO_MODULE))\"
$(BUILD)/model/image/image.o: mk/model.mk
$(OIIO_MODULE): model/image/image_io.cpp model/image/image_io.h model/image/image.h $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -fPIC -shared $< -o $@ -lOpenImageIO -lOpenImageIO_Util
LIBPREE   := $(BUILD)/libpree.a
LDLIBS    += -lassimp -lz -ljansson

UNIT_SRC  := $(wildcard tests/unit/test_*.c)
UNIT_BIN  := $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)

TEST_PREREQS += $(BUILD)/pree $(UNIT_BIN)

$(BUILD)/%.o: %.c $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -c $< -o $@

$(BUILD)/%.o: %.cpp $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -c $< -o $@

$(LIBPREE): $(MODEL_OBJ) | $(OIIO_MODULE)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^


$(BUILD)/tests/%: tests/unit/%.c $(LIBPREE)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Itests/unit -DSCENES_DIR=\"$(CURDIR)/scenes\" -c $< -o $@.o
	$(CXX) $(LDFLAGS) $@.o $(LIBPREE) -o $@ $(LDLIBS) -lcmocka

-include $(wildcard $(BUILD)/model/*/*.d $(BUILD)/cli/*.d $(BUILD)/tests/*.d)
