// The geometric tests that label a cut block (cutting/model.hpp): a point surely
// inside it (for the region it belongs to), whether it lies along one of the domain's edges,
// whether it lies inside a polygon. Pure functions over plain doubles.
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// A point inside the simple counter-clockwise polygon `block`: its centroid when that lies
// inside it (always for a convex block), otherwise (a concave block whose centroid falls
// outside, or on its boundary within `tol`) the midpoint of the longest piece of the
// horizontal line through the centroid that lies inside the block. That line crosses the
// block, as the centroid's height is strictly between the lowest and highest vertex.
Vec2 interior_point(const Polygon& block, double tol);

// Distance from `p` to the segment from `a` to `b`.
double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b);

// True when some edge of `block` lies along the segment from `a` to `b`: both of its ends
// within `tol` of the segment's line, and its projection onto the segment overlapping it by
// more than `tol`.
bool has_edge_along(const Polygon& block, const Vec2& a, const Vec2& b, double tol);

// True when every vertex of `block` lies inside `polygon` or within `tol` of its boundary.
bool lies_within(const Polygon& block, const Polygon& polygon, double tol);

}  // namespace dda
