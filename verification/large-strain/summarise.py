#!/usr/bin/python3
"""Summarises verification/large-strain/run.sh OUT_DIR: OUT_DIR/report.md and report.json,
a row a run (scene, treatment, exit, steps, solves, the energy account's largest gain and
largest loss of the remainder over the scene's energy scale, CPU time), and exits 1 if the
default treatment (finite_rotation_polar) fails a check:

  - a scene expected to run reaches its end (exit 0) with the remainder's largest gain and
    largest loss within the tolerance of its kind (below) of the energy scale;
  - in every run of a scene with plastic blocks (a material other than elastic), the
    plastic dissipation (history.csv `plastic_dissipation`, cumulative) and its increments
    between the rows written (each step in the thrown, crushed and static scenes, every 10th step
    in the 3000-step drops) are never below -PLASTIC_ROUNDOFF x the energy scale;
  - the Mohr-Coulomb block without a tension cut-off stops (exit not 0) with a message
    that names the block and the reason (the stress beyond the apex, which psi = 0 cannot
    return), not only that the step was cut.

finite_rotation's rows are reported, not checked: the study is there to show it fail.

    summarise.py OUT_DIR
"""
import csv
import json
import os
import re
import sys

DEFAULT = "finite_rotation_polar"

# |remainder| / scale allowed to the default, by kind of scene. Both are the largest share
# measured (README.md) with a margin of about 1.6, and both lie far below
# control.energy_tolerance (0.02), the guard that stopped finite_rotation's runs.
TOLERANCE = {
    # Blocks set on the base and loaded by gravity at once, no impact: largest measured
    # 1.84e-4 (soft6, the 6 m block straining 15 % at its foot). finite_rotation's stack,
    # which runs to its end, gains 2.0e-3 and fails this; the default's stack 2.2e-6.
    "settling": 3e-4,
    # A block dropped onto the base: largest measured 1.23e-3 (drop1, the 1 m drop), all of
    # it built up over the impact's steps, as in the same block elastic (elastic_drop1:
    # 1.12e-3 at dt 0.001 s; the hard cases' impacts lose up to 1.1e-2,
    # docs/energy-balance.md). 1.6e-3 is that with a margin of 1.3, tight enough to fail
    # the 0.7e-3 the plastic block gained in flight after the rebound until its spins had
    # to agree with its answer (step.cpp, follow_spins; drop1 then gained 1.92e-3).
    "impact": 1.6e-3,
}

# Round-off allowed to the plastic dissipation below zero, as a share of the energy scale.
# A step's plastic dissipation is A (sigma1 - sigma0) . d_eps - dU_el - A/2 dsigma : C^-1 :
# dsigma (docs/energy-balance.md), a difference of terms no larger than the scene's energy
# (scale): what is left of it in a step without plastic flow is round-off of those terms,
# a few 1e-16 of them. Measured over every run: the most negative increment
# -9.5e-13 J/m (drop1, rows every 10th step; 1.9e-17 of its scale; throw -2.3e-13), the
# most negative total -1.8e-12 J/m (drop1, which flows only at its tension cut-off,
# where sigma . d_eps_p = 0). 1e-12 of the scale (2.7e-8 to 3.4e-7 J/m here) is ~4e4
# times that, and ~1e-9 of the smallest plastic work a step books where the block yields
# (push_static's last flowing steps, 1e-1 J/m): a flow that booked negative work would
# fail it, round-off would not.
PLASTIC_ROUNDOFF = 1e-12

# The one thing a message about a stalled step must not be reduced to.
STEP_CUT = "time step cut below 1e-9"


def load_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def error_message(out, file, summary):
    """The run's reason for stopping: summary.json's message, or the log's error line (a
    scene refused before it ran writes no summary)."""
    if summary and summary.get("message"):
        return summary["message"]
    try:
        with open(os.path.join(out, "runs", file + ".log")) as f:
            lines = [l.strip() for l in f if "error" in l]
        return lines[-1] if lines else ""
    except OSError:
        return ""


def warnings(out, file):
    try:
        with open(os.path.join(out, "runs", file + ".log")) as f:
            return [l.strip() for l in f if l.startswith("dda: warning")]
    except OSError:
        return []


def check_stop(message, free_blocks):
    """A clear stop: names one of the free blocks and the material's reason."""
    names_block = any(re.search(rf"\bblock {i}\b", message) for i in free_blocks)
    names_reason = "beyond the apex" in message
    problems = []
    if not names_block:
        problems.append("does not name the block")
    if not names_reason:
        problems.append("does not give the reason (stress beyond the apex)")
    # The reason must come first: a message that opens with the step cut reads as a solver
    # failure (a user needs the block and the reason, "not a step cut below 1e-9").
    if STEP_CUT in message.split(";")[0]:
        problems.append("leads with the step cut, not the reason")
    return problems


def plastic_blocks(scene):
    """Indices of the free blocks whose material is not elastic."""
    mats = scene.get("materials", {})
    return [i for i, b in enumerate(scene["blocks"]) if not b.get("fixed")
            and mats.get(b.get("material"), {}).get("model", "elastic") != "elastic"]


def plastic_history(out, file):
    """(steps, cumulative plastic dissipation) from history.csv, one value a step written
    (a scene total, repeated on each block's row; a step written twice is taken once)."""
    steps, values = [], []
    try:
        with open(os.path.join(out, "runs", file, "history.csv")) as f:
            for r in csv.DictReader(f):
                step = int(r["step"])
                if steps and steps[-1] == step:
                    continue
                steps.append(step)
                values.append(float(r["plastic_dissipation"]))
    except (OSError, ValueError, KeyError):
        return None
    return steps, values


def plastic_check(out, file, scale):
    """The plastic dissipation's final value, its most negative total and most negative
    increment between written rows (with their steps), and the problems found."""
    h = plastic_history(out, file)
    if h is None or not h[0]:
        return {}, ["no history.csv to check the plastic dissipation"]
    steps, values = h
    tol = PLASTIC_ROUNDOFF * scale
    i_min = min(range(len(values)), key=lambda i: values[i])
    res = {"plastic_final": values[-1], "plastic_min": min(0.0, values[i_min]),
           "plastic_min_step": steps[i_min] if values[i_min] < 0 else None,
           "plastic_min_increment": 0.0, "plastic_min_increment_step": None,
           "plastic_rows": len(steps), "plastic_tolerance": tol}
    for k in range(1, len(values)):
        inc = values[k] - values[k - 1]
        if inc < res["plastic_min_increment"]:
            res["plastic_min_increment"] = inc
            res["plastic_min_increment_step"] = steps[k]
    problems = []
    if res["plastic_min"] < -tol:
        problems.append(f"plastic dissipation {res['plastic_min']:.3g} J/m at step "
                        f"{res['plastic_min_step']} < -{tol:.2g}")
    if res["plastic_min_increment"] < -tol:
        problems.append(f"plastic dissipation fell by {-res['plastic_min_increment']:.3g} J/m "
                        f"at step {res['plastic_min_increment_step']} (> {tol:.2g})")
    return res, problems


def fmt_energy(x):
    return "–" if x is None else f"{x:.3g}"


def fmt_share(x):
    return "–" if x is None else f"{x:.2e}"


def main():
    if len(sys.argv) != 2:
        print("usage: summarise.py OUT_DIR", file=sys.stderr)
        return 2
    out = sys.argv[1]
    manifest = load_json(os.path.join(out, "manifest.json"))
    if manifest is None:
        print(f"summarise.py: {out}/manifest.json missing or unreadable (run make_scenes.py)",
              file=sys.stderr)
        return 2
    status = {}
    try:
        with open(os.path.join(out, "status.tsv")) as f:
            for line in f:
                name, rc, user, sys_ = line.rstrip("\n").split("\t")
                status[name] = {"exit": int(rc), "cpu_s": float(user) + float(sys_)}
    except (OSError, ValueError) as e:
        print(f"summarise.py: {out}/status.tsv: {e}", file=sys.stderr)
        return 2

    rows, failed = [], False
    for m in manifest:
        file = m["file"]
        scene = load_json(os.path.join(out, "scenes", file + ".json"))
        free = [i for i, b in enumerate(scene["blocks"]) if not b.get("fixed")]
        s = load_json(os.path.join(out, "runs", file, "summary.json"))
        st = status.get(file, {"exit": None, "cpu_s": None})
        row = {**m, "exit": st["exit"], "cpu_s": st["cpu_s"], "summary": s is not None}
        if s:
            e = s["energy"]
            row.update({"steps": s["steps"], "solves": s["iterations"],
                        "cut_steps": s["cut_steps"], "end_time": s["end_time"],
                        "scale": e["scale"], "gain": e["remainder_max"],
                        "gain_share": e["remainder_max_share"],
                        "gain_step": e["remainder_max_step"], "loss": e["remainder_min"],
                        "loss_share": e["remainder_min_share"],
                        "loss_step": e["remainder_min_step"]})
        row["message"] = error_message(out, file, s) if st["exit"] else ""
        row["warnings"] = warnings(out, file)
        problems = []
        if m["expect"] == "run":
            tol = TOLERANCE[m["kind"]]
            row["tolerance"] = tol
            if st["exit"] != 0:
                problems.append(f"exit {st['exit']}")
            if not s:
                problems.append("no summary.json")
            elif s["diverged"] or s["interrupted"]:
                # the message itself is listed under the table
                problems.append(f"stopped at step {s['steps']}")
            else:
                if abs(row["gain_share"]) > tol:
                    problems.append(f"gain {row['gain_share']:.2e} > {tol:g}")
                if abs(row["loss_share"]) > tol:
                    problems.append(f"loss {row['loss_share']:.2e} > {tol:g}")
        else:
            if st["exit"] in (0, None):
                problems.append(f"exit {st['exit']}: ran to its end")
            else:
                problems += check_stop(row["message"], free)
            row["message_leads_with_step_cut"] = STEP_CUT in row["message"].split(";")[0]
        row["plastic"] = bool(plastic_blocks(scene))
        if row["plastic"] and s:
            res, pproblems = plastic_check(out, file, s["energy"]["scale"])
            row.update(res)
            problems += pproblems
        row["problems"] = problems
        if m["default"]:
            row["check"] = "FAIL: " + "; ".join(problems) if problems else "pass"
            failed |= bool(problems)
        else:
            row["check"] = "reported (" + ("; ".join(problems) if problems else "would pass") + ")"
        rows.append(row)

    # Solves over the same steps: the default's runs cut at the step where finite_rotation
    # stopped (full study only), or the whole runs where both reached their end.
    same_steps = []
    by = {(r["name"], r["treatment"]): r for r in rows}
    for r in rows:
        if r["treatment"] != "finite_rotation" or not r["summary"]:
            continue
        polar = by.get((r["name"], DEFAULT))
        if not polar or not polar["summary"]:
            continue
        if r["exit"] == 0 and polar["exit"] == 0:
            same_steps.append({"name": r["name"], "steps": r["steps"],
                               "finite_rotation": r["solves"], DEFAULT: polar["solves"],
                               "note": "both to their end"})
            continue
        if r["exit"] == 0 or polar["exit"] != 0:
            continue
        file = f"{r['name']}_{DEFAULT}_to{r['steps']}"
        t = load_json(os.path.join(out, "runs", file, "summary.json"))
        if t:
            same_steps.append({"name": r["name"], "steps": t["steps"],
                               "finite_rotation": r["solves"], DEFAULT: t["iterations"],
                               "note": f"to finite_rotation's stop (default cut at step {t['steps']})"})
    for c in same_steps:
        c["ratio"] = c[DEFAULT] / c["finite_rotation"]

    lines = ["# Blocks that strain a lot: the default treatment against finite_rotation", "",
             "Energy shares are the energy account's remainder over the scene's energy scale "
             "(summary.json `energy.remainder_max_share`, `remainder_min_share`; "
             "docs/energy-balance.md). Tolerances for the default: "
             + ", ".join(f"{k} {v:g}" for k, v in TOLERANCE.items())
             + " (summarise.py says why). finite_rotation's rows are reported, not checked. "
             "Plastic dissipation (scenes with plastic blocks): its value at the end and its "
             "most negative increment between rows of history.csv (J/m), neither allowed below "
             f"-{PLASTIC_ROUNDOFF:g} of the scale.", "",
             "| scene | treatment | exit | steps | solves | largest gain / scale | largest loss / scale | CPU (s) | check | plastic dissipation (J/m) | most negative increment (J/m) |",
             "|---|---|---:|---:|---:|---:|---:|---:|---|---:|---:|"]
    for r in rows:
        steps = r.get("steps", "–")
        solves = r.get("solves", "–")
        cpu = "–" if r["cpu_s"] is None else f"{r['cpu_s']:.2f}"
        lines.append(f"| {r['name']} | {r['treatment']} | {r['exit']} | {steps} | {solves} | "
                     f"{fmt_share(r.get('gain_share'))} | {fmt_share(r.get('loss_share'))} | "
                     f"{cpu} | {r['check']} | {fmt_energy(r.get('plastic_final'))} | "
                     f"{fmt_energy(r.get('plastic_min_increment'))} |")
    if same_steps:
        lines += ["", "Solves over the same steps (the default should take no more than finite_rotation):", "",
                  "| scene | steps | finite_rotation | finite_rotation_polar | ratio | |",
                  "|---|---:|---:|---:|---:|---|"]
        for c in same_steps:
            lines.append(f"| {c['name']} | {c['steps']} | {c['finite_rotation']} | {c[DEFAULT]} | "
                         f"{c['ratio']:.2f} | {c['note']} |")
    stops = [r for r in rows if r["exit"] not in (0, None)]
    if stops:
        lines += ["", "Why runs stopped:", ""]
        for r in stops:
            lines.append(f"- {r['name']}, {r['treatment']} (exit {r['exit']}): {r['message']}")
    lines += ["", "Warnings of the default's runs:", ""]
    seen = False
    for r in rows:
        if r["default"]:
            for w in r["warnings"]:
                lines.append(f"- {r['name']}: {w}")
                seen = True
    if not seen:
        lines.append("- none")
    lines += ["", "Default treatment: " + ("FAIL" if failed else "every check passed")]

    report = {"tolerance": TOLERANCE, "plastic_roundoff": PLASTIC_ROUNDOFF, "runs": rows, "same_steps": same_steps,
              "default_passed": not failed}
    for name, text in (("report.md", "\n".join(lines) + "\n"),
                       ("report.json", json.dumps(report, indent=1) + "\n")):
        path = os.path.join(out, name)
        with open(path + ".part", "w") as f:
            f.write(text)
        os.replace(path + ".part", path)
    print("\n".join(lines))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
