#!/usr/bin/env bash
# Times dda cut then dda fos on a ~2000-block jointed slope
# (models/slope-fos.json), on both cores. Prints the cut's and the search's wall times and
# the factor with its bracket; leaves the scene, the report and the pictures in OUT_DIR.
#
#   bench/cut_then_fos.sh OUT_DIR     (env DDA_BUILD_DIR: default build/release)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
if [ $# -ne 1 ]; then
  echo "usage: $0 OUT_DIR" >&2
  exit 2
fi
out="$1"
exe="${DDA_BUILD_DIR:-$root/build/release}/dda"
[ -x "$exe" ] || { echo "$0: $exe not found; build first (cmake --preset release && cmake --build --preset release)" >&2; exit 2; }
mkdir -p "$out"
t0=$(date +%s.%N)
"$exe" cut "$root/models/slope-fos.json" --out "$out/slope-fos-scene.json"
t1=$(date +%s.%N)
"$exe" fos "$out/slope-fos-scene.json" --out "$out/fos"
t2=$(date +%s.%N)
python3 - "$out/fos/report.json" "$t0" "$t1" "$t2" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
t0, t1, t2 = map(float, sys.argv[2:5])
print(f"cut: {t1 - t0:.1f} s; fos: {t2 - t1:.1f} s "
      f"(consolidation {r['consolidation']['wall_time_s']:.1f} s, {len(r['trials'])} trials); "
      f"F = {r['factor_of_safety']:.3f} in [{r['bracket'][0]:.4f}, {r['bracket'][1]:.4f}]")
la = r.get("limit_analysis")
if la is not None:
    print(f"limit analysis beside it: F = {la['factor']}, {la['programs']} programs, "
          f"{la['wall_time_s']:.1f} s")
PY
