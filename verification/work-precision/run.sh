#!/usr/bin/env bash
# Multi-block work-precision (README.md): writes the scenes, runs each with `dda run`
# (pinned to one core when taskset is there), then OUT_DIR/report.md.
#
#   verification/work-precision/run.sh OUT_DIR [--smoke]
#
# --smoke: two time steps at the scene's penalty (CI); with it the errors are also checked
# against their bounds (summarise.py --check: exit 1 beyond them).
# Runs $DDA_BUILD_DIR/dda (default build/release). Exit 1 if a run fails to write its
# summary, 2 on bad use.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke]" "$@")" || exit 2
shift
exe="$(verification_program "$0" dda)" || exit 2
py=/usr/bin/python3
check=()
for arg in "$@"; do
  case "$arg" in
    --smoke) check=(--check) ;;
    *) echo "$0: unknown option $arg (--smoke)" >&2; exit 2 ;;
  esac
done
rm -rf "$out/scenes" "$out/runs"
"$py" "$here/make_scenes.py" "$out" "$@"
pin=()
if command -v taskset >/dev/null 2>&1; then pin=(taskset -c 0); fi
status=0
for scene in "$out"/scenes/*.json; do
  name="$(basename "$scene" .json)"
  mkdir -p "$out/runs"
  "${pin[@]}" "$exe" run "$scene" --out "$out/runs/$name" >"$out/runs/$name.log" 2>&1 || true
  [ -f "$out/runs/$name/summary.json" ] || { echo "work-precision: $name wrote no summary" >&2; status=1; }
done
"$py" "$here/summarise.py" "$out" "${check[@]}" || status=1
exit $status
