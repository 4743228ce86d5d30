#!/usr/bin/env bash
# The footing verification in one command: a smooth rigid strip footing
# pressed into a weightless Tresca layer of plastic blocks, against Prandtl's (2 + pi) c,
# with its refinement study (cell size, load step) and cost. Prints the report and leaves
# curves.csv, runs.csv, zone_*.csv, report.md and the PNGs (curves.png, limit.png,
# zone_*.png) in OUT_DIR.
#
#   verification/footing/run.sh OUT_DIR [--smoke] [dda_verify_footing options]
#
# The full study takes about 30 min of CPU (most of it the finest mesh,
# 8192 blocks); --smoke runs the coarsest mesh only (a few seconds). It builds nothing: it
# runs $DDA_BUILD_DIR/dda_verify_footing (default: build/release of this repository; build
# it with `cmake --build --preset release --target dda_verify_footing`), then draws the
# PNGs with Debian's /usr/bin/python3 (matplotlib).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke] [--cells H,...] [--steps N,...] [--mesh crossed|diagonal|uniform|both|all] [--phi DEG] [--penalty F] [--jobs N]" "$@")" || exit 2
shift
exe="$(verification_program "$0" dda_verify_footing)" || exit 2
"$exe" --out "$out" "$@"
/usr/bin/python3 "$here/plot_footing.py" "$out"
