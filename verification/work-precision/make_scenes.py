#!/usr/bin/python3
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
         syy = -rho g (4 x 0.5 + 0.25) (-59 594 Pa);
  chain  three rigid blocks (1.0, 0.8 and 0.6 m wide, 0.5 m tall, centred) on a fixed base,
         bonded, gravity at once, dynamic for 0.4 s: they oscillate on their contact springs
         (two per interface, one under each corner of the narrower block: 2p), a linear
         spring-mass chain whose modal solution is the reference for the top block's
         vertical displacement (RMS over the history rows at every 0.02 s, relative to its
         largest); the penalty p (1, 2 and 4 MN/m) is part of the model;
  topple  a rigid 0.2 m x 1.0 m block standing on its corner on a fixed base, turned 0.2 rad
         past the vertical through that corner, friction 70 degrees, dynamic from rest for
         0.6 s: a rigid body turning about a fixed corner, I_O theta'' = m g r sin(theta),
         integrated by RK4 at 1e-5 s; the quantity is the turn at 0.6 s (0.763 rad).

  topple_tight  the same with an allowed penetration of 2e-7 m (auto: 2e-4 m), which also
         tightens the secant angle's tolerance (1e-3 of it at the farthest vertex; docs/
         contact-solver.md, item 4), at 50 and 500 E.

The references of chain and topple (and Shi's step applied to the same models, which
tells the integrator's share of the error from the contacts') are functions here, which
summarise.py imports.
"""
import argparse
import functools
import json
import math
import os

import numpy as np

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


# The chain (case chain): block widths, their height, and the joint that bonds them (a
# bonded contact's normal spring acts at either sign: docs/contact-solver.md, "The
# regularised Coulomb law"). Unbonded, the two upper interfaces of this chain open after one
# period of its first mode (0.197 s at p = 2 MN/m, from the modal solution below), the springs
# stop being linear and the closed form no longer holds.
CHAIN_WIDTHS = (1.0, 0.8, 0.6)
CHAIN_HEIGHT = 0.5
CHAIN_END = 0.4
CHAIN_ROW_EVERY = 0.02  # s between the history rows the error is taken over
# The allowance: deeper than any compression of the chain (0.032 m at most, at 1 MN/m), so
# that no augmentation (past half of it) or penetration cut changes the linear springs.
CHAIN_ALLOWED_PENETRATION = 0.1

# The toppling block (case topple).
TOPPLE_W, TOPPLE_H = 0.2, 1.0
TOPPLE_THETA0 = 0.2  # rad past the vertical through the corner, clockwise
TOPPLE_END = 0.6
TOPPLE_FRICTION = 70.0


def chain_matrices(penalty):
    """Masses (kg per m) and stiffness matrix of the chain: interface j (j = 0 on the base)
    holds block j by the two springs under the narrower block's corners, 2p in all."""
    m = np.array([DENSITY * w * CHAIN_HEIGHT for w in CHAIN_WIDTHS])
    n, k = len(m), 2.0 * penalty
    K = np.zeros((n, n))
    for j in range(n):
        K[j, j] += k
        if j > 0:
            K[j - 1, j - 1] += k
            K[j, j - 1] -= k
            K[j - 1, j] -= k
    return m, K


def chain_exact(penalty, times):
    """Vertical displacements (rows: blocks, columns: times) of the chain under gravity
    applied at once from rest and unloaded springs: u = u_s + sum_j phi_j c_j cos(w_j t),
    u_s = -K^-1 M g, with the mass-normalised modes phi_j (K phi = w^2 M phi) and
    c_j = phi_j^T M (0 - u_s)."""
    m, K = chain_matrices(penalty)
    static = np.linalg.solve(K, -m * G)
    scale = np.diag(m ** -0.5)
    w2, v = np.linalg.eigh(scale @ K @ scale)
    modes = scale @ v
    c = modes.T @ (m * -static)
    t = np.asarray(times, dtype=float)
    return static[:, None] + modes @ (c[:, None] * np.cos(np.sqrt(w2)[:, None] * t))


def chain_shi_step(penalty, dt, steps):
    """Shi's step (Newmark, beta = 1/2, gamma = 1: a1 = 2/dt^2 d - 2/dt v0, v1 = 2 d/dt - v0;
    docs/closed-forms.md) applied to the same linear chain: displacements after 0..steps
    steps (rows: blocks). DDA on the chain should agree with it to the springs' round-off."""
    m, K = chain_matrices(penalty)
    lhs = np.diag(2.0 * m / dt ** 2) + K
    x, v = np.zeros(len(m)), np.zeros(len(m))
    out = [x.copy()]
    for _ in range(steps):
        d = np.linalg.solve(lhs, -m * G - K @ x + 2.0 * m * v / dt)
        v = 2.0 * d / dt - v
        x = x + d
        out.append(x.copy())
    return np.array(out).T


def topple_rate():
    """theta'' = lambda^2 sin(theta): m g r / I_O with r = d/2, I_O = m d^2 / 3 (d the
    diagonal: the rectangle's I_c = m d^2 / 12 plus m r^2)."""
    return 1.5 * G / math.hypot(TOPPLE_W, TOPPLE_H)


@functools.lru_cache(maxsize=None)
def topple_exact(end=TOPPLE_END, step=1e-5):
    """The turn past the start at `end` (rad) of the rigid rotation about the fixed corner,
    by RK4 at `step` (its error ~ step^4, far below DDA's), with the largest friction ratio
    |R_x| / R_y and the smallest R_y / (m g) of the corner's reaction along the way
    (R = m a_c - m g: the corner must neither slip nor lift for the reference to hold)."""
    lam2, r = topple_rate(), 0.5 * math.hypot(TOPPLE_W, TOPPLE_H)
    f = lambda y: np.array([y[1], lam2 * math.sin(y[0])])
    y = np.array([TOPPLE_THETA0, 0.0])
    ratio, lift = 0.0, 1.0
    n = round(end / step)
    for _ in range(n):
        k1 = f(y)
        k2 = f(y + 0.5 * step * k1)
        k3 = f(y + 0.5 * step * k2)
        k4 = f(y + step * k3)
        y = y + step / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        th, om = y
        al = lam2 * math.sin(th)
        ry = G - r * al * math.sin(th) - r * om * om * math.cos(th)
        rx = r * al * math.cos(th) - r * om * om * math.sin(th)
        ratio, lift = max(ratio, abs(rx) / ry), min(lift, ry / G)
    # The energy integral theta'^2 = 2 lambda^2 (cos theta0 - cos theta) checks the RK4.
    energy = y[1] ** 2 - 2.0 * lam2 * (math.cos(TOPPLE_THETA0) - math.cos(y[0]))
    assert abs(energy) < 1e-9 * y[1] ** 2, energy
    return y[0] - TOPPLE_THETA0, ratio, lift


def topple_shi_step_angle(dt, end=TOPPLE_END):
    """Shi's step applied to the angle's own equation, theta'' = lambda^2 sin(theta) (scalar
    Newton on the implicit end-of-step acceleration): the turn at `end`. Not what DDA
    solves (topple_shi_step_body); kept as the naive expectation, first order in dt."""
    lam2 = topple_rate()
    th, v = TOPPLE_THETA0, 0.0
    for _ in range(round(end / dt)):
        d = v * dt
        for _ in range(50):
            res = d - v * dt - 0.5 * dt * dt * lam2 * math.sin(th + d)
            d -= res / (1.0 - 0.5 * dt * dt * lam2 * math.cos(th + d))
            if abs(res) < 1e-15:
                break
        v = 2.0 * d / dt - v
        th += d
    return th - TOPPLE_THETA0


def _rotation(a):
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])


def topple_shi_step_body(dt, end=TOPPLE_END):
    """Shi's step in DDA's own unknowns, the centroid's translation d_t and the turn r, for a
    rigid block whose corner (the origin) is held exactly: the secant rotation column
    s = (R(r) - I) a / r (a: the corner less the centroid; scene-format.md, "finite_rotation")
    puts the corner at d_t + (R(r) - I) a = 0, the translation's inertia
    m (2/dt^2 d_t - 2/dt v0) = m g + F gives the corner's reaction F, and the turn's
    J_r (2/dt^2 r - 2/dt w0) = s . F, with J_r = J (2 - 2 cos r) / r^2, the rigid block's
    polar moment over the secant column (scene-format.md, "Rigid blocks"). Solved for r by
    the secant method each step. The turn at `end`. Gravity is a constant force here and
    the reaction a constraint force fixed at the step's end, so this is second order in dt
    where Shi's step on the angle's equation (its torque lagging) is first."""
    m = DENSITY * TOPPLE_W * TOPPLE_H
    inertia = m * (TOPPLE_W ** 2 + TOPPLE_H ** 2) / 12.0
    r_c = 0.5 * math.hypot(TOPPLE_W, TOPPLE_H)
    centroid = np.array([r_c * math.sin(TOPPLE_THETA0), r_c * math.cos(TOPPLE_THETA0)])
    weight = np.array([0.0, -m * G])
    v, w, turn = np.zeros(2), 0.0, 0.0

    def residual(r, a, v, w):
        dt_ = -(_rotation(r) - np.eye(2)) @ a
        force = m * (2.0 / dt ** 2 * dt_ - 2.0 / dt * v) - weight
        column = -dt_ / r
        j_r = inertia * (2.0 - 2.0 * math.cos(r)) / r ** 2
        return j_r * (2.0 / dt ** 2 * r - 2.0 / dt * w) - column @ force, dt_

    for _ in range(round(end / dt)):
        a = -centroid
        r0 = w * dt if w != 0.0 else -1e-6
        r1 = 1.01 * r0 - 1e-7
        f0, f1 = residual(r0, a, v, w)[0], residual(r1, a, v, w)[0]
        for _ in range(100):
            r0, r1, f0 = r1, r1 - f1 * (r1 - r0) / (f1 - f0), f1
            f1 = residual(r1, a, v, w)[0]
            if abs(r1 - r0) < 1e-15:
                break
        d_t = residual(r1, a, v, w)[1]
        v, w = 2.0 * d_t / dt - v, 2.0 * r1 / dt - w
        centroid = centroid + d_t
        turn += r1
    return -turn  # it turns clockwise


def chain(dt, penalty_factor):
    s = base_scene(dt, CHAIN_END, 1.0, penalty_factor, [0.0, -G], 30.0)
    s["materials"]["rock"]["rigid"] = True
    s["control"]["max_displacement_ratio"] = 1.0
    s["control"]["allowed_penetration"] = CHAIN_ALLOWED_PENETRATION
    s["control"]["output_every"] = round(CHAIN_ROW_EVERY / dt)
    # Bonded from the start (closed then): the springs pull as they push. The strengths
    # (100 MPa over half the faces' overlap) are far above the chain's forces (1e4 N).
    s["joint_materials"]["default"].update({"cohesion": 1e8, "tensile_strength": 1e8})
    s["blocks"].append({"vertices": rect(-1.0, -0.5, 2.0, 0.0), "material": "rock", "fixed": True})
    y = 0.0
    for w in CHAIN_WIDTHS:
        s["blocks"].append({"vertices": rect(0.5 - 0.5 * w, y, 0.5 + 0.5 * w, y + CHAIN_HEIGHT),
                            "material": "rock"})
        y += CHAIN_HEIGHT
    top = chain_exact(penalty_factor * YOUNG, np.linspace(0.0, CHAIN_END, 4001))[-1]
    return s, {"quantity": "RMS of the top block's vertical displacement over the history rows, "
                           "relative to its largest (m)",
               "block": len(CHAIN_WIDTHS), "exact": float(np.abs(top).max()),
               "start_y": y - 0.5 * CHAIN_HEIGHT, "penalty": penalty_factor * YOUNG}


def topple(dt, penalty_factor):
    s = base_scene(dt, TOPPLE_END, 1.0, penalty_factor, [0.0, -G], TOPPLE_FRICTION)
    s["materials"]["rock"]["rigid"] = True
    # The turn moves the top corners by up to 0.06 m a step at dt = 0.02 s; the ratio lets
    # it, so that every run takes the schedule's steps.
    s["control"]["max_displacement_ratio"] = 1.0
    s["blocks"].append({"vertices": rect(-1.0, -0.5, 1.5, 0.0), "material": "rock", "fixed": True})
    # The block about its right-hand bottom corner (the origin), turned clockwise by the
    # start angle plus the angle of its diagonal, so that its centroid is theta0 past the
    # vertical through the corner.
    turn = TOPPLE_THETA0 + math.atan2(TOPPLE_W, TOPPLE_H)
    c, sn = math.cos(turn), math.sin(turn)
    verts = [[x * c + y * sn, -x * sn + y * c] for x, y in rect(-TOPPLE_W, 0.0, 0.0, TOPPLE_H)]
    verts[1] = [0.0, 0.0]
    s["blocks"].append({"vertices": verts, "material": "rock"})
    exact, ratio, lift = topple_exact()
    assert ratio < math.tan(math.radians(TOPPLE_FRICTION)) and lift > 0.0, (ratio, lift)
    return s, {"quantity": f"turn of the block at {TOPPLE_END:g} s (rad, clockwise)", "block": 1,
               "exact": exact, "friction_needed": ratio, "least_normal_share": lift,
               "shi_step": topple_shi_step_body(dt), "shi_step_angle": topple_shi_step_angle(dt)}


def topple_tight(dt, penalty_factor):
    s, reference = topple(dt, penalty_factor)
    # Twice the corner's deepest compression at 50 E (1e-7 m, m g / p at the start's
    # impact); no augmentation, so that a deeper one cuts (summarise.py flags cuts) rather
    # than adding force.
    s["control"]["allowed_penetration"] = 2e-7
    s["control"]["max_augmentations"] = 0
    return s, reference


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
    sweeps["chain"] = ([0.01, 0.005] if args.smoke else [0.02, 0.01, 0.005, 0.0025, 0.00125, 0.000625],
                       [2e-3] if args.smoke else [1e-3, 2e-3, 4e-3])
    sweeps["topple"] = ([0.01, 0.005] if args.smoke else [0.02, 0.01, 0.005, 0.0025, 0.00125, 0.000625],
                        [50.0] if args.smoke else [5.0, 50.0, 500.0])
    sweeps["topple_tight"] = ([0.01, 0.005] if args.smoke else [0.02, 0.01, 0.005, 0.0025, 0.00125, 0.000625],
                              [50.0] if args.smoke else [50.0, 500.0])
    manifest = []
    for case, (dts, penalties) in sweeps.items():
        for dt in dts:
            for p in penalties:
                make = {"slide": slide, "slide_free": slide_free, "stack": stack, "chain": chain,
                        "topple": topple, "topple_tight": topple_tight}[case]
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
