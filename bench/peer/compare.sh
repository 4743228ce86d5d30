#!/bin/bash
# Side-by-side runs of ntdda and this project's dda on the same scenes
# (docs/peer-comparison.md).
#
#   NTDDA_DRIVER=/path/to/ntdda_run bench/peer/compare.sh SCENE.json...
#
# For each scene: converts it to ntdda's input (scene_to_ntdda.py), then runs ntdda's driver
# and `dda run` RUNS times each, interleaved (ntdda, ours, ntdda, ours, ...), every run
# pinned to one core (taskset -c $CPU), and prints a table of the fastest run of each (whole
# process, wall clock; its CPU time beside) with its steps and iterations. ntdda is not part of this repository:
# NTDDA_DRIVER is a driver built outside it (see the doc); it is called as
#   $NTDDA_DRIVER GEO ANA ROOT
# in a scratch directory, under a file-size limit (ulimit -f), and prints one JSON line.
#
# Environment (all optional but NTDDA_DRIVER):
#   NTDDA_DRIVER   the driver; unset or empty: ours only
#   DDA            our binary (default: build/release/dda of this checkout)
#   RUNS           runs of each program per scene (default 3)
#   CPU            the core to pin to (default 1)
#   OUT            working directory (default: a new directory under /tmp)
#   TIMEOUT        seconds a run may take (default 3600)
#   FSIZE_KB       ntdda's file-size limit, KiB (default 4000000: its log can grow without end)
#   NTDDA_G2       ntdda variants, by its maximum displacement ratio g2 (scene_to_ntdda.py
#                  --g2): a space-separated list, each run as a row of its own (default
#                  "metres": the same step limit in metres as ours; "ratio": the scene's
#                  ratio as g2, Shi's usual use; see the doc)
#   CONVERT_ARGS   extra arguments for scene_to_ntdda.py (e.g. "--oc-limit 99")
# Results: $OUT/results.json (every run) and the table on stdout (markdown).
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
PY=/usr/bin/python3
DDA=${DDA:-$ROOT/build/release/dda}
RUNS=${RUNS:-3}
CPU=${CPU:-1}
TIMEOUT=${TIMEOUT:-3600}
FSIZE_KB=${FSIZE_KB:-4000000}
CONVERT_ARGS=${CONVERT_ARGS:-}
NTDDA_G2=${NTDDA_G2:-metres}
NTDDA_DRIVER=${NTDDA_DRIVER:-}
OUT=${OUT:-$(mktemp -d /tmp/peer-compare.XXXXXX)}
mkdir -p "$OUT"
[ $# -ge 1 ] || { echo "usage: NTDDA_DRIVER=... $0 SCENE.json..." >&2; exit 2; }
[ -x "$DDA" ] || { echo "compare.sh: no dda binary at $DDA (set DDA)" >&2; exit 2; }
if [ -n "$NTDDA_DRIVER" ] && [ ! -x "$NTDDA_DRIVER" ]; then
  echo "compare.sh: NTDDA_DRIVER=$NTDDA_DRIVER is not executable" >&2; exit 2
fi

# Each scene's runs are kept under its file's name: two scenes of one name (the wall1000 of
# make_scenes.py --moving and that of peer_scenes.py) would overwrite each other's results.
names=$(for scene in "$@"; do basename "$scene" .json; done | sort | uniq -d)
if [ -n "$names" ]; then
  echo "compare.sh: two scenes share the name $(echo $names | tr '\n' ' ')(one call per name, or rename one)" >&2
  exit 2
fi

now() { date +%s.%N; }
elapsed() { printf "%.6f" "$(echo "$2 - $1" | bc)"; }
# user + system CPU seconds from /usr/bin/time's "%U %S" (the last line: it may add a note)
cpu() { tail -n 1 "$1" 2>/dev/null | awk '{ if (NF == 2) printf "%.3f", $1 + $2; else print "null" }'; }
RESULTS=$OUT/runs.jsonl
: > "$RESULTS"

for scene in "$@"; do
  name=$(basename "$scene" .json)
  dir=$OUT/$name
  mkdir -p "$dir/ours"
  scene_abs=$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")
  variants=()
  if [ -n "$NTDDA_DRIVER" ]; then
    for g2 in $NTDDA_G2; do
      mkdir -p "$dir/ntdda-$g2"
      # shellcheck disable=SC2086
      if conv=$($PY "$HERE/scene_to_ntdda.py" "$scene_abs" "$dir/ntdda-$g2/$name" --g2 "$g2" \
                $CONVERT_ARGS); then
        echo "$conv" > "$dir/ntdda-$g2/convert.json"
        variants+=("$g2")
      else
        echo "compare.sh: $name: cannot convert for ntdda" >&2
      fi
    done
  fi
  for ((i = 1; i <= RUNS; i++)); do
    for g2 in "${variants[@]}"; do
      t0=$(now)
      line=$(set -o pipefail; cd "$dir/ntdda-$g2" && rm -rf output cut.log pnp.log massmat.m &&
             ulimit -f "$FSIZE_KB" &&
             /usr/bin/time -f "%U %S" -o cpu.txt \
               timeout "$TIMEOUT" taskset -c "$CPU" "$NTDDA_DRIVER" "$name.geo" "$name.ana" "$name" \
               2> "$name.stderr" | tail -n 1)
      rc=$?
      t1=$(now)
      [ -n "$line" ] || line='{}'
      echo "{\"scene\": \"$name\", \"program\": \"ntdda g2 $g2\", \"run\": $i, \"rc\": $rc," \
           "\"wall_s\": $(elapsed "$t0" "$t1"), \"cpu_s\": $(cpu "$dir/ntdda-$g2/cpu.txt")," \
           "\"convert\": $(cat "$dir/ntdda-$g2/convert.json")," \
           "\"out\": $line}" >> "$RESULTS"
      printf '%s ntdda (g2 %s) run %d: %.3f s\n' "$name" "$g2" "$i" "$(elapsed "$t0" "$t1")" >&2
    done
    t0=$(now)
    /usr/bin/time -f "%U %S" -o "$dir/ours.cpu.txt" \
      timeout "$TIMEOUT" taskset -c "$CPU" "$DDA" run "$scene_abs" --out "$dir/ours" \
      > "$dir/ours.stdout" 2> "$dir/ours.stderr"
    rc=$?
    t1=$(now)
    # keep the summary of every run (the next run overwrites the directory)
    cp "$dir/ours/summary.json" "$dir/ours.summary.$i.json" 2>/dev/null
    echo "{\"scene\": \"$name\", \"program\": \"ours\", \"run\": $i, \"rc\": $rc," \
         "\"wall_s\": $(elapsed "$t0" "$t1"), \"cpu_s\": $(cpu "$dir/ours.cpu.txt")," \
         "\"summary\": \"$dir/ours.summary.$i.json\"," \
         "\"scene_file\": \"$scene_abs\"}" >> "$RESULTS"
    printf '%s ours run %d: %.3f s\n' "$name" "$i" "$(elapsed "$t0" "$t1")" >&2
  done
done

$PY "$HERE/compare_table.py" "$RESULTS" "$OUT/results.json"
echo "(runs and outputs in $OUT)" >&2
