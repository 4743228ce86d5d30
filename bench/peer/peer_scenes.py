#!/usr/bin/python3
"""Writes the scenes of the side-by-side comparison with ntdda (docs/peer-comparison.md).

    peer_scenes.py OUT_DIR [--end-time T]

OUT_DIR/wallN.json, N = 30, 110, 420, 1000, 4000: brick walls as a user writes them, settling
from their built state: bricks 1 m x 0.5 m in running bond (the odd rows closed by half
bricks), on a fixed base 1 m thick reaching 1 m beyond either end, as bench/brick_wall.hpp
builds them; rock (2700 kg/m3, E 1 GPa, nu 0.25), joints at 30 degrees without cohesion,
dt 0.002 s, 200 steps (with --end-time T: run to T seconds instead, as the comparison to
0.4 s does), everything else at its default (penalty auto = 50 E).
The moving scenes (box150, hopper300, ...) come from
verification/hard-cases/make_scenes.py --moving.
"""
import argparse
import json
import math
import os

ROCK = {"model": "elastic", "density": 2700.0, "young": 1.0e9, "poisson": 0.25}
JOINT = {"friction_angle": 30.0, "cohesion": 0.0, "tensile_strength": 0.0}


def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def wall(n, steps=200, end_time=None):
    cols = math.ceil(math.sqrt(2.0 * n))
    blocks = [{"vertices": rect(-1.0, -1.0, cols + 1.0, 0.0), "material": "rock", "fixed": True}]
    row = placed = 0
    while placed < n:
        if row % 2 == 0:
            joints = list(range(cols + 1))
        else:
            joints = [0.0] + [c + 0.5 for c in range(cols)] + [float(cols)]
        y = 0.5 * row
        for x0, x1 in zip(joints, joints[1:]):
            if placed == n:
                break
            blocks.append({"vertices": rect(float(x0), y, float(x1), y + 0.5), "material": "rock"})
            placed += 1
        row += 1
    return {"description": f"brick wall of {n} bricks in running bond settling from its built "
                           "state (bench/peer/peer_scenes.py)",
            "gravity": [0.0, -9.81],
            "control": ({"time_step": 0.002, "end_time": end_time} if end_time
                        else {"time_step": 0.002, "steps": steps}),
            "materials": {"rock": ROCK},
            "joint_materials": {"default": JOINT},
            "blocks": blocks}


def positive_seconds(text):
    value = float(text)
    if not value > 0.0:
        raise ValueError(text)
    return value


def main():
    # argparse: an option is never read as OUT_DIR (one once wrote the walls into a
    # directory named "--help").
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir")
    ap.add_argument("--end-time", type=positive_seconds, default=None,
                    help="run each wall to this many seconds instead of 200 steps")
    a = ap.parse_args()
    os.makedirs(a.out_dir, exist_ok=True)
    scenes = {f"wall{n}": wall(n, end_time=a.end_time) for n in (30, 110, 420, 1000, 4000)}
    for name, s in scenes.items():
        with open(os.path.join(a.out_dir, name + ".json"), "w") as f:
            json.dump(s, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
