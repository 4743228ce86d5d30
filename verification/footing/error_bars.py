#!/usr/bin/python3
"""Error bars of the footing's refinement study from its curves.csv.

    /usr/bin/python3 verification/footing/error_bars.py DIR [--mesh crossed] [--steps 150]

For each cell size h of the mesh (runs of the given step count), q/c at s/B = 1, 2 and 3 %
(linear between the curve's rows; a run that stopped before is left out). Then, for every
three consecutive sizes (ratio 2), the observed order p = log2((f3 - f2) / (f2 - f1)), the
Richardson extrapolation f1 + (f1 - f2) / (2^p - 1) and Roache's grid convergence index of
the finest, GCI = 1.25 |(f2 - f1) / f1| / (2^p - 1) (Roache 1998, "Verification and
Validation in Computational Science and Engineering", Fs = 1.25 for three or more grids).
With four sizes the two triples check each other: an order that holds from the one to the
other is an order, not a fit. Against Prandtl's (2 + pi).
"""
import argparse
import csv
import math
import sys
from collections import defaultdict

PRANDTL = 2.0 + math.pi
WIDTH = 2.0  # footing width B (m): s/B = 1 % at s = 0.02 m
SHARES = (0.01, 0.02, 0.03)


def read_curves(path, mesh, steps):
    curves = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["mesh"] != mesh or int(row["steps"]) != steps:
                continue
            curves[float(row["cell"])].append((float(row["settlement"]), float(row["q_over_c"])))
    return {h: sorted(points) for h, points in curves.items()}


def at_share(points, share):
    s = share * WIDTH
    for (s0, q0), (s1, q1) in zip(points, points[1:]):
        if s0 <= s <= s1 and s1 > s0:
            return q0 + (q1 - q0) * (s - s0) / (s1 - s0)
    # The push ends at 5.99 cm (its last step lands within 0.2 % of 6 cm): its end is 3 %.
    if points and points[-1][0] >= 0.99 * s:
        return points[-1][1]
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    parser.add_argument("--mesh", default="crossed")
    parser.add_argument("--steps", type=int, default=150)
    args = parser.parse_args()
    curves = read_curves(f"{args.dir}/curves.csv", args.mesh, args.steps)
    if not curves:
        sys.exit(f"error_bars.py: no {args.mesh} runs of {args.steps} steps in {args.dir}/curves.csv")
    sizes = sorted(curves, reverse=True)
    print(f"| h (m) | q/c at s/B = 1 % | 2 % | 3 % | error at 3 % |")
    print("|---:|---:|---:|---:|---:|")
    values = {}
    for h in sizes:
        q = [at_share(curves[h], share) for share in SHARES]
        values[h] = q
        cells = " | ".join("-" if v is None else f"{v:.4f}" for v in q)
        err = "-" if q[2] is None else f"{100 * (q[2] / PRANDTL - 1):+.2f} %"
        print(f"| {h:g} | {cells} | {err} |")
    print()
    print("| s/B | sizes (m) | observed order | extrapolated q/c | vs Prandtl | GCI of the finest |")
    print("|---:|---|---:|---:|---:|---:|")
    for k, share in enumerate(SHARES):
        for a, b, c in zip(sizes, sizes[1:], sizes[2:]):
            f3, f2, f1 = values[a][k], values[b][k], values[c][k]
            if None in (f1, f2, f3) or (f3 - f2) * (f2 - f1) <= 0.0:
                print(f"| {100 * share:.0f} % | {a:g}, {b:g}, {c:g} | - | - | - | - |")
                continue
            p = math.log2((f3 - f2) / (f2 - f1))
            extrapolated = f1 + (f1 - f2) / (2.0 ** p - 1.0)
            gci = 1.25 * abs((f2 - f1) / f1) / (2.0 ** p - 1.0)
            print(f"| {100 * share:.0f} % | {a:g}, {b:g}, {c:g} | {p:.3f} | {extrapolated:.4f} | "
                  f"{100 * (extrapolated / PRANDTL - 1):+.2f} % | {100 * gci:.2f} % |")


if __name__ == "__main__":
    main()
