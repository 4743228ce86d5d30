#!/usr/bin/python3
"""Draws the iso-error maps that dda_verify_constitutive wrote into DIR: NAME.png per map (left:
the relative error ||s - s*|| / ||s*|| of one call, coloured by decade with labelled contours;
right: the branch the one call took) and overview.png (every map's error side by side).
Usage: /usr/bin/python3 verification/constitutive/plot_constitutive.py DIR
(Debian's python3 with numpy and matplotlib; the Agg backend, no display needed.)"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

# Error bins: round-off (<= 1e-12) first, then decades and the usual iso-error levels.
BOUNDS = [0.0, 1e-12, 1e-4, 1e-3, 1e-2, 2e-2, 5e-2, 1e-1, 2e-1, 5e-1, 1e9]
BIN_LABELS = ["round-off", "< 0.01 %", "0.01-0.1 %", "0.1-1 %", "1-2 %", "2-5 %", "5-10 %",
              "10-20 %", "20-50 %", "> 50 %"]
CONTOURS = [1e-3, 1e-2, 5e-2, 1e-1, 2e-1]  # drawn as labelled lines (0.1 % ... 20 %)
BRANCHES = ["elastic", "plane", "edge", "apex", "cone", "tension"]
BRANCH_COLOURS = ["#ffffff", "#4c72b0", "#dd8452", "#c44e52", "#55a868", "#8172b3"]


def read(dirname, name):
    with open(os.path.join(dirname, name), newline="") as f:
        return list(csv.DictReader(f))


def grid(rows):
    xs = sorted({float(r["x"]) for r in rows})
    ys = sorted({float(r["y"]) for r in rows})
    err = np.full((len(ys), len(xs)), np.nan)
    branch = np.zeros((len(ys), len(xs)), dtype=int)
    ix = {x: i for i, x in enumerate(xs)}
    iy = {y: j for j, y in enumerate(ys)}
    for r in rows:
        i, j = ix[float(r["x"])], iy[float(r["y"])]
        e = float(r["error"])
        err[j, i] = e if r["status"] == "ok" else np.nan
        branch[j, i] = BRANCHES.index(r["branch"])
    return np.array(xs), np.array(ys), err, branch


def error_bins(err):
    """The bin index of each error (0: round-off ... 9: > 50 %); NaN (failed) goes to bin 0."""
    e = np.nan_to_num(err, nan=0.0)
    return np.clip(np.digitize(e, BOUNDS[1:-1], right=True), 0, len(BIN_LABELS) - 1)


ERROR_CMAP = ListedColormap(["#f7f7f7"] + [tuple(c) for c in
                                           plt.get_cmap("YlOrRd")(np.linspace(0.1, 1.0, 9))])


def error_panel(ax, xs, ys, err, title, xlabel, ylabel):
    mesh = ax.pcolormesh(xs, ys, error_bins(err), cmap=ERROR_CMAP, vmin=-0.5,
                         vmax=len(BIN_LABELS) - 0.5, shading="nearest")
    failed = np.argwhere(np.isnan(err))
    if len(failed):
        ax.plot(xs[failed[:, 1]], ys[failed[:, 0]], "kx", ms=4, label="failed")
        ax.legend(loc="lower left", fontsize=7)
    if len(xs) >= 3 and len(ys) >= 3 and np.nanmax(err) > CONTOURS[0]:
        cs = ax.contour(xs, ys, np.nan_to_num(err, nan=0.0), levels=CONTOURS, colors="k",
                        linewidths=0.7)
        ax.clabel(cs, fmt=lambda v: f"{100 * v:g} %", fontsize=7)
    ax.plot([0], [0], "k*", ms=9)  # the start, on the yield surface
    ax.set_title(title, fontsize=9)
    ax.set_xlabel(xlabel, fontsize=8)
    ax.set_ylabel(ylabel, fontsize=8)
    ax.set_aspect("equal")
    return mesh


def colourbar(fig, mesh, ax):
    cb = fig.colorbar(mesh, ax=ax, ticks=range(len(BIN_LABELS)))
    cb.ax.set_yticklabels(BIN_LABELS, fontsize=7)
    cb.ax.set_title("error", fontsize=7)


def branch_panel(ax, xs, ys, branch, xlabel):
    cmap = ListedColormap(BRANCH_COLOURS)
    ax.pcolormesh(xs, ys, branch, cmap=cmap, vmin=-0.5, vmax=len(BRANCHES) - 0.5,
                  shading="nearest", edgecolors="none")
    present = sorted(set(branch.flatten().tolist()))
    handles = [plt.Rectangle((0, 0), 1, 1, fc=BRANCH_COLOURS[b], ec="0.5") for b in present]
    ax.legend(handles, [BRANCHES[b] for b in present], loc="upper left", fontsize=7,
              framealpha=0.9)
    ax.plot([0], [0], "k*", ms=9)
    ax.set_title("branch of the one call", fontsize=9)
    ax.set_xlabel(xlabel, fontsize=8)
    ax.set_aspect("equal")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    args = parser.parse_args()
    maps = read(args.dir, "maps.csv")
    data = {}
    for m in maps:
        xs, ys, err, branch = grid(read(args.dir, m["name"] + ".csv"))
        data[m["name"]] = (xs, ys, err, branch)
        fig, (a0, a1) = plt.subplots(1, 2, figsize=(12, 5.8))
        fig.suptitle(f"{m['title']}, {m['flow']}\nstart: {m['start']} (the star); "
                     f"reference: {m['substeps']} sub-increments", fontsize=10)
        title = (f"||s - s*|| / ||s*|| of one call: max {100 * float(m['max_error']):.3g} % "
                 f"at ({float(m['max_x']):g}, {float(m['max_y']):g})")
        mesh = error_panel(a0, xs, ys, err, title, m["x_label"], m["y_label"])
        colourbar(fig, mesh, a0)
        branch_panel(a1, xs, ys, branch, m["x_label"])
        fig.tight_layout()
        fig.savefig(os.path.join(args.dir, m["name"] + ".png"), dpi=110)
        plt.close(fig)

    cols = 4
    rows = math.ceil(len(maps) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 4.0 * rows), squeeze=False)
    mesh = None
    for ax, m in zip(axes.flat, maps):
        xs, ys, err, _ = data[m["name"]]
        title = f"{m['name']}\nmax {100 * float(m['max_error']):.3g} %"
        mesh = error_panel(ax, xs, ys, err, title, "deviatoric / e_y",
                           "shear / e_y" if "shear" in m["y_label"] else "volumetric / e_y")
    for ax in list(axes.flat)[len(maps):]:
        ax.axis("off")
    fig.tight_layout()
    if mesh is not None:
        colourbar(fig, mesh, axes.ravel().tolist())
    fig.savefig(os.path.join(args.dir, "overview.png"), dpi=90)
    plt.close(fig)
    print(f"plot_constitutive.py: {len(maps)} maps and overview.png in {args.dir}")


if __name__ == "__main__":
    main()
