#!/usr/bin/env bash
# The iso-error maps of the material library in one command (docs/closed-forms.md,
# "Tangents and convergence"). Prints the report and leaves report.md, the CSVs, the PNGs and
# projection_check.md in OUT_DIR.
#
#   verification/constitutive/run.sh OUT_DIR [--smoke]
#
# It builds nothing: it runs $DDA_BUILD_DIR/dda_verify_constitutive (default: build/release of
# this repository; build it first with `cmake --preset release && cmake --build --preset
# release`), then draws the PNGs and runs the independent check of every map with Debian's
# /usr/bin/python3 (numpy, matplotlib; the python3 on PATH may be another interpreter without
# them).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke]" "$@")" || exit 2
shift
exe="$(verification_program "$0" dda_verify_constitutive)" || exit 2
"$exe" --out "$out" "$@"
/usr/bin/python3 "$here/plot_constitutive.py" "$out"
/usr/bin/python3 "$here/check_projection.py" "$out"
