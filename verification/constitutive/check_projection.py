#!/usr/bin/python3
"""An independent check of every iso-error map that dda_verify_constitutive wrote into DIR.

For chosen points of each map (the worst one, and on every branch the one call or the reference
took, its worst point and its points at a quarter, half and three quarters of the grid order),
this script recomputes the one call and the reference
(the same number of equal sub-increments, the plastic strain and eps_p carried) from the
equations, in numpy, without the C++ library, and compares the program's stresses and eps_p
with them.

- Elasticity in tensor form: s = s0 + lambda tr(e - e_p) 1 + 2G (e - e_p), plane strain
  (ezz = 0, exz = eyz = 0), exy = gxy / 2.
- Mohr-Coulomb (de Souza Neto, Peric and Owen 2008, section 8.2), with or without the tension
  cut-off, associated or not, perfectly plastic or with a piecewise-linear cohesion table: the
  trial's principal stresses (numpy's eigh of the in-plane 2 x 2 block, szz the third) are
  returned in principal space and the stress rebuilt in the trial's axes, so the shear maps'
  turning axes are included. The domain is the intersection of the six planes
  (s_i - s_j) + (s_i + s_j) sin(phi) <= 2 c cos(phi), i != j (no principal order assumed) and
  s_i <= T; plane (i, j) flows along the gradient of the same expression with psi, the cut-off
  along its normal. EVERY set of one to three planes is solved for its multipliers, s = t - D
  sum(dgamma_k m_k) with f_k(s) = 0; with a cohesion table c(eps_p), eps_p = eps_p0 + 2 cos(phi)
  sum(dgamma_k over the Mohr-Coulomb planes) (the rate conjugate to c: 2 c cos(phi) sum dgamma
  is the dissipation on the surface), and the consistency equation, linear in eps_p on each
  segment of the table, is solved exactly segment by segment. A set is a solution when its
  multipliers are >= 0 and every plane holds at its end (KKT); all solutions must give the
  same stress (for associated flow the closest point in the energy norm is unique; for
  psi != phi the script checks it), else the point counts as a disagreement.
- Drucker-Prager (sections 6.4.6 and 8.3), perfectly plastic, the plane-strain match
  eta = 3 tan(phi) / sqrt(9 + 12 tan^2 phi), xi = 3 / sqrt(9 + 12 tan^2 phi), eta_bar the
  same with psi: closed form, dgamma = f_trial / (G + K eta eta_bar),
  s = (1 - G dgamma / sqrt(J2_trial)) s'_trial + (p_trial - K eta_bar dgamma) 1, eps_p += xi
  dgamma; when sqrt(J2_trial) - G dgamma < 0, the apex p = xi c / eta with eps_p += xi dv /
  eta_bar, dv = (p_trial - p) / K the plastic volume change.

Tolerance: ||s_program - s_check|| <= 1e-10 c and |eps_p_program - eps_p_check| <= 1e-10 e_y,
for the one call and for the reference. Why: each return is a few dozen flops on stresses of at
most ~10 c, so it carries ~1e-15 of 10 c; a return does not amplify a difference in its trial
(a projection, or close to one), so over 1000 sub-increments the two computations can drift
apart by at most ~1000 x 1e-14 c = 1e-11 c; any difference of the algorithm (a wrong branch, a
wrong flow, a wrong hardening slope) is many orders larger.

Writes DIR/projection_check.md and prints it; exit 1 if a point disagrees or a map has no
plastic point to check.
Usage: /usr/bin/python3 verification/constitutive/check_projection.py DIR
(Debian's python3 with numpy.)"""
import argparse
import csv
import itertools
import os
import sys
import time

import numpy as np

STRESS_TOLERANCE = 1e-10  # of c, on ||s_program - s_check|| (the docstring says why)
EPS_P_TOLERANCE = 1e-10   # of e_y, on |eps_p_program - eps_p_check|
# KKT decisions: 1e-12 of the stress scale, some thousand times the round-off of a return; a
# multiplier is a strain, so the same over 2G.
DECISION = 1e-12


def read(dirname, name):
    with open(os.path.join(dirname, name), newline="") as f:
        return list(csv.DictReader(f))


# ---- elasticity and tensors (plane strain, tension positive) ----

class Elasticity:
    def __init__(self, young, poisson):
        self.g = young / (2 * (1 + poisson))
        self.k = young / (3 * (1 - 2 * poisson))
        self.lam = self.k - 2 * self.g / 3
        # Principal-space stiffness: s_i = lambda sum(e) + 2G e_i.
        self.principal = np.full((3, 3), self.lam) + 2 * self.g * np.eye(3)

    def stress(self, e):
        """Stress tensors of strain tensors e (..., 3, 3)."""
        tr = np.trace(e, axis1=-2, axis2=-1)[..., None, None]
        return self.lam * tr * np.eye(3) + 2 * self.g * e

    def strain(self, s):
        """The strain tensors of stress tensors: s' / 2G + p / 3K 1."""
        p = np.trace(s, axis1=-2, axis2=-1)[..., None, None] / 3
        return (s - p * np.eye(3)) / (2 * self.g) + p / (3 * self.k) * np.eye(3)


def strain_tensors(exx, eyy, gxy):
    e = np.zeros((len(exx), 3, 3))
    e[:, 0, 0], e[:, 1, 1] = exx, eyy
    e[:, 0, 1] = e[:, 1, 0] = 0.5 * gxy  # engineering shear in the CSV
    return e


def stress_tensor(sxx, syy, szz, sxy):
    return np.array([[sxx, sxy, 0.0], [sxy, syy, 0.0], [0.0, 0.0, szz]])


def components(s):
    """(sxx, syy, szz, sxy) of stress tensors (..., 3, 3)."""
    return np.stack([s[..., 0, 0], s[..., 1, 1], s[..., 2, 2], s[..., 0, 1]], axis=-1)


def tensor_norm(s):
    return np.sqrt(np.sum(s * s, axis=(-2, -1)))


# ---- the cohesion table ----

class Cohesion:
    """c(eps_p), piecewise linear through the table, constant beyond its ends."""

    def __init__(self, text, constant):
        if text == "none":
            self.points = [(0.0, constant)]
        else:
            self.points = [tuple(float(v) for v in p.split(":")) for p in text.split(";")]
        # Segments (lo, hi, c at lo, slope) covering the whole line.
        e, c = zip(*self.points)
        self.table = (np.array(e), np.array(c))
        if len(e) == 1:
            self.segments = [(-np.inf, np.inf, c[0], 0.0)]
            return
        self.segments = [(-np.inf, e[0], c[0], 0.0)]
        for k in range(len(e) - 1):
            self.segments.append((e[k], e[k + 1], c[k], (c[k + 1] - c[k]) / (e[k + 1] - e[k])))
        self.segments.append((e[-1], np.inf, c[-1], 0.0))

    def value(self, eps_p):
        e, c = self.table
        return np.interp(eps_p, e, c)  # constant beyond the ends, as the table says


# ---- Mohr-Coulomb with the cut-off: every active set in unsorted principal space ----

class MohrCoulomb:
    def __init__(self, m, el):
        self.el = el
        phi, psi = np.radians(float(m["friction_angle"])), np.radians(float(m["dilation_angle"]))
        sp, cp, spsi = np.sin(phi), np.cos(phi), np.sin(psi)
        self.cohesion = Cohesion(m["hardening"], float(m["cohesion"]))
        normals, flows, rc, r0, weight = [], [], [], [], []
        for i, j in itertools.permutations(range(3), 2):
            n, g = np.zeros(3), np.zeros(3)
            n[i], n[j] = 1 + sp, -(1 - sp)
            g[i], g[j] = 1 + spsi, -(1 - spsi)
            normals.append(n), flows.append(g), rc.append(2 * cp), r0.append(0.0)
            weight.append(2 * cp)  # d eps_p = 2 cos(phi) dgamma (the docstring says why)
        if m["tensile_strength"]:
            for i in range(3):
                n = np.eye(3)[i]
                normals.append(n), flows.append(n), rc.append(0.0)
                r0.append(float(m["tensile_strength"])), weight.append(0.0)
        self.normals, self.flows = np.array(normals), np.array(flows)
        self.rc, self.r0, self.weight = np.array(rc), np.array(r0), np.array(weight)
        self.is_tension = np.arange(len(normals)) >= 6
        self.groups = [self._group(k) for k in (1, 2, 3)]

    def _group(self, k):
        """The regular sets of k planes, stacked (S sets): what their returns need that does
        not depend on the trial."""
        sets, inverses = [], []
        for active in itertools.combinations(range(len(self.normals)), k):
            a, b = self.normals[list(active)], self.flows[list(active)]
            mat = a @ self.el.principal @ b.T
            if np.linalg.cond(mat) > 1e12:
                continue  # parallel normals or flows: no unique multipliers
            sets.append(active)
            inverses.append(np.linalg.inv(mat))
        idx, inv = np.array(sets), np.array(inverses)
        g = {"size": k, "inv": inv, "a": self.normals[idx], "r0": self.r0[idx],
             "w": self.weight[idx], "tension": self.is_tension[idx].any(axis=1),
             # D B^T: (S, 3, k)
             "d_bt": np.einsum("ij,skj->sik", self.el.principal, self.flows[idx])}
        # dgamma(c) = g0 - g1 c, from A (t - D B^T dgamma) = r0 + rc c.
        g["g1"] = np.einsum("skl,sl->sk", inv, self.rc[idx])
        g["wg1"] = np.einsum("sk,sk->s", g["w"], g["g1"])
        return g

    def yields(self, s, c):
        """Every plane's value at principal stresses s (N, 3) with cohesions c (N,)."""
        return s @ self.normals.T - np.outer(c, self.rc) - self.r0

    def _solutions(self, t, eps0, grp):
        """The end stress, eps_p and KKT flag of each set of one group, for each segment of the
        cohesion table: a list over the segments of arrays (N, S, ...)."""
        g1, wg1, d_bt = grp["g1"], grp["wg1"], grp["d_bt"]
        g0 = np.einsum("skl,nsl->nsk", grp["inv"],
                       np.einsum("skj,nj->nsk", grp["a"], t) - grp["r0"])
        # eps_p = eps0 + w.dgamma(c(eps_p)); on a segment c = c_lo + H (eps_p - lo), linear.
        base = eps0[:, None] + np.einsum("sk,nsk->ns", grp["w"], g0)
        out = []
        for lo, hi, c_lo, slope in self.cohesion.segments:
            if slope == 0.0:
                e = base - wg1 * c_lo  # the cohesion is c_lo on it: eps_p follows directly
            else:
                # eps_p = base - wg1 (c_lo + H (eps_p - lo)); 1 + wg1 H = 0 only if the
                # softening cancels the elastic stiffness (no unique return: no root here).
                with np.errstate(divide="ignore", invalid="ignore"):
                    e = (base - wg1 * (c_lo - slope * lo)) / (1 + wg1 * slope)
            c = self.cohesion.value(e)
            dgamma = g0 - g1[None] * c[..., None]
            s = t[:, None, :] - np.einsum("sik,nsk->nsi", d_bt, dgamma)
            scale = np.maximum(np.abs(t).max(axis=1), c.max(axis=1))[:, None]
            tol_e = DECISION * np.maximum(np.abs(e), 1e-30)
            in_segment = (e >= lo - tol_e) & (e <= hi + tol_e) & (e >= eps0[:, None] - tol_e)
            f = np.einsum("ij,nsj->nsi", self.normals, s) - c[..., None] * self.rc - self.r0
            ok = (in_segment & (dgamma >= -DECISION * scale[..., None] / (2 * self.el.g)).all(-1)
                  & (f <= DECISION * scale[..., None]).all(-1))
            out.append((s, e, ok))
        return out

    def return_principal(self, t, eps0):
        """Returned principal stresses, eps_p, the active set's size and the number of distinct
        solutions (1 unless ambiguous or none) for principal trials t (N, 3)."""
        n = len(t)
        c0 = self.cohesion.value(eps0)
        scale = np.maximum(np.abs(t).max(axis=1), c0)
        inside = (self.yields(t, c0) <= DECISION * scale[:, None]).all(axis=1)
        s, e = t.copy(), eps0.copy()
        size = np.zeros(n, dtype=int)
        tension = np.zeros(n, dtype=bool)
        distinct = np.where(inside, 1, 0)
        outside = np.nonzero(~inside)[0]
        found = {p: [] for p in outside}
        if len(outside):
            for grp in self.groups:
                for s_k, e_k, ok in self._solutions(t[outside], eps0[outside], grp):
                    for p, q in zip(*np.nonzero(ok)):
                        found[outside[p]].append((s_k[p, q], e_k[p, q], grp["size"],
                                                  grp["tension"][q]))
        for p in outside:
            sols = found[p]
            if not sols:
                continue
            # Solutions within the comparison tolerance are the same point (a one-plane return
            # ending on an edge is also the edge's solution with a zero multiplier).
            ref = sols[0][0]
            same = [np.linalg.norm(x[0] - ref) <= STRESS_TOLERANCE * self.cohesion.points[0][1]
                    for x in sols]
            distinct[p] = 1 if all(same) else 2
            s[p], e[p], size[p], tension[p] = sols[0]
        return s, e, size, tension, distinct

    def integrate(self, trial, eps0):
        """Return stress tensors, eps_p, branch names and the distinct-solution counts."""
        vals, vecs = np.linalg.eigh(trial[:, :2, :2])  # in-plane principal pair
        t = np.column_stack([vals, trial[:, 2, 2]])      # szz is principal (plane strain)
        s, e, size, tension, distinct = self.return_principal(t, eps0)
        out = np.zeros_like(trial)
        out[:, :2, :2] = np.einsum("nij,nj,nkj->nik", vecs, s[:, :2], vecs)
        out[:, 2, 2] = s[:, 2]
        names = np.array(["elastic", "plane", "edge", "apex"])[size]
        names = np.where(tension, "tension", names)
        return out, e, names, distinct


# ---- Drucker-Prager, closed form ----

def plane_strain_match(angle_deg):
    t = np.tan(np.radians(angle_deg))
    d = np.sqrt(9 + 12 * t * t)
    return 3 * t / d, 3 / d


class DruckerPrager:
    def __init__(self, m, el):
        if m["match"] != "plane_strain" or m["hardening"] != "none":
            raise NotImplementedError("only the perfectly plastic plane-strain match is checked")
        self.el = el
        self.c = float(m["cohesion"])
        self.eta, self.xi = plane_strain_match(float(m["friction_angle"]))
        self.eta_bar, _ = plane_strain_match(float(m["dilation_angle"]))

    def integrate(self, trial, eps0):
        """The cone return scales the trial's deviator and shifts its mean stress along the
        potential's gradient; when it would pass the axis (sqrt(J2) - G dgamma < 0) the stress
        is the apex, reached by a plastic volume change alone."""
        g, k = self.el.g, self.el.k
        p = np.trace(trial, axis1=1, axis2=2) / 3
        dev = trial - p[:, None, None] * np.eye(3)
        q = np.sqrt(0.5 * np.sum(dev * dev, axis=(1, 2)))  # sqrt(J2)
        f = q + self.eta * p - self.xi * self.c
        scale = np.maximum.reduce([q, np.abs(p), np.full_like(q, self.xi * self.c)])
        plastic = f > DECISION * scale
        dgamma = np.where(plastic, f, 0.0) / (g + k * self.eta * self.eta_bar)
        apex = plastic & (q - g * dgamma < 0)
        with np.errstate(divide="ignore", invalid="ignore"):
            factor = np.where(q > 0, 1 - g * dgamma / q, 0.0)
        mean = p - k * self.eta_bar * dgamma
        s = factor[:, None, None] * dev + mean[:, None, None] * np.eye(3)
        e = eps0 + self.xi * dgamma
        p_apex = self.xi * self.c / self.eta
        s[apex] = p_apex * np.eye(3)
        e[apex] = eps0[apex] + self.xi * (p[apex] - p_apex) / (k * self.eta_bar)
        names = np.where(apex, "apex", np.where(plastic, "cone", "elastic"))
        return s, e, names, np.ones(len(q), dtype=int)


# ---- one call and the sub-incremented reference ----

def one_and_reference(model, el, s0, strains, substeps):
    """One call and `substeps` equal sub-increments for each total strain tensor in strains
    (N, 3, 3), from stress s0 at zero strain, no plastic strain and eps_p 0."""
    n = len(strains)
    zero = np.zeros(n)
    one, one_e, one_branch, one_distinct = model.integrate(s0 + el.stress(strains), zero)
    ep, eps_p = np.zeros_like(strains), zero.copy()
    distinct = np.ones(n, dtype=int)
    for j in range(1, substeps + 1):
        trial = s0 + el.stress(strains * (j / substeps) - ep)
        s, eps_p, ref_branch, d = model.integrate(trial, eps_p)
        ep = ep + el.strain(trial - s)
        distinct = np.where(d != 1, d, distinct)
    return (one, one_e, one_branch, one_distinct), (s, eps_p, ref_branch, distinct)


def picks(rows):
    """The worst point; per one-call and per reference branch (plastic), its worst point and
    its points at a quarter, half and three quarters of the grid order, so that every branch
    is checked at several increments."""
    worst = max(rows, key=lambda r: float(r["error"]))
    out = [worst]
    for key in ("branch", "reference_branch"):
        for b in sorted({r[key] for r in rows} - {"elastic"}):
            on = [r for r in rows if r[key] == b and r["branch"] != "elastic"]
            if on:
                out.append(max(on, key=lambda r: float(r["error"])))
                out += [on[q * len(on) // 4] for q in (1, 2, 3)]
    unique = []
    for r in out:
        if all(r is not u for u in unique):
            unique.append(r)
    return unique


def check_map(m, dirname, lines):
    """Checks one map's chosen points; appends table rows; returns (points, disagreements,
    largest stress difference / c, largest eps_p difference / e_y, one-call branches,
    reference branches)."""
    el = Elasticity(float(m["young"]), float(m["poisson"]))
    model = (MohrCoulomb if m["model"] == "mohr_coulomb" else DruckerPrager)(m, el)
    c, e_y = float(m["cohesion"]), float(m["yield_strain"])
    s0 = stress_tensor(*(float(m[k]) for k in ("start_sxx", "start_syy", "start_szz",
                                                "start_sxy")))
    rows = [r for r in read(dirname, m["name"] + ".csv") if r["status"] == "ok"]
    chosen = [r for r in picks(rows) if r["branch"] != "elastic" or
              r["reference_branch"] != "elastic"]
    if not chosen:
        lines.append(f"| `{m['name']}` | no plastic point | | | | | | | **not checked** |")
        return 0, 1, 0.0, 0.0, set(), set()
    col = lambda key: np.array([float(r[key]) for r in chosen])
    strains = strain_tensors(col("exx"), col("eyy"), col("gxy"))
    (one, one_e, one_b, one_d), (ref, ref_e, ref_b, ref_d) = one_and_reference(
        model, el, s0, strains, int(m["substeps"]))
    p_one = np.array([stress_tensor(*(float(r[k]) for k in ("sxx", "syy", "szz", "sxy")))
                      for r in chosen])
    p_ref = np.array([stress_tensor(*(float(r[k]) for k in ("ref_sxx", "ref_syy", "ref_szz",
                                                            "ref_sxy"))) for r in chosen])
    d_one, d_ref = tensor_norm(p_one - one) / c, tensor_norm(p_ref - ref) / c
    de_one = np.abs(col("eps_p") - one_e) / e_y
    de_ref = np.abs(col("reference_eps_p") - ref_e) / e_y
    err = tensor_norm(one - ref) / tensor_norm(ref)
    bad = 0
    for i, r in enumerate(chosen):
        ok = (max(d_one[i], d_ref[i]) <= STRESS_TOLERANCE and
              max(de_one[i], de_ref[i]) <= EPS_P_TOLERANCE and one_d[i] == 1 and ref_d[i] == 1)
        flag = "" if ok else " **disagrees**"
        if one_d[i] != 1 or ref_d[i] != 1:
            flag += " (no unique return)"
        bad += not ok
        lines.append(
            f"| `{m['name']}` | ({float(r['x']):g}, {float(r['y']):g}) | {r['branch']} / "
            f"{one_b[i]} | {r['reference_branch']} / {ref_b[i]} | {float(r['error']):.4g} | "
            f"{err[i]:.4g} | {d_one[i]:.1e} | {d_ref[i]:.1e} | "
            f"{max(de_one[i], de_ref[i]):.1e}{flag} |")
    return (len(chosen), bad, max(d_one.max(), d_ref.max()), max(de_one.max(), de_ref.max()),
            {r["branch"] for r in chosen}, {r["reference_branch"] for r in chosen})


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    args = parser.parse_args()
    start = time.time()
    lines = ["# Independent check of every map", "",
             "One call and reference of the program against an independent return computed "
             "from the equations in numpy (check_projection.py: Mohr-Coulomb by every active "
             "set of its six planes and the cut-off in the trial's principal axes, the cohesion "
             "table solved segment by segment; Drucker-Prager in closed form), at the worst "
             "point of each map and, on every branch, its worst point and the points at a "
             "quarter, half and three quarters of the grid order. Stress "
             f"differences are ||s_program - s_check|| / c (limit {STRESS_TOLERANCE:g}), "
             f"eps_p differences |eps_p_program - eps_p_check| / e_y (limit "
             f"{EPS_P_TOLERANCE:g}), the larger of the one call's and the reference's. Branch "
             "names of the check: the smallest active set of its solution (at a point that "
             "lies on an edge the program may name the edge and the check the plane, or the "
             "other way round).", "",
             "| map | (x, y) | one call: branch (program / check) | reference: last branch "
             "(program / check) | error (program) | error (check) | one call: stress "
             "difference | reference: stress difference | eps_p difference |",
             "|---|---|---|---|---:|---:|---:|---:|---:|"]
    maps = read(args.dir, "maps.csv")
    bad = points = 0
    worst_s = worst_e = 0.0
    summary = ["", "Per map:", "", "| map | points | one-call branches | reference branches | "
               "largest stress difference / c | largest eps_p difference / e_y |",
               "|---|---:|---|---|---:|---:|"]
    for m in maps:
        n, b, ds, de, one_b, ref_b = check_map(m, args.dir, lines)
        points, bad = points + n, bad + b
        worst_s, worst_e = max(worst_s, ds), max(worst_e, de)
        summary.append(f"| `{m['name']}` | {n} | {', '.join(sorted(one_b))} | "
                       f"{', '.join(sorted(ref_b))} | {ds:.1e} | {de:.1e} |")
    lines += summary
    lines += ["", f"{points} points over {len(maps)} maps; largest differences {worst_s:.1e} c "
              f"(stress), {worst_e:.1e} e_y (eps_p); {time.time() - start:.1f} s.", "",
              "All points agree." if bad == 0 else f"{bad} point(s) disagree.", ""]
    text = "\n".join(lines)
    with open(os.path.join(args.dir, "projection_check.md"), "w") as f:
        f.write(text)
    print(text)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
