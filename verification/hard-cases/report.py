#!/usr/bin/python3
"""Judges the hard-case runs and writes OUT_DIR/report.md and OUT_DIR/CASE.png.

    report.py OUT_DIR

Reads OUT_DIR/scenes/manifest.json (make_scenes.py), OUT_DIR/runs/status.tsv (run.sh) and
each run's summary.json and history.csv. Prints the report; exits 1 if any run fails.
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The remainder tolerances, as shares of the case's energy scale. Gains: 1e-3. Shi's scheme
# with penalty contacts only removes energy, so an honest gain is the account's own error
# (terms taken at the step's end, round-off); measured on every run of the suite, of
# --moving (both contact solvers), --moving-small and --arches: at most
# 1.1e-4 with the default solver (the falling column at dt 0.002 s), 2.6e-4 with Shi's
# loop (the dominoes). 1e-3 is four times the largest. (It was formerly 1 %, a gain a
# user would see in a plot.) Losses: 2 %. A contact solved open over the step it
# opens in neither returns nor books what its spring held (docs/energy-balance.md,
# "Losses"): the head-on collision at dt 0.0002 s loses 1.13 %, the dynamic piles and the
# toppling columns 0.2 to 0.6 % (of the energy that moved, judge()); 2 % is not quite twice
# the largest, and three times any other.
TOLERANCE = 1e-3
LOSS_TOLERANCE = 0.02
FULL_ACCOUNT = "energy_remainder"
TERMS = ["kinetic", "potential", "strain_energy", "contact_energy", "load_work",
         "friction_dissipation", "plastic_dissipation", "damping_dissipation"]


def read_history(path):
    """One dict per output step (energies are scene totals) and, per step, the blocks'
    xc, yc, vx, vy."""
    steps = {}
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        columns = reader.fieldnames or []
        for row in reader:
            step = int(row["step"])
            s = steps.setdefault(step, {k: float(v) for k, v in row.items()
                                        if k not in ("step", "block")})
            s.setdefault("blocks", {})[int(row["block"])] = (
                float(row["xc"]), float(row["yc"]), float(row["vx"]), float(row["vy"]))
    return [steps[k] for k in sorted(steps)], columns


def area(poly):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))


def profile_height(profile, x):
    """Height of a polyline surface at x: the highest non-vertical segment over x, the end
    values beyond its ends (so a block that leaves the surface's end shows as below it)."""
    if x <= profile[0][0]:
        return profile[0][1]
    if x >= profile[-1][0]:
        return profile[-1][1]
    best = -math.inf
    for (x0, y0), (x1, y1) in zip(profile, profile[1:]):
        if x0 < x1 and x0 <= x <= x1:
            best = max(best, y0 + (y1 - y0) * (x - x0) / (x1 - x0))
    return best


# Each check returns (passed, measured text). `run` holds the history frames, the final
# state from summary.json, the free blocks and their masses, the scale and the summary.

def check_inside(run, c):
    margin = min(min(x - c["x_min"], c["x_max"] - x, y - c["y_min"])
                 for x, y, _, _ in run["final"].values())
    return margin > 0, f"inside margin {margin:.3g} m"


def check_rest(run, c):
    share = run["kinetic_end"] / run["scale"]
    return share <= c["fraction"], f"KE end/scale {share:.2g} (<= {c['fraction']:g})"


def check_released(run, c):
    share = (run["frames"][0]["potential"] - run["potential_end"]) / run["scale"]
    return share >= c["min"], f"released {share:.2f} of scale (>= {c['min']:g})"


def check_drift_x(run, c):
    start = run["frames"][0]["blocks"]
    drift = max(abs(x - start[i][0]) for i, (x, _, _, _) in run["final"].items())
    return drift <= c["limit"], f"x drift {drift:.2g} m (<= {c['limit']:g})"


def check_still(run, c):
    start = run["frames"][0]["blocks"]
    moved = max(math.hypot(x - start[i][0], y - start[i][1])
                for state in run["states"] for i, (x, y, _, _) in state.items())
    return moved <= c["limit"], f"moved {moved:.2g} m (<= {c['limit']:g})"


def momentum(run, state):
    return sum(run["mass"][i] * vx for i, (_, _, vx, _) in state.items())


def check_momentum(run, c):
    start = run["frames"][0]["blocks"]
    ref = sum(run["mass"][i] * abs(start[i][2]) for i in run["free"]) or 1.0
    change = abs(momentum(run, run["final"]) - momentum(run, {i: start[i] for i in run["free"]}))
    return change / ref <= c["limit"], f"momentum change {change / ref:.2g} of sum m|v|"


def check_restitution(run, c):
    a, b = run["free"][:2]
    start = run["frames"][0]["blocks"]
    before = abs(start[a][2] - start[b][2])
    after = abs(run["final"][a][2] - run["final"][b][2])
    ratio = after / before if before else 0.0
    return ratio <= 1.0 + 1e-9, f"restitution {ratio:.3f} (<= 1)"


def check_above(run, c):
    clear = min(y - profile_height(c["profile"], x)
                for state in run["states"] for x, y, _, _ in state.values())
    return clear >= c["clearance"], f"clearance {clear:.3g} m (>= {c['clearance']:.3g})"


def check_descend(run, c):
    start = run["frames"][0]["blocks"]
    fall = min(start[i][1] - y for i, (_, y, _, _) in run["final"].items())
    return fall >= c["min"], f"descended {fall:.3g} m (>= {c['min']:.3g})"


def check_open_close_mean(run, c):
    mean = run["summary"]["open_close_iterations"]["mean"]
    return mean <= c["limit"], f"open-close mean {mean:.2f} (<= {c['limit']:g})"


def check_fallen(run, c):
    """Every free block has turned by at least min_deg (a row of dominoes that fell)."""
    turned = min(abs(math.degrees(run["summary"]["blocks"][i]["rotation"])) for i in run["free"])
    return turned >= c["min_deg"], f"least turn {turned:.3g} deg (>= {c['min_deg']:g})"


def crown_drops(run, c):
    """The drop of the listed blocks' centroids (the crown) from the start, at every output
    frame and at the end: the largest of the listed blocks in each state."""
    start = run["frames"][0]["blocks"]
    return [max(start[i][1] - state[i][1] for i in c["blocks"]) for state in run["states"]]


def check_stands(run, c):
    drop = max(crown_drops(run, c))
    return drop <= c["limit"], f"crown drop {drop:.2g} m (<= {c['limit']:g})"


def check_collapses(run, c):
    drop = crown_drops(run, c)[-1]
    return drop >= c["min"], f"crown drop {drop:.3g} m at the end (>= {c['min']:g})"


def check_fall_at_g(run, c):
    """The block's centroid fell g t^2 / 2 over the time the run reached, to rel_tol."""
    i = c["block"]
    g = math.hypot(*run["gravity"])
    t = run["end_time"]
    expected = 0.5 * g * t * t
    drop = run["frames"][0]["blocks"][i][1] - run["final"][i][1]
    error = abs(drop / expected - 1.0) if expected > 0 else math.inf
    return error <= c["rel_tol"], (f"drop {drop:.4g} m of g t^2/2 = {expected:.4g} m at "
                                   f"t {t:g} s (rel. error {error:.2g} <= {c['rel_tol']:g})")


CHECKS = {name[len("check_"):]: f for name, f in globals().items() if name.startswith("check_")}


def worst(values):
    """The largest value; infinite if any is missing or not a number (a diverged run
    writes nan to the CSV and null to the JSON)."""
    if any(v is None or v != v for v in values):
        return math.inf
    return max(values)


def load_run(out, m):
    """Everything a run left, or None when it left no results (bad input, crash)."""
    rdir = os.path.join(out, "runs", m["name"])
    summary_path = os.path.join(rdir, "summary.json")
    if not (os.path.exists(summary_path) and os.path.exists(os.path.join(rdir, "history.csv"))):
        return None
    with open(summary_path) as f:
        summary = json.load(f)
    with open(os.path.join(out, m["scene"])) as f:
        scene = json.load(f)
    frames, columns = read_history(os.path.join(rdir, "history.csv"))
    density = {k: v["density"] for k, v in scene["materials"].items()}
    free = [i for i, b in enumerate(scene["blocks"]) if not b.get("fixed")]
    mass = {i: density[scene["blocks"][i]["material"]] * area(scene["blocks"][i]["vertices"])
            for i in free}
    final = {i: (*summary["blocks"][i]["centroid"], *summary["blocks"][i]["velocity"][:2])
             for i in free}
    energy = summary.get("energy", {})
    run = {"summary": summary, "frames": frames, "free": free, "mass": mass, "final": final,
           "scale": m["scale"], "full": FULL_ACCOUNT in columns,
           "states": [{i: f["blocks"][i] for i in free} for f in frames] + [final],
           "gravity": scene.get("gravity", [0.0, -9.81]), "end_time": summary.get("end_time"),
           "kinetic_end": energy.get("kinetic", frames[-1]["kinetic"]),
           "potential_end": energy.get("potential", frames[-1]["potential"])}
    if run["full"]:
        # summary.json's maximum covers every step, the history only the output steps.
        series = [f[FULL_ACCOUNT] for f in frames]
        run["remainder_max"] = worst([energy.get("remainder_max", 0.0)] + series)
        # The most negative remainder (a binary older than the key: the output steps').
        run["remainder_min"] = -worst([-energy.get("remainder_min", 0.0)] + [-v for v in series])
    else:
        # The binary has no energy account: kinetic + potential + strain against the start.
        # It leaves out the contact springs and every dissipation, so it can hide a gain
        # that friction or damping took back at the same time.
        e0 = frames[0]["kinetic"] + frames[0]["potential"] + frames[0]["strain_energy"]
        series = [f["kinetic"] + f["potential"] + f["strain_energy"] - e0 for f in frames]
        run["remainder_max"] = worst([0.0] + series)
        run["remainder_min"] = 0.0  # not judged: the partial account leaves out every dissipation
    run["series"] = series
    return run


def judge(m, run, rc):
    """(passed, remainder share, physics text) of one run."""
    if run is None:
        return False, None, "no results"
    share = run["remainder_max"] / run["scale"]
    results = []
    for c in m["checks"]:
        try:
            results.append(CHECKS[c["kind"]](run, c))
        except (TypeError, ValueError) as e:  # null or nan in a diverged run's state
            results.append((False, f"{c['kind']} not measurable ({e})"))
    physics_ok = all(ok for ok, _ in results)
    text = "; ".join(("" if ok else "FAIL ") + t for ok, t in results)
    # A loss is judged against the energy that moved: the larger of the case's scale and
    # the run's own (summary.json's energy.scale holds the largest kinetic energy reached;
    # the toppling columns release 2.4 times their case's scale).
    moved = max(run["scale"], run["summary"].get("energy", {}).get("scale", 0.0))
    loss = -run["remainder_min"] / moved
    if loss > LOSS_TOLERANCE:
        physics_ok = False
        text = (text + "; " if text else "") + f"FAIL lost {loss:.3g} of the scale unbooked (<= {LOSS_TOLERANCE:g})"
    return rc == 0 and share <= TOLERANCE and physics_ok, share, text


def fmt(x, spec=".3g"):
    return "n/a" if x is None else format(x, spec)


def plot_case(out, case, entries):
    """One column per run of the case: the energy terms over time above, the remainder as
    a share of the scale (against the tolerance) below."""
    fig, axes = plt.subplots(2, len(entries), figsize=(4.5 * len(entries), 6), squeeze=False,
                             sharex="col", gridspec_kw={"height_ratios": [2, 1]})
    for col, (m, run) in enumerate(entries):
        top, bottom = axes[0][col], axes[1][col]
        top.set_title(f"{m['mode']}, dt {m['dt']:g} s", fontsize=9)
        bottom.set_xlabel("time (s)")
        if run is None:
            top.text(0.5, 0.5, "no output", ha="center", transform=top.transAxes)
            continue
        t = [f["time"] for f in run["frames"]]
        for term in TERMS:
            if term in run["frames"][0]:
                ref = run["frames"][0][term] if term == "potential" else 0.0
                label = "potential - start" if term == "potential" else term
                top.plot(t, [f[term] - ref for f in run["frames"]], label=label, lw=1)
        bottom.plot(t, [r / run["scale"] for r in run["series"]], "k", lw=1,
                    label="remainder" if run["full"] else "KE+PE+SE - start (partial)")
        bottom.axhline(TOLERANCE, color="r", lw=0.8, ls=":", label="tolerance")
        if not any(ax.get_legend() for ax in axes[0]):  # one legend, on the first run drawn
            top.legend(fontsize=7)
            bottom.legend(fontsize=7)
    axes[0][0].set_ylabel("J/m")
    axes[1][0].set_ylabel("remainder / scale")
    fig.suptitle(f"{case}: energy terms (scale {entries[0][0]['scale']:.4g} J/m)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"{case}.png"), dpi=80)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        print("usage: report.py OUT_DIR", file=sys.stderr)
        return 2
    out = sys.argv[1]
    with open(os.path.join(out, "scenes", "manifest.json")) as f:
        manifest = json.load(f)
    status = {}
    with open(os.path.join(out, "runs", "status.tsv")) as f:
        for line in f:
            name, rc, wall = line.split("\t")
            status[name] = (int(rc), float(wall))
    rows, notes, by_case, failed, partial = [], [], {}, 0, False
    for m in manifest:
        rc, wall = status.get(m["name"], (None, None))
        run = load_run(out, m)
        ok, share, physics = judge(m, run, rc)
        failed += not ok
        by_case.setdefault(m["case"], []).append((m, run))
        s = run["summary"] if run else {}
        partial |= bool(run and not run["full"])
        oc = s.get("open_close_iterations", {})
        deepest = s.get("contacts", {}).get("deepest_penetration")
        rem = fmt(share) + ("" if run is None or run["full"] else "*")
        rows.append(f"| {m['case']} | {m['dt']:g} | {m['mode']} | {fmt(rc, 'd')} | "
                    f"{s.get('steps', 'n/a')} | {s.get('cut_steps', 'n/a')} | "
                    f"{fmt(oc.get('mean'), '.2f')} / {oc.get('max', 'n/a')} | "
                    f"{fmt(deepest)} | {s.get('penalty_raises', 'n/a')} | {fmt(wall, '.1f')} | "
                    f"{rem} | {physics} | **{'pass' if ok else 'FAIL'}** |")
        if s.get("message"):
            notes.append(f"- `{m['name']}`: {s['message'][:400]}")
    lines = ["# Hard cases: multi-block dynamics that never gains energy", "",
             f"{len(manifest) - failed} of {len(manifest)} runs pass. A run passes when `dda` "
             f"exits 0, its energy remainder stays below {TOLERANCE:g} of the case's energy "
             f"scale (and above -{LOSS_TOLERANCE:g}: energy lost unbooked) and its physics "
             "checks hold (`verification/hard-cases/README.md`).", "",
             "| case | dt (s) | mode | exit | steps | cut steps | open-close mean / max | "
             "deepest penetration (m) | penalty raises | wall (s) | remainder / scale | "
             "physics (measured) | verdict |",
             "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|"] + rows
    if partial:
        lines += ["", "\\* The binary writes no energy account (no `energy_remainder` column): "
                  "the remainder shown is kinetic + potential + strain energy against the "
                  "start, at output steps only; it leaves out contact springs and "
                  "dissipation, so it can miss a gain."]
    lines += ["", "Energy scales (J/m): " + ", ".join(
        f"{case} {entries[0][0]['scale']:.4g} ({entries[0][0]['scale_note']})"
        for case, entries in by_case.items()) + "."]
    if notes:
        lines += ["", "Runs that stopped early:", ""] + notes
    lines += ["", "Energy terms over time: " + ", ".join(f"`{c}.png`" for c in by_case) + "."]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "report.md"), "w") as f:
        f.write(text)
    for case, entries in by_case.items():
        plot_case(out, case, entries)
    print(text, end="")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
