// Narrow phase: the vertex-to-edge contacts between two polygons, with Shi's entrance
// criteria (Shi 1988, ch. 4): a vertex can enter an edge only if the wedge of its block at
// that vertex faces the edge. Vertex-to-vertex meetings are turned into one vertex-to-edge
// contact on the edge the vertex would enter. Concave (reflex) vertices never act as the
// entering vertex (they cannot be the first point of their block to reach a straight edge),
// but their edges receive vertices like any other. Pure functions over plain data.
#pragma once

#include <vector>

#include "kinematics/types.hpp"

namespace dda {

// An edge of a counter-clockwise polygon: from vertex `edge` to vertex `edge + 1`.
struct EdgeFrame {
  Vec2 start;
  Vec2 end;
  Vec2 tangent;  // unit, start -> end
  Vec2 normal;   // unit, pointing out of the polygon (to the right of the tangent)
  double length = 0.0;
};

EdgeFrame edge_frame(const Polygon& poly, int edge);

// Where a point lies relative to an edge: `gap` its signed distance from the edge's line,
// positive outside the edge's polygon; `t` the parameter of its projection (0 at start).
struct EdgeProjection {
  double gap = 0.0;
  double t = 0.0;
};
EdgeProjection project_on_edge(const Vec2& p, const EdgeFrame& e);

// How squarely the wedge of `poly` at `vertex` faces an edge of outward normal `normal`:
// the smaller of a.n / |a| over the wedge's two edge directions a. >= 0 when both edges leave
// the vertex on the outer side of the edge (the vertex can enter it).
double wedge_score(const Polygon& poly, int vertex, const Vec2& normal);

// True when the interior angle at `vertex` is below 180 degrees (up to round-off).
bool is_convex_vertex(const Polygon& poly, int vertex);

// A vertex of one block against an edge of another. `a` is always the lower-indexed block.
struct ContactCandidate {
  int vertex_block = -1;
  int vertex = -1;
  int edge_block = -1;
  int edge = -1;
  bool vertex_to_vertex = false;  // found by the vertex-to-vertex rule
};

// Tolerance of the entrance criterion: edges within about 1 degree of the contact edge
// (sin 1 deg) still count as facing it, so that face-to-face contacts keep both corners.
inline constexpr double kWedgeTolerance = 0.0175;

// Appends the contacts between polygons a (block ia) and b (block ib), ia < ib, for vertices
// within `search_distance` of an edge (on either side). Deterministic: the same geometry
// always gives the same list in the same order.
void find_contacts(const Polygon& a, int ia, const Polygon& b, int ib, double search_distance,
                   std::vector<ContactCandidate>& out);

}  // namespace dda
