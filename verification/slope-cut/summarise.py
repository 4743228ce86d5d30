"""Reads the dda fos reports under OUT_DIR/CASE/fos_*/ (CASE: spacing_S for the staggered
slopes, steep*_S for those with steep cross joints) and writes OUT_DIR/report.md and
OUT_DIR/report.json: per slope, each setting's strength-reduction factor and bracket, the
spread of the factors (max - min over their mean), the limit-analysis factor and the smallest
single-block bound, and the planar factor tan(40)/tan(35) (a bound only without cohesion).

    /usr/bin/python3 summarise.py OUT_DIR
"""
import glob
import json
import math
import os
import sys

out = sys.argv[1]
planar = math.tan(math.radians(40.0)) / math.tan(math.radians(35.0))
slopes = []
case_dirs = sorted(glob.glob(os.path.join(out, "spacing_*")))
case_dirs += sorted(glob.glob(os.path.join(out, "steep*_*")))
for case_dir in case_dirs:
    with open(os.path.join(case_dir, "scene.json")) as f:
        scene = json.load(f)
    with open(os.path.join(case_dir, "model.json")) as f:
        model = json.load(f)
    bedding = model["joint_materials"]["bedding"]
    free = sum(1 for b in scene["blocks"] if not b.get("fixed"))
    runs = []
    for report_path in sorted(glob.glob(os.path.join(case_dir, "fos_*", "report.json"))):
        with open(report_path) as f:
            r = json.load(f)
        la = r.get("limit_analysis", {})
        bounds = la.get("single_block_bounds") or []
        runs.append({
            "setting": os.path.basename(os.path.dirname(report_path))[4:],
            "factor": r["factor_of_safety"],
            "bracket": r["bracket"],
            "message": r["message"],
            "trials": len(r["trials"]),
            "wall_time_s": r["wall_time_s"],
            "limit_analysis": la.get("factor"),
            "single_block_bound": bounds[0]["factor"] if bounds else None,
            "mode": (r.get("failing_mechanism") or {}).get("mode"),
            "dynamic_check": r.get("dynamic_check", {}),
        })
    found = [x["factor"] for x in runs if x["factor"] is not None]
    spread = (max(found) - min(found)) / (sum(found) / len(found)) if len(found) > 1 else None
    slopes.append({"case": os.path.basename(case_dir),
                   "spacing": float(case_dir.rsplit("_", 1)[1]), "free_blocks": free,
                   "description": model["description"],
                   "cohesive": bedding["cohesion"] > 0 or bedding["tensile_strength"] > 0,
                   "runs": runs, "spread": spread})
report = {"planar_factor": planar, "slopes": slopes}
with open(os.path.join(out, "report.json"), "w") as f:
    json.dump(report, f, indent=1)
    f.write("\n")
lines = ["# Cut slopes: the factor over dt and penalty", "",
         f"Planar factor tan(40)/tan(35) = {planar:.4f} (every slab alone). Strength reduction (SR): "
         "dda fos's search (tolerance 0.01); LA: the rigid-block limit analysis beside it "
         "(associative friction: an upper bound where the mechanism dilates); bound: the "
         "smallest single-block factor.", ""]
for s in slopes:
    lines.append(f"## {s['case']}: bedding spacing {s['spacing']} m, {s['free_blocks']} free blocks")
    lines.append("")
    lines.append(s["description"])
    lines.append("")
    lines.append("| setting | SR factor | bracket | LA | bound | mechanism | trials | wall (s) | note |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for x in s["runs"]:
        fmt = lambda v: "-" if v is None else f"{v:.4f}"
        bracket = "-" if x["bracket"] is None else f"[{x['bracket'][0]:.4f}, {x['bracket'][1]:.4f}]"
        lines.append(f"| {x['setting']} | {fmt(x['factor'])} | {bracket} | {fmt(x['limit_analysis'])} | "
                     f"{fmt(x['single_block_bound'])} | {x['mode'] or '-'} | {x['trials']} | "
                     f"{x['wall_time_s']:.0f} | {x['message']} |")
    for x in s["runs"]:
        if x["dynamic_check"].get("computed"):
            lines.append("")
            lines.append(f"Static against dynamic trials ({x['setting']}): {x['dynamic_check']['text']}.")
    if s["spread"] is not None:
        lines.append("")
        lines.append(f"Spread of the SR factors: {100 * s['spread']:.1f} % (max - min over the mean).")
    lines.append("")
with open(os.path.join(out, "report.md"), "w") as f:
    f.write("\n".join(lines))
print("\n".join(lines))
