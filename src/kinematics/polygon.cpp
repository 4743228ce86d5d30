#include "kinematics/polygon.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <vector>

namespace dda {
namespace {

// Twice the signed area of triangle abc: > 0 when a, b, c turn counter-clockwise.
double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross(b - a, c - a); }

// p lies on segment ab, given that a, b, p are collinear.
bool within_box(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// Closed segments ab and cd share at least one point.
bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) {
    return true;
  }
  return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) ||
         (o3 == 0 && within_box(c, d, a)) || (o4 == 0 && within_box(c, d, b));
}

}  // namespace

double signed_area(const Polygon& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return 0.0;
  // Relative to the first vertex, so that far-away coordinates lose no digits.
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) twice += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  return 0.5 * twice;
}

Moments polygon_moments(const Polygon& poly) {
  const std::size_t n = poly.size();
  assert(n >= 3);
  Moments m;
  // Pass 1: area and centroid by Green's theorem, relative to vertex 0.
  const Vec2 origin = poly[0];
  double twice_area = 0.0;
  Vec2 first = Vec2::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = poly[i] - origin, b = poly[(i + 1) % n] - origin;
    const double c = cross(a, b);
    twice_area += c;
    first += (a + b) * c;
  }
  m.area = 0.5 * twice_area;
  m.centroid = origin + first / (3.0 * twice_area);
  // Pass 2: second moments about the centroid, edge by edge (exact for straight edges):
  //   int x^2 = 1/12 sum (xi^2 + xi xj + xj^2) ci,  int xy = 1/24 sum (xi yj + 2 xi yi + 2 xj yj + xj yi) ci
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = poly[i] - m.centroid, b = poly[(i + 1) % n] - m.centroid;
    const double c = cross(a, b);
    m.sxx += (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) * c;
    m.syy += (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) * c;
    m.sxy += (a.x() * b.y() + 2.0 * a.x() * a.y() + 2.0 * b.x() * b.y() + b.x() * a.y()) * c;
  }
  m.sxx /= 12.0;
  m.syy /= 12.0;
  m.sxy /= 24.0;
  return m;
}

namespace {

// Edges i and j (i != j) share a vertex.
bool neighbours(std::size_t i, std::size_t j, std::size_t n) {
  return (i + 1) % n == j || (j + 1) % n == i;
}

// The rule both paths apply to a pair of edges i < j: neighbours must not fold back onto each
// other, other edges must not touch at all.
bool pair_breaks_simplicity(const Polygon& poly, std::size_t i, std::size_t j) {
  const std::size_t n = poly.size();
  const Vec2& a = poly[i];
  const Vec2& b = poly[(i + 1) % n];
  const Vec2& c = poly[j];
  const Vec2& d = poly[(j + 1) % n];
  if (!neighbours(i, j, n)) return segments_touch(a, b, c, d);
  // Neighbours: the turn at the shared vertex folds back when the three are collinear and
  // the two edges leave it on the same side.
  const bool i_first = (i + 1) % n == j;
  const Vec2& from = i_first ? a : c;
  const Vec2& shared = i_first ? b : d;
  const Vec2& to = i_first ? d : b;
  return orient(from, shared, to) == 0.0 && (from - shared).dot(to - shared) > 0.0;
}

}  // namespace

bool is_self_intersecting_reference(const Polygon& poly) {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (poly[i] == poly[(i + 1) % n]) return true;  // a zero-length edge
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (pair_breaks_simplicity(poly, i, j)) return true;
    }
  }
  return false;
}

EdgeCrossing first_crossing(const Polygon& poly, long pair_budget) {
  const std::size_t n = poly.size();
  EdgeCrossing out;
  for (std::size_t i = 0; i < n; ++i) {
    if (poly[i] == poly[(i + 1) % n]) {
      out.found = true;
      out.edge_a = out.edge_b = static_cast<int>(i);
      return out;
    }
  }
  // Edges in order of their left end; the active ones are those whose right end is not left
  // of the present edge's left end. Two edges whose closed boxes do not overlap cannot touch,
  // so every pair that can break simplicity is tested once.
  struct Span {
    double min_x, max_x, min_y, max_y;
    std::size_t edge;
  };
  std::vector<Span> spans(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    spans[i] = {std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
                std::max(a.y(), b.y()), i};
  }
  std::sort(spans.begin(), spans.end(),
            [](const Span& p, const Span& q) { return p.min_x < q.min_x; });
  std::vector<const Span*> active;
  long tested = 0;
  for (const Span& e : spans) {
    std::size_t kept = 0;
    for (const Span* f : active) {
      if (f->max_x < e.min_x) continue;  // ended before e begins: drop it
      active[kept++] = f;
      if (++tested > pair_budget) {  // every pair side by side in x costs a look
        out.too_intricate = true;
        return out;
      }
      if (f->max_y < e.min_y || e.max_y < f->min_y) continue;
      const std::size_t i = std::min(e.edge, f->edge), j = std::max(e.edge, f->edge);
      if (pair_breaks_simplicity(poly, i, j)) {
        out.found = true;
        out.edge_a = static_cast<int>(i);
        out.edge_b = static_cast<int>(j);
        return out;
      }
    }
    active.resize(kept);
    active.push_back(&e);
  }
  return out;
}

bool is_self_intersecting(const Polygon& poly) {
  return first_crossing(poly, std::numeric_limits<long>::max()).found;
}

bool contains_point(const Polygon& poly, const Vec2& p) {
  const std::size_t n = poly.size();
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[j];
    const Vec2& b = poly[i];
    // On the edge (within a relative round-off band) counts as inside.
    const double len2 = (b - a).squaredNorm();
    if (std::abs(orient(a, b, p)) <= 1e-12 * len2 && within_box(a, b, p)) return true;
    if ((b.y() > p.y()) != (a.y() > p.y())) {
      const double x_cross = b.x() + (p.y() - b.y()) * (a.x() - b.x()) / (a.y() - b.y());
      if (p.x() < x_cross) inside = !inside;
    }
  }
  return inside;
}

Box bounding_box(const Polygon& poly) {
  Box box{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
  for (const Vec2& v : poly) {
    box.min = box.min.cwiseMin(v);
    box.max = box.max.cwiseMax(v);
  }
  return box;
}

Box bounding_box(const std::vector<Polygon>& polys) {
  Box box{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
  for (const Polygon& poly : polys) {
    const Box b = bounding_box(poly);
    box.min = box.min.cwiseMin(b.min);
    box.max = box.max.cwiseMax(b.max);
  }
  return box;
}

}  // namespace dda
