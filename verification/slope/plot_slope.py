#!/usr/bin/python3
"""Draws the mechanism of each slope case from the outlines dda_verify_slope wrote into DIR
(mechanism_<case>.json): the blocks as consolidated (grey) and at the end of the first failing
trial (coloured; fixed blocks hatched), with the free blocks' displacements exaggerated so a
mechanism of a few centimetres shows. Writes mechanism_<case>.png beside each file.
Usage: /usr/bin/python3 verification/slope/plot_slope.py DIR
(Debian's python3 with matplotlib; the Agg backend, no display needed.)"""
import argparse
import glob
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Polygon  # noqa: E402


def exaggeration(before, after, fixed):
    """A factor that makes the largest free-vertex displacement 3 % of the scene's size."""
    xs = [p[0] for poly in before for p in poly]
    ys = [p[1] for poly in before for p in poly]
    size = max(max(xs) - min(xs), max(ys) - min(ys))
    largest = 0.0
    for b, a, f in zip(before, after, fixed):
        if f:
            continue
        for p, q in zip(b, a):
            largest = max(largest, ((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2) ** 0.5)
    if largest <= 0.0:
        return 1.0
    return max(1.0, 0.03 * size / largest)


def draw(path):
    with open(path) as f:
        m = json.load(f)
    before, after, fixed = m["before"], m["after"], m["fixed"]
    fig, ax = plt.subplots(figsize=(8, 6))
    scale = exaggeration(before, after, fixed) if after else 1.0
    cmap = plt.get_cmap("tab20")
    for i, (poly, is_fixed) in enumerate(zip(before, fixed)):
        ax.add_patch(Polygon(poly, closed=True, fill=is_fixed, facecolor="0.85",
                             edgecolor="0.5", hatch="//" if is_fixed else None, lw=0.8))
        if is_fixed or not after:
            continue
        moved = [[p[0] + scale * (q[0] - p[0]), p[1] + scale * (q[1] - p[1])]
                 for p, q in zip(poly, after[i])]
        ax.add_patch(Polygon(moved, closed=True, fill=True, alpha=0.45,
                             facecolor=cmap(i % 20), edgecolor="k", lw=1.0))
    xs = [p[0] for poly in before for p in poly]
    ys = [p[1] for poly in before for p in poly]
    ax.set_xlim(min(xs), max(xs))
    ax.set_ylim(min(ys), max(ys))
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    if after:
        sub = "first failing trial F = %.4f (LE %.4f); displacements x %.0f" % (
            m["first_failing"], m["le_factor"], scale)
    else:
        sub = "no failing trial (consolidated state only)"
    ax.set_title("%s\n%s" % (m["title"], sub), fontsize=9)
    out = os.path.splitext(path)[0] + ".png"
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.dir, "mechanism_*.json")))
    if not files:
        raise SystemExit("plot_slope.py: no mechanism_*.json in %s" % args.dir)
    for path in files:
        print(draw(path))


if __name__ == "__main__":
    main()
