// Do two polygons overlap (share interior), as opposed to merely touching? Used by the scene
// reader to reject blocks that overlap at the start. Pure function over plain data; convex
// and concave (simple, counter-clockwise) polygons alike.
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// True when the interiors of the simple counter-clockwise polygons `a` and `b` overlap by
// more than `tol` (a length, > 0). Touching is not overlapping: shared edges, shared
// vertices, a vertex on an edge, and gaps or overlaps no deeper than about `tol` all give
// false. Reported as overlap (each test is symmetric in a and b):
//   1. two edges properly cross: each edge's endpoints lie on opposite sides of the other
//      edge's line, every one farther than `tol` from it;
//   2. a vertex of one polygon lies inside the other, farther than `tol` from its boundary;
//   3. a piece of an edge of one polygon lies inside the other: each edge is cut at the
//      other polygon's vertices that lie on it (within `tol`), and the midpoint of every
//      piece is tested. A midpoint farther than `tol` inside is overlap. A midpoint on the
//      other's boundary (within `tol`, e.g. a shared or coincident edge) is decided by a
//      point offset from it into its own polygon by ~1e-6 x the polygon's size (at least
//      100 x tol): overlap if that point is inside both polygons by more than `tol`. This
//      catches identical polygons and coincident edges with both interiors on one side.
// Tests 1 and 2 alone miss overlaps whose boundaries meet only at vertices lying on edges
// (e.g. a square whose corners sit on the sides of a larger square, or a "pinwheel" of two
// polygons each with a corner on the other's edge); test 3 covers those, because with no
// proper crossing each piece of an edge between such contacts lies wholly inside, outside
// or along the other polygon.
// Cost O(n m log m) for polygons of n and m vertices; callers cull far pairs first
// (contact/broad_phase).
bool polygons_overlap(const Polygon& a, const Polygon& b, double tol);

}  // namespace dda
