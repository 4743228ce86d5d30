#!/usr/bin/python3
"""Converts a scene of this project (docs/scene-format.md) to ntdda's DDAML input.

    scene_to_ntdda.py SCENE.json OUT_STEM [--g2 metres|ratio|VALUE] [--oc-limit N]
                      [--rotation linear|exact] [--edge-node-dist E]

writes OUT_STEM.geo (the blocks' outlines as joint lines, fixed points, load, measured and
hole points, material lines) and OUT_STEM.ana (analysis controls, block materials, joint
properties, point-load histories), and prints one JSON line describing the conversion.
Used by compare.sh for side-by-side runs with ntdda (docs/peer-comparison.md); ntdda is
not part of this repository.

What a scene becomes in ntdda
- Blocks: ntdda cuts its blocks out of joint lines. Every block edge is split at every
  vertex of another block lying on it, and each piece is written once, so that touching
  blocks share their joint lines exactly and no two lines overlap. A closed region that is
  no block of the scene (an opening enclosed by blocks, such as the space under an arch
  standing on a base) gets a hole point, or ntdda would make a block of it.
- Fixed blocks: ntdda has none. A fixed block becomes a free block held by fixed points
  (penalty springs, in ntdda 100 times the contact penalty): its vertices moved a tenth of
  the way towards its centroid, and the centroid if fewer than three of those lie inside.
- Pins become fixed points, point loads load points with a constant history, monitors
  measured points.
- Materials: ntdda gives each block one material number, with its density, E, nu, initial
  stress and initial velocity. Each distinct (material, velocity, initial stress) of the
  scene's blocks becomes one; the commonest is number 1 (ntdda's default), the others are
  set by a short material line inside each block that uses them.
- Joints: "default" is joint type 1; a pair in "joints" that touches at the start gets its
  material's type on the lines it shares (ntdda keeps joint types on lines, not pairs).
- Control: the time step is fixed (no automatic time step), the penalty is fixed at the
  scene's (auto: 50 x the largest E; ntdda's pfactor), the steps are `steps` or
  end_time / time_step, the analysis is dynamic (dynamic_coefficient 1) or static (0).
  max_displacement_ratio: ours limits each block by r x half its own bounding box, ntdda
  the whole scene by g2 x w0 (w0 = half the larger side of the scene's bounding box);
  --g2 metres (default) sets g2 so that the median free block's limit is the same in
  metres (and so ntdda's contact search distance, 2.5 g2 w0, is ours), --g2 ratio passes
  r as g2 (Shi's usual reading of the same number), a number is g2 itself. allowed_penetration, when
  given in metres, becomes ntdda's NormSpringPen ratio (x w0); auto is 4e-4 in both.
  max_open_close becomes ntdda's OCLimit (--oc-limit overrides it); see the doc for what
  ntdda does with it.
Not supported (an error names them): rigid blocks, plastic materials, water, base motion,
stages, a time-step list of different values, gravity with an x component, a dynamic
coefficient other than 0 or 1.
"""
import argparse
import json
import math
import os
import sys


def fail(msg):
    sys.exit(f"scene_to_ntdda: {msg}")


def area(poly):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))


def centroid(poly):
    a = area(poly)
    cx = sum((x0 + x1) * (x0 * y1 - x1 * y0) for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))
    cy = sum((y0 + y1) * (x0 * y1 - x1 * y0) for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))
    return cx / (6 * a), cy / (6 * a)


def inside(poly, x, y):
    """Strictly inside (ray casting); points on the boundary may go either way."""
    c = False
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (y0 > y) != (y1 > y):
            if x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
                c = not c
    return c


def dist_to_boundary(poly, x, y):
    best = math.inf
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        dx, dy = x1 - x0, y1 - y0
        L2 = dx * dx + dy * dy
        t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy) / L2))
        best = min(best, math.hypot(x - x0 - t * dx, y - y0 - t * dy))
    return best


def interior_point(poly):
    """A point well inside a simple polygon (counter-clockwise or not)."""
    cx, cy = centroid(poly)
    if inside(poly, cx, cy) and dist_to_boundary(poly, cx, cy) > 0:
        best = (dist_to_boundary(poly, cx, cy), cx, cy)
    else:
        best = (-1.0, cx, cy)
    sgn = 1.0 if area(poly) > 0 else -1.0
    n = len(poly)
    for i in range(n):  # points to the left of each edge's midpoint (inside for CCW)
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        L = math.hypot(x1 - x0, y1 - y0)
        if L == 0:
            continue
        nx, ny = -sgn * (y1 - y0) / L, sgn * (x1 - x0) / L
        for f in (0.3, 0.1, 0.03, 0.01):
            x, y = 0.5 * (x0 + x1) + f * L * nx, 0.5 * (y0 + y1) + f * L * ny
            if inside(poly, x, y):
                d = dist_to_boundary(poly, x, y)
                if d > best[0]:
                    best = (d, x, y)
                break
    if best[0] <= 0:
        fail("cannot find a point inside a polygon")
    return best[1], best[2]


class Graph:
    """The planar graph of all block outlines: vertices merged within tol, every edge split
    at the vertices on it, each piece once, with the blocks it bounds."""

    def __init__(self, polys, tol):
        self.tol = tol
        self.pts = []
        self.grid = {}
        self.cell = None
        lengths = sorted(math.hypot(b[0] - a[0], b[1] - a[1])
                         for p in polys for a, b in zip(p, p[1:] + p[:1]))
        self.cell = max(lengths[len(lengths) // 2], 100 * tol)
        ids = [[self.vertex(x, y) for x, y in p] for p in polys]
        self.seg = {}  # (i, j) with i < j -> set of blocks
        for b, vs in enumerate(ids):
            n = len(vs)
            for k in range(n):
                a, c = vs[k], vs[(k + 1) % n]
                chain = self.split(a, c)
                for u, v in zip(chain, chain[1:]):
                    self.seg.setdefault((min(u, v), max(u, v)), set()).add(b)

    def key(self, x, y):
        return (math.floor(x / self.cell), math.floor(y / self.cell))

    def vertex(self, x, y):
        kx, ky = self.key(x, y)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for i in self.grid.get((kx + dx, ky + dy), ()):
                    px, py = self.pts[i]
                    if abs(px - x) <= self.tol and abs(py - y) <= self.tol:
                        return i
        self.pts.append((x, y))
        self.grid.setdefault((kx, ky), []).append(len(self.pts) - 1)
        return len(self.pts) - 1

    def split(self, a, c):
        (x0, y0), (x1, y1) = self.pts[a], self.pts[c]
        dx, dy = x1 - x0, y1 - y0
        L2 = dx * dx + dy * dy
        kx0, ky0 = self.key(min(x0, x1) - self.tol, min(y0, y1) - self.tol)
        kx1, ky1 = self.key(max(x0, x1) + self.tol, max(y0, y1) + self.tol)
        on = []
        for kx in range(kx0, kx1 + 1):
            for ky in range(ky0, ky1 + 1):
                for i in self.grid.get((kx, ky), ()):
                    if i in (a, c):
                        continue
                    px, py = self.pts[i]
                    t = ((px - x0) * dx + (py - y0) * dy) / L2
                    if t <= 0 or t >= 1:
                        continue
                    if math.hypot(px - x0 - t * dx, py - y0 - t * dy) <= self.tol:
                        on.append((t, i))
        return [a] + [i for _, i in sorted(on)] + [c]

    def faces(self):
        """Bounded faces (counter-clockwise vertex lists of coordinates)."""
        out = {}
        for (u, v) in self.seg:
            out.setdefault(u, []).append(v)
            out.setdefault(v, []).append(u)
        ang = {}
        for u, nb in out.items():
            ux, uy = self.pts[u]
            nb.sort(key=lambda w: math.atan2(self.pts[w][1] - uy, self.pts[w][0] - ux))
            ang[u] = {w: k for k, w in enumerate(nb)}
        seen, faces = set(), []
        for (u, v) in self.seg:
            for start in ((u, v), (v, u)):
                if start in seen:
                    continue
                cyc, e = [], start
                while e not in seen:
                    seen.add(e)
                    cyc.append(e[0])
                    a, b = e
                    nb = out[b]
                    # next edge: the one just clockwise of (b -> a) around b
                    w = nb[(ang[b][a] - 1) % len(nb)]
                    e = (b, w)
                poly = [self.pts[i] for i in cyc]
                if len(poly) >= 3 and area(poly) > 0:
                    faces.append(poly)
        return faces


def fmt(x):
    return repr(float(x))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene")
    ap.add_argument("out_stem")
    ap.add_argument("--g2", default="metres",
                    help="metres (default), ratio, or a number: ntdda's maximum displacement ratio")
    ap.add_argument("--oc-limit", type=int, default=None,
                    help="ntdda's OCLimit (default: the scene's max_open_close, 8)")
    ap.add_argument("--rotation", default="linear", choices=["linear", "exact"])
    ap.add_argument("--edge-node-dist", type=float, default=1e-4,
                    help="ntdda's Edgenodedist (x w0): nodes this close are merged when cutting")
    args = ap.parse_args()

    with open(args.scene) as f:
        s = json.load(f)
    for k in ("water", "base_motion", "stages"):
        if k in s:
            fail(f"{k}: not supported by the converter")
    gx, gy = s.get("gravity", [0.0, -9.81])
    if gx != 0 or gy > 0:
        fail("gravity: ntdda takes a downward gravity only")
    g = -gy
    c = s["control"]
    dts = c["time_step"] if isinstance(c["time_step"], list) else [c["time_step"]]
    if max(dts) != min(dts):
        fail("control.time_step: a list of different steps is not supported")
    dt = dts[0]
    steps = c["steps"] if "steps" in c else int(round(c["end_time"] / dt))
    kdyn = c.get("dynamic_coefficient", 1.0)
    if kdyn not in (0, 1):
        fail("control.dynamic_coefficient: ntdda is dynamic (1) or static (0)")
    mats = s["materials"]
    for name, m in mats.items():
        if m.get("model", "elastic") != "elastic":
            fail(f"materials.{name}: only elastic materials")
        if m.get("rigid"):
            fail(f"materials.{name}: rigid blocks are not supported")
    blocks = s["blocks"]
    polys = [[tuple(map(float, v)) for v in b["vertices"]] for b in blocks]
    for i, b in enumerate(blocks):
        if b.get("rigid"):
            fail(f"blocks[{i}].rigid: not supported")
        if area(polys[i]) <= 0:
            fail(f"blocks[{i}]: clockwise polygon")

    # Scene scale: ntdda's w0 is half the larger side of the joints' bounding box.
    xs = [x for p in polys for x, _ in p]
    ys = [y for p in polys for _, y in p]
    w0 = max(max(xs) - min(xs), max(ys) - min(ys)) / 2
    tol = 1e-9 * max(1.0, max(map(abs, xs + ys)))

    # Block materials: (material, velocity, initial stress) -> ntdda material number.
    def props(b):
        return (b["material"], tuple(b.get("velocity", (0.0, 0.0, 0.0))),
                tuple(b.get("initial_stress", (0.0, 0.0, 0.0))))
    count = {}
    for b in blocks:
        count[props(b)] = count.get(props(b), 0) + 1
    order = sorted(count, key=lambda k: -count[k])
    matno = {k: i + 1 for i, k in enumerate(order)}

    # Joint types: 1 = default, then the other joint materials in order of name.
    jmats = s.get("joint_materials", {"default": {"friction_angle": 0.0, "cohesion": 0.0,
                                                  "tensile_strength": 0.0}})
    jnames = ["default"] + sorted(k for k in jmats if k != "default")
    jtype = {n: i + 1 for i, n in enumerate(jnames)}
    pair_type = {}
    for j in s.get("joints", []):
        a, b = j["blocks"]
        pair_type[(min(a, b), max(a, b))] = jtype[j["material"]]

    gr = Graph(polys, tol)
    lines = []
    used_pairs = set()
    for (u, v), owners in gr.seg.items():
        t = 1
        if len(owners) == 2:
            a, b = sorted(owners)
            if (a, b) in pair_type:
                t = pair_type[(a, b)]
                used_pairs.add((a, b))
        elif len(owners) > 2:
            fail(f"blocks {sorted(owners)} overlap along an edge")
        (x0, y0), (x1, y1) = gr.pts[u], gr.pts[v]
        lines.append((t, x0, y0, x1, y1))
    warnings = []
    for p in pair_type:
        if p not in used_pairs:
            warnings.append(f"joints: blocks {p} do not touch at the start; ntdda keeps joint "
                            "types on lines, so their contacts will use the default")

    # Closed regions that are no block: hole points.
    holes = []
    for face in gr.faces():
        x, y = interior_point(face)
        if not any(inside(p, x, y) for p in polys):
            holes.append((x, y))
    nfree_faces = len(gr.faces()) - len(holes)
    if nfree_faces != len(blocks):
        warnings.append(f"the outlines enclose {nfree_faces} regions, the scene has "
                        f"{len(blocks)} blocks")

    # Fixed points: fixed blocks, then pins.
    fixed_pts = []
    for p, b in zip(polys, blocks):
        if not b.get("fixed"):
            continue
        cx, cy = centroid(p)
        pts = [(x + 0.1 * (cx - x), y + 0.1 * (cy - y)) for x, y in p]
        pts = [q for q in pts if inside(p, *q)]
        if len(pts) < 3:
            pts.append(interior_point(p))
        fixed_pts += pts
    fixed_pts += [tuple(pin["point"]) for pin in s.get("pins", [])]
    loads = s.get("point_loads", [])
    monitors = s.get("monitors", [])

    # Material lines for blocks whose material number is not 1.
    matlines = []
    for p, b in zip(polys, blocks):
        k = matno[props(b)]
        if k == 1:
            continue
        x, y = interior_point(p)
        d = 1e-3 * min(dist_to_boundary(p, x, y), 1.0)
        matlines.append((k, x - d, y, x + d, y))

    # Maximum displacement ratio g2.
    r = c.get("max_displacement_ratio", 0.01)
    free = [p for p, b in zip(polys, blocks) if not b.get("fixed")] or polys
    halves = sorted(max(max(x for x, _ in p) - min(x for x, _ in p),
                        max(y for _, y in p) - min(y for _, y in p)) / 2 for p in free)
    if args.g2 == "metres":
        g2 = r * halves[len(halves) // 2] / w0
    elif args.g2 == "ratio":
        g2 = r
    else:
        g2 = float(args.g2)
    ap_pen = c.get("allowed_penetration", "auto")
    g3 = 4e-4 if ap_pen == "auto" else float(ap_pen) / w0
    emax = max(m["young"] for m in mats.values())
    pen = c.get("penalty", "auto")
    pfactor = 50.0 if pen == "auto" else float(pen) / emax
    oc_limit = args.oc_limit if args.oc_limit is not None else c.get("max_open_close", 8)
    plane_strain = s.get("plane", "strain") == "strain"

    ns = 'xmlns:Berkeley="http://www.tsoft.com/~bdoolin/dda"'
    geo = ['<?xml version="1.0" standalone="no"?>', '<!DOCTYPE DDA SYSTEM "geometry.dtd">',
           f'<Berkeley:DDA {ns}>', '<Berkeley:Geometry>',
           f'<Berkeley:Edgenodedist distance="{fmt(args.edge_node_dist)}"/>', '<Jointlist>']
    geo += [f'<Joint type="{t}"> {fmt(a)} {fmt(b)} {fmt(cc)} {fmt(d)} </Joint>'
            for t, a, b, cc, d in lines]
    geo.append('</Jointlist>')
    if matlines:
        geo.append('<Matlinelist>')
        geo += [f'<Line type="{k}"> {fmt(a)} {fmt(b)} {fmt(cc)} {fmt(d)} </Line>'
                for k, a, b, cc, d in matlines]
        geo.append('</Matlinelist>')
    if fixed_pts:
        geo.append('<Fixedpointlist>')
        geo += [f'<Point> {fmt(x)} {fmt(y)} </Point>' for x, y in fixed_pts]
        geo.append('</Fixedpointlist>')
    if loads:
        geo.append('<Loadpointlist>')
        geo += [f'<Point> {fmt(l["point"][0])} {fmt(l["point"][1])} </Point>' for l in loads]
        geo.append('</Loadpointlist>')
    if monitors:
        geo.append('<Measuredpointlist>')
        geo += [f'<Point> {fmt(m["point"][0])} {fmt(m["point"][1])} </Point>' for m in monitors]
        geo.append('</Measuredpointlist>')
    if holes:
        geo.append('<Holepointlist>')
        geo += [f'<Point> {fmt(x)} {fmt(y)} </Point>' for x, y in holes]
        geo.append('</Holepointlist>')
    geo += ['</Berkeley:Geometry>', '</Berkeley:DDA>', '']

    ana = ['<?xml version="1.0" standalone="no"?>', '<!DOCTYPE DDA SYSTEM "analysis.dtd">',
           f'<Berkeley:DDA {ns}>', '<Analysis>',
           f'<Analysistype type="{"dynamic" if kdyn == 1 else "static"}"/>',
           f'<Rotation type="{args.rotation}"/>',
           '<Gravity flag="no"/>',
           f'<Gravaccel value="{fmt(g)}"/>',
           '<Autotimestep flag="no"/>',
           f'<Autopenalty flag="no" pfactor="{fmt(pfactor)}"/>',
           f'<Planestrain flag="{"yes" if plane_strain else "no"}"/>',
           f'<Numtimesteps timesteps="{steps}"/>',
           f'<Maxtimestep maxtimestep="{fmt(dt)}"/>',
           f'<Opencloselimit maxopenclose="{oc_limit}"/>',
           f'<Maxdisplacement maxdisplacement="{fmt(g2)}"/>',
           f'<Saveinterval step="{c.get("output_every", 10)}"/>',
           '<AConstants>',
           '<Openclose value="0.0002"/>', '<Opencriteria value="0.0000002"/>',
           f'<NormSpringPen value="{fmt(g3)}"/>',
           '<AngleOverlap value="3.0"/>', '<ShearNormRatio value="2.5"/>',
           '</AConstants>']
    for k in order:
        name, vel, st = k
        m = mats[name]
        rho = m["density"]
        ana += [f'<Blockmaterial type="{matno[k]}">',
                f'<Unitmass> {fmt(rho)} </Unitmass>', f'<Unitweight> {fmt(rho * g)} </Unitweight>',
                f'<Youngsmod> {fmt(m["young"])} </Youngsmod>',
                f'<Poissonratio> {fmt(m["poisson"])} </Poissonratio>',
                '<Damping> 0.0 </Damping>',
                f'<Istress> {fmt(st[0])} {fmt(st[1])} {fmt(st[2])} </Istress>',
                '<Istrain> 0.0 0.0 0.0 </Istrain>',
                f'<Ivelocity> {fmt(vel[0])} {fmt(vel[1])} {fmt(vel[2])} </Ivelocity>',
                '</Blockmaterial>']
    for n in jnames:
        jm = jmats[n]
        ana += [f'<Jointproperties type="{jtype[n]}">',
                f'<Friction> {fmt(jm["friction_angle"])} </Friction>',
                f'<Cohesion> {fmt(jm["cohesion"])} </Cohesion>',
                f'<Tensile> {fmt(jm["tensile_strength"])} </Tensile>',
                '</Jointproperties>']
    if loads:
        T = steps * dt * 10
        ana.append('<Loadpointlist>')
        for l in loads:
            fx, fy = l["force"]
            ana.append(f'<Loadpoint numpoints="2"> 0 {fmt(fx)} {fmt(fy)}; '
                       f'{fmt(T)} {fmt(fx)} {fmt(fy)}; </Loadpoint>')
        ana.append('</Loadpointlist>')
    ana += ['</Analysis>', '</Berkeley:DDA>', '']

    os.makedirs(os.path.dirname(os.path.abspath(args.out_stem)), exist_ok=True)
    with open(args.out_stem + ".geo", "w") as f:
        f.write("\n".join(geo))
    with open(args.out_stem + ".ana", "w") as f:
        f.write("\n".join(ana))
    info = {"blocks": len(blocks), "fixed_blocks": sum(bool(b.get("fixed")) for b in blocks),
            "joint_lines": len(lines), "fixed_points": len(fixed_pts), "holes": len(holes),
            "materials": len(order), "steps": steps, "dt": dt, "w0": w0, "g2": g2,
            "oc_limit": oc_limit, "pfactor": pfactor, "warnings": warnings}
    print(json.dumps(info))
    for w in warnings:
        print(f"scene_to_ntdda: warning: {w}", file=sys.stderr)


if __name__ == "__main__":
    main()
