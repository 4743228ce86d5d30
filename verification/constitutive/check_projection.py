#!/usr/bin/python3
"""An independent check of the iso-error maps that dda_verify_constitutive wrote into DIR.

For the associated, perfectly plastic Mohr-Coulomb maps whose increments keep the principal
axes (no shear), one call of the return map is the closest-point projection of the trial stress
onto the elastic domain in the energy norm (s - t) . D^-1 (s - t). This script recomputes it
without the library: in principal space, the domain is the intersection of the six planes
(s_i - s_j) + (s_i + s_j) sin(phi) <= 2 c cos(phi), i != j, and the cut-off s_i <= T when there
is one; every set of one to three active planes is tried and the one whose multipliers are
non-negative and whose stress is inside every plane is the projection (the QP is strictly
convex, so it is unique). The reference repeats it over the same sub-increments, carrying the
plastic strain. At the worst point of each such map and at three other plastic points, the
stresses of the program (one call and reference) must agree with these to 1e-9 of c.

Writes DIR/projection_check.md and prints it; exit 1 if a point disagrees.
Usage: /usr/bin/python3 verification/constitutive/check_projection.py DIR
(Debian's python3 with numpy.)"""
import argparse
import csv
import itertools
import os
import sys

import numpy as np

TOLERANCE = 1e-9  # of c, on ||s_program - s_here||


def read(dirname, name):
    with open(os.path.join(dirname, name), newline="") as f:
        return list(csv.DictReader(f))


class Domain:
    def __init__(self, m):
        e, nu = float(m["young"]), float(m["poisson"])
        self.c = float(m["cohesion"])
        phi = np.radians(float(m["friction_angle"]))
        g = e / (2 * (1 + nu))
        lam = e * nu / ((1 + nu) * (1 - 2 * nu))
        self.d = np.full((3, 3), lam) + 2 * g * np.eye(3)
        self.multiplier_tol = 1e-12 * self.c / g
        sp, cp = np.sin(phi), np.cos(phi)
        self.planes = []
        for i, j in itertools.permutations(range(3), 2):
            n = np.zeros(3)
            n[i], n[j] = 1 + sp, -(1 - sp)
            self.planes.append((n, 2 * self.c * cp))
        if m["tensile_strength"]:
            for i in range(3):
                n = np.zeros(3)
                n[i] = 1.0
                self.planes.append((n, float(m["tensile_strength"])))

    def inside(self, s, tol):
        return all(n @ s <= b + tol for n, b in self.planes)

    def project(self, t):
        if self.inside(t, 1e-12 * self.c):
            return t
        for k in (1, 2, 3):
            for active in itertools.combinations(range(len(self.planes)), k):
                n = np.array([self.planes[a][0] for a in active])
                b = np.array([self.planes[a][1] for a in active])
                a_mat = n @ self.d @ n.T
                if np.linalg.matrix_rank(a_mat) < k:
                    continue
                mult = np.linalg.solve(a_mat, n @ t - b)
                if (mult < -self.multiplier_tol).any():
                    continue
                s = t - self.d @ n.T @ mult
                if self.inside(s, 1e-9 * self.c):
                    return s
        raise RuntimeError("no active set gives the projection")


def principal_start(m):
    s = np.array([float(m[k]) for k in ("start_sxx", "start_syy", "start_szz", "start_sxy")])
    assert s[3] == 0.0
    return s[:3]


def one_and_reference(dom, s0, strain, substeps):
    e = np.array([strain[0], strain[1], 0.0])  # exx, eyy, ezz = 0 (gxy = 0 on these maps)
    one = dom.project(s0 + dom.d @ e)
    ep = np.zeros(3)
    s = s0
    for k in range(1, substeps + 1):
        t = s0 + dom.d @ (e * k / substeps - ep)
        s = dom.project(t)
        ep = ep + np.linalg.solve(dom.d, t - s)
    return one, s


def eligible(m):
    return (m["model"] == "mohr_coulomb" and float(m["friction_angle"]) == float(m["dilation_angle"])
            and m["hardening"] == "none" and float(m["dx_gxy"]) == 0.0
            and float(m["dy_gxy"]) == 0.0 and float(m["start_sxy"]) == 0.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    args = parser.parse_args()
    lines = ["# Independent check of the associated Mohr-Coulomb maps", "",
             "One call and reference of the program against an independent closest-point "
             "projection (check_projection.py: every active set of the six Mohr-Coulomb planes "
             "and the cut-off, in numpy), at the worst point of each map and three other plastic "
             f"points. Differences are ||s_program - s_check|| / c; they must stay below "
             f"{TOLERANCE:g}.", "",
             "| map | (x, y) | error (program) | error (check) | one call: difference | "
             "reference: difference |", "|---|---|---:|---:|---:|---:|"]
    bad = 0
    for m in read(args.dir, "maps.csv"):
        if not eligible(m):
            continue
        dom = Domain(m)
        s0 = principal_start(m)
        rows = [r for r in read(args.dir, m["name"] + ".csv") if r["status"] == "ok"]
        worst = max(rows, key=lambda r: float(r["error"]))
        plastic = [r for r in rows if r["branch"] != "elastic" and r is not worst]
        picks = [worst] + [plastic[k * len(plastic) // 3] for k in range(3) if plastic]
        for r in picks:
            strain = (float(r["exx"]), float(r["eyy"]))
            one, ref = one_and_reference(dom, s0, strain, int(m["substeps"]))
            p_one = np.array([float(r[k]) for k in ("sxx", "syy", "szz")])
            p_ref = np.array([float(r[k]) for k in ("ref_sxx", "ref_syy", "ref_szz")])
            d_one = np.linalg.norm(p_one - one) / dom.c
            d_ref = np.linalg.norm(p_ref - ref) / dom.c
            err = np.linalg.norm(one - ref) / np.linalg.norm(ref)
            flag = "" if max(d_one, d_ref) <= TOLERANCE else " **disagrees**"
            bad += flag != ""
            lines.append(f"| `{m['name']}` | ({float(r['x']):g}, {float(r['y']):g}) | "
                         f"{float(r['error']):.4g} | {err:.4g} | {d_one:.1e} | "
                         f"{d_ref:.1e}{flag} |")
    lines += ["", "All points agree." if bad == 0 else f"{bad} point(s) disagree.", ""]
    text = "\n".join(lines)
    with open(os.path.join(args.dir, "projection_check.md"), "w") as f:
        f.write(text)
    print(text)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
