#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Controllers lint clean: verilator --lint-only -Wall, no waivers, for NumPreu 4/8/16 (and both
# EarlyReady settings of the dispatcher).
# level: quick
set -u
cd "$(dirname "$0")/../.."
if ! make -s ctrl-lint; then echo "FAIL; rerun: make ctrl-lint"; exit 1; fi
