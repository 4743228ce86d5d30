#!/usr/bin/python3
"""Draws a run's blocks at a few output frames and its centroid paths, from DIR/blocks.pvd
and DIR/history.csv, into DIR/run.png. Usage: verification/plot_run.py DIR [--frames N]"""
import argparse
import csv
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtk_frames  # noqa: E402  (the frames in either encoding, ASCII or zlib binary)


def read_frame(path):
    """Block polygons of one .vtp frame, as a list of (n, 2) arrays."""
    return [np.array(p, float).reshape(-1, 2) for p in vtk_frames.polygons(vtk_frames.read_vtp(path))]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("dir")
    ap.add_argument("--frames", type=int, default=8, help="frames drawn (evenly spaced)")
    args = ap.parse_args()
    frames = [(float(d.get("timestep")), d.get("file"))
              for d in ET.parse(os.path.join(args.dir, "blocks.pvd")).getroot().iter("DataSet")]
    picks = np.unique(np.linspace(0, len(frames) - 1, min(args.frames, len(frames))).astype(int))
    fig, ax = plt.subplots(figsize=(8, 6))
    cmap = plt.get_cmap("viridis")
    for k, i in enumerate(picks):
        t, name = frames[i]
        colour = cmap(k / max(1, len(picks) - 1))
        for poly in read_frame(os.path.join(args.dir, name)):
            closed = np.vstack([poly, poly[:1]])
            ax.plot(closed[:, 0], closed[:, 1], color=colour, lw=1)
        ax.plot([], [], color=colour, label=f"t = {t:.3g} s")
    paths = {}
    with open(os.path.join(args.dir, "history.csv")) as f:
        for row in csv.DictReader(f):
            paths.setdefault(int(row["block"]), []).append((float(row["xc"]), float(row["yc"])))
    for b, p in paths.items():
        p = np.array(p)
        ax.plot(p[:, 0], p[:, 1], "k:", lw=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"{args.dir}: blocks at {len(picks)} frames, centroid paths dotted")
    ax.legend(fontsize=7, loc="best")
    out = os.path.join(args.dir, "run.png")
    fig.savefig(out, dpi=110, bbox_inches="tight")
    print(out)


if __name__ == "__main__":
    main()
