#!/usr/bin/env bash
# Installs the Debian packages this project builds, tests and plots with.
# Safe to run again: apt-get skips what is already there.
#   scripts/install-deps.sh        what the default build needs
#   scripts/install-deps.sh mpi    that and OpenMPI, for the mpi preset (docs/mpi.md)
set -euo pipefail
pkgs=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libsundials-dev
  libopenblas0-pthread
  libcgal-dev coinor-libclp-dev zlib1g-dev
  catch2 nlohmann-json3-dev libcli11-dev libbenchmark-dev
  python3 python3-numpy python3-matplotlib
  python3-dev pybind11-dev python3-pybind11 python3-pytest
)
if [ "${1:-}" = mpi ]; then
  pkgs+=(openmpi-bin libopenmpi-dev)
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
