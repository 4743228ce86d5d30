"""Writes a dda cut model of a jointed slope whose factor is known by construction.

A 30 m slope with a 65 degree face (looking towards -x), bedding dipping 35 degrees out of
the face with one bedding plane through the toe, and cross joints normal to the bedding,
staggered layer by layer like bricks (so that no column of blocks runs through the layers).
The rock below the toe's bedding plane is one fixed block. Every joint has friction angle
PHI and no cohesion or tensile strength, so every slab between two bedding planes is free
to slide on its own plane: the planar limit-equilibrium factor is tan(PHI) / tan(35) at any
block size (1.1983 for PHI = 40). Face slivers and multi-block mechanisms may fail below it
(the limit analysis of dda fos finds them).

    /usr/bin/python3 make_model.py SPACING OUT.json [PHI] [--steep] [--cohesion C] [--tension T]

SPACING is the bedding spacing (m); the cross joints are 1.1 x SPACING apart along the bedding.
--steep: instead of the staggered cross joints, one persistent set dipping 75 degrees into the
slope (trace direction 105 degrees), 1.1 x SPACING apart: parallelogram columns that reach
from the face to the bedding, each block free to slide on its own bedding base or to
topple. --cohesion C (Pa) and --tension T (Pa) are the bedding's cohesion and tensile
strength (the cross joints keep none). With cohesion no single factor holds at every block
size: each block's own bound (limit equilibrium on its base, computed by dda fos) is the
reference.
"""
import json
import math
import sys


def model(spacing, phi, steep=False, cohesion=0.0, tension=0.0):
    a = math.radians(35.0)
    n = (-math.sin(a), math.cos(a))  # bedding normal
    u = (math.cos(a), math.sin(a))   # along the bedding, up the dip
    toe = (20.0, 10.0)
    height = 30.0
    crest = (toe[0] + height / math.tan(math.radians(65.0)), toe[1] + height)
    top_of_plane = (toe[0] + height / math.tan(a), toe[1] + height)
    below_toe = (toe[0] - n[0], toe[1] - n[1])  # the fixed band: 1 m under the toe's plane
    below_top = (top_of_plane[0] - n[0], top_of_plane[1] - n[1])
    corner = (below_top[0], toe[1] + height)
    domain = [below_toe, below_top, corner, crest, toe]
    dot = lambda p, q: p[0] * q[0] + p[1] * q[1]
    offset = dot(n, toe)
    e = 1e-3
    band = [(below_toe[0] - e, below_toe[1] - e), (below_top[0] + e, below_top[1] - e),
            (corner[0] + e, corner[1] + e), (top_of_plane[0] + e, top_of_plane[1] + e),
            (toe[0] - e, toe[1] + e)]
    cross = 1.1 * spacing
    a_min = min(dot(u, p) for p in domain) - cross
    a_max = max(dot(u, p) for p in domain) + cross
    b_max = max(dot(n, p) for p in domain)
    joints = []
    k = 0
    while not steep and offset + k * spacing < b_max:
        # Each cross joint spans one layer and a little more (the overhang is cut away).
        b0 = offset + (k - 0.05) * spacing
        b1 = offset + (k + 1.05) * spacing
        along = a_min + (0.5 * cross if k % 2 else 0.0)
        while along < a_max:
            p0 = (u[0] * along + n[0] * b0, u[1] * along + n[1] * b0)
            p1 = (u[0] * along + n[0] * b1, u[1] * along + n[1] * b1)
            joints.append({"from": [round(p0[0], 9), round(p0[1], 9)],
                           "to": [round(p1[0], 9), round(p1[1], 9)]})
            along += cross
        k += 1
    joint_sets = [{"dip": 35.0, "spacing": spacing, "offset": offset, "joint_material": "bedding"}]
    if steep:
        joint_sets.append({"dip": 105.0, "spacing": cross, "offset": 0.0})
        cross_text = "persistent cross joints dipping 75 degrees into the slope"
    else:
        cross_text = "cross joints normal to the bedding staggered layer by layer"
    if cohesion == 0.0 and tension == 0.0:
        verdict = f"every slab slides on its own plane at F = tan({phi}) / tan(35)"
    else:
        verdict = "each block's own limit-equilibrium bound is the reference"
    return {
        "description": (f"Planar bedding at 35 degrees, phi {phi}, c {cohesion:g} Pa, tensile "
                        f"strength {tension:g} Pa, {cross_text}, bedding spacing {spacing} m: "
                        f"{verdict} (verification/slope-cut/make_model.py)"),
        "gravity": [0.0, -9.81],
        "control": {"time_step": 0.01, "max_displacement_ratio": 0.01, "max_open_close": 20,
                    "output_every": 50},
        "materials": {"rock": {"model": "elastic", "density": 2500.0, "young": 5e9,
                               "poisson": 0.25, "rigid": True}},
        "joint_materials": {
            "default": {"friction_angle": phi, "cohesion": 0.0, "tensile_strength": 0.0},
            "bedding": {"friction_angle": phi, "cohesion": cohesion, "tensile_strength": tension}},
        "material": "rock",
        "domain": [list(p) for p in domain],
        "seed": 7,
        "joint_sets": joint_sets,
        "joints": joints,
        "fixed": {"edges": [0, 1], "polygon": [list(p) for p in band]},
        "min_block_area": 0.05 * spacing * spacing,
        "stages": [{"duration": 0.3, "dynamic_coefficient": 0.0, "gravity_ramp": [0, 1]}],
    }


if __name__ == "__main__":
    args = sys.argv[1:]
    steep = "--steep" in args
    args = [a for a in args if a != "--steep"]
    options = {"--cohesion": 0.0, "--tension": 0.0}
    for name in options:
        if name in args:
            i = args.index(name)
            options[name] = float(args[i + 1])
            del args[i:i + 2]
    if len(args) not in (2, 3):
        sys.exit("usage: make_model.py SPACING OUT.json [PHI] [--steep] [--cohesion C] [--tension T]")
    phi = float(args[2]) if len(args) == 3 else 40.0
    with open(args[1], "w") as f:
        json.dump(model(float(args[0]), phi, steep, options["--cohesion"], options["--tension"]),
                  f, indent=1)
        f.write("\n")
