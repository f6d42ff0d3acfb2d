#!/usr/bin/env bash
# Install the Debian packages PREE needs, only those missing; silent when all are present.
set -euo pipefail
pkgs=(build-essential pkg-config libembree-dev libopenimageio-dev libcmocka-dev
      libassimp-dev verilator iverilog yosys gtkwave gnuplot-nox zlib1g-dev python3 bc valgrind)
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
