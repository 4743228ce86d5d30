#!/usr/bin/env bash
# Fresh machine to a tested build: installs what is missing, builds the given preset
# (release by default; also debug or asan) and runs the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
./scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
# A build that registered no test must fail, not pass with nothing run.
ctest --preset "$preset" --no-tests=error
