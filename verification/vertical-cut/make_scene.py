#!/usr/bin/python3
"""Writes the scene of a vertical cut in Tresca soil built of blocks whose joints can open
and slide (verification/vertical-cut/README.md).

    make_scene.py OUT.json [--cells-per-height N] [--stability-number S] [--joints MODE]
                  [--joint-strength R] [--model MODEL] [--softening EPS]

The cut is H = 10 m high, its toe at (0, 0); the soil reaches H in front of the toe, 2 H
behind it and 0.4 H below it, on a fixed rough base, between fixed smooth side walls. The
soil is a Tresca material (mohr_coulomb, phi = 0, psi = 0) of unit weight 20 kN/m^3 and
cohesion c = gamma H / S (S = 3 by default, so that the cut's factor of safety is the
critical stability number N = gamma H_c / c over S: 3.64 to 3.83, best estimate 3.78, so F
= 1.21 to 1.28, 1.26). Each square cell of side H / N is cut into four triangles by its
diagonals (the crossed mesh of verification/footing: constant-strain triangles lock in
isochoric flow less this way).

--joints MODE: "soil" (default): every joint between soil blocks is a Coulomb-slip bond
with the soil's cohesion, no friction and a tensile strength of 2 c (the soil's strength in
uniaxial tension under Tresca), so a mechanism may slip along the mesh's lines as a
velocity discontinuity of the same soil or form inside the blocks; "strong": the joints
are bonded at 1000 c (a finite-element mesh: only the blocks can yield).

--model MODEL: "mohr_coulomb" (default; Tresca at phi = 0) or "drucker_prager" (von Mises
at phi = 0, fitted with the plane-strain match, which in plane strain has Tresca's limit
loads: the same critical height).

--softening EPS: the soil's cohesion falls linearly from c to c / 2 as its equivalent plastic
strain grows from 0 to EPS (a hardening table), constant beyond (default: none, perfectly
plastic). The joints keep c.

--joint-strength R: with "soil" joints, their cohesion and tensile strength are R times the
soil's (default 1). Below about 0.97 the planar wedge that slides on the mesh's 45-degree
line from the toe is weaker than any mechanism through the blocks: its factor is then
4 R c / (gamma H) exactly (the joints carry c R along the line, the wedge's weight
gamma H^2 / 2 pulls along it at 45 degrees).
"""
import argparse
import json

GAMMA = 20e3      # N/m^3
G = 9.81
H = 10.0          # m
YOUNG = 1e8       # Pa
POISSON = 0.45


def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def scene(cells_per_height=5, stability_number=3.0, joints="soil", joint_strength=1.0,
          model="mohr_coulomb", softening=0.0):
    h = H / cells_per_height
    front = cells_per_height            # cells from the toe to the left wall (H)
    back = 2 * cells_per_height         # cells from the toe to the right wall (2 H)
    below = round(0.4 * cells_per_height)  # cells below the toe (0.4 H)
    if below < 1:
        raise SystemExit("make_scene.py: --cells-per-height must be at least 3")
    depth = below * h
    c = GAMMA * H / stability_number
    wall = 2.0
    blocks = [
        {"vertices": rect(-front * h - wall, -depth - wall, back * h + wall, -depth), "material": "base", "fixed": True},
        {"vertices": rect(-front * h - wall, -depth, -front * h, 0.5 * H), "material": "base", "fixed": True},
        {"vertices": rect(back * h, -depth, back * h + wall, 1.5 * H), "material": "base", "fixed": True},
    ]
    left, right = [], []  # soil blocks touching the side walls
    rows_back = below + cells_per_height
    for i in range(-front, back):
        rows = below if i < 0 else rows_back
        for j in range(rows):
            x0, y0 = i * h, -depth + j * h
            x1, y1 = x0 + h, y0 + h
            xm, ym = x0 + 0.5 * h, y0 + 0.5 * h
            for tri in ([[x0, y0], [x1, y0], [xm, ym]], [[x1, y0], [x1, y1], [xm, ym]],
                        [[x1, y1], [x0, y1], [xm, ym]], [[x0, y1], [x0, y0], [xm, ym]]):
                k = len(blocks)
                blocks.append({"vertices": tri, "material": "soil"})
                xs = [p[0] for p in tri]
                if min(xs) == -front * h:
                    left.append(k)
                if max(xs) == back * h:
                    right.append(k)
    strong = 1000.0 * c
    cj = joint_strength * c
    joint_soil = ({"friction_angle": 0.0, "cohesion": cj, "tensile_strength": 2.0 * cj, "law": "coulomb_slip"}
                  if joints == "soil" else
                  {"friction_angle": 0.0, "cohesion": strong, "tensile_strength": strong, "law": "coulomb_slip"})
    return {
        "description": f"vertical cut H = {H:g} m in Tresca soil, c = {c:.1f} Pa (gamma H / c = "
                       f"{stability_number:g}), {len(blocks) - 3} triangular blocks, joints {joints} "
                       f"(strength ratio {joint_strength:g}), {model} "
                       "(verification/vertical-cut)",
        "gravity": [0.0, -G],
        "plane": "strain",
        "control": {"time_step": 0.01, "max_displacement_ratio": 0.001, "output_every": 50},
        # Gravity ramped up over 0.5 s, then held 2 s: a static step relaxes towards
        # equilibrium against its inertia term 2 M / dt^2, which for this soft, 14 m deep
        # soil (rho H^2 / (E dt^2) about 40) takes on the order of a hundred steps.
        "stages": [{"duration": 0.5, "dynamic_coefficient": 0.0, "gravity_ramp": [0.0, 1.0]},
                   {"duration": 2.0, "dynamic_coefficient": 0.0}],
        "materials": {
            "soil": dict({"model": model, "density": GAMMA / G, "young": YOUNG, "poisson": POISSON,
                          "cohesion": c, "friction_angle": 0.0, "dilation_angle": 0.0},
                         **({"match": "plane_strain"} if model == "drucker_prager" else {}),
                         **({"hardening": [[0.0, c], [softening, 0.5 * c]]} if softening > 0.0 else {})),
            "base": {"model": "elastic", "density": GAMMA / G, "young": YOUNG, "poisson": POISSON},
        },
        "joint_materials": {
            "default": joint_soil,
            "smooth": {"friction_angle": 0.0, "cohesion": 0.0, "tensile_strength": 0.0},
        },
        "joints": [{"blocks": [1, k], "material": "smooth"} for k in left] +
                  [{"blocks": [2, k], "material": "smooth"} for k in right],
        "blocks": blocks,
        "monitors": [{"name": "crest", "point": [0.05 * h, H - 0.05 * h]},
                     {"name": "face", "point": [0.05 * h, 0.5 * H]}],
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", metavar="OUT.json")
    ap.add_argument("--cells-per-height", type=int, default=5)
    ap.add_argument("--stability-number", type=float, default=3.0)
    ap.add_argument("--joints", choices=("soil", "strong"), default="soil")
    ap.add_argument("--joint-strength", type=float, default=1.0)
    ap.add_argument("--model", choices=("mohr_coulomb", "drucker_prager"), default="mohr_coulomb")
    ap.add_argument("--softening", type=float, default=0.0)
    a = ap.parse_args()
    s = scene(a.cells_per_height, a.stability_number, a.joints, a.joint_strength, a.model,
              a.softening)
    with open(a.out, "w") as f:
        json.dump(s, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
