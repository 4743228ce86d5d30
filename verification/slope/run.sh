#!/usr/bin/env bash
# The slope verification in one command: DDA strength reduction against the
# limit-equilibrium factors of Hoek & Bray's examples. Prints the report and leaves slope.csv,
# report.md, report.json, mechanism_*.json and mechanism_*.png in OUT_DIR.
#
#   verification/slope/run.sh OUT_DIR [--smoke] [--case NAME]... [--dynamic] [--verbose] [--spread]
#
# It builds nothing: it runs $DDA_BUILD_DIR/dda_verify_slope (default: build/release of this
# repository; build it first with `cmake --preset release && cmake --build --preset release`),
# then draws the PNGs with Debian's /usr/bin/python3 (matplotlib; the python3 on PATH may be
# another interpreter without it).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke] [--case NAME]... [--dynamic] [--verbose] [--spread]" "$@")" || exit 2
shift
exe="$(verification_program "$0" dda_verify_slope)" || exit 2
"$exe" --out "$out" "$@"
/usr/bin/python3 "$here/plot_slope.py" "$out"
