#include "contact/narrow_phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "kinematics/polygon.hpp"

namespace dda {
namespace {

int wrap(int i, int n) { return (i % n + n) % n; }

// A vertex-to-vertex meeting: vertex va of a near vertex vb of b.
struct VertexPair {
  int va;
  int vb;
};

// Half the shortest edge at a vertex: a contact "reaches" no farther than this into a block,
// so that a large search distance cannot pair a vertex with the far side of a small block.
double half_shortest_edge_at(const Polygon& poly, int v) {
  const int n = static_cast<int>(poly.size());
  return 0.5 * std::min((poly[v] - poly[wrap(v - 1, n)]).norm(), (poly[wrap(v + 1, n)] - poly[v]).norm());
}

// wedge_score of vertex v from its features: the same expression on the same unit vectors.
double wedge_score(const PolygonFeatures& f, int v, const Vec2& normal) {
  const VertexFeatures& k = f[static_cast<std::size_t>(v)];
  return std::min(k.to_prev.dot(normal), k.to_next.dot(normal));
}

// Whether edge `e` of `ep` is the nearest part of its boundary to `p`, a point behind the
// edge's line by `depth` (> 0): no other edge comes nearer. A point that sits on (or nearer
// to) another edge is that edge's: a vertex of a neighbour resting at a corner of `ep` next
// to a short edge lies "0.24 m deep" behind the long edge's line while touching the corner
// (a cut rock slope had dozens; each entered as a 0.24 m penetration at the first step).
bool nearest_edge(const PolygonFeatures& ef, int e, const Vec2& p, double depth) {
  for (std::size_t k = 0; k < ef.size(); ++k) {
    if (static_cast<int>(k) == e) continue;
    const EdgeFrame& f = ef[k].edge;
    const double s = std::clamp((p - f.start).dot(f.tangent), 0.0, f.length);
    if ((p - (f.start + s * f.tangent)).norm() < depth) return false;
  }
  return true;
}

// Edge e of a block is covered by a block other than `other` (mark_covered_edges): no
// vertex of `other` enters it.
bool covered_against(const PolygonFeatures& f, int e, int other, bool firm_only = false) {
  const VertexFeatures& k = f[static_cast<std::size_t>(e)];
  return k.covered_by >= 0 && k.covered_by != other && (!firm_only || k.covered_firmly);
}

// Vertex v sits at an edge covered by a block other than `other` that runs parallel to
// `target` (an edge of `other`): v is no corner to push on that face (mark_covered_edges).
bool blocked_at_covered_edge(const PolygonFeatures& f, int v, int other, const EdgeFrame& target,
                             bool firm_only = false) {
  const int n = static_cast<int>(f.size());
  for (const int k : {v, wrap(v - 1, n)}) {
    if (!covered_against(f, k, other, firm_only)) continue;
    if (std::abs(f[static_cast<std::size_t>(k)].edge.tangent.dot(target.tangent)) >= 1.0 - kWedgeTolerance) {
      return true;
    }
  }
  return false;
}

// Whether edge `e` lies on the antiparallel face `f` over its whole length, within
// `tolerance` (or kCoveredShare of its length).
bool covered_by(const EdgeFrame& e, const EdgeFrame& f, double tolerance) {
  if (e.tangent.dot(f.tangent) > -(1.0 - kWedgeTolerance)) return false;
  const double tol = std::max(kCoveredShare * e.length, tolerance);
  if (std::abs((f.start - e.start).dot(e.normal)) > tol ||
      std::abs((f.end - e.start).dot(e.normal)) > tol) {
    return false;
  }
  const double s0 = (f.start - e.start).dot(e.tangent), s1 = (f.end - e.start).dot(e.tangent);
  return std::min(s0, s1) <= tol && std::max(s0, s1) >= e.length - tol;
}

bool in_vertex_pair(const std::vector<VertexPair>& pairs, int va, int vb) {
  return std::any_of(pairs.begin(), pairs.end(),
                     [&](const VertexPair& p) { return p.va == va && p.vb == vb; });
}

// Vertex `v` of `vp` against every edge of `ep`, skipping edges that end at a vertex paired
// with `v` (those meetings are decided by the vertex-to-vertex rule). Every test below only
// rules a meeting out, so their order does not change the answer; the projection's reach,
// which rules out all but a few of a pair's vertex-edge meetings, goes first (in a hopper of
// 300 polygons the covers and vertex pairs tested first had made this 7 % of the run).
void vertex_to_edge(const Polygon& vp, const PolygonFeatures& vf, int vblock, const Polygon& ep,
                    const PolygonFeatures& ef, int eblock, double d0,
                    const std::vector<VertexPair>& pairs, bool v_is_a,
                    std::vector<ContactCandidate>& out) {
  const int nv = static_cast<int>(vp.size());
  const int ne = static_cast<int>(ep.size());
  for (int v = 0; v < nv; ++v) {
    if (!vf[static_cast<std::size_t>(v)].convex) continue;
    for (int e = 0; e < ne; ++e) {
      const EdgeFrame& frame = ef[static_cast<std::size_t>(e)].edge;
      const EdgeProjection proj = project_on_edge(vp[v], frame);
      // Outside by up to d0, or inside by no more than half the local edge lengths.
      const double reach =
          std::min({d0, vf[static_cast<std::size_t>(v)].half_shortest_edge, 0.5 * frame.length});
      if (proj.t < 0.0 || proj.t > 1.0 || proj.gap > d0 || proj.gap < -reach) continue;
      if (covered_against(ef, e, vblock, true)) continue;
      if (blocked_at_covered_edge(vf, v, eblock, frame, true)) continue;
      const int e_end = wrap(e + 1, ne);
      const bool paired_start = v_is_a ? in_vertex_pair(pairs, v, e) : in_vertex_pair(pairs, e, v);
      const bool paired_end = v_is_a ? in_vertex_pair(pairs, v, e_end) : in_vertex_pair(pairs, e_end, v);
      // A paired vertex is left to the vertex-pair rule only where it projects near the
      // paired end: two faces that overlap by more than that (blocks face to face, offset
      // along the face) need both end vertices on the other's edge, and a rocking block
      // pushed the one the pair rule had dropped 0.5 mm into its neighbour unopposed.
      // Only while it is outside or barely inside the edge: a paired vertex found deep
      // behind an edge's line near the paired corner is beyond the corner's other edge
      // (outside the block) and belongs to the pair rule (a pack of random blocks had one
      // "3 cm deep" behind the line of an acute corner's edge).
      const double clearance = kPairClearanceShare * d0;
      if ((paired_start || paired_end) && proj.gap < -clearance) continue;
      if ((paired_start && proj.t * frame.length < clearance) ||
          (paired_end && (1.0 - proj.t) * frame.length < clearance)) {
        continue;
      }
      if (wedge_score(vf, v, frame.normal) < -kCandidateWedgeTolerance) continue;
      // Behind the edge's line but outside its block: beyond the other edge of an acute
      // corner, where the line's extension says "deep inside" (a pack of random blocks had
      // such a vertex enter 3.5 cm deep and lock). Not a contact of this edge.
      if (proj.gap < 0.0 && !contains_point(ep, vp[v])) continue;
      // Behind the line and inside the block, but nearer to another of its edges: that
      // edge's contact, not this one's.
      if (proj.gap < 0.0 && !nearest_edge(ef, e, vp[v], -proj.gap)) continue;
      out.push_back({vblock, v, eblock, e, false});
    }
  }
}

// A vertex pair of two convex vertices (Shi 1988, ch. 4, "angle to angle" contacts with both
// angles below 180 degrees): near a convex corner the free space is the *union* of the outer
// half-planes of its two edges, so only one of the four edges at the two vertices is a true
// constraint; entering two of them would hold the vertex out of free space it may occupy (a
// block would hang on the edge line it has already passed). The one chosen: among the edges
// whose wedge test passes, the one across which the vertex lies farthest out (the axis of
// least penetration, as in a separating-axis test; Shi picks his entrance line from the
// angles of the two wedges, df05 in ntdda). Ties (within round-off) go to the first in a
// fixed order, so that the choice does not flicker in face-to-face stacks. If no edge passes
// the wedge test, the squarest one is taken.
std::optional<ContactCandidate> resolve_convex_pair(const Polygon& a, const PolygonFeatures& fa, int ia,
                                     const Polygon& b, const PolygonFeatures& fb, int ib,
                                     const VertexPair& pair) {
  const int na = static_cast<int>(a.size());
  const int nb = static_cast<int>(b.size());
  struct Option {
    ContactCandidate contact;
    double score;
    double gap;
  };
  auto option = [](const Polygon& vp, const PolygonFeatures& vf, int vblock, int v,
                   const PolygonFeatures& ef, int eblock, int e) {
    const EdgeFrame& frame = ef[static_cast<std::size_t>(e)].edge;
    return Option{{vblock, v, eblock, e, true}, wedge_score(vf, v, frame.normal),
                  project_on_edge(vp[v], frame).gap};
  };
  // Vertex of b on the edges of a at va (before and after it), then vertex of a on b's.
  const std::array<Option, 4> options = {
      option(b, fb, ib, pair.vb, fa, ia, wrap(pair.va - 1, na)),
      option(b, fb, ib, pair.vb, fa, ia, pair.va),
      option(a, fa, ia, pair.va, fb, ib, wrap(pair.vb - 1, nb)),
      option(a, fa, ia, pair.va, fb, ib, pair.vb)};
  constexpr double kTie = 1e-12;  // m: gaps equal up to the round-off of O(1) coordinates
  // Covered edges, and vertices at them pushing on a face parallel to theirs
  // (mark_covered_edges): a firm cover (two fixed blocks) rules options out; a cover
  // between free blocks only steers the choice: when it would leave no option, the pair
  // keeps the contact it had without it (the two may part, and then that contact is a
  // constraint: the limit analysis of a cut slope lost a 25-block mechanism's worth of them
  // at "+" junctions). It steers only among options that pass the wedge test: where none
  // does, the squarest of all is taken as without covers. Taking the squarest uncovered one
  // instead put a surface triangle's corner on its neighbour's surface edge, end to end
  // (wedge score -0.71), at every surface node of a crossed triangle mesh: a support that
  // held the columns of verification/vertical-cut against shearing past each other
  // (3 cells a height: F 1.3724 against 1.3496).
  const auto allowed = [&](const Option& o, bool firm_only) {
    const ContactCandidate& c = o.contact;
    const PolygonFeatures& vf = c.vertex_block == ia ? fa : fb;
    const PolygonFeatures& ef = c.vertex_block == ia ? fb : fa;
    return !covered_against(ef, c.edge, c.vertex_block, firm_only) &&
           !blocked_at_covered_edge(vf, c.vertex, c.edge_block,
                                    ef[static_cast<std::size_t>(c.edge)].edge, firm_only);
  };
  for (const bool firm_only : {false, true}) {
    const Option* best = nullptr;
    for (const Option& o : options) {
      if (o.score < -kWedgeTolerance || !allowed(o, firm_only)) continue;
      if (best == nullptr || o.gap > best->gap + kTie) best = &o;
    }
    if (best == nullptr && firm_only) {
      for (const Option& o : options) {
        if (!allowed(o, firm_only)) continue;
        if (best == nullptr || o.score > best->score) best = &o;
      }
    }
    if (best != nullptr) return best->contact;
  }
  return std::nullopt;
}

// A convex vertex `v` of `vp` meeting a reflex vertex `r` of `ep`: two vertex-to-edge
// contacts, `v` on each edge of the reflex corner. This is Shi's angle-to-angle rule (Shi
// 1988, ch. 4) as his program applies it: a concave angle gives the other vertex a contact
// with each of its two edges, a pair of convex angles one contact (df04 in src/contact.c of
// ntdda, the public descendant of his code). Why: near a reflex corner the block fills 270
// degrees, and the free space is the *intersection* of the outer half-planes of its two
// edges, so both edges are true constraints at once (a vertex in the inner corner of a
// stepped base is held by the tread and by the riser, and neither constraint forbids a place
// the vertex may legally be). Choosing one of them, as for two convex vertices, lets the
// vertex through the other: a block resting on the tread with its corner a few millimetres
// from the riser had that corner put on the riser (the larger gap), lost its support there,
// tipped into the tread and was thrown out of the corner.
// The two contacts are also what the vertex-to-edge rule gives the same vertex just outside
// the pairing distance (it then projects onto both edges), so contacts do not jump as the
// vertex comes within that distance; for the same reason each of the two passes the same
// entrance test as a vertex-to-edge candidate (Shi's wedge criterion, his "angle overlapping
// check" in df05, with the candidate tolerance kCandidateWedgeTolerance): a vertex one of
// whose sides heads into the edge's block cannot enter that edge.
// Both projections may fall just past the reflex end of their edges (the vertex is then
// inside the corner, behind both edges); the constraints still hold there, since the block
// behind each edge's line near r is the block itself.
void reflex_pair_contacts(const PolygonFeatures& vf, int vblock, int v, const PolygonFeatures& ef,
                          int eblock, int r, std::vector<ContactCandidate>& out) {
  const int ne = static_cast<int>(ef.size());
  for (const int e : {wrap(r - 1, ne), r}) {  // the edge ending at r, then the one leaving it
    if (covered_against(ef, e, vblock, true)) continue;
    if (blocked_at_covered_edge(vf, v, eblock, ef[static_cast<std::size_t>(e)].edge, true)) continue;
    const Vec2& normal = ef[static_cast<std::size_t>(e)].edge.normal;
    if (wedge_score(vf, v, normal) < -kCandidateWedgeTolerance) continue;
    out.push_back({vblock, v, eblock, e, true});
  }
}

// The contacts of a vertex pair (Shi 1988, ch. 4, angle-to-angle contacts), by the kinds of
// the two angles:
//  - both convex: one contact, on the edge of least penetration (resolve_convex_pair);
//  - one reflex: the convex vertex on both edges of the reflex one (reflex_pair_contacts);
//  - both reflex: none. Two reflex angles cannot meet without overlapping (their angles add
//    up to more than 360 degrees), and a reflex vertex is never the first point of its block
//    to reach another block, so the neighbouring convex vertices carry such a meeting.
void vertex_pair_contacts(const Polygon& a, const PolygonFeatures& fa, int ia, const Polygon& b,
                          const PolygonFeatures& fb, int ib, const VertexPair& pair,
                          std::vector<ContactCandidate>& out) {
  const bool a_convex = fa[static_cast<std::size_t>(pair.va)].convex;
  const bool b_convex = fb[static_cast<std::size_t>(pair.vb)].convex;
  if (a_convex && b_convex) {
    if (const auto c = resolve_convex_pair(a, fa, ia, b, fb, ib, pair)) out.push_back(*c);
  } else if (b_convex) {
    reflex_pair_contacts(fb, ib, pair.vb, fa, ia, pair.va, out);
  } else if (a_convex) {
    reflex_pair_contacts(fa, ia, pair.va, fb, ib, pair.vb, out);
  }
}

}  // namespace

EdgeFrame edge_frame(const Polygon& poly, int edge) {
  const int n = static_cast<int>(poly.size());
  return edge_frame(poly[wrap(edge, n)], poly[wrap(edge + 1, n)]);
}

EdgeFrame edge_frame(const Vec2& start, const Vec2& end) {
  EdgeFrame f;
  f.start = start;
  f.end = end;
  const Vec2 d = f.end - f.start;
  f.length = d.norm();
  f.tangent = d / f.length;
  f.normal = Vec2(f.tangent.y(), -f.tangent.x());
  return f;
}

EdgeProjection project_on_edge(const Vec2& p, const EdgeFrame& e) {
  const Vec2 r = p - e.start;
  return {r.dot(e.normal), r.dot(e.tangent) / e.length};
}

double wedge_score(const Polygon& poly, int vertex, const Vec2& normal) {
  const int n = static_cast<int>(poly.size());
  const Vec2& p = poly[vertex];
  const Vec2 to_prev = (poly[wrap(vertex - 1, n)] - p).normalized();
  const Vec2 to_next = (poly[wrap(vertex + 1, n)] - p).normalized();
  return std::min(to_prev.dot(normal), to_next.dot(normal));
}

bool is_convex_vertex(const Polygon& poly, int vertex) {
  const int n = static_cast<int>(poly.size());
  const Vec2 in = poly[vertex] - poly[wrap(vertex - 1, n)];
  const Vec2 out = poly[wrap(vertex + 1, n)] - poly[vertex];
  const double turn = in.x() * out.y() - in.y() * out.x();
  return turn >= -1e-12 * in.norm() * out.norm();  // straight (180 deg) counts as convex
}

void polygon_features(const Polygon& poly, PolygonFeatures& out) {
  const int n = static_cast<int>(poly.size());
  out.resize(poly.size());
  for (int i = 0; i < n; ++i) {
    VertexFeatures& k = out[static_cast<std::size_t>(i)];
    k.edge = edge_frame(poly, i);
    // As wedge_score makes them.
    k.to_prev = (poly[wrap(i - 1, n)] - poly[i]).normalized();
    k.to_next = (poly[wrap(i + 1, n)] - poly[i]).normalized();
    k.half_shortest_edge = half_shortest_edge_at(poly, i);
    k.convex = is_convex_vertex(poly, i);
    k.covered_by = -1;
    k.covered_firmly = false;
  }
}

void mark_covered_edges(PolygonFeatures& fa, int ia, PolygonFeatures& fb, int ib,
                        double tolerance, bool firm) {
  for (VertexFeatures& ka : fa) {
    for (VertexFeatures& kb : fb) {
      if (covered_by(ka.edge, kb.edge, tolerance)) {
        ka.covered_by = ib;
        ka.covered_firmly = firm;
      }
      if (covered_by(kb.edge, ka.edge, tolerance)) {
        kb.covered_by = ia;
        kb.covered_firmly = firm;
      }
    }
  }
}

FaceShares face_shares(const Polygon& vp, int v, const Vec2& edge_start, const Vec2& edge_end) {
  const int n = static_cast<int>(vp.size());
  FaceShares out;
  const Vec2 along = edge_end - edge_start;
  const double edge_length = along.norm();
  if (!(edge_length > 0.0)) return out;
  const Vec2 t = along / edge_length;
  const Vec2 normal(t.y(), -t.x());
  for (int w : {wrap(v - 1, n), wrap(v + 1, n)}) {
    const Vec2 a = vp[w] - vp[v];
    if (std::abs(a.dot(normal)) > kWedgeTolerance * a.norm()) continue;  // at an angle
    // The face's and the edge's extents along the edge, and their overlap.
    const double s_vertex = t.dot(vp[v] - edge_start), s_other = t.dot(vp[w] - edge_start);
    const double lo = std::max(std::min(s_vertex, s_other), 0.0);
    const double hi = std::min(std::max(s_vertex, s_other), edge_length);
    if (!(hi > lo)) continue;  // end to end, or beside it: no common face
    // The half of the overlap next to the vertex: from the overlap's end nearer the
    // vertex towards its middle.
    const double near = s_other >= s_vertex ? lo : hi;
    const double middle = 0.5 * (lo + hi);
    const double scale = (middle - near) / (s_other - s_vertex);
    out.from[out.count] = vp[v] + ((near - s_vertex) / (s_other - s_vertex)) * a;
    out.halves[out.count] = scale * a;
    out.edges[out.count] = w == wrap(v + 1, n) ? v : w;  // edge k runs from vertex k to k + 1
    ++out.count;
  }
  return out;
}

void find_contacts(const Polygon& a, int ia, const Polygon& b, int ib, double search_distance,
                   std::vector<ContactCandidate>& out) {
  PolygonFeatures fa, fb;
  polygon_features(a, fa);
  polygon_features(b, fb);
  find_contacts(a, fa, ia, b, fb, ib, search_distance, out);
}

void find_contacts(const Polygon& a, const PolygonFeatures& fa, int ia, const Polygon& b,
                   const PolygonFeatures& fb, int ib, double search_distance,
                   std::vector<ContactCandidate>& out) {
  const std::size_t start = out.size();  // this pair of polygons' contacts begin here
  std::vector<VertexPair> pairs;
  for (int va = 0; va < static_cast<int>(a.size()); ++va) {
    for (int vb = 0; vb < static_cast<int>(b.size()); ++vb) {
      const double reach =
          std::min({search_distance, fa[static_cast<std::size_t>(va)].half_shortest_edge,
                    fb[static_cast<std::size_t>(vb)].half_shortest_edge});
      if ((a[va] - b[vb]).norm() <= reach) pairs.push_back({va, vb});
    }
  }
  vertex_to_edge(a, fa, ia, b, fb, ib, search_distance, pairs, true, out);
  vertex_to_edge(b, fb, ib, a, fa, ia, search_distance, pairs, false, out);
  // A pair's contact may be one the vertex-to-edge rule has already found (its vertex
  // projects clear of the paired end): keep one of each. Compacted in place: out[start,
  // kept) holds this pair of polygons' kept contacts, and kept <= i, so a write never
  // overtakes the read (the earlier pairs' contacts before `start` are not touched: copying
  // them here made detection quadratic in the number of contacts).
  const std::size_t first_pair_contact = out.size();
  for (const VertexPair& pair : pairs) vertex_pair_contacts(a, fa, ia, b, fb, ib, pair, out);
  std::size_t kept = first_pair_contact;
  for (std::size_t i = first_pair_contact; i < out.size(); ++i) {
    const ContactCandidate c = out[i];
    const auto first = out.begin() + static_cast<std::ptrdiff_t>(start);
    const auto last = out.begin() + static_cast<std::ptrdiff_t>(kept);
    const auto same = std::find_if(first, last, [&](const ContactCandidate& k) {
      return k.vertex_block == c.vertex_block && k.vertex == c.vertex &&
             k.edge_block == c.edge_block && k.edge == c.edge;
    });
    if (same == last) {
      out[kept++] = c;
    } else {
      same->vertex_to_vertex = true;  // found by both rules
    }
  }
  out.resize(kept);
}

}  // namespace dda
