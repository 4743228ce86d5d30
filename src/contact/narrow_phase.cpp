#include "contact/narrow_phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>

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

bool in_vertex_pair(const std::vector<VertexPair>& pairs, int va, int vb) {
  return std::any_of(pairs.begin(), pairs.end(),
                     [&](const VertexPair& p) { return p.va == va && p.vb == vb; });
}

// Vertex `v` of `vp` against every edge of `ep`, skipping edges that end at a vertex paired
// with `v` (those meetings are decided by the vertex-to-vertex rule).
void vertex_to_edge(const Polygon& vp, int vblock, const Polygon& ep, int eblock, double d0,
                    const std::vector<VertexPair>& pairs, bool v_is_a,
                    std::vector<ContactCandidate>& out) {
  const int nv = static_cast<int>(vp.size());
  const int ne = static_cast<int>(ep.size());
  for (int v = 0; v < nv; ++v) {
    if (!is_convex_vertex(vp, v)) continue;
    for (int e = 0; e < ne; ++e) {
      const int e_end = wrap(e + 1, ne);
      const bool paired = v_is_a ? (in_vertex_pair(pairs, v, e) || in_vertex_pair(pairs, v, e_end))
                                 : (in_vertex_pair(pairs, e, v) || in_vertex_pair(pairs, e_end, v));
      if (paired) continue;
      const EdgeFrame frame = edge_frame(ep, e);
      const EdgeProjection proj = project_on_edge(vp[v], frame);
      // Outside by up to d0, or inside by no more than half the local edge lengths.
      const double reach = std::min({d0, half_shortest_edge_at(vp, v), 0.5 * frame.length});
      if (proj.t < 0.0 || proj.t > 1.0 || proj.gap > d0 || proj.gap < -reach) continue;
      if (wedge_score(vp, v, frame.normal) < -kWedgeTolerance) continue;
      out.push_back({vblock, v, eblock, e, false});
    }
  }
}

// Of the four edges meeting at a vertex pair, the one the other vertex meets: among the
// edges whose wedge test passes, the one across which the vertex lies farthest out (the axis
// of least penetration, as in a separating-axis test). Ties (within round-off) go to the
// first in a fixed order, so that the choice does not flicker in face-to-face stacks. If no
// edge passes the wedge test, the squarest one is taken.
ContactCandidate resolve_vertex_pair(const Polygon& a, int ia, const Polygon& b, int ib,
                                     const VertexPair& pair) {
  const int na = static_cast<int>(a.size());
  const int nb = static_cast<int>(b.size());
  struct Option {
    ContactCandidate contact;
    double score;
    double gap;
  };
  auto option = [](const Polygon& vp, int vblock, int v, const Polygon& ep, int eblock, int e) {
    const EdgeFrame frame = edge_frame(ep, e);
    // Reflex vertices cannot enter an edge.
    const double score = is_convex_vertex(vp, v) ? wedge_score(vp, v, frame.normal) : -INFINITY;
    return Option{{vblock, v, eblock, e, true}, score, project_on_edge(vp[v], frame).gap};
  };
  // Vertex of b on the edges of a at va (before and after it), then vertex of a on b's.
  const std::array<Option, 4> options = {
      option(b, ib, pair.vb, a, ia, wrap(pair.va - 1, na)), option(b, ib, pair.vb, a, ia, pair.va),
      option(a, ia, pair.va, b, ib, wrap(pair.vb - 1, nb)), option(a, ia, pair.va, b, ib, pair.vb)};
  constexpr double kTie = 1e-12;  // m: gaps equal up to the round-off of O(1) coordinates
  const Option* best = nullptr;
  for (const Option& o : options) {
    if (o.score < -kWedgeTolerance) continue;
    if (best == nullptr || o.gap > best->gap + kTie) best = &o;
  }
  if (best == nullptr) {
    best = &options[0];
    for (const Option& o : options) {
      if (o.score > best->score) best = &o;
    }
  }
  return best->contact;
}

}  // namespace

EdgeFrame edge_frame(const Polygon& poly, int edge) {
  const int n = static_cast<int>(poly.size());
  EdgeFrame f;
  f.start = poly[wrap(edge, n)];
  f.end = poly[wrap(edge + 1, n)];
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

void find_contacts(const Polygon& a, int ia, const Polygon& b, int ib, double search_distance,
                   std::vector<ContactCandidate>& out) {
  std::vector<VertexPair> pairs;
  for (int va = 0; va < static_cast<int>(a.size()); ++va) {
    for (int vb = 0; vb < static_cast<int>(b.size()); ++vb) {
      const double reach =
          std::min({search_distance, half_shortest_edge_at(a, va), half_shortest_edge_at(b, vb)});
      if ((a[va] - b[vb]).norm() <= reach) pairs.push_back({va, vb});
    }
  }
  vertex_to_edge(a, ia, b, ib, search_distance, pairs, true, out);
  vertex_to_edge(b, ib, a, ia, search_distance, pairs, false, out);
  for (const VertexPair& pair : pairs) out.push_back(resolve_vertex_pair(a, ia, b, ib, pair));
}

}  // namespace dda
