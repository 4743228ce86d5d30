#include "cutting/block_labels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "kinematics/polygon.hpp"

namespace dda {
namespace {

double distance_to_boundary(const Polygon& polygon, const Vec2& p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    d = std::min(d, distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  }
  return d;
}

}  // namespace

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

Vec2 interior_point(const Polygon& block, double tol) {
  const Vec2 c = polygon_moments(block).centroid;
  if (contains_point(block, c) && distance_to_boundary(block, c) > tol) return c;
  // Crossings of the line y = c.y with the edges, each edge taken as half-open in y (one
  // end in, one out) so that a vertex on the line counts once or not at all, and the
  // crossings pair up into pieces inside the block: (x0, x1), (x2, x3), ...
  const double y = c.y();
  std::vector<double> xs;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const Vec2& p = block[i];
    const Vec2& q = block[(i + 1) % block.size()];
    if ((p.y() <= y) == (q.y() <= y)) continue;
    xs.push_back(p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
  }
  std::sort(xs.begin(), xs.end());
  Vec2 best = c;
  double longest = -1.0;
  for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
    if (xs[k + 1] - xs[k] > longest) {
      longest = xs[k + 1] - xs[k];
      best = Vec2(0.5 * (xs[k] + xs[k + 1]), y);
    }
  }
  return best;
}

bool has_edge_along(const Polygon& block, const Vec2& a, const Vec2& b, double tol) {
  const double length = (b - a).norm();
  if (length <= tol) return false;
  const Vec2 u = (b - a) / length;
  const auto off_line = [&](const Vec2& p) {
    const Vec2 d = p - a;
    return std::abs(u.x() * d.y() - u.y() * d.x());
  };
  for (std::size_t i = 0; i < block.size(); ++i) {
    const Vec2& p = block[i];
    const Vec2& q = block[(i + 1) % block.size()];
    if (off_line(p) > tol || off_line(q) > tol) continue;
    const double tp = u.dot(p - a), tq = u.dot(q - a);
    const double overlap = std::min(std::max(tp, tq), length) - std::max(std::min(tp, tq), 0.0);
    if (overlap > tol) return true;
  }
  return false;
}

bool lies_within(const Polygon& block, const Polygon& polygon, double tol) {
  return std::all_of(block.begin(), block.end(), [&](const Vec2& v) {
    return contains_point(polygon, v) || distance_to_boundary(polygon, v) <= tol;
  });
}

}  // namespace dda
