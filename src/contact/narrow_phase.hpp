// Narrow phase: the vertex-to-edge contacts between two polygons, with Shi's entrance
// criteria (Shi 1988, ch. 4): a vertex can enter an edge only if the wedge of its block at
// that vertex faces the edge. Concave (reflex) vertices never act as the entering vertex
// (they cannot be the first point of their block to reach a straight edge), but their edges
// receive vertices like any other. Two vertices that meet (within the pairing distance) are
// Shi's angle-to-angle contact: two convex vertices give one vertex-to-edge contact, on the
// edge the vertex would enter (near a convex corner free space is the union of the two outer
// half-planes, so only one edge constrains); a convex vertex meeting a reflex one gives two,
// the convex vertex on each edge of the reflex corner (there free space is the intersection
// of the two outer half-planes: both constrain). Pure functions over plain data.
#pragma once

#include <array>
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
// The frame of the edge from `start` to `end` of a counter-clockwise polygon.
EdgeFrame edge_frame(const Vec2& start, const Vec2& end);

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
// A vertex that fails the entrance test by a little at the step's start can pass it by the
// end: two blocks face to face that rock against each other swap which corner leads within
// one step, and a corner left out of the list penetrates unopposed (a 30-block box gained
// 3x its energy so). Vertex-to-edge candidates are therefore kept up to this tolerance
// (sin 15 deg, about the relative turn the displacement ratio allows 0.25 m blocks in one
// step); an extra open candidate costs little, since it only closes if it really crosses
// the edge within the edge's span and reach.
inline constexpr double kCandidateWedgeTolerance = 0.26;
// A vertex paired with a vertex of another block still gets its own vertex-to-edge contact
// on an edge that ends at the paired vertex when it projects farther than this share of the
// search distance from that end (narrow_phase.cpp says why).
inline constexpr double kPairClearanceShare = 0.05;

// The share of a face-to-face contact that vertex `v` of `vp` carries against the contact
// edge from `edge_start` to `edge_end`: each of the vertex's two faces that lies along the
// edge (parallel within kWedgeTolerance) and overlaps it gives half of the overlap, the
// half next to the vertex: a segment from `from` (the vertex's place along the overlap) of
// vector `halves`. The two contacts at the ends of an overlap then carry it once between
// them: a block on a wider base its whole face; a brick over two bricks of the course
// below, on each, the length it covers (each of the two faces' vertices carrying half the
// overlap, not half its own face); two blocks whose faces meet end to end on one line
// (the corner of a mesh, diagonal neighbours in a grid) nothing. A vertex meeting the edge
// at an angle (a point contact) carries none. Contact::length is their total length (what
// cohesion and tensile strength act on); joint water wets them.
struct FaceShares {
  int count = 0;
  std::array<Vec2, 2> from{Vec2::Zero(), Vec2::Zero()};
  std::array<Vec2, 2> halves{Vec2::Zero(), Vec2::Zero()};
  std::array<int, 2> edges{-1, -1};  // the vertex's polygon's edge each half lies on
};
FaceShares face_shares(const Polygon& vp, int v, const Vec2& edge_start, const Vec2& edge_end);

// Appends the contacts between polygons a (block ia) and b (block ib), ia < ib, for vertices
// within `search_distance` of an edge (on either side). Deterministic: the same geometry
// always gives the same list in the same order.
void find_contacts(const Polygon& a, int ia, const Polygon& b, int ib, double search_distance,
                   std::vector<ContactCandidate>& out);

// What the narrow phase asks of vertex k of a polygon, and of the edge that starts there,
// again and again. A block meets several neighbours, so detection makes these once per block
// and step instead of once per vertex and pair (on a settled 1000-brick wall the narrow
// phase took 2.9 ms a step without them, 0.7 ms with them). Made by the functions the narrow
// phase would otherwise call, the same expressions on the same numbers, so the contacts
// found with them are the same bit for bit.
struct VertexFeatures {
  EdgeFrame edge;                   // edge_frame(poly, k)
  Vec2 to_prev = Vec2::Zero();      // unit, from the vertex to the one before (wedge_score)
  Vec2 to_next = Vec2::Zero();      // unit, from the vertex to the one after
  double half_shortest_edge = 0.0;  // half the shorter of its two edges (m)
  bool convex = false;              // is_convex_vertex(poly, k)
  // The block whose face covers this edge (from k to k + 1) whole, touching it
  // (mark_covered_edges); -1 if none. To any third block the two blocks' shared faces are
  // inside their assembly, not a surface: no vertex of a third block enters this edge, and
  // the vertices at its ends do not push on a third block's face parallel to it (there the
  // assembly's boundary runs straight on or turns inward: they are not corners of it).
  int covered_by = -1;
  // The cover is firm (both blocks fixed: they never part): then the rules above hold for
  // every contact; a cover between free blocks only steers the vertex-pair rule's choice.
  bool covered_firmly = false;
};
using PolygonFeatures = std::vector<VertexFeatures>;

// Fills `out` for `poly`, reusing its storage.
void polygon_features(const Polygon& poly, PolygonFeatures& out);

// Two blocks side by side (a row of blocks drawn as an incline, the blocks under a bedding
// plane): an edge of either that the other's face covers whole (antiparallel within
// kWedgeTolerance; on its line within `tolerance`, or kCoveredShare of its length if that
// is more; over its whole length within the same) is marked as covered by the other (ia or
// ib) in its features. A block sliding along the row's top would otherwise meet each joint
// as a step as high as its own penetration: its leading corner, a hair below the top,
// entered the next block's side face (or that block's corner pushed on its front face) and
// was stopped (a block on a row of eight fixed blocks kept 59 % of the closed-form slide at
// dt 0.01 s; on a row of eight bonded free blocks it stopped at the first joint).
// `tolerance`: how far apart two faces may lie (0 for fixed blocks, the allowed penetration
// for free ones); `firm`: the pair never parts (both fixed). docs/contacts.md, "Covered
// faces".
void mark_covered_edges(PolygonFeatures& fa, int ia, PolygonFeatures& fb, int ib,
                        double tolerance, bool firm = true);
inline constexpr double kCoveredShare = 1e-6;

// find_contacts with each polygon's features made beforehand (fa of a, fb of b).
void find_contacts(const Polygon& a, const PolygonFeatures& fa, int ia, const Polygon& b,
                   const PolygonFeatures& fb, int ib, double search_distance,
                   std::vector<ContactCandidate>& out);

}  // namespace dda
