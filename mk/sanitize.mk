# SPDX-License-Identifier: Apache-2.0
# make test-sanitize (issue 14): the engine, the program and the unit tests built with
# AddressSanitizer and UndefinedBehaviorSanitizer in their own directory (build-san), then the
# unit tests and the bad-input checks run against them; any sanitizer report fails
# (scripts/test-sanitize.sh). .ci/run runs it after make test.
SAN_BUILD := build-san
SAN_UNITS := $(UNIT_SRC:tests/unit/%.c=$(SAN_BUILD)/tests/%)
.PHONY: test-sanitize

test-sanitize: $(DEPS_STAMP)
	@$(MAKE) --no-print-directory $(PARALLEL) BUILD=$(SAN_BUILD) SANITIZER=address,undefined \
	  $(SAN_BUILD)/pree $(SAN_UNITS)
	@scripts/test-sanitize.sh $(SAN_BUILD)
