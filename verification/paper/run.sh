#!/usr/bin/env bash
# The paper reproduction in one command: Jiang and Zheng (2015), Section 5, for
# every rotation treatment. Prints the report and leaves report.md, the CSVs and the PNGs
# in OUT_DIR.
#
#   verification/paper/run.sh OUT_DIR [--smoke]
#
# It builds nothing: it runs $DDA_BUILD_DIR/dda_verify_paper (default: build/release of this
# repository; build it first with `cmake --preset release && cmake --build --preset release`),
# then draws the PNGs with Debian's /usr/bin/python3 (numpy, matplotlib; the python3 on PATH
# may be another interpreter without them).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke]" "$@")" || exit 2
shift
exe="$(verification_program "$0" dda_verify_paper)" || exit 2
"$exe" --out "$out" "$@"
/usr/bin/python3 "$here/plot_paper.py" "$out"
