#!/usr/bin/env bash
# Times the scenes that must be fast (verification/hard-cases/README.md, "Moving scenes"):
# writes them with make_scenes.py --moving, runs each as one whole `dda run` process pinned
# to one core, and prints a table of simulated time, wall time, steps, cuts by reason,
# solves, the energy remainder and the hard-case checks; then the hard-case report.
#
#   bench/moving_scenes.sh OUT_DIR [--solver NAME] [--only NAME...] [--small] [--timeout S]
#                          [--cpu N] [--fos]
#
#   --solver NAME  sets control.contact_solver to NAME in every scene ("open_close" or
#                  "newton"); a build that does not know the key rejects the scene (exit 2,
#                  its message in OUT_DIR/runs/NAME.log). Without it the scenes leave the
#                  key out and the build's default solver runs.
#   --only NAME... only these scenes (box150 hopper300 rockfall10 dominoes15 arch18
#                  wall1000 hang); default all.
#   --small        the small versions instead (make_scenes.py --moving-small: hopper40,
#                  rockfall3, dominoes15, arch18, wall110, hang); not with --only.
#   --timeout S    seconds a run may take before it is stopped (default 1200); a stopped
#                  run shows exit 124 and the simulated time it reached (dda writes its
#                  summary on SIGTERM).
#   --cpu N        the core to pin the runs to (default 1).
#   --fos          also cut models/slope-fos.json (1965 rigid blocks) and run `dda fos` on it,
#                  as bench/cut_then_fos.sh does (on both cores, unpinned: fos runs two
#                  trials at a time), with --solver's key in the scene, into OUT_DIR/fos;
#                  prints each trial's F, verdict, steps and wall time. It is a bench only,
#                  not a hard case (no energy check of its own).
#
# Env DDA_BUILD_DIR: the build directory (default build/release). OUT_DIR has the layout of
# verification/hard-cases/run.sh (scenes/, runs/NAME/, runs/status.tsv), so
# verification/hard-cases/report.py OUT_DIR judges it; the table is also in OUT_DIR/bench.md.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
usage() {
  echo "usage: $0 OUT_DIR [--solver NAME] [--only NAME... | --small] [--timeout S] [--cpu N] [--fos]" >&2
  exit 2
}
if [ $# -lt 1 ] || [ "${1#-}" != "$1" ]; then usage; fi
out="$1"
shift
solver=""
only=()
limit=1200
cpu=1
fos=0
small=0
while [ $# -gt 0 ]; do
  case "$1" in
    --solver) [ $# -ge 2 ] || usage; solver="$2"; shift 2 ;;
    --timeout) [ $# -ge 2 ] || usage; limit="$2"; shift 2 ;;
    --cpu) [ $# -ge 2 ] || usage; cpu="$2"; shift 2 ;;
    --fos) fos=1; shift ;;
    --small) small=1; shift ;;
    --only)
      shift
      while [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; do only+=("$1"); shift; done
      [ ${#only[@]} -gt 0 ] || usage
      ;;
    *) usage ;;
  esac
done
if [ "$small" = 1 ] && [ ${#only[@]} -gt 0 ]; then usage; fi
case "$limit" in '' | *[!0-9]*) echo "$0: --timeout wants whole seconds, not '$limit'" >&2; exit 2 ;; esac
exe="${DDA_BUILD_DIR:-$root/build/release}/dda"
[ -x "$exe" ] || { echo "$0: $exe not found; build first (cmake --preset release && cmake --build --preset release)" >&2; exit 2; }
py=/usr/bin/python3  # Debian's: numpy and matplotlib for the report

mkdir -p "$out"
rm -rf "$out/scenes" "$out/runs"
if [ "$small" = 1 ]; then
  "$py" "$root/verification/hard-cases/make_scenes.py" "$out" --moving-small
else
  "$py" "$root/verification/hard-cases/make_scenes.py" "$out" --moving "${only[@]}"
fi
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
: >"$out/runs/cpu.tsv"  # name, CPU seconds (user + system)
names=$("$py" -c 'import json, sys; print("\n".join(m["name"] for m in json.load(open(sys.argv[1]))))' \
  "$out/scenes/manifest.json")
for name in $names; do
  echo "$name: running (at most $limit s) ..." >&2
  start=$(date +%s.%N)
  rc=0
  # SIGTERM first (dda finishes its step and writes summary.json), SIGKILL 60 s later.
  # bash's `time` gives the CPU seconds of the run (user and system): on a core shared with
  # other work they stay what the run needs while its wall time grows.
  TIMEFORMAT='%U %S'
  { time timeout -k 60 "$limit" taskset -c "$cpu" "$exe" run "$out/scenes/$name.json" \
      --out "$out/runs/$name" >"$out/runs/$name.log" 2>&1; } 2>"$out/runs/$name.time" || rc=$?
  end=$(date +%s.%N)
  wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  cpu_s=$(awk '{ printf "%.2f", $1 + $2 }' "$out/runs/$name.time")
  printf '%s\t%s\t%s\n' "$name" "$rc" "$wall" >>"$status"
  printf '%s\t%s\n' "$name" "$cpu_s" >>"$out/runs/cpu.tsv"
  echo "$name: exit $rc, $wall s ($cpu_s s CPU)" >&2
done
"$py" "$here/moving_scenes_table.py" "$out" "${solver:-default}" | tee "$out/bench.md"
"$py" "$root/verification/hard-cases/report.py" "$out" >/dev/null || true
echo "checks and energy plots: $out/report.md" >&2

if [ "$fos" = 1 ]; then
  rm -rf "$out/fos"
  mkdir -p "$out/fos"
  scene="$out/fos/slope-fos-scene.json"
  "$exe" cut "$root/models/slope-fos.json" --out "$scene" >"$out/fos/cut.log" 2>&1
  if [ -n "$solver" ]; then
    "$py" -c 'import json, sys
p, solver = sys.argv[1:3]
s = json.load(open(p)); s["control"]["contact_solver"] = solver
json.dump(s, open(p, "w"), indent=1)' "$scene" "$solver"
  fi
  echo "fos: running (at most $limit s) ..." >&2
  start=$(date +%s.%N)
  rc=0
  timeout -k 60 "$limit" "$exe" fos "$scene" --out "$out/fos/run" >"$out/fos/fos.log" 2>&1 || rc=$?
  end=$(date +%s.%N)
  "$py" - "$out/fos/run/report.json" "$rc" "$start" "$end" <<'PY' | tee -a "$out/bench.md"
import json, os, sys
path, rc, t0, t1 = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
print(f"\ndda fos on models/slope-fos.json: exit {rc}, {t1 - t0:.1f} s in all")
if not os.path.exists(path):
    # Stopped before the search ended: the trials it finished are in its log.
    log = os.path.join(os.path.dirname(os.path.dirname(path)), "fos.log")
    print("no report; the trials it finished (fos/fos.log):\n")
    with open(log, errors="replace") as f:
        print("".join(ln for ln in f if ln.startswith("dda: trial ")), end="")
    sys.exit(0)
r = json.load(open(path))
print(f"consolidation {r['consolidation']['wall_time_s']:.1f} s; F = {r.get('factor_of_safety')} "
      f"in {r.get('bracket')}\n")
print("| F | verdict | steps | simulated (s) | wall (s) |\n|---:|---|---:|---:|---:|")
for t in r["trials"]:
    verdict = ("stable, " if t["stable"] else "failing, ") + t["verdict"]
    print(f"| {t['F']:.4f} | {verdict} | {t['steps']} | {t['simulated_time']:.3g} "
          f"| {t['wall_time_s']:.1f} |")
walls = {v: [t["wall_time_s"] for t in r["trials"] if t["stable"] == v] for v in (True, False)}
if walls[True] and walls[False]:
    print(f"\nslowest failing trial {max(walls[False]):.1f} s, slowest stable one "
          f"{max(walls[True]):.1f} s")
PY
fi
