#!/usr/bin/env bash
# Fresh machine to first results: installs what is missing, builds (release preset) and runs
# the built-in default scene into out/default (summary.json, history.csv, blocks.pvd).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target dda
./build/release/dda run --out out/default "$@"
