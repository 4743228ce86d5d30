#!/usr/bin/env bash
# Runs a fixed set of scenes and studies with one build and keeps what they write, so that a
# change meant to keep every result (a refactor) can be checked bit for bit against the
# build before it:
#
#   scripts/same-results.sh BUILD_DIR OUT_DIR           # e.g. the build of main, then of the change
#   /usr/bin/python3 scripts/compare_results.py OUT_A OUT_B
#
# The set: every scene of scenes/, the hard cases (the default set: statics, dynamics,
# plastic and concave blocks), the small moving scenes, box150 to 0.5 s, the paper
# reproduction's smoke run, the slope mechanisms' smoke run (factors of safety), the
# footing's smoke run, and `dda cut` then `dda fos` of models/small-slope.json. About ten
# minutes on one core. Times, dates and paths differ between two runs; compare_results.py
# leaves those out and compares every other number as text.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 BUILD_DIR OUT_DIR" >&2
  exit 2
fi
build="$(cd "$1" && pwd)"
out="$2"
root="$(cd "$(dirname "$0")/.." && pwd)"
py=/usr/bin/python3
rm -rf "$out"
mkdir -p "$out/scenes" "$out/hard" "$out/moving"
printf '%s\n' "$root" >"$out/repository.txt"  # read by compare_results.py: two worktrees differ in it
for scene in "$root"/scenes/*.json; do
  name="$(basename "$scene" .json)"
  "$build/dda" run "$scene" --out "$out/scenes/$name" >"$out/scenes/$name.log" 2>&1 || echo "exit $?" >>"$out/scenes/$name.log"
done
"$py" "$root/verification/hard-cases/make_scenes.py" "$out/hard/in" >/dev/null
"$py" "$root/verification/hard-cases/make_scenes.py" "$out/moving/in" --moving-small >/dev/null
"$py" "$root/verification/hard-cases/make_scenes.py" "$out/moving/box" --moving box150 >/dev/null
"$py" - "$out/moving/box/scenes/box150.json" <<'PY'
import json, sys
path = sys.argv[1]
scene = json.load(open(path))
scene["control"]["end_time"] = 0.5
json.dump(scene, open(path, "w"), indent=1)
PY
for set in hard/in moving/in moving/box; do
  for scene in "$out/$set"/scenes/*.json; do
    [ "$(basename "$scene")" = manifest.json ] && continue
    name="$(basename "$scene" .json)"
    dest="$out/$set/../runs/$name"
    mkdir -p "$out/$set/../runs"
    timeout 900 "$build/dda" run "$scene" --out "$dest" >"$dest.log" 2>&1 || echo "exit $?" >>"$dest.log"
  done
done
"$build/dda_verify_paper" --smoke --out "$out/paper" >/dev/null 2>&1 || echo "paper: exit $?" >>"$out/studies.log"
"$build/dda_verify_slope" --smoke --out "$out/slope" >/dev/null 2>&1 || echo "slope: exit $?" >>"$out/studies.log"
"$build/dda_verify_footing" --smoke --out "$out/footing" >/dev/null 2>&1 || echo "footing: exit $?" >>"$out/studies.log"
mkdir -p "$out/fos"
"$build/dda" cut "$root/models/small-slope.json" --out "$out/fos/scene.json" >"$out/fos/cut.log" 2>&1 || echo "exit $?" >>"$out/fos/cut.log"
"$build/dda" fos "$out/fos/scene.json" --out "$out/fos/run" --jobs 1 >"$out/fos/fos.log" 2>&1 || echo "exit $?" >>"$out/fos/fos.log"
echo "$out: done"
