# The C reference engine: libpree.a from model/*.c and model/*.cpp, the `pree` program,
# and the cmocka unit tests in tests/unit (one binary per test_*.c).

MODEL_C   := $(filter-out model/main.c,$(wildcard model/*.c))
MODEL_CXX := $(wildcard model/*.cpp)
MODEL_OBJ := $(MODEL_C:%.c=$(BUILD)/%.o) $(MODEL_CXX:%.cpp=$(BUILD)/%.o)
LIBPREE   := $(BUILD)/libpree.a
LDLIBS    += -lassimp -lz

UNIT_SRC  := $(wildcard tests/unit/test_*.c)
UNIT_BIN  := $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)

TEST_PREREQS += $(BUILD)/pree $(UNIT_BIN)

$(BUILD)/%.o: %.c $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -c $< -o $@

$(BUILD)/%.o: %.cpp $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -c $< -o $@

$(LIBPREE): $(MODEL_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^


$(BUILD)/tests/%: tests/unit/%.c $(LIBPREE)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Itests/unit -DSCENES_DIR=\"$(CURDIR)/scenes\" -c $< -o $@.o
	$(CXX) $(LDFLAGS) $@.o $(LIBPREE) -o $@ $(LDLIBS) -lcmocka

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
