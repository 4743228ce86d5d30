#!/usr/bin/env bash
# The hard-case suite in one command: writes the scenes, runs each with
# `dda run`, timing it, then writes OUT_DIR/report.md and one PNG per case, and prints the
# report. Exits 1 if any run fails its checks (everything is still written), 2 on bad use.
#
#   verification/hard-cases/run.sh OUT_DIR [--smoke | --moving | --moving-small | --arches]
#
# --moving runs the scenes that must be fast (README.md, "Moving scenes"; the hopper alone
# takes over an hour today), --moving-small smaller versions of them (seconds each),
# --arches the static arches below and above the thrust-line limit; none of them is part of
# the default runs. Env HARD_CASES_LIMIT: the seconds a run may take before it is stopped
# (default 1800, 120 with --smoke).
#
# It builds nothing: it runs $DDA_BUILD_DIR/dda (default: build/release of this repository;
# build it first with `cmake --preset release && cmake --build --preset release`), and
# Debian's /usr/bin/python3 (numpy, matplotlib; the python3 on PATH may lack them).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
usage() {
  echo "usage: $0 OUT_DIR [--smoke | --moving | --moving-small | --arches]   (env DDA_BUILD_DIR: the build directory, default build/release)" >&2
  exit 2
}
if [ $# -lt 1 ] || [ "${1#-}" != "$1" ]; then usage; fi
out="$1"
shift
flags=()
limit=1800  # s per run: a run that hangs must not hang the suite (reported as exit 124)
if [ $# -gt 1 ]; then usage; fi
for arg in "$@"; do
  case "$arg" in
    --smoke) flags=(--smoke); limit=120 ;;
    --moving | --moving-small | --arches) flags=("$arg") ;;
    *) usage ;;
  esac
done
limit="${HARD_CASES_LIMIT:-$limit}"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
exe="$(verification_program "$0" dda)" || exit 2
py=/usr/bin/python3

# A fresh set each time: runs left over from another set would enter the report.
mkdir -p "$out"
rm -rf "$out/scenes" "$out/runs"
"$py" "$here/make_scenes.py" "$out" "${flags[@]}"
mkdir -p "$out/runs"
status="$out/runs/status.tsv"  # name, exit code, wall time (s): read by report.py
: >"$status"
names=$("$py" -c 'import json, sys; print("\n".join(m["name"] for m in json.load(open(sys.argv[1]))))' \
  "$out/scenes/manifest.json")
for name in $names; do
  start=$(date +%s.%N)
  rc=0
  timeout "$limit" "$exe" run "$out/scenes/$name.json" --out "$out/runs/$name" \
    >"$out/runs/$name.log" 2>&1 || rc=$?
  end=$(date +%s.%N)
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  printf '%s\t%s\t%s\n' "$name" "$rc" "$wall" >>"$status"
  echo "$name: exit $rc, $wall s" >&2
done
"$py" "$here/report.py" "$out"
