#!/usr/bin/env bash
# Fresh machine to a tested build: installs what is missing, builds the given preset
# (release by default; also debug or asan) and runs the whole test suite with ctest.
# `mpi`: installs OpenMPI as well, builds the MPI-enabled dda alone and runs the tests
# labelled mpi (two ranks each, against the one-process runs; docs/mpi.md).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
if [ "$preset" = mpi ]; then
  ./scripts/install-deps.sh mpi
  cmake --preset mpi >/dev/null
  cmake --build --preset mpi --target dda
  # CI machines run as root, which OpenMPI refuses unless told.
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  ctest --preset mpi --no-tests=error
  exit 0
fi
./scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
# A build that registered no test must fail, not pass with nothing run.
ctest --preset "$preset" --no-tests=error
