#!/usr/bin/env bash
# Times the scenes that must be fast (verification/hard-cases/README.md, "Moving scenes"):
# writes them with make_scenes.py --moving, runs each as one whole `dda run` process pinned
# to one core, and prints a table of simulated time, wall time, steps, cuts by reason,
# solves, the energy remainder and the hard-case checks; then the hard-case report.
#
#   bench/moving_scenes.sh OUT_DIR [--solver NAME] [--only NAME...] [--timeout S] [--cpu N]
#
#   --solver NAME  sets control.contact_solver to NAME in every scene ("open_close" or
#                  "newton"); a build that does not know the key rejects the scene (exit 2,
#                  its message in OUT_DIR/runs/NAME.log). Without it the scenes leave the
#                  key out and the build's default solver runs.
#   --only NAME... only these scenes (box150 hopper300 rockfall10 dominoes15 arch18
#                  wall1000 hang); default all.
#   --timeout S    seconds a run may take before it is stopped (default 1200); a stopped
#                  run shows exit 124 and the simulated time it reached (dda writes its
#                  summary on SIGTERM).
#   --cpu N        the core to pin the runs to (default 1).
#
# Env DDA_BUILD_DIR: the build directory (default build/release). OUT_DIR has the layout of
# verification/hard-cases/run.sh (scenes/, runs/NAME/, runs/status.tsv), so
# verification/hard-cases/report.py OUT_DIR judges it; the table is also in OUT_DIR/bench.md.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
usage() {
  echo "usage: $0 OUT_DIR [--solver NAME] [--only NAME...] [--timeout S] [--cpu N]" >&2
  exit 2
}
if [ $# -lt 1 ] || [ "${1#-}" != "$1" ]; then usage; fi
out="$1"
shift
solver=""
only=()
limit=1200
cpu=1
while [ $# -gt 0 ]; do
  case "$1" in
    --solver) [ $# -ge 2 ] || usage; solver="$2"; shift 2 ;;
    --timeout) [ $# -ge 2 ] || usage; limit="$2"; shift 2 ;;
    --cpu) [ $# -ge 2 ] || usage; cpu="$2"; shift 2 ;;
    --only)
      shift
      while [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; do only+=("$1"); shift; done
      [ ${#only[@]} -gt 0 ] || usage
      ;;
    *) usage ;;
  esac
done
case "$limit" in '' | *[!0-9]*) echo "$0: --timeout wants whole seconds, not '$limit'" >&2; exit 2 ;; esac
exe="${DDA_BUILD_DIR:-$root/build/release}/dda"
[ -x "$exe" ] || { echo "$0: $exe not found; build first (cmake --preset release && cmake --build --preset release)" >&2; exit 2; }
py=/usr/bin/python3  # Debian's: numpy and matplotlib for the report

mkdir -p "$out"
rm -rf "$out/scenes" "$out/runs"
"$py" "$root/verification/hard-cases/make_scenes.py" "$out" --moving "${only[@]}"
if [ -n "$solver" ]; then
  "$py" - "$out/scenes" "$solver" <<'PY'
import json, os, sys
scene_dir, solver = sys.argv[1:3]
for m in json.load(open(os.path.join(scene_dir, "manifest.json"))):
    path = os.path.join(scene_dir, m["name"] + ".json")
    scene = json.load(open(path))
    scene["control"]["contact_solver"] = solver
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")
PY
fi
mkdir -p "$out/runs"
status="$out/runs/status.tsv"  # name, exit code, wall time (s): read by report.py
: >"$status"
names=$("$py" -c 'import json, sys; print("\n".join(m["name"] for m in json.load(open(sys.argv[1]))))' \
  "$out/scenes/manifest.json")
for name in $names; do
  echo "$name: running (at most $limit s) ..." >&2
  start=$(date +%s.%N)
  rc=0
  # SIGTERM first (dda finishes its step and writes summary.json), SIGKILL 60 s later.
  timeout -k 60 "$limit" taskset -c "$cpu" "$exe" run "$out/scenes/$name.json" \
    --out "$out/runs/$name" >"$out/runs/$name.log" 2>&1 || rc=$?
  end=$(date +%s.%N)
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  printf '%s\t%s\t%s\n' "$name" "$rc" "$wall" >>"$status"
  echo "$name: exit $rc, $wall s" >&2
done
"$py" "$here/moving_scenes_table.py" "$out" "${solver:-default}" | tee "$out/bench.md"
"$py" "$root/verification/hard-cases/report.py" "$out" >/dev/null || true
echo "checks and energy plots: $out/report.md" >&2
