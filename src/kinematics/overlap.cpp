#include "kinematics/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace dda {
namespace {

// Signed distance of p from the line through u and v: positive on the left of u -> v, which
// is the inner side of an edge of a counter-clockwise polygon.
double line_distance(const Vec2& u, const Vec2& v, const Vec2& p) {
  return cross(v - u, p - u) / (v - u).norm();
}

double segment_distance(const Vec2& u, const Vec2& v, const Vec2& p) {
  const Vec2 d = v - u;
  const double t = std::clamp((p - u).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (u + t * d)).norm();
}

// Crossing number (even-odd rule). Unreliable only for points on or very near the boundary,
// which `depth` never trusts (callers compare the depth with tol > 0).
bool crossing_inside(const Polygon& poly, const Vec2& p) {
  bool inside = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[j];
    const Vec2& b = poly[i];
    if ((b.y() > p.y()) != (a.y() > p.y())) {
      const double x_cross = b.x() + (p.y() - b.y()) * (a.x() - b.x()) / (a.y() - b.y());
      if (p.x() < x_cross) inside = !inside;
    }
  }
  return inside;
}

// Distance from p to the polygon's boundary, positive inside and negative outside.
double depth(const Polygon& poly, const Vec2& p) {
  double d = std::numeric_limits<double>::infinity();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    d = std::min(d, segment_distance(poly[i], poly[(i + 1) % n], p));
  }
  return crossing_inside(poly, p) ? d : -d;
}

// Each segment's endpoints strictly on opposite sides of the other's line, all four farther
// than tol from it: the interiors of the segments cross at one point, with no touching.
bool properly_cross(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2, double tol) {
  const auto opposite = [tol](double d1, double d2) {
    return (d1 > tol && d2 < -tol) || (d1 < -tol && d2 > tol);
  };
  return opposite(line_distance(p1, p2, q1), line_distance(p1, p2, q2)) &&
         opposite(line_distance(q1, q2, p1), line_distance(q1, q2, p2));
}

bool any_edges_cross(const Polygon& a, const Polygon& b, double tol) {
  const std::size_t n = a.size(), m = b.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      if (properly_cross(a[i], a[(i + 1) % n], b[j], b[(j + 1) % m], tol)) return true;
    }
  }
  return false;
}

bool any_vertex_inside(const Polygon& a, const Polygon& b, double tol) {
  return std::any_of(a.begin(), a.end(), [&](const Vec2& v) { return depth(b, v) > tol; });
}

double diagonal(const Polygon& poly) {
  Vec2 lo = poly[0], hi = poly[0];
  for (const Vec2& v : poly) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return (hi - lo).norm();
}

// Test 3 of polygons_overlap, one way round: a piece of an edge of `a` inside `b`.
bool any_edge_piece_inside(const Polygon& a, const Polygon& b, double tol) {
  // Probe offset: far above tol (so that a probe off a coincident edge is clearly on one
  // side of it) and far below the polygon's size (so that it stays near the edge).
  const double probe = std::max(1e-6 * diagonal(a), 100.0 * tol);
  const std::size_t n = a.size();
  std::vector<double> cuts;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = a[i];
    const Vec2 d = a[(i + 1) % n] - p;
    const double length = d.norm();
    const Vec2 inward = Vec2(-d.y(), d.x()) / length;  // left of the edge: into `a`

    // Where b's vertices lie on this edge, as parameters in (0, 1). Cuts closer than 2 tol to
    // each other or to the edge's ends are merged: they are the same contact point.
    cuts.clear();
    for (const Vec2& v : b) {
      if (segment_distance(p, p + d, v) <= tol) cuts.push_back((v - p).dot(d) / (length * length));
    }
    std::sort(cuts.begin(), cuts.end());
    const double merge = 2.0 * tol / length;
    double from = 0.0;
    std::size_t k = 0;
    while (from < 1.0) {
      while (k < cuts.size() && (cuts[k] <= from + merge || cuts[k] >= 1.0 - merge)) ++k;
      const double to = k < cuts.size() ? cuts[k] : 1.0;
      const Vec2 mid = p + 0.5 * (from + to) * d;
      const double mid_depth = depth(b, mid);
      if (mid_depth > tol) return true;
      if (mid_depth >= -tol) {
        // The piece runs along b's boundary. Step into `a`, by no more than a quarter of the
        // piece's length so that the probe stays beside this piece and not past b's corners.
        const double offset = std::min(probe, 0.25 * (to - from) * length);
        if (offset > 4.0 * tol) {
          const Vec2 x = mid + offset * inward;
          if (depth(a, x) > tol && depth(b, x) > tol) return true;
        }
      }
      from = to;
    }
  }
  return false;
}

bool boxes_apart(const Polygon& a, const Polygon& b, double tol) {
  Vec2 a_lo = a[0], a_hi = a[0], b_lo = b[0], b_hi = b[0];
  for (const Vec2& v : a) {
    a_lo = a_lo.cwiseMin(v);
    a_hi = a_hi.cwiseMax(v);
  }
  for (const Vec2& v : b) {
    b_lo = b_lo.cwiseMin(v);
    b_hi = b_hi.cwiseMax(v);
  }
  // Boxes overlapping by at most tol along an axis: every shared point is within tol of
  // both boundaries, which is touching.
  const Vec2 shared = a_hi.cwiseMin(b_hi) - a_lo.cwiseMax(b_lo);
  return shared.x() <= tol || shared.y() <= tol;
}

}  // namespace

bool polygons_overlap(const Polygon& a, const Polygon& b, double tol) {
  if (a.size() < 3 || b.size() < 3 || boxes_apart(a, b, tol)) return false;
  return any_edges_cross(a, b, tol) || any_vertex_inside(a, b, tol) ||
         any_vertex_inside(b, a, tol) || any_edge_piece_inside(a, b, tol) ||
         any_edge_piece_inside(b, a, tol);
}

}  // namespace dda
