#!/usr/bin/env bash
# Strong scaling of the probabilistic factor of safety over MPI ranks (docs/mpi.md,
# "Scaling"): the 1965-block slope of models/slope-fos.json with its bedding's friction
# angle drawn from N(30, 2) degrees (truncated to 20 to 40), SAMPLES samples judged at
# F = 1, on 1, 2 and 4 ranks (one thread each), and a table: wall time, cost per sample,
# parallel efficiency against one rank, and an estimate for a 64-core node.
#
#   bench/fos_scaling.sh OUT_DIR [SAMPLES] [RANKS...]   (defaults: 100 samples; 1 2 4 ranks)
#   env DDA_MPI_BUILD_DIR: default build/mpi (cmake --preset mpi && cmake --build --preset mpi)
#   env DDA_SCALING_MODEL: default models/slope-fos.json (a model with a joint material
#     "bedding"; models/small-slope.json tries the script out in a minute)
#
# Each rank consolidates the slope itself (a few seconds, the serial part), then runs every
# R-th sample. Ranks beyond the machine's cores share them (mpirun --oversubscribe): their
# figures then measure the sharing, not the scaling, and the table says so.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
if [ $# -lt 1 ]; then
  echo "usage: $0 OUT_DIR [SAMPLES] [RANKS...]" >&2
  exit 2
fi
out="$1"
samples="${2:-100}"
shift $(( $# >= 2 ? 2 : 1 ))
ranks_list=("$@")
[ ${#ranks_list[@]} -gt 0 ] || ranks_list=(1 2 4)
exe="${DDA_MPI_BUILD_DIR:-$root/build/mpi}/dda"
[ -x "$exe" ] || { echo "$0: $exe not found; build first (cmake --preset mpi && cmake --build --preset mpi)" >&2; exit 2; }
mkdir -p "$out"
cores=$(nproc)
# One thread per rank: CHOLMOD's OpenMP loops and OpenBLAS would otherwise each start a
# team per rank and oversubscribe the cores.
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
# Containers and CI run as root, which OpenMPI refuses unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
/usr/bin/python3 - "${DDA_SCALING_MODEL:-$root/models/slope-fos.json}" "$out/model.json" <<'PY'
import json, sys
model = json.load(open(sys.argv[1]))
model["random_strengths"] = {"variables": [{
    "joint_material": "bedding", "property": "friction_angle", "distribution": "normal",
    "mean": 30.0, "standard_deviation": 2.0, "min": 20.0, "max": 40.0}]}
json.dump(model, open(sys.argv[2], "w"), indent=1)
PY
"$exe" cut "$out/model.json" --out "$out/scene.json" 2>/dev/null
table="$out/scaling.txt"
{
  echo "probabilistic fos of the $(/usr/bin/python3 -c "import json;print(sum(1 for b in json.load(open('$out/scene.json'))['blocks']))")-block slope, $samples samples at F = 1, seed 1, --jobs 1, $cores cores"
  echo "(slowest_share_s: the largest sum of one rank's sample times, samples dealt k mod R; balance: the mean share over it)"
  printf "%6s %10s %18s %11s %16s %8s %8s  %s\n" ranks wall_s core_s_per_sample efficiency slowest_share_s balance 'P(F<1)' note
} > "$table"
t1=""
for r in "${ranks_list[@]}"; do
  # Ranks bound to cores while they fit; beyond, unbound and oversubscribed.
  if [ "$r" -le "$cores" ]; then bind=(--bind-to core); note=""; else bind=(--bind-to none --oversubscribe); note="oversubscribed: $r ranks on $cores cores"; fi
  # A rank count measured before in this OUT_DIR (its wall time kept in ranks-R.wall_s) is
  # not run again: the counts can be measured one invocation at a time, e.g. one rank while
  # the other core is busy, the rest later, and the table still compares them all.
  if [ -s "$out/ranks-$r.wall_s" ] && [ -s "$out/ranks-$r/report.json" ]; then
    wall=$(cat "$out/ranks-$r.wall_s")
  else
    start=$(date +%s.%N)
    mpirun -n "$r" "${bind[@]}" "$exe" fos "$out/scene.json" --samples "$samples" --seed 1 \
      --at-factor 1 --jobs 1 --out "$out/ranks-$r" 2>"$out/ranks-$r.log" >/dev/null
    end=$(date +%s.%N)
    wall=$(/usr/bin/python3 -c "print(f'{$end - $start:.1f}')")
    echo "$wall" > "$out/ranks-$r.wall_s.tmp" && mv "$out/ranks-$r.wall_s.tmp" "$out/ranks-$r.wall_s"
  fi
  [ -n "$t1" ] || t1="$wall"
  /usr/bin/python3 - "$r" "$wall" "$t1" "$samples" "$note" "$out/ranks-$r/report.json" >> "$table" <<'PY'
import json, sys
r, wall, t1, n, note, report = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), sys.argv[5], sys.argv[6]
p = json.load(open(report))["probabilistic"]
efficiency = t1 / (r * wall)
# Each rank's share of the samples' own times as this run measured them (rank k runs the
# samples k, k + R, ...): the ranks wait for the slowest share at the end.
shares = [sum(x["wall_time_s"] for x in p["samples"] if x["index"] % r == k) for k in range(r)]
balance = sum(shares) / r / max(shares)
print(f"{r:6d} {wall:10.1f} {wall * r / n:18.2f} {efficiency:11.2f} {max(shares):16.1f} {balance:8.2f} "
      f"{p['probability_of_failure']:8.3f}  {note}")
PY
done
# The estimate for a 64-core node, from the first rank count's report (one rank: each
# sample's time alone on a core): one rank a core, each consolidating once (the serial
# part) and then running its samples. The run lasts as long as its slowest rank. For these
# samples dealt k mod 64 that is known exactly; for 1000 samples it is the mean over 400
# draws of 1000 sample times from the measured ones. Beside it, what a queue (each sample
# to the rank that is free first) would give for the same samples.
/usr/bin/python3 - "$out/ranks-${ranks_list[0]}/report.json" "$samples" >> "$table" <<'PY'
import heapq, json, random, sys
report, n = json.load(open(sys.argv[1])), int(sys.argv[2])
consolidation = report["consolidation"]["wall_time_s"]
times = [x["wall_time_s"] for x in sorted(report["probabilistic"]["samples"], key=lambda x: x["index"])]
R = 64

def dealt(ts):
    shares = [0.0] * R
    for k, t in enumerate(ts):
        shares[k % R] += t
    return max(shares)

def queued(ts):
    free = [0.0] * R
    for t in ts:
        heapq.heappush(free, heapq.heappop(free) + t)
    return max(free)

rng = random.Random(1)
draws = [[rng.choice(times) for _ in range(1000)] for _ in range(400)]
for N, d, q, total in ((n, dealt(times), queued(times), sum(times)),
                       (1000, sum(map(dealt, draws)) / len(draws), sum(map(queued, draws)) / len(draws),
                        sum(map(sum, draws)) / len(draws))):
    one = consolidation + total
    t64, tq = consolidation + d, consolidation + q
    print(f"64 cores, {N} samples: about {t64:.0f} s dealt k mod 64 (consolidation {consolidation:.1f} s + "
          f"the slowest rank's {d:.0f} s; efficiency {one / (R * t64):.2f}), {tq:.0f} s from a queue "
          f"(efficiency {one / (R * tq):.2f}), against {one:.0f} s on one core")
PY
cat "$table"
