#include "io/polygon_input.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "io/input_limits.hpp"
#include "kinematics/polygon.hpp"

namespace dda::input {

namespace {

double bbox_diagonal(const Polygon& poly) {
  const Box box = bounding_box(poly);
  return (box.max - box.min).stableNorm();  // no underflow for a block 1e-300 m across
}

// Degeneracy tolerance relative to the polygon's bounding-box diagonal d: lengths <= 1e-12 d
// and areas <= 1e-12 d^2 count as zero. Scale-free, far above rounding in the sums (~1e-16
// relative) and far below any real block.
constexpr double kRelativeTolerance = 1e-12;

// A repeated vertex gives a zero-length edge; the common cause is closing the polygon by
// repeating the first vertex, which gets its own hint.
void check_no_repeated_vertex(const Field& f, const Polygon& poly, double diagonal) {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if ((poly[i] - poly[j]).norm() > kRelativeTolerance * diagonal) continue;
    if (j == 0) {
      f.fail("the last vertex repeats the first; list each corner once (the polygon is "
             "closed automatically)");
    }
    f.fail("vertices " + std::to_string(i) + " and " + std::to_string(j) +
           " are the same point; list each corner once");
  }
}

// All vertices on one line: checked before self-intersection so that a flat polygon is
// reported as having zero area rather than as overlapping edges.
bool all_collinear(const Polygon& poly, double diagonal) {
  std::size_t far = 0;
  for (std::size_t i = 1; i < poly.size(); ++i) {
    if ((poly[i] - poly[0]).norm() > (poly[far] - poly[0]).norm()) far = i;
  }
  const Vec2 axis = poly[far] - poly[0];
  return std::all_of(poly.begin(), poly.end(), [&](const Vec2& p) {
    return std::abs(cross(axis, p - poly[0])) <= kRelativeTolerance * diagonal * diagonal;
  });
}

}  // namespace

// Edge pairs the simplicity sweep may test before it gives up (first_crossing): about a
// second of work. A block outline of any size needs a few per edge (80 000 vertices on a
// circle: about 2 each); only a comb of long teeth overlapping in x needs more.
constexpr long kCrossingPairBudget = 50'000'000;

// Order matters: a self-crossing polygon can have any signed area (a figure eight has zero),
// so crossing is checked before area and orientation.
void check_polygon_shape(const Field& f, const Polygon& poly) {
  const double diagonal = bbox_diagonal(poly);
  // Below this size areas and second moments (diagonal^4) leave double precision's normal
  // range; the coordinates' own bound (read_polygon) keeps the squares finite above.
  if (diagonal < kSmallestPolygon) {
    f.fail("polygon is only " + format_number(diagonal) + " m across; a block or region must be at "
           "least " + format_number(kSmallestPolygon) + " m across (see docs/scene-format.md, "
           "\"Limits\")");
  }
  check_no_repeated_vertex(f, poly, diagonal);
  if (all_collinear(poly, diagonal)) {
    f.fail("polygon has zero area: all its vertices lie on one line");
  }
  const EdgeCrossing crossing = first_crossing(poly, kCrossingPairBudget);
  if (crossing.too_intricate) {
    f.fail("polygon of " + std::to_string(poly.size()) + " vertices has more than " +
           std::to_string(kCrossingPairBudget) + " pairs of edges side by side, too many to check "
           "that it does not cross itself; split it into simpler blocks");
  }
  if (crossing.found) {
    const auto edge = [&](int k) {
      return "edge " + std::to_string(k) + " (vertices " + std::to_string(k) + " to " +
             std::to_string((static_cast<std::size_t>(k) + 1) % poly.size()) + ")";
    };
    f.fail("polygon crosses itself (" + edge(crossing.edge_a) + " and " + edge(crossing.edge_b) +
           " cross or touch); list the vertices in order around the boundary");
  }
  const double area = signed_area(poly);
  if (std::abs(area) <= kRelativeTolerance * diagonal * diagonal) {
    f.fail("polygon has zero area (" + format_number(area) + " m^2)");
  }
  if (area < 0.0) f.fail("polygon is clockwise; list the vertices counter-clockwise");
}

Polygon read_polygon(const Field& f) {
  Polygon poly;
  for (const Field& vertex : f.elements(3, "a polygon needs at least 3 vertices")) {
    poly.push_back(within_limit(vertex, vertex.vec2("[x, y]"), kLargestCoordinate, "m"));
  }
  check_polygon_shape(f, poly);
  return poly;
}

}  // namespace dda::input
