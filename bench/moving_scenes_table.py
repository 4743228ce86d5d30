#!/usr/bin/python3
"""Prints the table of bench/moving_scenes.sh: one row per run of OUT_DIR.

    moving_scenes_table.py OUT_DIR [SOLVER_LABEL]

Reads OUT_DIR/scenes/manifest.json, OUT_DIR/runs/status.tsv and each run's summary.json,
and judges each run with verification/hard-cases/report.py (the same checks and energy
scale as the hard-case report).
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "verification", "hard-cases"))
import report  # noqa: E402


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    out = sys.argv[1]
    label = sys.argv[2] if len(sys.argv) == 3 else "default"
    with open(os.path.join(out, "scenes", "manifest.json")) as f:
        manifest = json.load(f)
    status = {}
    with open(os.path.join(out, "runs", "status.tsv")) as f:
        for line in f:
            name, rc, wall = line.rstrip("\n").split("\t")
            status[name] = (int(rc), float(wall))
    cpu = {}
    cpu_path = os.path.join(out, "runs", "cpu.tsv")
    if os.path.exists(cpu_path):
        with open(cpu_path) as f:
            for line in f:
                name, seconds = line.rstrip("\n").split("\t")
                cpu[name] = float(seconds)
    lines = [f"Moving scenes, contact solver: {label} (whole `dda run` process, one core)", "",
             "| scene | solver | simulated (s) | wall (s) | CPU (s) | steps | cut steps (disp / "
             "open-close / penetr. / overshoot / material) | solves | open-close mean / max | "
             "remainder max / scale | exit | verdict | checks (measured) |",
             "|---|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---|---|"]
    for m in manifest:
        rc, wall = status.get(m["name"], (None, None))
        with open(os.path.join(out, m["scene"])) as f:
            control = json.load(f)["control"]
        target = (f"{control['end_time']:g}" if "end_time" in control
                  else f"{control['steps']} steps")
        path = os.path.join(out, "runs", m["name"], "summary.json")
        if not os.path.exists(path):
            why = ""
            log = os.path.join(out, "runs", m["name"] + ".log")
            if os.path.exists(log):
                with open(log, errors="replace") as f:
                    errors = [ln.strip() for ln in f if ln.startswith("dda: error")]
                why = (": " + errors[-1][:300].replace("|", "/")) if errors else ""
            lines.append(f"| {m['name']} | – | – / {target} | {report.fmt(wall, '.1f')} "
                         f"| {report.fmt(cpu.get(m['name']), '.1f')} | – | – | – "
                         f"| – | – | {report.fmt(rc, 'd')} | FAIL | no results{why} |")
            continue
        with open(path) as f:
            s = json.load(f)
        cuts = s.get("cuts", {})
        cut_text = (f"{s.get('cut_steps', 0)} ({cuts.get('displacement', 0)} / "
                    f"{cuts.get('open_close', 0)} / {cuts.get('penetration', 0)} / "
                    f"{cuts.get('overshoot', 0)} / {cuts.get('material', 0)})")
        oc = s.get("open_close_iterations", {})
        # The solver the run used, when the build writes it; with the Newton solver, how
        # many solves its line search took only in part.
        solver = s.get("settings", {}).get("contact_solver", "–")
        shortened = s.get("contact_solver", {}).get("line_searches_shortened")
        if solver == "newton" and shortened is not None:
            solver += f" ({shortened} shortened)"
        run = report.load_run(out, m)
        ok, share, physics = report.judge(m, run, rc)
        verdict = "pass" if ok else "FAIL"
        lines.append(
            f"| {m['name']} | {solver} | {s.get('end_time', 0):.4g} / {target} "
            f"| {report.fmt(wall, '.1f')} "
            f"| {report.fmt(cpu.get(m['name']), '.1f')} | {s.get('steps')} | {cut_text} "
            f"| {s.get('iterations')} "
            f"| {report.fmt(oc.get('mean'), '.2f')} / {oc.get('max')} | {report.fmt(share, '.2g')} "
            f"| {report.fmt(rc, 'd')} | {verdict} | {physics} |")
    lines += ["", "solver: summary.json's settings.contact_solver (– when the build does not "
              "write it), with the Newton solver's line searches that took a solve only in "
              "part; simulated: the time the run reached / its end (or steps); wall: the whole "
              "process; CPU: its user + system seconds; solves: linear "
              "solves in all (summary.json `iterations`); remainder: the largest energy "
              "remainder over the hard-case scale of the scene (tolerance "
              f"{report.TOLERANCE:g}); checks: verification/hard-cases/README.md."]
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
