#!/usr/bin/python3
"""Draws the PNGs of the paper reproduction from the CSVs that dda_verify_paper wrote into DIR:
falling_scene.png, falling_area_error.png, swinging_energy.png, speed_error.png,
rotation_stress.png, speed_incline.png, speed_plastic.png.
Usage: /usr/bin/python3 verification/paper/plot_paper.py DIR
(Debian's python3 with numpy and matplotlib; the Agg backend, no display needed.)"""
import argparse
import csv
import math
import os
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Relative errors that are exactly 0 (round-off luck) cannot go on a log axis: they are drawn
# at this floor, below anything a double can resolve relative to 1 (2.2e-16).
LOG_FLOOR = 1e-17

SETTINGS = [("dt0.01", "0.01 s x 400, ratio 0.01"),
            ("dt0.02", "0.02 s x 300, ratio 0.02"),
            ("alternating", "0.01/0.02 s alternately x 300, ratio 0.02")]
# The paper's Table 1 areas (m^2), for markers at the last step; initial area 0.707107.
PAPER_AREAS = {"original": [0.834560, 1.264527, 1.132795],
               "post_adjustment": [0.707120, 0.707114, 0.707113],
               "sin_variable": [0.708365, 0.731127, 0.742573],
               "local_frame": [0.707119, 0.707116, 0.707119]}
PAPER_A0 = 0.707107


def read(dirname, name):
    with open(os.path.join(dirname, name), newline="") as f:
        return list(csv.DictReader(f))


# The treatments' names (docs/scene-format.md, "Rotation treatments"), in the program's order:
# each keeps its colour in every figure, whichever of them a run has.
TREATMENTS = ["original", "second_order", "post_adjustment", "sin_variable", "local_frame",
              "local_frame_as_printed", "finite_rotation"]


def colours(names):
    cmap = plt.get_cmap("tab10")
    known = {n: cmap(i) for i, n in enumerate(TREATMENTS)}
    extra = [n for n in names if n not in known]
    known.update({n: cmap((len(TREATMENTS) + i) % 10) for i, n in enumerate(extra)})
    return known


def ordered_treatments(rows):
    seen = []
    for r in rows:
        if r["treatment"] not in seen:
            seen.append(r["treatment"])
    return seen


def available(summary_rows):
    """Treatments with a summary row (every treatment runs; a diverged run has its row too)."""
    return {r["treatment"] for r in summary_rows}


def plot_falling_scene(d):
    scene = read(d, "falling_scene.csv")
    path = read(d, "falling_path.csv")
    area = read(d, "falling_area.csv")
    ok = available(read(d, "falling_summary.csv"))
    names = [t for t in ordered_treatments(area) if t in ok]
    col = colours(names)
    blocks = defaultdict(list)
    for r in scene:
        blocks[(int(r["block"]), r["role"])].append((float(r["x"]), float(r["y"])))
    fig, axes = plt.subplots(len(SETTINGS), 1, figsize=(11, 4.2 * len(SETTINGS)))
    for ax, (key, label) in zip(axes, SETTINGS):
        for (_, role), pts in sorted(blocks.items()):
            if role == "fixed":
                ax.add_patch(plt.Polygon(pts, closed=True, fc="0.8", ec="0.3", lw=0.8))
        frames = defaultdict(list)
        for r in path:
            if r["treatment"] == "original" and r["setting"] == key:
                frames[int(r["step"])].append((float(r["x"]), float(r["y"])))
        cmap = plt.get_cmap("viridis")
        steps = sorted(frames)
        for k, s in enumerate(steps):
            ax.add_patch(plt.Polygon(frames[s], closed=True, fill=False,
                                     ec=cmap(k / max(1, len(steps) - 1)), lw=1.0))
        for t in names:
            xs = [float(r["xc"]) for r in area if r["treatment"] == t and r["setting"] == key]
            ys = [float(r["yc"]) for r in area if r["treatment"] == t and r["setting"] == key]
            ax.plot(xs, ys, lw=0.8, color=col[t], label=f"centroid path, {t}")
        ax.set_aspect("equal")
        ax.autoscale_view()
        ax.set_title(f"{label}: the rock (original) every 20 steps, dark = early")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "falling_scene.png"), dpi=110)
    plt.close(fig)


def plot_falling_area(d):
    area = read(d, "falling_area.csv")
    ok = available(read(d, "falling_summary.csv"))
    names = [t for t in ordered_treatments(area) if t in ok]
    col = colours(names)
    fig, axes = plt.subplots(1, len(SETTINGS), figsize=(16, 5), sharey=True)
    for i, (ax, (key, label)) in enumerate(zip(axes, SETTINGS)):
        for t in names:
            rows = [r for r in area if r["treatment"] == t and r["setting"] == key]
            steps = [int(r["step"]) for r in rows]
            err = [max(float(r["area_rel_error"]), LOG_FLOOR) for r in rows]
            ax.plot(steps, err, color=col[t], lw=1.0, label=t)
            if t in PAPER_AREAS and steps:
                paper = abs(PAPER_AREAS[t][i] - PAPER_A0) / PAPER_A0
                ax.plot([steps[-1]], [paper], marker="*", ms=11, color=col[t], ls="none",
                        mec="k", mew=0.5)
        ax.set_yscale("log")
        ax.set_xlabel("step")
        ax.set_title(label, fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("|A - A0| / A0 of the rock (zero drawn at 1e-17)")
    axes[-1].legend(fontsize=8, title="star: the paper's final value", title_fontsize=8)
    fig.suptitle("Table 1: area error of the falling octagon against step")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "falling_area_error.png"), dpi=110)
    plt.close(fig)


def plot_swinging_energy(d):
    energy = read(d, "swinging_energy.csv")
    summary = read(d, "swinging_summary.csv")
    ok = available(summary)
    mgl = {r["treatment"]: float(r["mgl_J"]) for r in summary}
    names = [t for t in ordered_treatments(energy) if t in ok]
    col = colours(names)
    fig, (ax_e, ax_s) = plt.subplots(2, 1, figsize=(11, 9), sharex=True)
    for t in names:
        rows = [r for r in energy if r["treatment"] == t]
        time = np.array([float(r["time"]) for r in rows])
        total = np.array([float(r["total"]) for r in rows])
        pin = np.array([float(r["pin_energy"]) for r in rows])
        swing = np.array([float(r["swing_angle"]) for r in rows])
        ax_e.plot(time, (total - total[0]) / mgl[t], color=col[t], lw=0.9, label=t)
        ax_e.plot(time, pin / mgl[t], color=col[t], lw=0.5, ls=":")
        ax_s.plot(time, swing, color=col[t], lw=0.9, label=t)
    # symlog: linear within +-1e-6 m g l (the size of the pin spring's energy at rest),
    # logarithmic beyond, so that both a slow loss and a runaway gain are readable.
    ax_e.set_yscale("symlog", linthresh=1e-6)
    ax_e.set_ylim(-10.0, 1e3)
    ax_e.axhline(0.0, color="k", lw=0.6)
    ax_e.set_ylabel("(E - E0) / (m g l); dotted: pin spring energy / (m g l)")
    ax_e.set_title("Swinging octagon: kinetic + potential energy E against time "
                   "(above 0 = energy gained; runs that diverge leave the axis)")
    ax_e.legend(fontsize=8, loc="upper left")
    for y in (math.pi, -math.pi):
        ax_s.axhline(y, color="k", lw=0.6, ls="--")
    ax_s.set_ylim(-1.5 * math.pi, 3.0 * math.pi)
    ax_s.set_ylabel("angle swept by pin -> centroid (rad)")
    ax_s.set_title("swing angle; dashed: +-pi, the mirror position (a curve leaving the top "
                   "went over and spins)", fontsize=10)
    ax_s.set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "swinging_energy.png"), dpi=110)
    plt.close(fig)


def plot_speed(d):
    spin = [r for r in read(d, "speed_spin.csv") if r["status"] == "completed"]
    pend = [r for r in read(d, "speed_pendulum.csv") if r["status"] == "completed"]
    names = ordered_treatments(read(d, "speed_spin.csv"))
    col = colours(names)
    panels = [(spin, "area_rel_error", "spinning block: area drift |A - A0| / A0"),
              (pend, "period_rel_error", "pendulum: period error (vs CVODE)"),
              (pend, "amplitude_rel_error", "pendulum: amplitude error (vs CVODE)")]
    fig, axes = plt.subplots(1, 3, figsize=(17, 5.2))
    for ax, (rows, key, title) in zip(axes, panels):
        for t in names:
            # joined in the order of the sweep (largest dt first), not by wall time, whose
            # noise would zigzag the line
            pts = sorted(((float(r["wall_s"]), max(float(r[key]), LOG_FLOOR), float(r["dt"]))
                          for r in rows if r["treatment"] == t and not math.isnan(float(r[key]))),
                         key=lambda p: -p[2])
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=4, lw=1.0,
                    color=col[t], label=t)
        # dt labels once, on the first treatment's points
        first = [r for r in rows if r["treatment"] == names[0]]
        for r in first:
            if math.isnan(float(r[key])):
                continue
            xy = (float(r["wall_s"]), max(float(r[key]), LOG_FLOOR))
            ax.annotate(f"dt {float(r['dt']):g}", xy, fontsize=6, xytext=(3, 3),
                        textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time of the run (s)")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("error (zero drawn at 1e-17)")
    axes[0].legend(fontsize=8)
    fig.suptitle("Speed against error over a sweep of time steps")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "speed_error.png"), dpi=110)
    plt.close(fig)


def plot_rotation(d):
    """rotation_stress.png: left, the swinging octagon's stress along its long axis over one
    period against the quasi-static closed form; right, the energy gain against dt."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    swing = read(d, "rotation_swing.csv")
    styles = {("finite_rotation", "pseudo_rigid"): "-", ("local_frame", "pseudo_rigid"): "--",
              ("finite_rotation", "shi"): ":", ("post_adjustment", "shi"): "-."}
    drawn_reference = False
    for (t, inertia), style in styles.items():
        rows = [r for r in swing if r["treatment"] == t and r["inertia"] == inertia]
        if not rows:
            continue
        time = [float(r["time"]) for r in rows]
        if not drawn_reference:
            left.plot(time, [float(r["expected_sxx"]) / 1e3 for r in rows], color="black",
                      lw=5, alpha=0.25, label="closed form on CVODE's pendulum", zorder=1)
            drawn_reference = True
        left.plot(time, [float(r["sxx"]) / 1e3 for r in rows], style,
                  color=colours(TREATMENTS)[t], label=f"{t} ({inertia} inertia)")
    left.set_xlabel("time (s)")
    left.set_ylabel("stress along the block's x axis (kPa)")
    left.set_title("swinging octagon, dt 0.02 s, one period")
    left.legend(fontsize=8)
    gain = [r for r in read(d, "rotation_gain.csv") if r["study"] == "dt"]
    markers = {"post_adjustment": ("o-", 9), "local_frame": ("x--", 7)}
    for t in ordered_treatments(gain):
        rows = [r for r in gain if r["treatment"] == t and float(r["gain_over_mgl"]) > 0]
        if not rows:
            continue
        style, size = markers.get(t, ("s-", 6))
        right.loglog([float(r["dt"]) for r in rows], [float(r["gain_over_mgl"]) for r in rows],
                     style, ms=size, color=colours(TREATMENTS)[t], label=t)
    dts = sorted({float(r["dt"]) for r in gain})
    if dts:
        ref = [0.5 * x / dts[-1] for x in dts]
        right.loglog(dts, ref, "k:", label="slope 1")
    right.set_xlabel("dt (s)")
    right.set_ylabel("energy gain / (m g l)")
    right.set_title("energy gain of the swinging octagon (finite_rotation: none)\n"
                    "local_frame and post_adjustment coincide")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "rotation_stress.png"), dpi=110)
    plt.close(fig)


def plot_work_precision(d, csv_name, png_name, curves, title, slope_key):
    """Two panels: each error against the wall time of its run, and against dt with a
    first-order guide through the curve named slope_key. `curves`: (column, label, marker)."""
    rows = [r for r in read(d, csv_name) if r["status"] == "completed"]
    rows.sort(key=lambda r: -float(r["dt"]))
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    for key, label, marker in curves:
        wall = [float(r["wall_s"]) for r in rows]
        dts = [float(r["dt"]) for r in rows]
        err = [max(abs(float(r[key])), LOG_FLOOR) for r in rows]
        axes[0].plot(wall, err, marker=marker, ms=4, lw=1.0, label=label)
        axes[1].plot(dts, err, marker=marker, ms=4, lw=1.0, label=label)
        if key == slope_key:
            for r, x, y in zip(rows, wall, err):
                axes[0].annotate(f"dt {float(r['dt']):g}", (x, y), fontsize=6, xytext=(3, 3),
                                 textcoords="offset points")
            if dts:
                ref = np.array([max(dts), min(dts)])
                axes[1].plot(ref, err[0] * ref / dts[0], color="grey", ls=":", lw=0.8,
                             label="first order (through the largest dt)")
    axes[0].set_xlabel("wall time of the run (s)")
    axes[1].set_xlabel("dt (s)")
    for ax in axes:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, which="major", alpha=0.3)
        ax.set_ylabel("relative error (zero drawn at 1e-17)")
    axes[1].legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(d, png_name), dpi=110)
    plt.close(fig)


def plot_closed_form_speed(d):
    plot_work_precision(
        d, "speed_incline.csv", "speed_incline.png",
        [("rel_error", "distance at 1 s vs g (sin a - cos a tan phi) t^2/2", "o"),
         ("acc_rel_error", "sliding acceleration (travel from 1 s to 2 s)", "s")],
        "Block sliding down a 30 degree incline, friction 20 degrees: error against cost over dt",
        "rel_error")
    plot_work_precision(
        d, "speed_plastic.csv", "speed_plastic.png",
        [("error_present", "s1 vs N P / h + 2 c sqrt(N) (present height)", "o"),
         ("error_nominal", "s1 vs N s3 + 2 c sqrt(N) (nominal s3)", "s"),
         ("lag_term", "one step's shortening N P v dt / (h^2 s1)", "x")],
        "Mohr-Coulomb specimen pushed through a platen (static analysis): error against cost "
        "over dt", "error_present")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("dir", help="the --out directory of dda_verify_paper")
    args = ap.parse_args()
    # What each figure needs; a --closed-form-only run has only the last two.
    figures = [(plot_falling_scene, ["falling_scene.csv", "falling_path.csv", "falling_area.csv",
                                     "falling_summary.csv"], ["falling_scene.png"]),
               (plot_falling_area, ["falling_area.csv", "falling_summary.csv"],
                ["falling_area_error.png"]),
               (plot_swinging_energy, ["swinging_energy.csv", "swinging_summary.csv"],
                ["swinging_energy.png"]),
               (plot_speed, ["speed_spin.csv", "speed_pendulum.csv"], ["speed_error.png"]),
               (plot_closed_form_speed, ["speed_incline.csv", "speed_plastic.csv"],
                ["speed_incline.png", "speed_plastic.png"]),
               (plot_rotation, ["rotation_swing.csv", "rotation_gain.csv"],
                ["rotation_stress.png"])]
    drawn = 0
    for plot, needs, pngs in figures:
        if all(os.path.exists(os.path.join(args.dir, n)) for n in needs):
            plot(args.dir)
            for name in pngs:
                print(os.path.join(args.dir, name))
            drawn += 1
    if drawn == 0:
        raise SystemExit(f"{args.dir}: no CSV of dda_verify_paper found")


if __name__ == "__main__":
    main()
