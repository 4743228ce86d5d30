#!/usr/bin/python3
"""Figures of the footing verification (verification/footing/README.md) from the CSVs of
dda_verify_footing: curves.png (load against settlement, every run, Prandtl's line),
limit.png (the limit pressure's error against the cell size, log-log, with the cost),
zone_<label>.png (each block of a run coloured by its plastic strain, the deformed mesh).
Reads and draws only; usage: plot_footing.py DIR."""
import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

PRANDTL = 2.0 + math.pi
HALF_WIDTH = 1.0  # b (m); B = 2 b


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def write_table(out, runs, curves):
    """table.md: each run's limit pressure (at the end of the push, s / B = 3 %, and at
    1 and 2 %), its error against Prandtl, the slope of the curve's last third against its first
    step's (how level it ended), the observed order of the error between successive cells,
    and the cost."""
    lines = ["| mesh | phi | h (m) | b / h | blocks | steps | q/c at s/B = 1 % | 2 % | 3 % | error at 3 % | "
             "order | last-third slope / initial | wall (s) | CPU (s) | solves | cut steps |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    def phi_of(run):
        return "0" if abs(float(run["prandtl_q_over_c"]) - PRANDTL) < 1e-9 else run["label"].split("phi")[-1]

    # The observed order against the run of twice the cell (same mesh and phi, fewest steps).
    reference = {}
    for run in sorted(runs, key=lambda r: -int(r["steps"])):
        reference[(run["mesh"], phi_of(run), float(run["cell"]))] = float(run["relative_error"])
    for run in sorted(runs, key=lambda r: (r["mesh"], phi_of(r), int(r["steps"]), -float(r["cell"]))):
        rows = curves.get(run["label"], [])
        if len(rows) < 4:
            continue
        s = [float(r["settlement"]) for r in rows]
        q = [float(r["q_over_c"]) for r in rows]
        n = len(rows) - 1
        at1 = q[min(range(len(s)), key=lambda k: abs(s[k] - 0.02))]
        at2 = q[min(range(len(s)), key=lambda k: abs(s[k] - 0.04))]
        k3 = (2 * n) // 3
        slope = (q[n] - q[k3]) / (s[n] - s[k3]) / (q[1] / s[1])
        err = float(run["relative_error"])
        coarser = reference.get((run["mesh"], phi_of(run), 2 * float(run["cell"])))
        order = "-"
        if coarser is not None and err > 0 and coarser > 0:
            order = f"{math.log(coarser / err) / math.log(2.0):.2f}"
        note = ""
        if run["ok"] != "1":
            note = (f" (stopped: {run['message'].split(':')[0]}, at s/B = {100 * s[n] / (2 * HALF_WIDTH):.2f} %"
                    + (", energy guard" if "energy" in run["message"] else "") + ")")
        lines.append(
            f"| {run['mesh']} | {phi_of(run)} | {float(run['cell']):g} | {HALF_WIDTH / float(run['cell']):g} | "
            f"{run['blocks']} | {run['steps']} | {at1:.3f} | {at2:.3f} | {q[n]:.3f} | {100 * err:+.1f} % | {order} | "
            f"{slope:.4f} | {float(run['wall_s']):.1f} | {float(run['cpu_s']):.1f} | {run['solves']} | "
            f"{run['cut_steps']}{note} |")
    (out / "table.md").write_text("\n".join(lines) + "\n")


def main(out):
    out = Path(out)
    runs = read(out / "runs.csv")
    curves = {}
    for row in read(out / "curves.csv"):
        curves.setdefault(row["label"], []).append(row)

    write_table(out, runs, curves)

    # Load-settlement curves.
    fig, ax = plt.subplots(figsize=(7, 4.8))
    prandtl_values = sorted({round(float(r["prandtl_q_over_c"]), 6) for r in runs})
    top = 1.6 * max(prandtl_values)  # a cut step's spike is drawn at the top
    for run in runs:
        rows = curves.get(run["label"], [])
        s = [float(r["settlement"]) / (2 * HALF_WIDTH) * 100 for r in rows]
        q = [float(r["q_over_c"]) for r in rows]
        style = "-" if run["mesh"] == "crossed" else ":"
        width = 1.0 if int(run["steps"]) > 150 else 1.8
        line, = ax.plot(s, q, style, lw=width,
                        label=f"{run['mesh']} h = {float(run['cell']):g} m, {run['steps']} steps")
        cut = [k for k, r in enumerate(rows) if int(r.get("cuts") or 0) > 0]
        ax.plot([s[k] for k in cut], [min(q[k], top) for k in cut], "x", color=line.get_color(), ms=6)
    for value in prandtl_values:
        name = "Prandtl (2 + π) c" if abs(value - PRANDTL) < 1e-5 else f"Prandtl N_c c = {value:.3f} c"
        ax.axhline(value, color="k", lw=1, ls="--", label=name)
    ax.set_xlabel("settlement s / B (%)")
    ax.set_ylabel("footing pressure q / c")
    ax.set_title("Smooth rigid strip footing on a layer of plastic blocks")
    ax.set_ylim(0, top)
    ax.plot([], [], "kx", label="a step that was cut (not an equilibrium; clipped)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(out / "curves.png", dpi=120)
    plt.close(fig)

    # Error of the limit pressure against the cell size, and the cost.
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(10, 4.2))
    for mesh, marker in (("crossed", "o"), ("diagonal", "s"), ("uniform", "^")):
        for steps in sorted({int(r["steps"]) for r in runs if r["mesh"] == mesh}):
            sel = [r for r in runs if r["mesh"] == mesh and int(r["steps"]) == steps and r["ok"] == "1"]
            if not sel:
                continue
            sel.sort(key=lambda r: float(r["cell"]))
            h = [HALF_WIDTH / float(r["cell"]) for r in sel]
            err = [100 * float(r["relative_error"]) for r in sel]
            ax.loglog(h, err, marker + ("-" if steps == 150 else "--"), label=f"{mesh}, {steps} steps")
            blocks = [int(r["blocks"]) for r in sel]
            wall = [float(r["wall_s"]) for r in sel]
            cpu = [float(r["cpu_s"]) for r in sel]
            line, = ax2.loglog(blocks, cpu, marker + ("-" if steps == 150 else "--"),
                               label=f"{mesh}, {steps} steps: CPU")
            ax2.loglog(blocks, wall, marker, mfc="none", color=line.get_color(), alpha=0.5,
                       label=f"{mesh}, {steps} steps: wall")
    ax.set_xlabel("cells across the footing's half width, b / h")
    ax.set_ylabel("q_DDA / q_Prandtl − 1 (%)")
    # (runs of one friction angle per directory: the error is against that angle's N_c)
    ax.set_title("Limit pressure at s / B = 3 %")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    ax.set_xticks(sorted({HALF_WIDTH / float(r["cell"]) for r in runs}))
    ax.set_yticks([1, 2, 5, 10, 20, 50])
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        axis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax2.set_xlabel("blocks in the layer")
    ax2.set_ylabel("time of the run (s)")
    ax2.set_title("Cost (shared 2-core machine)")
    ax2.grid(alpha=0.3, which="both")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "limit.png", dpi=120)
    plt.close(fig)

    # Plastic zones.
    for run in runs:
        path = out / f"zone_{run['label']}.csv"
        if not path.exists():
            continue
        polys, eps = {}, {}
        for r in read(path):
            b = int(r["block"])
            polys.setdefault(b, []).append((float(r["x"]), float(r["y"])))
            eps[b] = float(r["eps_p"])
        keys = sorted(polys)
        values = [eps[k] for k in keys]
        fig, ax = plt.subplots(figsize=(8, 4.4))
        # The colour scale stops at the 95th percentile: the footing's corner concentrates
        # the largest strains in a few blocks and would leave the rest of the zone dark.
        ranked = sorted(values)
        top = ranked[int(0.95 * (len(ranked) - 1))] if ranked else 0.0
        top = top if top > 0 else (max(values) if values and max(values) > 0 else 1.0)
        coll = PolyCollection([polys[k] for k in keys], array=values, cmap="viridis",
                              edgecolors="none" if len(keys) > 600 else "0.6", linewidths=0.2)
        coll.set_clim(0, top)
        ax.add_collection(coll)
        b = HALF_WIDTH
        tresca = abs(float(run["prandtl_q_over_c"]) - PRANDTL) < 1e-9
        r0 = b * math.sqrt(2)
        fan = [(b + r0 * math.cos(a), r0 * math.sin(a))
               for a in [-3 * math.pi / 4 + k * (math.pi / 2) / 40 for k in range(41)]]
        if tresca:  # Prandtl's mechanism (half): the active wedge, the fan, the passive wedge
            ax.plot([0, 0, b], [0, -b, 0], "w-", lw=1)
            ax.plot([p[0] for p in fan], [p[1] for p in fan], "w-", lw=1.2)
            ax.plot([b + r0 * math.cos(-math.pi / 4), 3 * b], [r0 * math.sin(-math.pi / 4), 0], "w-", lw=1.2)
            ax.plot([b, b + r0 * math.cos(-math.pi / 4)], [0, r0 * math.sin(-math.pi / 4)], "w-", lw=0.6)
        rows = curves.get(run["label"], [])
        settled = float(rows[-1]["settlement"]) if rows else 0.0
        ax.add_patch(plt.Rectangle((0, -settled), b, 0.25, color="0.4"))
        ax.set_xlim(-0.05, 4.05)
        ax.set_ylim(-2.05, 0.35)
        ax.set_aspect("equal")
        fig.colorbar(coll, ax=ax, label="equivalent plastic strain (scale to the 95th percentile)", shrink=0.8)
        ax.set_title(f"{run['label']}: plastic strain at s / B = 3 %"
                     + (" (white: Prandtl's mechanism)" if tresca else ""), fontsize=9)
        fig.tight_layout()
        fig.savefig(out / f"zone_{run['label']}.png", dpi=120)
        plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: plot_footing.py DIR")
    main(sys.argv[1])
