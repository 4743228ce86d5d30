"""Checks a slope-cut run (OUT_DIR/report.json from summarise.py) against the bounds every
factor must respect, and exits 1 naming each breach:

- without cohesion, the limit-analysis factor is at most the planar factor tan(40)/tan(35):
  the planar slide of the lowest slab is one of the mechanisms it minimises over (plus its
  bisection's 1e-3);
- each strength-reduction factor is at most the smallest single-block bound, and at most the
  limit-analysis factor, plus the search's half-bracket (0.005) and its verdict's resolution
  on a 35 degree plane (F x 2 x 0.002 / sin 35 = 0.008 at F = 1.2): rigid blocks with
  non-associative friction fail no later than with associative friction;
- the run at the scene's own settings has its dynamic check (dynamic trials at 0.95 F and
  1.05 F), which says whether the dynamic factor lies within 5 % of the static one, or why
  not.

    /usr/bin/python3 check.py OUT_DIR
"""
import json
import os
import sys

report = json.load(open(os.path.join(sys.argv[1], "report.json")))
planar = report["planar_factor"]
slack = 0.005 + 0.008
breaches = []
for s in report["slopes"]:
    for x in s["runs"]:
        where = f"{s.get('case', s['spacing'])}, {x['setting']}"
        la, bound, sr = x["limit_analysis"], x["single_block_bound"], x["factor"]
        if la is None:
            breaches.append(f"{where}: no limit-analysis factor")
        elif not s.get("cohesive") and la > planar * (1 + 1e-3):
            breaches.append(f"{where}: limit analysis {la:.4f} above the planar factor {planar:.4f}")
        if sr is None:
            breaches.append(f"{where}: no strength-reduction factor ({x['message']})")
            continue
        if bound is not None and sr > bound + slack:
            breaches.append(f"{where}: SR {sr:.4f} above the smallest single-block bound {bound:.4f}")
        if la is not None and sr > la + slack:
            breaches.append(f"{where}: SR {sr:.4f} above the limit-analysis factor {la:.4f}")
        dynamic = x.get("dynamic_check", {})
        if x["setting"] == "scene" and not (dynamic.get("computed") and dynamic.get("text")):
            breaches.append(f"{where}: no dynamic check")
for b in breaches:
    print("check.py: " + b, file=sys.stderr)
sys.exit(1 if breaches else 0)
