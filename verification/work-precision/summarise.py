#!/usr/bin/env python3
"""Reads OUT/manifest.json and each run's summary.json (OUT/runs/NAME/) and writes
OUT/report.md: per case, the error against its closed form, the solver's wall time, steps
and solves, over dt and the penalty; the observed order of the error in dt at the scene's
penalty (50 E).

    /usr/bin/python3 verification/work-precision/summarise.py OUT
"""
import argparse
import json
import math
import os


def quantity(summary, entry):
    block = summary["blocks"][entry["block"]]
    if entry["case"] == "slide":
        return block["centroid"][0] - 0.30  # the block's centroid starts at x = 0.30 m
    return block["stress"][1]


def main():
    parser = argparse.ArgumentParser(description="work-precision report")
    parser.add_argument("out")
    args = parser.parse_args()
    manifest = json.load(open(os.path.join(args.out, "manifest.json")))
    lines = ["# Work-precision of multi-block contact cases (issue 27, item 6)", "",
             "Error against the closed form and the solver's wall time (`summary.json` "
             "`wall_time_s`, one run each, one core), by time step and penalty (a factor of "
             "E = 1 GPa). README.md has the cases and what the figures say.", ""]
    for case in ("slide", "stack"):
        rows = [m for m in manifest if m["case"] == case]
        if not rows:
            continue
        lines += [f"## {case}: {rows[0]['quantity']}, exact {rows[0]['exact']:.6g}", "",
                  "| dt (s) | penalty / E | value | relative error | wall (s) | steps | solves | exit |",
                  "|---:|---:|---:|---:|---:|---:|---:|---|"]
        errors = {}
        for m in rows:
            path = os.path.join(args.out, "runs", m["name"], "summary.json")
            if not os.path.exists(path):
                lines.append(f"| {m['dt']:g} | {m['penalty_factor']:g} | - | - | - | - | - | no summary |")
                continue
            s = json.load(open(path))
            value = quantity(s, m)
            error = abs(value / m["exact"] - 1.0)
            errors[(m["dt"], m["penalty_factor"])] = error
            status = "diverged" if s["diverged"] else "completed"
            lines.append(f"| {m['dt']:g} | {m['penalty_factor']:g} | {value:.6g} | {error:.2e} | "
                         f"{s['wall_time_s']:.3f} | {s['steps']} | {s['iterations']} | {status} |")
        dts = sorted({d for d, p in errors if p == 50.0}, reverse=True)
        orders = []
        for a, b in zip(dts, dts[1:]):
            ea, eb = errors[(a, 50.0)], errors[(b, 50.0)]
            if ea > 0 and eb > 0:
                orders.append(f"{math.log(ea / eb) / math.log(a / b):.2f} ({a:g} to {b:g})")
        lines += ["", "Observed order in dt at 50 E: " + (", ".join(orders) if orders else "-"), ""]
    with open(os.path.join(args.out, "report.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
