#!/usr/bin/python3
"""Table of compare.sh's runs: the fastest run of each program on each scene.

    compare_table.py RUNS.jsonl RESULTS.json

Prints a markdown table and writes RESULTS.json (one entry per scene and program: the
fastest run's wall time, every run's time, steps, iterations, cuts, simulated time and
the largest centroid movement).
"""
import json
import math
import sys


def poly_centroid(poly):
    a = cx = cy = 0.0
    for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
        c = x0 * y1 - x1 * y0
        a += c
        cx += (x0 + x1) * c
        cy += (y0 + y1) * c
    return cx / (3 * a), cy / (3 * a)


def ours_run(r):
    try:
        with open(r["summary"]) as f:
            s = json.load(f)
    except OSError:
        return None
    with open(r["scene_file"]) as f:
        scene = json.load(f)
    move = 0.0
    for b0, b1 in zip(scene["blocks"], s["blocks"]):
        x0, y0 = poly_centroid(b0["vertices"])
        x1, y1 = b1["centroid"]
        move = max(move, math.hypot(x1 - x0, y1 - y0))
    return {"ok": not s.get("diverged") and not s.get("interrupted"), "steps": s["steps"],
            "solves": s["iterations"], "cut_steps": s["cut_steps"], "cuts": s["cuts"],
            "simulated_time": s["end_time"], "max_centroid_move": move,
            "message": s.get("message", ""), "blocks": len(scene["blocks"])}


def ntdda_run(r):
    o = r.get("out") or {}
    if "steps" not in o:
        return {"ok": False, "message": o.get("message", f"rc {r['rc']}"),
                "steps": o.get("failed_step", 0)}
    return {"ok": o.get("ok") == 1 and r["rc"] == 0, "steps": o["steps"],
            "solves": o["solves"], "repeated": o["repeated"],
            "repeated_oc_limit": o["repeated_oc_limit"],
            "simulated_time": o["simulated_time"], "max_centroid_move": o["max_centroid_move"],
            "blocks": o["blocks"], "analysis_s": o["analysis_s"]}


def main():
    runs = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
    scenes = []
    for r in runs:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    results = {}
    for sc in scenes:
        results[sc] = {}
        progs = []
        for r in runs:
            if r["scene"] == sc and r["program"] not in progs:
                progs.append(r["program"])
        for prog in progs:
            rs = [r for r in runs if r["scene"] == sc and r["program"] == prog]
            if not rs:
                continue
            best = min(rs, key=lambda r: r["wall_s"])
            info = ntdda_run(best) if prog.startswith("ntdda") else ours_run(best)
            if info is None:
                info = {"ok": False, "message": f"rc {best['rc']}, no summary"}
            info["wall_s"] = best["wall_s"]
            cpus = [r.get("cpu_s") for r in rs if r.get("cpu_s") is not None]
            info["cpu_s"] = min(cpus) if cpus else None
            info["wall_s_all"] = [r["wall_s"] for r in rs]
            if prog.startswith("ntdda"):
                info["convert"] = best.get("convert")
            results[sc][prog] = info
    with open(sys.argv[2], "w") as f:
        json.dump(results, f, indent=1)

    head = ["scene", "blocks", "program", "wall s (min)", "CPU s (min)", "ms/step", "steps (simulated)",
            "solves/step", "redone or cut", "largest move m"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for sc in scenes:
        blocks = next((i.get("blocks") for i in results[sc].values() if i.get("blocks")), "-")
        for prog, i in results[sc].items():
            row = [sc, str(blocks), prog]
            if "solves" not in i:
                row += [f"{i['wall_s']:.3g}", "-", "-", f"failed at step {i.get('steps', '-')}",
                        "-", i.get("message", "-"), "-"]
            else:
                st = max(i["steps"], 1)
                redo = (f"{i['repeated']} redone ({i['repeated_oc_limit']} at the OC limit)"
                        if prog.startswith("ntdda") else
                        f"{i['cut_steps']} cut ({i['cuts'].get('open_close', 0)} open-close)")
                cpu = "-" if i.get("cpu_s") is None else f"{i['cpu_s']:.3g}"
                row += [f"{i['wall_s']:.3g}" + ("" if i.get("ok") else " (stopped)"), cpu,
                        f"{1000 * i['wall_s'] / st:.3g}",
                        f"{i['steps']} ({i['simulated_time']:.3g} s)",
                        f"{i['solves'] / st:.2f}", redo, f"{i['max_centroid_move']:.2g}"]
            print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
