# SPDX-License-Identifier: Apache-2.0
# Fuzzing (issue 14): libFuzzer harnesses (clang-14, libclang-rt-14-dev) for the scene parser, the pbrt-v4 reader
# and the mesh loader, built with AddressSanitizer and UndefinedBehaviorSanitizer from the
# scene sources alone (no OpenMP, Embree or OpenImageIO in the harness).
#   make fuzz [FUZZ_TIME=600]  each harness FUZZ_TIME seconds on a working corpus in
#                              build/fuzz/corpus-NAME (seeded from tests/fuzz/corpus/NAME);
#                              a crash is saved as build/fuzz/crash-NAME-* and fails the target
# The short run inside make test: tests/checks/fuzz_short.sh (20 s a harness).
FUZZ_CC    ?= clang-14
FUZZ_DIR   := $(BUILD)/fuzz
FUZZ_NAMES := scene mesh pbrt
FUZZ_BINS  := $(FUZZ_NAMES:%=$(FUZZ_DIR)/fuzz_%)
FUZZ_SRC   := $(wildcard model/scene/*.c) model/util/file_in.c model/util/text_escape.c
FUZZ_FLAGS := -std=c11 -D_GNU_SOURCE -g -O1 -fsanitize=fuzzer,address,undefined \
              -fno-sanitize-recover=undefined -fno-omit-frame-pointer $(MODEL_INC) -Itests/fuzz
FUZZ_TIME  ?= 600
.PHONY: fuzz fuzz-build

$(FUZZ_DIR)/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_file.h $(FUZZ_SRC) $(wildcard model/scene/*.h) | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(call say,LINK,$@)$(FUZZ_CC) $(FUZZ_FLAGS) $< $(FUZZ_SRC) -o $@ -lassimp -lz -lm

TEST_PREREQS += $(FUZZ_BINS)

fuzz-build: $(FUZZ_BINS)
fuzz: $(FUZZ_BINS)
	@for n in $(FUZZ_NAMES); do \
	  mkdir -p $(FUZZ_DIR)/corpus-$$n && cp -n tests/fuzz/corpus/$$n/* $(FUZZ_DIR)/corpus-$$n/ && \
	  echo "fuzz: $$n for $(FUZZ_TIME) s" && \
	  (cd $(FUZZ_DIR) && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 ./fuzz_$$n -max_total_time=$(FUZZ_TIME) -timeout=10 -rss_limit_mb=2048 \
	     -print_final_stats=1 -artifact_prefix=crash-$$n- corpus-$$n 2>&1 | tee fuzz-$$n.log | \
	     grep -E '^(#[0-9]+.*(pulse|DONE)|stat::|==[0-9]+==ERROR|SUMMARY)') || exit 1; \
	  grep -q '^stat::number_of_executed_units' $(FUZZ_DIR)/fuzz-$$n.log || exit 1; \
	done
