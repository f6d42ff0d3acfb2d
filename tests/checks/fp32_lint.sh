#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The binary32 units under verilator --lint-only -Wall (no file-wide waivers): any warning fails.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" lint-fp32
