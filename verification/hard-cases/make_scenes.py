#!/usr/bin/python3
"""Writes the hard-case scenes (issue 9) and their manifest.

    make_scenes.py OUT_DIR [--smoke]

OUT_DIR/scenes/NAME.json are scenes in docs/scene-format.md (documented keys only);
OUT_DIR/scenes/manifest.json lists every run: its scene, case, dt, mode, the case's energy
scale (J/m) and the physics checks report.py applies. Deterministic: the random shapes and
tilts come from fixed seeds.
"""
import argparse
import json
import math
import os
import random

G = 9.81
RHO = 2700.0
ROCK = {"model": "elastic", "density": RHO, "young": 1.0e9, "poisson": 0.25}
FRICTION = 30.0  # degrees, every joint but the slope's (which names its own)


def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def square(cx, cy, side, angle_deg=0.0):
    c, s, h = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg)), side / 2
    return [[cx + c * x - s * y, cy + s * x + c * y] for x, y in ((-h, -h), (h, -h), (h, h), (-h, h))]


def area(poly):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))


def centroid_y(poly):
    a = area(poly)
    return sum((y0 + y1) * (x0 * y1 - x1 * y0)
               for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1])) / (6 * a)


def weight(poly):
    return RHO * area(poly) * G


def fixed(poly):
    return {"vertices": poly, "material": "rock", "fixed": True}


def free(poly, velocity=None):
    b = {"vertices": poly, "material": "rock"}
    if velocity:
        b["velocity"] = velocity
    return b


def box_walls(width, height):
    """A floor and two walls 0.2 m thick around the inner space [0, width] x [0, height]."""
    return [fixed(rect(-0.2, -0.2, width + 0.2, 0.0)), fixed(rect(-0.2, 0.0, 0.0, height)),
            fixed(rect(width, 0.0, width + 0.2, height))]


def settled_layer_scale(polys, width):
    """Potential energy the blocks release if they settle into a void-free layer on the floor
    (y = 0) of a box `width` wide: their weight times the fall of their centroid to that
    layer's mid-height. It is the 'drop available' of a pile; a real pile has voids, so it
    releases a little less, and the tolerance is then a little more lenient."""
    total_area = sum(area(p) for p in polys)
    layer_mid = total_area / width / 2
    return sum(weight(p) * (centroid_y(p) - layer_mid) for p in polys)


def rest_inside(width):
    # At rest: what is left moving holds under 1 % of the energy the drop released; a
    # pile still sliding or rocking holds far more, one resting on its springs far less.
    return [{"kind": "inside", "x_min": 0.0, "x_max": width, "y_min": 0.0},
            {"kind": "rest", "fraction": 0.01}]


def released(fraction):
    """The drop happened: the potential energy released is at least this share of the
    scale (a pile with voids releases less than the void-free layer of the scale, about
    0.8 of it for these boxes; a run that stalls or stops early releases much less)."""
    return {"kind": "released", "min": fraction}


# Each case returns its blocks, the energy scale (J/m, with how it was found), the checks,
# how long a dynamic run lasts ("end_time" in s, or "steps" for every run) and "fall", the
# largest drop of any block (m), which sizes the static runs. The scale is the larger of
# the potential energy drop available and the initial kinetic energy (README.md).

def case_box(n, rng):
    width, per_row, pitch = 1.5, 5, 0.3
    polys = []
    for k in range(n):
        row, col = divmod(k, per_row)
        cx = pitch * (col + 0.5) + rng.uniform(-0.01, 0.01)
        cy = 0.3 + 0.125 + 0.35 * row  # lowest row's bottom 0.3 m above the floor
        polys.append(square(cx, cy, 0.25, rng.uniform(-5.0, 5.0)))
    top = max(y for p in polys for _, y in p)
    blocks = box_walls(width, top + 0.3) + [free(p) for p in polys]
    rows = (n + per_row - 1) // per_row
    return dict(blocks=blocks, scale=settled_layer_scale(polys, width),
                scale_note="m g (centroid - mid-height of a void-free layer), summed",
                checks=rest_inside(width) + [released(0.5)], end_time=2.0,
                fall=0.3 + 0.1 * rows)  # the top row: 0.3 m and the 0.1 m gaps below


def case_column(n=20):
    polys = [rect(-0.125, 0.01 + 0.26 * k, 0.125, 0.26 + 0.26 * k) for k in range(n)]
    blocks = [fixed(rect(-1.0, -0.2, 1.0, 0.0))] + [free(p) for p in polys]
    # Block k closes its own 1 cm gap and the k gaps below it.
    scale = sum(weight(p) * 0.01 * (k + 1) for k, p in enumerate(polys))
    # A column of squares has no reason to lean: its drift is round-off, chatter and friction.
    # Static runs (no impacts): the elastic squares spread sideways under the column's
    # weight, and the lowest one's base corners slip outwards on the floor, each by up to
    # nu (1 + nu) sigma (b / 2) / E (plane strain, sigma the column's weight over the base).
    # Since 2026-11-23 a corner that locks again keeps the friction it slid against
    # (docs/contacts.md, "Relocking"), and which of the two corners locks first in a step is
    # decided by round-off: the column may shift by up to that slip (measured 1.5e-6 and
    # 2.1e-6 m at the two time steps; before, with the friction dropped at each lock, 1e-9 to
    # 5e-8 m). The limit is that slip, 5.2e-6 m.
    # Dynamic runs: the squares land flat on each other, and a landing a hair off flat
    # tilts; the impacts amplify round-off about 1e10-fold between 0.12 s and 0.2 s, on the
    # plain factorise path as on the kept-factor one (measured 2026-11-23: 1e-15 m -> 1e-5
    # m), and the drift saturates at millimetres whose value is a chaotic outcome: over nine
    # time steps from 0.0005 to 0.0022 s it ranged from 0.3 to 13.4 mm (13.4 at 0.002 s,
    # 0.3 at 0.00205 s; measured 2026-11-23), so a limit inside that range would pass or fail
    # on round-off. The check asks for no lean a user would see and that the column
    # stands: 2.5 cm, a tenth of a block's width, a 0.3 degree lean of the 5.2 m column.
    # (It was 2.5 mm until 2026-11-23, then 1 cm when the kept factor's CG showed 3.6 mm.)
    half_width, poisson, young = 0.125, ROCK["poisson"], ROCK["young"]
    sigma = n * RHO * G * (2 * half_width) ** 2 / (2 * half_width)
    spread = poisson * (1 + poisson) * sigma * half_width / young
    return dict(blocks=blocks, scale=scale, scale_note="m g x gaps closed below each block",
                checks=[{"kind": "drift_x", "limit": 0.025, "dynamic_only": True},
                        {"kind": "drift_x", "limit": round(spread, 8), "static_only": True},
                        {"kind": "rest", "fraction": 0.01}, released(0.9)],
                end_time=1.0, fall=0.2)


def case_collision():
    left, right = square(-0.175, 0.0, 0.25), square(0.175, 0.0, 0.25)
    blocks = [free(left, [1.0, 0.0, 0.0]), free(right, [-1.0, 0.0, 0.0])]
    m = RHO * area(left)
    # They meet at t = 0.05 s; the run goes on long enough for them to part again.
    return dict(blocks=blocks, gravity=[0.0, 0.0], scale=2 * 0.5 * m * 1.0 ** 2,
                scale_note="initial kinetic energy",
                checks=[{"kind": "momentum", "limit": 1e-6}, {"kind": "restitution"}],
                end_time=0.3, fall=0.0)


def case_slope():
    """A regular hexagon on a 35-degree slope cut into five fixed blocks, friction 40
    degrees: it cannot slide but tips (a hexagon tips beyond 30 degrees), so it tumbles
    down, impact after impact, across the seams between the slope's blocks onto a floor."""
    angle, height, nslices = math.radians(35.0), 1.5, 5
    length = height / math.tan(angle)
    surf = lambda x: height - x * math.tan(angle)
    xs = [length * i / nslices for i in range(nslices + 1)]
    blocks = [fixed([[xs[i], -0.3], [xs[i + 1], -0.3], [xs[i + 1], surf(xs[i + 1])],
                     [xs[i], surf(xs[i])]]) for i in range(nslices)]
    blocks.append(fixed(rect(length, -0.3, length + 3.0, 0.0)))
    r = 0.15
    inr = r * math.cos(math.radians(30))
    # Resting on an edge, 2 mm above the surface near the top of the slope.
    nx, ny = math.sin(angle), math.cos(angle)  # outward normal of the slope surface
    x0 = 0.35
    cx, cy = x0 + nx * (inr + 0.002), surf(x0) + ny * (inr + 0.002)
    # Vertices 30 degrees either side of the inward normal (-90 - 35 degrees): one edge
    # lies along the slope.
    first = -90.0 - math.degrees(angle) - 30.0
    hexagon = [[cx + r * math.cos(math.radians(first + 60 * k)),
                cy + r * math.sin(math.radians(first + 60 * k))] for k in range(6)]
    blocks.append(free(hexagon))
    profile = [[-1.0, surf(-1.0)], [0.0, height], [length, 0.0], [length + 3.0, 0.0]]
    scale = weight(hexagon) * (cy - inr)
    return dict(blocks=blocks, joint=40.0, scale=scale,
                scale_note="m g x fall of the centroid to resting on the floor",
                checks=[{"kind": "above", "profile": profile, "clearance": 0.5 * inr},
                        {"kind": "descend", "min": 0.5 * (cy - inr), "dynamic_only": True}],
                end_time=2.0, fall=cy - inr)


def convex_shape(cx, cy, rng):
    """A convex polygon: 4 to 7 points at jittered angles on a randomly turned ellipse
    (points on an ellipse in angular order are always convex)."""
    k = rng.randint(4, 7)
    a, b, turn = rng.uniform(0.09, 0.135), rng.uniform(0.09, 0.135), rng.uniform(0, math.pi)
    step = 2 * math.pi / k
    angles = [step * (i + rng.uniform(-0.3, 0.3)) for i in range(k)]
    c, s = math.cos(turn), math.sin(turn)
    return [[cx + c * a * math.cos(t) - s * b * math.sin(t),
             cy + s * a * math.cos(t) + c * b * math.sin(t)] for t in angles]


def case_pack(n, rng):
    """Random convex shapes, one per 0.3 m cell (so they cannot overlap), settling in a box."""
    per_row, pitch = 8, 0.3
    width = per_row * pitch
    polys = []
    for k in range(n):
        row, col = divmod(k, per_row)
        polys.append(convex_shape(pitch * (col + 0.5), 0.2 + pitch * row, rng))
    top = max(y for p in polys for _, y in p)
    blocks = box_walls(width, top + 0.3) + [free(p) for p in polys]
    return dict(blocks=blocks, scale=settled_layer_scale(polys, width),
                scale_note="m g (centroid - mid-height of a void-free layer), summed",
                checks=rest_inside(width) + [released(0.5)], end_time=2.0, fall=1.1)


def case_concave_base():
    """One fixed concave base with two steps (reflex corner at (2, 1)); four blocks drop
    onto it: against the riser, onto each step, and one tilted onto a corner."""
    base = [[0, 0], [4, 0], [4, 1], [2, 1], [2, 2], [0, 2]]
    drops = [(square(2.01 + 0.2, 1.0 + 0.2 + 0.2, 0.4), 1.0),    # beside the riser, 0.2 m drop
             (square(3.2, 1.0 + 0.15 + 0.1, 0.3, 20.0), 1.0),     # tilted: lands on a corner
             (square(0.8, 2.0 + 0.15 + 0.1, 0.3), 2.0),           # on the upper step
             (square(1.92, 2.0 + 0.125 + 0.05, 0.25, -5.0), 2.0)]  # over the upper step's edge
    blocks = [fixed(base)] + [free(p) for p, _ in drops]
    scale = sum(weight(p) * (min(y for _, y in p) - floor) for p, floor in drops)
    profile = [[0, 2], [2, 2], [2, 1], [4, 1]]
    return dict(blocks=blocks, scale=scale, scale_note="m g x gap under each block, summed",
                checks=[{"kind": "above", "profile": profile, "clearance": 0.06},
                        {"kind": "inside", "x_min": 0.0, "x_max": 4.0, "y_min": 1.0},
                        {"kind": "rest", "fraction": 0.01}, released(0.9)],
                end_time=1.5, fall=0.2)


def case_wall():
    """5 rows of 0.5 m x 0.25 m bricks in running bond (half bricks close the odd rows) on
    a fixed floor; it is built touching and must stay put."""
    bl, bh, per_row = 0.5, 0.25, 6
    blocks = [fixed(rect(-0.5, -0.3, per_row * bl + 0.5, 0.0))]
    for row in range(5):
        y0, y1 = row * bh, (row + 1) * bh
        edges = ([i * bl for i in range(per_row + 1)] if row % 2 == 0 else
                 [0.0] + [bl / 2 + i * bl for i in range(per_row)] + [per_row * bl])
        blocks += [free(rect(a, y0, b, y1)) for a, b in zip(edges, edges[1:])]
    # Nothing drops: the scale is what the wall would release by sinking the 1 mm the
    # 'still' check allows, and the remainder is judged against that.
    still = 0.001
    scale = sum(weight(b["vertices"]) * still for b in blocks[1:])
    return dict(blocks=blocks, scale=scale, scale_note="m g x 1 mm (the still check's limit)",
                checks=[{"kind": "still", "limit": still},
                        {"kind": "open_close_mean", "limit": 2.0},
                        {"kind": "rest", "fraction": 0.01}],
                steps=1000)


def case_topple():
    """A toppling slope (after Hoek and Bray's example): 16 columns 1 m wide, 2 to 5.5 m
    tall, standing on the treads of a stepped base drawn as one concave polygon (1 m treads,
    0.5 m risers), the whole turned 20 degrees counter-clockwise so the treads dip towards
    the face; friction 38 degrees. The tall columns lean past their base and topple onto
    the ones below; nothing may be thrown out of the slope or gain energy."""
    n, w, rise, turn = 16, 1.0, 0.5, math.radians(20.0)
    c, s_ = math.cos(turn), math.sin(turn)
    rot = lambda p: [[x * c - y * s_, x * s_ + y * c] for x, y in p]
    profile = []
    for i in range(n):
        profile += [[i * w, i * rise], [(i + 1) * w, i * rise]]
    right = n * w + 2.0
    base = [[0.0, -2.0], [right, -2.0], [right, (n - 1) * rise]] + profile[::-1][1:]
    heights = [2.0 + 0.35 * i if i < 10 else 5.5 - 0.3 * (i - 10) for i in range(n)]
    columns = [rot(rect(i * w, i * rise, (i + 1) * w, i * rise + h)) for i, h in enumerate(heights)]
    blocks = [fixed(rot(base))] + [free(p) for p in columns]
    # Scale: the potential energy the columns would release lying flat on their treads
    # (centroid from h/2 to w/2 above the tread, along the turned vertical).
    scale = sum(RHO * w * h * G * (h - w) / 2 * c for h in heights)
    return dict(blocks=blocks, joint=38.0, scale=scale,
                scale_note="m g x fall of each column's centroid lying flat on its tread",
                checks=[released(0.01) | {"dynamic_only": True}],
                end_time=3.0, fall=1.0)

def cases(smoke):
    rng = random.Random(9)  # issue 9; every random draw below comes from this one stream
    box5, box30 = case_box(5, rng), case_box(30, rng)
    pack16, pack48 = case_pack(16, rng), case_pack(48, rng)
    every = {"box5": box5, "box30": box30, "column": case_column(),
             "collision": case_collision(), "slope": case_slope(), "pack16": pack16,
             "pack48": pack48, "concave_base": case_concave_base(), "wall": case_wall(),
             "topple": case_topple()}
    if smoke:
        del every["pack48"]  # over a minute of settling today
    return every


# Time steps, two a factor 10 apart per mode. A static step (velocities dropped) moves a
# free block only g dt^2 / 2, so a drop of h takes 2 h / (g dt^2) steps: 0.8 m at 0.0002 s
# would be 4 million. Static runs therefore use 0.04 s and 0.004 s (a free block falls
# 7.8 mm and 0.08 mm a step, under the displacement limit of every scene here) and run
# for the time the largest drop needs to land, plus 500 steps to settle. They are bounded
# by time, not steps: a cut step (dt x 0.3) moves a static block only 9 % as far.
DYNAMIC_DTS = [0.002, 0.0002]
STATIC_DTS = [0.04, 0.004]


def static_end_time(c, dt):
    return (math.ceil(1.2 * 2 * c["fall"] / (G * dt * dt)) + 500) * dt


def scene(name, c, dt, mode):
    control = {"time_step": dt, "max_displacement_ratio": 0.01,
               "dynamic_coefficient": 1.0 if mode == "dynamic" else 0.0,
               "penalty": "auto", "allowed_penetration": "auto"}
    if "steps" in c:
        control["steps"] = c["steps"]
        control["output_every"] = max(1, c["steps"] // 100)  # about 100 frames a run
    else:
        end = c["end_time"] if mode == "dynamic" else static_end_time(c, dt)
        control["end_time"] = round(end, 6)
        control["output_every"] = max(1, round(end / dt / 100))
    return {"description": f"hard case {name} ({mode}, dt {dt} s): "
                           "verification/hard-cases/README.md",
            "gravity": c.get("gravity", [0.0, -G]),
            "control": control,
            "materials": {"rock": ROCK},
            "joint_materials": {"default": {"friction_angle": c.get("joint", FRICTION),
                                            "cohesion": 0.0, "tensile_strength": 0.0}},
            "blocks": c["blocks"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir")
    ap.add_argument("--smoke", action="store_true")
    args = ap.parse_args()
    scene_dir = os.path.join(args.out_dir, "scenes")
    os.makedirs(scene_dir, exist_ok=True)
    dts = {"dynamic": DYNAMIC_DTS[:1] if args.smoke else DYNAMIC_DTS,
           "static": STATIC_DTS[:1] if args.smoke else STATIC_DTS}
    manifest = []
    for case, c in cases(args.smoke).items():
        for mode in ("dynamic", "static"):
            for dt in dts[mode]:
                name = f"{case}-{mode}-dt{dt:g}"
                path = os.path.join(scene_dir, name + ".json")
                with open(path, "w") as f:
                    json.dump(scene(name, c, dt, mode), f, indent=1)
                    f.write("\n")
                checks = [k for k in c["checks"]
                          if not (k.get("dynamic_only") and mode == "static")
                          and not (k.get("static_only") and mode == "dynamic")]
                manifest.append({"name": name, "case": case, "dt": dt, "mode": mode,
                                 "scene": os.path.relpath(path, args.out_dir),
                                 "scale": c["scale"], "scale_note": c["scale_note"],
                                 "checks": checks})
    with open(os.path.join(scene_dir, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
