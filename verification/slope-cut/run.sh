#!/usr/bin/env bash
# Factor of safety of slopes cut by dda cut, over the time step and the penalty
# (docs/factor-of-safety.md): make_model.py writes a bedding slope whose planar factor is
# tan(40)/tan(35) = 1.1983 at any block size, dda cut cuts it, and dda fos runs on the scene as
# cut and with dt 0.002 / 0.05 s and the penalty auto / 10 and auto x 10. summarise.py
# writes OUT_DIR/report.md and report.json: each strength-reduction factor, its spread, the
# limit-analysis factor and the smallest single-block bound beside it; check.py then exits 1
# if a factor breaks a bound it must respect.
#
#   verification/slope-cut/run.sh OUT_DIR [--smoke] [--large]
#
# --smoke: the 173-block slope at its own settings only (about 20 s; CI).
# Default: the 173- and 654-block slopes, and three slopes of about 190 blocks with steep
# persistent cross joints (no cohesion; bedding cohesion 20 kPa without and with tensile
# strength), five settings each (about 40 min on 2 cores).
# --large: also the 1848-block slope (about an hour more).
# It builds nothing: it runs $DDA_BUILD_DIR/dda (default build/release).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source=../common/program.sh
source "$root/verification/common/program.sh"
out="$(verification_out_dir "$0" "[--smoke] [--large]" "$@")" || exit 2
shift
smoke=0
large=0
for arg in "$@"; do
  case "$arg" in
    --smoke) smoke=1 ;;
    --large) large=1 ;;
    *) echo "$0: unknown option $arg (--smoke, --large)" >&2; exit 2 ;;
  esac
done
dda="$(verification_program "$0" dda)" || exit 2
py=/usr/bin/python3
mkdir -p "$out"
# Each case: its directory name, the bedding spacing, and make_model.py's options.
cases=("spacing_1.6 1.6")
variants=(scene)
if [ "$smoke" -eq 0 ]; then
  cases+=("spacing_0.8 0.8"
          "steep_1.6 1.6 --steep"
          "steep_cohesive_1.6 1.6 --steep --cohesion 20000"
          "steep_bonded_1.6 1.6 --steep --cohesion 20000 --tension 20000")
  variants=(scene dt0.002 dt0.05 penalty_div10 penalty_x10)
fi
if [ "$large" -eq 1 ]; then cases+=("spacing_0.47 0.47"); fi
for c in "${cases[@]}"; do
  read -r name s options <<< "$c"
  case_dir="$out/$name"
  mkdir -p "$case_dir"
  # shellcheck disable=SC2086 # the options are words
  "$py" "$here/make_model.py" "$s" "$case_dir/model.json" $options
  "$dda" cut "$case_dir/model.json" --out "$case_dir/scene.json" 2> "$case_dir/cut.log"
  for v in "${variants[@]}"; do
    "$py" "$here/variant.py" "$case_dir/scene.json" "$v" "$case_dir/$v.json"
    echo "$name, $v" >&2
    status=0
    # The scene's own settings also run dynamic trials at 0.95 F and 1.05 F (--dynamic-check).
    check=()
    if [ "$v" = scene ]; then check=(--dynamic-check); fi
    # The steep slopes' factor is about 0.58: at the consolidation's full strength they
    # cannot stand, and trials would start from columns already toppling. They consolidate
    # at double strength (docs/factor-of-safety.md, section 1), from which trials start at rest.
    case "$name" in steep_*) check+=(--consolidation-factor 0.5) ;; esac
    "$dda" fos "$case_dir/$v.json" --out "$case_dir/fos_$v" "${check[@]}" 2> "$case_dir/fos_$v.log" || status=$?
    echo "$status" > "$case_dir/fos_$v.exit"
    tail -n 1 "$case_dir/fos_$v.log" >&2
  done
done
"$py" "$here/summarise.py" "$out"
"$py" "$here/check.py" "$out"
