#!/usr/bin/env python3
"""Scenes of the multi-block work-precision study (README.md), one per case, time step and
penalty factor, with their closed forms in OUT/manifest.json.

    /usr/bin/python3 verification/work-precision/make_scenes.py OUT [--smoke]

Cases:
  slide  a 0.5 m x 0.25 m block on a row of eight fixed 0.25 m blocks (its base crosses their
         joints), gravity tilted by 30 degrees (an incline), friction 20 degrees, from rest
         for 1 s, dynamic: x(t) = g (sin 30 - cos 30 tan 20) t^2 / 2 (0.906 m);
  slide_free  the same on a row of eight free blocks bonded to a fixed base and to each
         other (a glue joint material: c = T = 10 MPa), so that the joints it crosses are
         between free blocks;
  stack  five 1 m x 0.5 m blocks on a fixed base, gravity at once, static steps for 2 s:
         the bottom block's mean vertical stress carries the four above and half of itself,
         syy = -rho g (4 x 0.5 + 0.25) (-59 594 Pa).
"""
import argparse
import json
import math
import os

G = 9.81
DENSITY = 2700.0
YOUNG = 1e9
SLOPE = 30.0
FRICTION = 20.0


def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def base_scene(dt, end_time, dynamic, penalty_factor, gravity, friction):
    return {
        "gravity": gravity,
        "control": {"time_step": dt, "end_time": end_time, "dynamic_coefficient": dynamic,
                    "max_displacement_ratio": 0.01, "penalty": penalty_factor * YOUNG,
                    "output_every": 1000000},
        "materials": {"rock": {"model": "elastic", "density": DENSITY, "young": YOUNG,
                               "poisson": 0.25}},
        "joint_materials": {"default": {"friction_angle": friction, "cohesion": 0.0,
                                        "tensile_strength": 0.0}},
        "blocks": [],
    }


def slide(dt, penalty_factor):
    t = math.radians(SLOPE)
    s = base_scene(dt, 1.0, 1.0, penalty_factor, [G * math.sin(t), -G * math.cos(t)], FRICTION)
    for k in range(8):
        s["blocks"].append({"vertices": rect(0.25 * k, -0.25, 0.25 * (k + 1), 0.0),
                            "material": "rock", "fixed": True})
    s["blocks"].append({"vertices": rect(0.05, 0.0, 0.55, 0.25), "material": "rock"})
    a = G * (math.sin(t) - math.cos(t) * math.tan(math.radians(FRICTION)))
    return s, {"quantity": "x displacement of the sliding block at 1 s (m)",
               "block": 8, "exact": 0.5 * a}


def slide_free(dt, penalty_factor):
    s, reference = slide(dt, penalty_factor)
    t = math.radians(SLOPE)
    s["blocks"] = [{"vertices": rect(-0.5, -1.25, 2.5, -0.25), "material": "rock", "fixed": True}]
    for k in range(8):
        s["blocks"].append({"vertices": rect(0.25 * k, -0.25, 0.25 * (k + 1), 0.0),
                            "material": "rock"})
    s["blocks"].append({"vertices": rect(0.05, 0.0, 0.55, 0.25), "material": "rock"})
    s["joint_materials"]["glue"] = {"friction_angle": 45.0, "cohesion": 1e7,
                                    "tensile_strength": 1e7}
    s["joints"] = [{"blocks": [0, k + 1], "material": "glue"} for k in range(8)] + \
                  [{"blocks": [k + 1, k + 2], "material": "glue"} for k in range(7)]
    reference["block"] = 9
    return s, reference


def stack(dt, penalty_factor):
    s = base_scene(dt, 2.0, 0.0, penalty_factor, [0.0, -G], 30.0)
    s["blocks"].append({"vertices": rect(-0.5, -0.5, 1.5, 0.0), "material": "rock", "fixed": True})
    for k in range(5):
        s["blocks"].append({"vertices": rect(0.0, 0.5 * k, 1.0, 0.5 * (k + 1)), "material": "rock"})
    return s, {"quantity": "mean Cauchy syy of the bottom block (Pa; per unit width at the start)",
               "block": 1, "exact": -DENSITY * G * (4 * 0.5 + 0.25), "initial_area": 0.5}


def main():
    parser = argparse.ArgumentParser(description="work-precision scenes")
    parser.add_argument("out")
    parser.add_argument("--smoke", action="store_true", help="two time steps, one penalty")
    args = parser.parse_args()
    os.makedirs(os.path.join(args.out, "scenes"), exist_ok=True)
    sweeps = {
        "slide": ([0.01, 0.005] if args.smoke else [0.02, 0.01, 0.005, 0.0025, 0.00125],
                  [50.0] if args.smoke else [5.0, 50.0, 500.0]),
        "slide_free": ([0.01, 0.005] if args.smoke else [0.02, 0.01, 0.005, 0.0025, 0.00125],
                       [50.0] if args.smoke else [5.0, 50.0, 500.0]),
        "stack": ([0.04, 0.02] if args.smoke else [0.04, 0.02, 0.01, 0.005],
                  [50.0] if args.smoke else [5.0, 50.0, 500.0]),
    }
    manifest = []
    for case, (dts, penalties) in sweeps.items():
        for dt in dts:
            for p in penalties:
                make = {"slide": slide, "slide_free": slide_free, "stack": stack}[case]
                scene, reference = make(dt, p)
                name = f"{case}_dt{dt:g}_p{p:g}"
                with open(os.path.join(args.out, "scenes", name + ".json"), "w") as f:
                    json.dump(scene, f, indent=1)
                manifest.append({"name": name, "case": case, "dt": dt, "penalty_factor": p,
                                 **reference})
    with open(os.path.join(args.out, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1)


if __name__ == "__main__":
    main()
