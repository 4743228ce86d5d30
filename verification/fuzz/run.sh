#!/usr/bin/env bash
# Mutation fuzzing of dda run, cut, material-point and fos with faults injected
# (verification/fuzz/README.md): fuzz.py mutates the repository's scenes, models and
# material-point specs (and a cut slope for dda fos), runs each mutant, sometimes under a
# file-size limit, SIGTERM or SIGINT, /dev/full or a regular file where a directory is
# wanted, and checks that nothing crashed, nothing exited without a message, no file under
# its final name is cut short, no run passed the memory limit and none hung.
#
#   verification/fuzz/run.sh OUT_DIR [--smoke] [--sanitized] [--seeds N] [--mutants M] [--first-seed S]
#
# Default: README.md's first campaign over again, 13 seeds of 250 mutants (3250 runs, about
# 70 s on two cores in the release build). --smoke: two seeds of 200 mutants (a few seconds;
# CI, also under the sanitizers). --sanitized: the program is an ASan/UBSan build (no
# address-space limit; a sanitizer report is a crash). OUT_DIR/report.md and report.json
# list every run; OUT_DIR/findings/ keeps each finding's input, command and stderr. Exit 1
# on any finding, 2 on bad use. It builds nothing: it runs $DDA_BUILD_DIR/dda (default
# build/release).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke] [--sanitized] [--seeds N] [--mutants M] [--first-seed S]" "$@")" || exit 2
shift
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --smoke) args+=(--seeds 2 --mutants 200) ;;
    --sanitized) args+=(--sanitized --timeout 60) ;;
    --seeds|--mutants|--first-seed)
      [ $# -ge 2 ] || { echo "$0: $1 needs a number" >&2; exit 2; }
      args+=("$1" "$2"); shift ;;
    *) echo "$0: unknown option $1 ([--smoke] [--sanitized] [--seeds N] [--mutants M] [--first-seed S])" >&2; exit 2 ;;
  esac
  shift
done
dda="$(verification_program "$0" dda)" || exit 2
mkdir -p "$out"
/usr/bin/python3 "$here/fuzz.py" --dda "$dda" --root "$root" --out "$out" "${args[@]}"
