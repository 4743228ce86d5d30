// Exact polygon integrals (Green's theorem over the edges) and small geometric predicates.
// Pure functions over plain data.
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// Area, centroid and second moments about the centroid of a simple polygon:
//   area = int dA,  centroid = int x dA / area,
//   sxx = int (x-xc)^2 dA,  syy = int (y-yc)^2 dA,  sxy = int (x-xc)(y-yc) dA.
// Counter-clockwise polygons give a positive area; clockwise ones a negative area
// (and moments of the same sign), which callers use to detect orientation.
struct Moments {
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
  double sxx = 0.0;
  double syy = 0.0;
  double sxy = 0.0;
};

Moments polygon_moments(const Polygon& poly);

// Signed area (positive when counter-clockwise).
double signed_area(const Polygon& poly);

// True when two edges that are not neighbours touch or cross, or neighbours overlap:
// the polygon is not simple. A sweep along x (first_crossing); no pair budget.
bool is_self_intersecting(const Polygon& poly);

// The simple reference path: every pair of edges, O(n^2). Same verdicts as the sweep
// (tests/kinematics/test_polygon.cpp compares them on random and degenerate polygons).
bool is_self_intersecting_reference(const Polygon& poly);

// The first pair of edges found that makes the polygon not simple (edge k runs from
// vertex k to vertex k + 1; a == b for a zero-length edge, b == a + 1 for neighbours that
// fold back), by a sweep along x that tests only edges whose boxes overlap: O(n log n) plus
// the number of edge pairs whose x-ranges overlap (a few per edge for any block outline).
// `too_intricate` is set, and the search stopped, when more than `pair_budget` pairs side by
// side in x would be looked at (a comb of long teeth); then nothing is known.
struct EdgeCrossing {
  bool found = false;
  bool too_intricate = false;
  int edge_a = -1, edge_b = -1;
};
EdgeCrossing first_crossing(const Polygon& poly, long pair_budget);

// Point in polygon (crossing number); points on the boundary count as inside.
bool contains_point(const Polygon& poly, const Vec2& p);

// Axis-aligned bounding box of a polygon, or of all the polygons: {min, max}.
struct Box {
  Vec2 min;
  Vec2 max;
};
Box bounding_box(const Polygon& poly);
Box bounding_box(const std::vector<Polygon>& polys);

}  // namespace dda
