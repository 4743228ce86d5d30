#!/usr/bin/env bash
# Blocks that strain a lot under the default rotation treatment (see
# verification/large-strain/README.md): make_scenes.py writes the scenes (soft elastic
# blocks, a soft/stiff stack, Mohr-Coulomb blocks dropped, one without a tension cut-off,
# two elastic controls, Mohr-Coulomb blocks thrown at a wall and crushed, static runs), `dda run` runs each under finite_rotation_polar (the default) and
# finite_rotation, and summarise.py writes OUT_DIR/report.md and report.json and exits 1
# if the default fails a check (its runs reach their end with the energy remainder within
# tolerance; the block without a tension cut-off stops with a message naming it and why).
#
#   verification/large-strain/run.sh OUT_DIR [--smoke]
#
# --smoke: the default treatment only (13 runs, about 1.5 s in the release build; CI).
# Default: both treatments, and where finite_rotation stopped early, the default again up
# to the step where it stopped, so that their solves are counted over the same steps
# (about 3 s). Runs are pinned to core 0 when taskset is there; CPU times are the runs'
# own (bash's `time`: user + sys). It builds nothing: it runs $DDA_BUILD_DIR/dda (default
# build/release). Exit 1 if the default fails a check or a run wrote no summary, 2 on bad
# use.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke]" "$@")" || exit 2
shift
smoke=()
for arg in "$@"; do
  case "$arg" in
    --smoke) smoke=(--smoke) ;;
    *) echo "$0: unknown option $arg (--smoke)" >&2; exit 2 ;;
  esac
done
dda="$(verification_program "$0" dda)" || exit 2
py=/usr/bin/python3
mkdir -p "$out"
rm -rf "$out/scenes" "$out/runs" "$out/truncated"
rm -f "$out/status.tsv" "$out/status.tsv.part" "$out/report.md" "$out/report.json"
"$py" "$here/make_scenes.py" "$out" "${smoke[@]}"
pin=()
if command -v taskset >/dev/null 2>&1; then pin=(taskset -c 0); fi
mkdir -p "$out/runs"

# run_one SCENE RUN_DIR: runs it, appends "name rc user sys" to status.tsv.part.
run_one() {
  local scene="$1" dir="$2" name rc cpu
  name="$(basename "$dir")"
  local TIMEFORMAT='%U %S'
  set +e
  cpu="$( { time "${pin[@]}" "$dda" run "$scene" --out "$dir" > "$dir.log" 2>&1; } 2>&1 )"
  rc=$?
  set -e
  # `time` reports after the run; rc is the run's own status.
  printf '%s\t%s\t%s\n' "$name" "$rc" "$cpu" | tr ' ' '\t' >> "$out/status.tsv.part"
  echo "$name: exit $rc"
}

for scene in "$out"/scenes/*.json; do
  name="$(basename "$scene" .json)"
  run_one "$scene" "$out/runs/$name"
done

# Where finite_rotation stopped early, the default up to the same step: it must need
# no more solves than finite_rotation, and a run that stopped at step 33 cannot be compared
# with one of 3000 steps by their totals.
if [ ${#smoke[@]} -eq 0 ]; then
  mkdir -p "$out/truncated"
  while IFS=$'\t' read -r name steps; do
    src="$out/scenes/${name}_finite_rotation_polar.json"
    dst="$out/truncated/${name}_finite_rotation_polar_to${steps}.json"
    "$py" - "$src" "$dst" "$steps" <<'EOF'
import json, os, sys
src, dst, steps = sys.argv[1], sys.argv[2], int(sys.argv[3])
with open(src) as f:
    scene = json.load(f)
scene["control"].pop("end_time", None)
scene["control"]["steps"] = steps
with open(dst + ".part", "w") as f:
    json.dump(scene, f, indent=1)
os.replace(dst + ".part", dst)
EOF
    run_one "$dst" "$out/runs/$(basename "$dst" .json)"
  done < <("$py" - "$out" <<'EOF'
import json, os, sys
out = sys.argv[1]
with open(os.path.join(out, "manifest.json")) as f:
    manifest = json.load(f)
def summary(file):
    try:
        with open(os.path.join(out, "runs", file, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None
for m in manifest:
    if m["treatment"] != "finite_rotation":
        continue
    fr, polar = summary(m["file"]), summary(m["name"] + "_finite_rotation_polar")
    if fr and polar and fr["diverged"] and not polar["diverged"]:
        print(f"{m['name']}\t{fr['steps']}")
EOF
)
fi
mv "$out/status.tsv.part" "$out/status.tsv"
"$py" "$here/summarise.py" "$out"
