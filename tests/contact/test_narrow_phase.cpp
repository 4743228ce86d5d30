// contact/narrow_phase against hand-worked geometry: edge frames and projections, the wedge
// (entrance) test, the classification of contacts, concave blocks. (The broad phase:
// test_broad_phase.cpp; the joint law's decisions: test_joint_law.cpp.)
//
// Conventions used in the hand derivations below (from narrow_phase.hpp):
//  - edge k of a counter-clockwise polygon runs from vertex k to vertex k+1;
//    tangent t = (end - start)/|end - start|, outward normal n = (t.y, -t.x) (to the right);
//  - project_on_edge: gap = (p - start).n, t = (p - start).t / length;
//  - wedge_score = min over the vertex's two edge directions a (unit, leaving the vertex)
//    of a.n.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "contact/narrow_phase.hpp"
#include "support/geometry_checks.hpp"
#include "support/scene_builders.hpp"

using namespace dda;
using Catch::Matchers::WithinAbs;

namespace {

// kTol (1e-14) and check_vec: support/geometry_checks.hpp.
using test::check_vec;
using test::kTol;

// A contact as a short readable string, so that lists compare with == and print on failure:
// "v<vertex_block>.<vertex> on e<edge_block>.<edge>", with " (vv)" when it came from the
// vertex-to-vertex rule.
std::string describe(const ContactCandidate& c) {
  std::ostringstream s;
  s << "v" << c.vertex_block << "." << c.vertex << " on e" << c.edge_block << "." << c.edge
    << (c.vertex_to_vertex ? " (vv)" : "");
  return s.str();
}

std::vector<std::string> contacts(const Polygon& a, const Polygon& b, double search_distance) {
  std::vector<ContactCandidate> out;
  find_contacts(a, 0, b, 1, search_distance, out);
  std::vector<std::string> names;
  for (const ContactCandidate& c : out) names.push_back(describe(c));
  return names;
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

// Rectangle helper from scene_builders: rectangle(x0, y0, w, h) gives, counter-clockwise,
// v0 = (x0, y0), v1 = (x0+w, y0), v2 = (x0+w, y0+h), v3 = (x0, y0+h); so edge 0 is the
// bottom (n = (0,-1)), edge 1 the right side (n = (1,0)), edge 2 the top (n = (0,1)),
// edge 3 the left side (n = (-1,0)).
using test::rectangle;

}  // namespace

// ---------------------------------------------------------------------------------------
// 1. edge_frame / project_on_edge
// ---------------------------------------------------------------------------------------

TEST_CASE("edge frames of a unit square: tangent, outward normal, length", "[contact-geometry]") {
  const Polygon sq = rectangle(0, 0, 1, 1);  // (0,0) (1,0) (1,1) (0,1)
  // edge k: start, end, tangent = end - start (unit already), normal = (t.y, -t.x).
  //  0: (0,0)->(1,0)  t (1,0)   n (0,-1)   bottom, normal points down (out)
  //  1: (1,0)->(1,1)  t (0,1)   n (1,0)    right side, normal points right
  //  2: (1,1)->(0,1)  t (-1,0)  n (0,1)    top, normal points up
  //  3: (0,1)->(0,0)  t (0,-1)  n (-1,0)   left side, normal points left
  const double expected[4][8] = {{0, 0, 1, 0, 1, 0, 0, -1},
                                 {1, 0, 1, 1, 0, 1, 1, 0},
                                 {1, 1, 0, 1, -1, 0, 0, 1},
                                 {0, 1, 0, 0, 0, -1, -1, 0}};
  for (int k = 0; k < 4; ++k) {
    INFO("edge " << k);
    const EdgeFrame f = edge_frame(sq, k);
    const double* e = expected[k];
    check_vec(f.start, e[0], e[1]);
    check_vec(f.end, e[2], e[3]);
    check_vec(f.tangent, e[4], e[5]);
    check_vec(f.normal, e[6], e[7]);
    CHECK_THAT(f.length, WithinAbs(1.0, kTol));
    // The normal points out: the centre (0.5, 0.5) is on its negative side, at depth 0.5.
    CHECK_THAT(project_on_edge(Vec2(0.5, 0.5), f).gap, WithinAbs(-0.5, kTol));
    CHECK_THAT(project_on_edge(Vec2(0.5, 0.5), f).t, WithinAbs(0.5, kTol));
  }
}

TEST_CASE("projections on the edges of a unit square: gap sign and t", "[contact-geometry]") {
  const Polygon sq = rectangle(0, 0, 1, 1);
  struct Case {
    int edge;
    Vec2 p;
    double gap;
    double t;
  };
  // r = p - start; gap = r.n; t = r.t / 1.
  const Case cases[] = {
      // edge 0, start (0,0), t (1,0), n (0,-1): (0.25,-0.5): r = (0.25,-0.5) -> gap 0.5, t 0.25
      {0, Vec2(0.25, -0.5), 0.5, 0.25},
      // inside, just above the bottom: (0.75, 0.1) -> gap -0.1, t 0.75
      {0, Vec2(0.75, 0.1), -0.1, 0.75},
      // edge 1, start (1,0), t (0,1), n (1,0): (1.2,0.3): r = (0.2,0.3) -> gap 0.2, t 0.3
      {1, Vec2(1.2, 0.3), 0.2, 0.3},
      // edge 2, start (1,1), t (-1,0), n (0,1): (0.1,1.3): r = (-0.9,0.3) -> gap 0.3, t 0.9
      {2, Vec2(0.1, 1.3), 0.3, 0.9},
      // edge 3, start (0,1), t (0,-1), n (-1,0): (-0.4,0.8): r = (-0.4,-0.2) -> gap 0.4, t 0.2
      {3, Vec2(-0.4, 0.8), 0.4, 0.2},
      // on the line of edge 3 beyond its end (0,0): r = (0,-1.5) -> gap 0, t 1.5 (t is not
      // clamped: the caller decides what lies beyond the edge's ends)
      {3, Vec2(0.0, -0.5), 0.0, 1.5},
      // before the start of edge 0: (-0.5, 0.2): r = (-0.5,0.2) -> gap -0.2, t -0.5
      {0, Vec2(-0.5, 0.2), -0.2, -0.5},
  };
  for (const Case& c : cases) {
    INFO("edge " << c.edge << ", point " << c.p.transpose());
    const EdgeProjection pr = project_on_edge(c.p, edge_frame(sq, c.edge));
    CHECK_THAT(pr.gap, WithinAbs(c.gap, kTol));
    CHECK_THAT(pr.t, WithinAbs(c.t, kTol));
  }
}

TEST_CASE("edge frames and projections of a 3-4-5 triangle", "[contact-geometry]") {
  const Polygon tri = {{0, 0}, {4, 0}, {0, 3}};  // counter-clockwise: (4,0) x (0,3) = 12 > 0
  SECTION("hypotenuse") {
    // edge 1: (4,0) -> (0,3), d = (-4,3), length 5, t = (-0.8, 0.6), n = (0.6, 0.8): away
    // from the right angle at the origin, i.e. out of the triangle.
    const EdgeFrame f = edge_frame(tri, 1);
    check_vec(f.start, 4, 0);
    check_vec(f.end, 0, 3);
    CHECK_THAT(f.length, WithinAbs(5.0, kTol));
    check_vec(f.tangent, -0.8, 0.6);
    check_vec(f.normal, 0.6, 0.8);
    // (4,3): r = (0,3): gap = 3*0.8 = 2.4, t = 3*0.6/5 = 0.36. Check: foot of the
    // perpendicular (4,0) + 0.36*(-4,3) = (2.56,1.08), and (4,3) - (2.56,1.08) = (1.44,1.92)
    // = 2.4*(0.6,0.8).
    EdgeProjection pr = project_on_edge(Vec2(4, 3), f);
    CHECK_THAT(pr.gap, WithinAbs(2.4, kTol));
    CHECK_THAT(pr.t, WithinAbs(0.36, kTol));
    // Centroid (4/3, 1): r = (-8/3, 1): gap = -1.6 + 0.8 = -0.8 (a third of the height
    // 2*area/5 = 12/5 = 2.4, negative: inside); t = (32/15 + 9/15)/5 = 41/75.
    pr = project_on_edge(Vec2(4.0 / 3.0, 1.0), f);
    CHECK_THAT(pr.gap, WithinAbs(-0.8, kTol));
    CHECK_THAT(pr.t, WithinAbs(41.0 / 75.0, kTol));
  }
  SECTION("legs") {
    // edge 0: (0,0) -> (4,0): t (1,0), n (0,-1), length 4. (1,-1): r = (1,-1): gap 1,
    // t = 1/4.
    EdgeFrame f = edge_frame(tri, 0);
    check_vec(f.tangent, 1, 0);
    check_vec(f.normal, 0, -1);
    CHECK_THAT(f.length, WithinAbs(4.0, kTol));
    EdgeProjection pr = project_on_edge(Vec2(1, -1), f);
    CHECK_THAT(pr.gap, WithinAbs(1.0, kTol));
    CHECK_THAT(pr.t, WithinAbs(0.25, kTol));
    // edge 2: (0,3) -> (0,0): t (0,-1), n (-1,0), length 3. (0.5, 1.5): r = (0.5,-1.5):
    // gap -0.5 (inside), t = 1.5/3 = 0.5.
    f = edge_frame(tri, 2);
    check_vec(f.tangent, 0, -1);
    check_vec(f.normal, -1, 0);
    CHECK_THAT(f.length, WithinAbs(3.0, kTol));
    pr = project_on_edge(Vec2(0.5, 1.5), f);
    CHECK_THAT(pr.gap, WithinAbs(-0.5, kTol));
    CHECK_THAT(pr.t, WithinAbs(0.5, kTol));
  }
}

// ---------------------------------------------------------------------------------------
// 2. wedge_score / is_convex_vertex
// ---------------------------------------------------------------------------------------

TEST_CASE("convex and reflex vertices of the L-shape, and a straight vertex is convex",
          "[contact-geometry]") {
  // L: v0 (0,0), v1 (2,0), v2 (2,1), v3 (1,1), v4 (1,2), v5 (0,2). Turning (cross product of
  // incoming and outgoing edge) at each vertex: left turns (+) everywhere except at v3,
  // where (−1,0) x (0,1) = −1: a right turn, interior angle 270 degrees.
  const Polygon l = test::l_shape();
  CHECK(is_convex_vertex(l, 0));
  CHECK(is_convex_vertex(l, 1));
  CHECK(is_convex_vertex(l, 2));
  CHECK_FALSE(is_convex_vertex(l, 3));
  CHECK(is_convex_vertex(l, 4));
  CHECK(is_convex_vertex(l, 5));

  // A square with an extra vertex in the middle of its bottom: (1,0) has in = out = (1,0),
  // cross product exactly 0, angle 180 degrees: counts as convex.
  const Polygon straight = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
  CHECK(is_convex_vertex(straight, 1));
  // The tolerance is only for round-off: a 1 mm dent into the block is reflex.
  // in = (1, 0.001), out = (1, -0.001): cross = -0.001 - 0.001 = -0.002 < -1e-12 |in||out|.
  const Polygon dented = {{0, 0}, {1, 0.001}, {2, 0}, {2, 2}, {0, 2}};
  CHECK_FALSE(is_convex_vertex(dented, 1));
  // The same vertex pushed out of the block (1, -0.001) is an ordinary convex vertex.
  const Polygon bulged = {{0, 0}, {1, -0.001}, {2, 0}, {2, 2}, {0, 2}};
  CHECK(is_convex_vertex(bulged, 1));
}

TEST_CASE("wedge scores at vertices of the L-shape", "[contact-geometry]") {
  const Polygon l = test::l_shape();
  const double h = std::sqrt(0.5);  // cos 45 deg
  struct Case {
    int vertex;
    Vec2 normal;  // outward normal of the edge the vertex might enter
    double score;
  };
  const Case cases[] = {
      // v0 (0,0): edges leave along (0,1) (to v5) and (1,0) (to v1).
      //  an edge facing up (n (0,1)), below the vertex: min(1, 0) = 0 (the bottom lies on it)
      {0, Vec2(0, 1), 0.0},
      //  an edge facing up-right, below-left of the corner: min(h, h) = h (squarely)
      {0, Vec2(h, h), h},
      //  an edge tilted 30 deg, n = (sin 30, cos 30): min(cos 30, sin 30) = 0.5
      {0, Vec2(0.5, std::sqrt(3.0) / 2.0), 0.5},
      //  an edge facing down (above the vertex, i.e. behind the block): min(-1, 0) = -1
      {0, Vec2(0, -1), -1.0},
      // v2 (2,1): edges leave along (0,-1) (to v1) and (-1,0) (to v3).
      //  an edge facing down-left, above-right of the corner: min(h, h) = h
      {2, Vec2(-h, -h), h},
      //  an edge facing down, above the vertex: min(1, 0) = 0 (the top lies on it)
      {2, Vec2(0, -1), 0.0},
      //  an edge facing right, left of the vertex (behind it): min(0, -1) = -1
      {2, Vec2(1, 0), -1.0},
      // v3 (1,1), reflex: edges leave along (1,0) (to v2) and (0,1) (to v4).
      //  n = (h, h): min(h, h) = h -- the wedge test alone would accept it, which is why
      //  find_contacts also excludes reflex vertices from entering.
      {3, Vec2(h, h), h},
      {3, Vec2(-h, -h), -h},
      {3, Vec2(0, 1), 0.0},
      // v4 (1,2): edges leave along (0,-1) (to v3) and (-1,0) (to v5): n = (-h,-h) -> h.
      {4, Vec2(-h, -h), h},
  };
  for (const Case& c : cases) {
    INFO("vertex " << c.vertex << ", normal " << c.normal.transpose());
    CHECK_THAT(wedge_score(l, c.vertex, c.normal), WithinAbs(c.score, kTol));
  }
}

// ---------------------------------------------------------------------------------------
// 3. find_contacts
// ---------------------------------------------------------------------------------------
//
// In every case a is block 0, b is block 1; names are "v<vertex_block>.<vertex> on
// e<edge_block>.<edge>" (see describe()). Coordinates are exact binary fractions unless
// said otherwise, so the gaps the code compares with 0 are exactly 0 where the blocks touch.

TEST_CASE("a square resting face-to-face on a wider block: its two bottom corners on the top",
          "[contact-geometry]") {
  // a = [0,3] x [0,1] (top edge 2: (3,1)->(0,1), n (0,1)); b = [1,2] x [1,2] (v0 (1,1),
  // v1 (2,1) its bottom corners). Search distance 0.01.
  //  b.v0: r = (1,1)-(3,1) = (-2,0): gap 0, t = 2/3; wedge: to v3 (0,1).n = 1, to v1
  //        (1,0).n = 0 -> 0 >= -tolerance: enters. Against a's left edge 3 (n (-1,0)):
  //        gap -1, deeper than the reach min(0.01, ...) -> no.
  //  b.v1: r = (-1,0): gap 0, t = 1/3; wedge min(0, 1) = 0: enters.
  //  b.v2, b.v3: gap 1 > 0.01. a's corners (0,1), (3,1): their projections on b's bottom
  //  fall outside it (t = -1, 2); on b's sides they are 1 away. No vertex pairs (the closest
  //  vertices are 1 apart).
  const Polygon a = rectangle(0, 0, 3, 1);
  const Polygon b = rectangle(1, 1, 1, 1);
  std::vector<ContactCandidate> out;
  find_contacts(a, 0, b, 1, 0.01, out);
  REQUIRE(out.size() == 2);
  std::sort(out.begin(), out.end(),
            [](const ContactCandidate& x, const ContactCandidate& y) { return x.vertex < y.vertex; });
  for (int k = 0; k < 2; ++k) {
    INFO("contact " << k << ": " << describe(out[k]));
    CHECK(out[k].vertex_block == 1);
    CHECK(out[k].vertex == k);  // b.v0 (1,1) and b.v1 (2,1)
    CHECK(out[k].edge_block == 0);
    CHECK(out[k].edge == 2);  // a's top
    CHECK_FALSE(out[k].vertex_to_vertex);
  }
}

TEST_CASE("two equal squares stacked corner on corner: two vertex-to-vertex contacts, oriented "
          "alike and deterministic",
          "[contact-geometry]") {
  // a = [0,1]^2, b = [0,1] x [1,2]. Vertex pairs (distance 0 <= reach): (a.v2, b.v1) at
  // (1,1) and (a.v3, b.v0) at (0,1). Every other vertex-edge combination is either excluded
  // (the edge ends at the paired vertex) or 1 deep / 1 away (beyond the reach or the search
  // distance 0.01).
  // Pair (a.v2, b.v1), options in the code's order:
  //  b.v1 on a.e1 (n (1,0)): b.v1 leaves along (-1,0): score -1, rejected;
  //  b.v1 on a.e2 (n (0,1)): score min(0, 1) = 0, gap 0          <- first admitted
  //  a.v2 on b.e0 (n (0,-1)): score min(1, 0) = 0, gap 0 (a tie: not larger by 1e-12)
  //  a.v2 on b.e1 (n (1,0)): a.v2 leaves along (-1,0): score -1, rejected.
  //  -> b.v1 on a's top edge 2.
  // Pair (a.v3, b.v0):
  //  b.v0 on a.e2 (n (0,1)): score min(1, 0) = 0, gap 0           <- first admitted
  //  b.v0 on a.e3 (n (-1,0)): b.v0 leaves along (1,0): -1, rejected;
  //  a.v3 on b.e3 (n (-1,0)): a.v3 leaves along (1,0): -1, rejected;
  //  a.v3 on b.e0 (n (0,-1)): score 0, gap 0 (tie).
  //  -> b.v0 on a's top edge 2.
  // So both contacts have the upper block's vertex on the lower block's top edge: the same
  // orientation, not one each way.
  const Polygon a = rectangle(0, 0, 1, 1);
  const Polygon b = rectangle(0, 1, 1, 1);
  const std::vector<std::string> first = contacts(a, b, 0.01);
  CHECK(sorted(first) == std::vector<std::string>{"v1.0 on e0.2 (vv)", "v1.1 on e0.2 (vv)"});
  // Deterministic: the same list, in the same order, every time.
  CHECK(contacts(a, b, 0.01) == first);
  CHECK(contacts(a, b, 0.01) == first);
}

TEST_CASE("a vertex of a square tilted 30 degrees on the middle of an edge", "[contact-geometry]") {
  // a = [0,4] x [-1,0], top edge 2: (4,0)->(0,0), n (0,1). b: unit square with its lowest
  // vertex p0 = (2,0) and sides e1 = (cos 30, sin 30), e2 = (-sin 30, cos 30):
  // p0, p0+e1 = (2.866, 0.5), p0+e1+e2 = (2.366, 1.366), p0+e2 = (1.5, 0.866); e1 x e2 = 1 > 0,
  // counter-clockwise.
  //  b.v0 on a.e2: r = (-2, 0): gap 0, t = 2/4 = 0.5 (the middle); wedge: e2.n = cos 30 =
  //  0.866, e1.n = sin 30 = 0.5 -> 0.5: enters.
  //  b.v1 is 0.5 above a (> 0.01), b.v2 and b.v3 higher. a's corners: (0,0) projects on b.e3
  //  at t = 0 but 1.73 away; (4,0) projects past the end of b.e0 (t = 1.73). No vertex pairs
  //  (closest vertices (0,0)-(1.5,0.866) and (4,0)-(2.866,0.5), both > 1 apart).
  const double c = std::sqrt(3.0) / 2.0, s = 0.5;
  const Vec2 p0(2.0, 0.0), e1(c, s), e2(-s, c);
  const Polygon a = rectangle(0, -1, 4, 1);
  const Polygon b = {p0, p0 + e1, p0 + e1 + e2, p0 + e2};
  std::vector<ContactCandidate> out;
  find_contacts(a, 0, b, 1, 0.01, out);
  REQUIRE(out.size() == 1);
  CHECK(out[0].vertex_block == 1);
  CHECK(out[0].vertex == 0);
  CHECK(out[0].edge_block == 0);
  CHECK(out[0].edge == 2);
  CHECK_FALSE(out[0].vertex_to_vertex);
  // The contact point is the middle of the edge.
  const EdgeProjection pr = project_on_edge(b[0], edge_frame(a, 2));
  CHECK_THAT(pr.t, WithinAbs(0.5, kTol));
  CHECK_THAT(pr.gap, WithinAbs(0.0, kTol));
}

TEST_CASE("entrance criterion: a vertex near an edge whose wedge does not face it does not enter",
          "[contact-geometry]") {
  SECTION("one of the wedge's edges heads into the other block") {
    // a = [0,1]^2, top edge 2 ((1,1)->(0,1), n (0,1)). b: unit square turned 20 degrees
    // clockwise, its corner q = (0.985, 1.008) 8 mm above a's top, 15 mm left of a's corner
    // (1,1): b = q, q+e1, q+e1+e2, q+e2 with e1 = (cos 20, -sin 20), e2 = (sin 20, cos 20).
    // b's lower edge leaves q going down-right at 20 degrees: at x = 1 it is at
    // y = 1.008 - 0.015 tan 20 = 1.00254 > 1, past a's corner, so the blocks do not overlap.
    //  b.v0 = q on a.e2: gap 0.008 <= 0.01, t = 0.015 in [0,1], but the wedge score is
    //  min(e1.n, e2.n) = -sin 20 = -0.342, below even the candidate tolerance -0.26 (which
    //  admits wedges turned away by up to 15 degrees, kCandidateWedgeTolerance): rejected.
    //  a's corner a.v2 (1,1) on b.e0 (q -> q+e1, n = (e1.y, -e1.x) = (-sin 20, -cos 20)):
    //  r = (0.015, -0.008): gap = -0.015 sin 20 + 0.008 cos 20 = 0.00239 > 0,
    //  t = 0.015 cos 20 + 0.008 sin 20 = 0.0168; a's wedge: (0,-1).n = cos 20,
    //  (-1,0).n = sin 20 -> 0.342: enters. That is the real contact.
    //  q is 0.017 m from (1,1), farther than the search distance 0.01: no vertex pair.
    //  The other vertices are either more than 0.9 m from the other block's edges or
    //  project outside them.
    const double c = std::cos(20.0 * M_PI / 180.0), s = std::sin(20.0 * M_PI / 180.0);
    const Vec2 q(0.985, 1.008), e1(c, -s), e2(s, c);
    const Polygon a = rectangle(0, 0, 1, 1);
    const Polygon b = {q, q + e1, q + e1 + e2, q + e2};
    // The premise: q is within the search distance of a's top edge, over it, and its
    // wedge is turned away by more than the candidate tolerance.
    const EdgeProjection pr = project_on_edge(q, edge_frame(a, 2));
    REQUIRE(pr.gap > 0.0);
    REQUIRE(pr.gap < 0.01);
    REQUIRE(pr.t > 0.0);
    REQUIRE(pr.t < 1.0);
    REQUIRE(wedge_score(b, 0, Vec2(0, 1)) < -kCandidateWedgeTolerance);
    CHECK(contacts(a, b, 0.01) == std::vector<std::string>{"v0.2 on e1.0"});
  }
  SECTION("a vertex behind the edge (on its back side) does not enter it") {
    // a: a thin plate [0,2] x [0,0.004]; bottom edge 0 (n (0,-1)), top edge 2 (n (0,1)).
    // b: a square of side 0.5 turned 45 degrees (a diamond) below the plate, its top vertex
    // b.v0 = (1, -0.001) 1 mm under the plate, built as top, left, bottom, right:
    // v0 (1,-0.001), v1 (1-h,-0.001-h), v2 (1,-0.001-2h), v3 (1+h,-0.001-h), h = 0.25 sqrt 2
    // = 0.354 (half the diagonal; sides h sqrt 2 = 0.5); counter-clockwise.
    //  b.v0 on a.e0: gap 0.001, t = 0.5; wedge: edges leave along (∓h,-h)/0.5, i.e.
    //  (∓0.707, -0.707); .n(0,-1) = 0.707 each -> enters.
    //  b.v0 on a.e2 (the top, seen from behind): r = (1,-0.001)-(2,0.004) = (-1,-0.005):
    //  gap -0.005, t = 0.5; the depth 0.005 is within the reach min(0.01, 0.25, 1) = 0.01,
    //  so only the wedge test stops it: score 0.707*(-1) = -0.707: rejected.
    //  b.v0 on the plate's ends: t = -0.25 and 1.25, outside. Other vertices >= 0.25 away.
    //  The plate's corners project outside b's upper edges or are >= 0.7 from them.
    const double h = 0.25 * std::sqrt(2.0);
    const Vec2 top(1.0, -0.001);
    const Polygon a = rectangle(0, 0, 2, 0.004);
    const Polygon b = {top, top + Vec2(-h, -h), top + Vec2(0, -2 * h), top + Vec2(h, -h)};
    // The premise: within reach of the top edge from behind, wedge turned away.
    const EdgeProjection pr = project_on_edge(top, edge_frame(a, 2));
    REQUIRE(pr.gap < 0.0);
    REQUIRE(pr.gap > -0.01);
    REQUIRE(wedge_score(b, 0, Vec2(0, 1)) < -kWedgeTolerance);
    CHECK(contacts(a, b, 0.01) == std::vector<std::string>{"v1.0 on e0.0"});
  }
}

TEST_CASE("a diamond's vertex beside a corner: the contact of least penetration is chosen",
          "[contact-geometry]") {
  // a = box [0,2] x [-1,0]: top-left corner a.v3 = (0,0); top edge a.e2 ((2,0)->(0,0),
  // n (0,1)), left edge a.e3 ((0,0)->(0,-1), n (-1,0)). b = a square of side 0.5 turned 45
  // degrees, built from its lowest vertex L: v0 = L, v1 = L + (r,r), v2 = L + (0,2r),
  // v3 = L + (-r,r), r = 0.5/sqrt 2. b.e0 (v0->v1) is its lower-right edge: t = (1,1)/sqrt 2,
  // n = (1,-1)/sqrt 2; b.e3 (v3->v0) its lower-left edge, n = (-1,-1)/sqrt 2.
  // |L - (0,0)| = sqrt(0.005^2 + 0.001^2) = 5.1 mm <= the search distance 0.01: a vertex pair
  // (a.v3, b.v0); every other vertex is >= 0.35 m from the other block. Options:
  //  b.v0 on a.e2 (top): b's wedge (-h,h).(0,1) = (h,h).(0,1) = 0.707: admitted, gap L.y.
  //  b.v0 on a.e3 (left): (h,h).(-1,0) = -0.707: rejected.
  //  a.v3 on b.e3: a.v3 leaves along (1,0): (1,0).(-1,-1)/sqrt 2 = -0.707: rejected.
  //  a.v3 on b.e0: a's wedge (1,0).n = 0.707, (0,-1).n = 0.707: admitted,
  //  gap = ((0,0) - L).(1,-1)/sqrt 2 = (L.y - L.x)/sqrt 2.
  // The larger gap (least penetration) wins.
  const double r = 0.5 / std::sqrt(2.0);
  const Polygon a = rectangle(0, -1, 2, 1);
  auto diamond = [&](const Vec2& L) {
    return Polygon{L, L + Vec2(r, r), L + Vec2(0, 2 * r), L + Vec2(-r, r)};
  };
  SECTION("vertex 5 mm left of the corner, 1 mm below the top: the corner on the diamond") {
    // L = (-0.005, -0.001): top option gap -0.001 (penetrating); corner option gap
    // (-0.001 + 0.005)/sqrt 2 = +0.00283 (open): the corner on b's lower-right edge.
    const Polygon b = diamond(Vec2(-0.005, -0.001));
    std::vector<ContactCandidate> out;
    find_contacts(a, 0, b, 1, 0.01, out);
    REQUIRE(out.size() == 1);
    INFO(describe(out[0]));
    CHECK(out[0].vertex_block == 0);
    CHECK(out[0].vertex == 3);
    CHECK(out[0].edge_block == 1);
    CHECK(out[0].edge == 0);
    CHECK(out[0].vertex_to_vertex);
  }
  SECTION("vertex 5 mm right of the corner, 1 mm above the top: the diamond on the top") {
    // L = (0.005, 0.001): top option gap +0.001; corner option gap (0.001-0.005)/sqrt 2 =
    // -0.00283: the diamond's vertex on the box's top edge.
    const Polygon b = diamond(Vec2(0.005, 0.001));
    std::vector<ContactCandidate> out;
    find_contacts(a, 0, b, 1, 0.01, out);
    REQUIRE(out.size() == 1);
    INFO(describe(out[0]));
    CHECK(out[0].vertex_block == 1);
    CHECK(out[0].vertex == 0);
    CHECK(out[0].edge_block == 0);
    CHECK(out[0].edge == 2);
    CHECK(out[0].vertex_to_vertex);
  }
}

TEST_CASE("a square in the notch of the L-shape: contacts on both walls, the reflex vertex never "
          "enters",
          "[contact-geometry]") {
  // a = L: v0 (0,0), v1 (2,0), v2 (2,1), v3 (1,1) reflex, v4 (1,2), v5 (0,2). The notch's
  // walls: a.e2 (2,1)->(1,1), n (0,1) (its floor) and a.e3 (1,1)->(1,2), n (1,0) (its wall).
  // b = a square of side 0.5 with its lower-left corner at (1+dx, 1+dy). Search distance 0.01.
  //  b.v1 (1.5+dx, 1+dy) on the floor a.e2: gap dy, t = (2 - 1.5 - dx) = 0.5 - dx; wedge
  //  min((-1,0).n, (0,1).n) = 0: enters.
  //  b.v3 (1+dx, 1.5+dy) on the wall a.e3: gap dx, t = 0.5 + dy; wedge min((1,0).n,
  //  (0,-1).n) = 0: enters.
  //  b.v0 is within 0.01 of a.v3: a vertex pair. a.v3 is reflex, so (Shi's angle-to-angle
  //  rule for a concave angle) b.v0 goes on both edges of the reflex corner: the floor (gap
  //  dy) and the wall (gap dx), each with wedge score 0. Near a reflex corner free space is
  //  the intersection of the two walls' outer sides: both hold the corner in. (Formerly
  //  the pair went to one wall only, the larger gap, and the corner could pass through the
  //  other.)
  //  a's other corners (2,1), (1,2) project outside b's edges or are 0.5 from them; b.v2 is
  //  0.5 from both walls.
  const Polygon a = test::l_shape();
  struct Case {
    double dx, dy;
    std::vector<std::string> expected;
  };
  const Case cases[] = {
      // touching both walls exactly: the corner on the floor and on the wall
      {0.0, 0.0, {"v1.1 on e0.2", "v1.3 on e0.3", "v1.0 on e0.2 (vv)", "v1.0 on e0.3 (vv)"}},
      // 3 mm from the wall, 2 mm above the floor: the same (the corner also projects onto
      // both walls clear of the paired end, so the vertex-to-edge rule finds them too; one
      // of each is kept)
      {0.003, 0.002, {"v1.1 on e0.2", "v1.3 on e0.3", "v1.0 on e0.2 (vv)", "v1.0 on e0.3 (vv)"}},
  };
  for (const Case& c : cases) {
    INFO("b's corner at (1 + " << c.dx << ", 1 + " << c.dy << ")");
    const Polygon b = rectangle(1.0 + c.dx, 1.0 + c.dy, 0.5, 0.5);
    std::vector<ContactCandidate> out;
    find_contacts(a, 0, b, 1, 0.01, out);
    std::vector<std::string> names;
    for (const ContactCandidate& k : out) names.push_back(describe(k));
    CHECK(sorted(names) == sorted(c.expected));
    bool on_floor = false, on_wall = false;
    for (const ContactCandidate& k : out) {
      // The L's reflex vertex v3 never enters anything.
      CHECK_FALSE((k.vertex_block == 0 && k.vertex == 3));
      if (k.vertex_block == 1 && k.edge_block == 0 && k.edge == 2) on_floor = true;
      if (k.vertex_block == 1 && k.edge_block == 0 && k.edge == 3) on_wall = true;
    }
    CHECK(on_floor);
    CHECK(on_wall);
  }
}

TEST_CASE("the L's reflex vertex does not enter even an edge its wedge faces",
          "[contact-geometry]") {
  // With blocks that do not overlap, an edge the reflex vertex's wedge faces would have to lie
  // inside the L, so the reflex rule only shows with overlap. b = [0.5,1.1] x [0.5,0.998], a
  // block embedded in the L's corner (as after a large penetration). Its top edge b.e2
  // ((1.1,0.998)->(0.5,0.998), n (0,1)) passes 2 mm under the reflex vertex a.v3 (1,1):
  // r = (-0.1, 0.002): gap 0.002 <= 0.01, t = 0.1/0.6 = 1/6; wedge (edges leaving along
  // (1,0) and (0,1)): min(0, 1) = 0, which passes the wedge test. Only the reflex rule keeps
  // a.v3 out. (b.v3 (0.5, 0.998) is 0.5 from everything; the rest of the list is not the
  // point here.)
  const Polygon a = test::l_shape();
  const Polygon b = rectangle(0.5, 0.5, 0.6, 0.498);
  const EdgeFrame top = edge_frame(b, 2);
  const EdgeProjection pr = project_on_edge(a[3], top);
  REQUIRE(pr.gap > 0.0);
  REQUIRE(pr.gap < 0.01);
  REQUIRE(pr.t > 0.0);
  REQUIRE(pr.t < 1.0);
  REQUIRE(wedge_score(a, 3, top.normal) >= -kWedgeTolerance);
  std::vector<ContactCandidate> out;
  find_contacts(a, 0, b, 1, 0.01, out);
  for (const ContactCandidate& k : out) {
    INFO(describe(k));
    CHECK_FALSE((k.vertex_block == 0 && k.vertex == 3));
  }
}

TEST_CASE("blocks farther apart than the search distance have no contacts", "[contact-geometry]") {
  // Two unit squares 20 mm apart, search distance 10 mm: every vertex is >= 0.02 from the
  // other block's edges (gap 0.02 > 0.01) and >= 0.02 from its vertices.
  const Polygon a = rectangle(0, 0, 1, 1);
  CHECK(contacts(a, rectangle(0, 1.02, 1, 1), 0.01).empty());  // above
  CHECK(contacts(a, rectangle(1.02, 0, 1, 1), 0.01).empty());  // beside
  CHECK(contacts(a, rectangle(0.5, 1.02, 1, 1), 0.01).empty());  // above, offset
  // Control: 9 mm apart (within the search distance) the offset square above has its
  // corner b.v0 (0.5, 1.009) over a's top and a's corner a.v2 (1, 1) under b's bottom.
  CHECK(sorted(contacts(a, rectangle(0.5, 1.009, 1, 1), 0.01)) ==
        std::vector<std::string>{"v0.2 on e1.0", "v1.0 on e0.2"});
}

TEST_CASE("a search distance larger than the blocks does not reach their far sides",
          "[contact-geometry]") {
  // Two unit squares stacked exactly, search distance 5 (five times their size). The reach
  // into a block is min(search distance, half the shortest edge at the vertex, half the
  // edge) = 0.5, so:
  //  a.v2 (1,1) on b's left edge b.e3 ((0,2)->(0,1), n (-1,0)): gap -1, t = 1, and its wedge
  //  faces it (min((0,-1).n, (-1,0).n) = min(0, 1) = 0) -- only the reach (-1 < -0.5) keeps
  //  it out. Likewise a.v3 on b.e1, b.v0 on a.e1 and b.v1 on a.e3 (all 1 deep).
  //  Vertices 1 away on the open side (a.v0, a.v1 under b.e0; b.v2, b.v3 over a.e2) are within
  //  the search distance but their wedges point away (score -1).
  //  Vertex pairs need distance <= min(5, 0.5, 0.5): only the two coinciding pairs.
  // So the result is the same as with a small search distance: the two real contacts.
  const Polygon a = rectangle(0, 0, 1, 1);
  const Polygon b = rectangle(0, 1, 1, 1);
  const std::vector<std::string> expected = {"v1.0 on e0.2 (vv)", "v1.1 on e0.2 (vv)"};
  CHECK(sorted(contacts(a, b, 5.0)) == expected);
  CHECK(sorted(contacts(a, b, 0.01)) == expected);
}

// ---------------------------------------------------------------------------------------
// 4. concave blocks: stepped bases, L-shaped blocks, vertices meeting reflex corners
// ---------------------------------------------------------------------------------------
//
// The stepped base used below, counter-clockwise:
//   v0 (0,0), v1 (4,0), v2 (4,1), v3 (2,1) reflex, v4 (2,2), v5 (0,2);
//   e0 (0,0)->(4,0) n (0,-1)   bottom
//   e1 (4,0)->(4,1) n (1,0)    right side
//   e2 (4,1)->(2,1) n (0,1)    lower tread, length 2
//   e3 (2,1)->(2,2) n (1,0)    riser, length 1
//   e4 (2,2)->(0,2) n (0,1)    upper tread, length 2
//   e5 (0,2)->(0,0) n (-1,0)   left side
// The search distance is 0.05 m, a scene's d0 = 2.5 x 0.01 x w0 with w0 = 2 m; the pair
// clearance is then kPairClearanceShare x 0.05 = 2.5 mm.

namespace {

Polygon stepped_base() { return {{0, 0}, {4, 0}, {4, 1}, {2, 1}, {2, 2}, {0, 2}}; }

constexpr double kStepSearch = 0.05;

// A contact as (vertex block, vertex, edge normal, gap), the constraint it imposes, for
// comparing two descriptions of the same geometry whose edges are numbered differently.
struct Constraint {
  int vertex_block;
  int vertex;
  Vec2 normal;
  double gap;
};

std::vector<Constraint> constraints(const std::vector<Polygon>& polys,
                                    const std::vector<ContactCandidate>& out) {
  std::vector<Constraint> list;
  for (const ContactCandidate& c : out) {
    const EdgeFrame f = edge_frame(polys[c.edge_block], c.edge);
    list.push_back({c.vertex_block, c.vertex, f.normal,
                    project_on_edge(polys[c.vertex_block][c.vertex], f).gap});
  }
  return list;
}

bool same_constraint(const Constraint& x, const Constraint& y) {
  return x.vertex == y.vertex && (x.normal - y.normal).norm() < 1e-12 &&
         std::abs(x.gap - y.gap) < 1e-12;
}

// Whether segments pq and ab cross at a point inside both (touching at an end or running
// along each other does not count).
bool segments_cross(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double eps = 1e-12;
  const double d1 = cross(q - p, a - p), d2 = cross(q - p, b - p);
  const double d3 = cross(b - a, p - a), d4 = cross(b - a, q - a);
  return ((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) &&
         ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps));
}

// A contact's vertex reaches its edge along the edge's normal: the segment from the vertex
// to the nearest point of the edge must not cross any other edge of the edge's block. If it
// did, the vertex would lie beyond another part of that block (for a penetrating contact:
// pushed out through a face it never crossed; for an open one: separated from the edge by the
// block itself).
bool reaches_edge(const Polygon& vp, int v, const Polygon& ep, int e) {
  const EdgeFrame f = edge_frame(ep, e);
  const double t = std::clamp(project_on_edge(vp[v], f).t, 0.0, 1.0);
  const Vec2 foot = f.start + t * (f.end - f.start);
  const int n = static_cast<int>(ep.size());
  for (int k = 0; k < n; ++k) {
    if (k != e && segments_cross(vp[v], foot, ep[k], ep[(k + 1) % n])) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("a square on the lower step of a stepped base: the corner by the riser is held by "
          "the tread and by the riser",
          "[contact-geometry][concave]") {
  // b = the square [2+dx, 2.5+dx] x [1+dy, 1.5+dy]: b.v0 (2+dx, 1+dy) its corner by the
  // reflex corner a.v3 (2,1); b.v1 (2.5+dx, 1+dy), b.v3 (2+dx, 1.5+dy).
  //  b.v1 on the tread a.e2: gap dy, t = (4 - 2.5 - dx)/2 = 0.75 - dx/2; wedge min((-1,0).n,
  //  (0,1).n) = 0: enters.
  //  b.v3 on the riser a.e3: gap dx (<= 0.05), t = 0.5 + dy; wedge min((1,0).n, (0,-1).n) = 0.
  //  b.v0 within 0.05 of a.v3: a vertex pair with a reflex vertex, so b.v0 goes on both edges
  //  of the corner (tread gap dy, riser gap dx; wedge scores 0). Where b.v0 projects farther
  //  than the 2.5 mm clearance from a.v3 along an edge, the vertex-to-edge rule finds the same
  //  contact; one of each is kept, marked (vv).
  //  Nothing else is within reach: b.v2 is 0.5 from every edge; a.v4 (2,2) projects past the
  //  end of b's left side (t = -1) and is 0.5 above b's top; a.v2 (4,1) is 1.5 away.
  // Formerly the pair went to one edge only (the larger gap): with dx = 2 mm, dy = 0
  // the riser, and b.v0 lost its support on the tread.
  const Polygon a = stepped_base();
  const std::vector<std::string> corner_held = {"v1.0 on e0.2 (vv)", "v1.0 on e0.3 (vv)",
                                                "v1.1 on e0.2", "v1.3 on e0.3"};
  struct Case {
    double dx, dy;
    std::vector<std::string> expected;
  };
  const Case cases[] = {
      {0.0, 0.0, corner_held},      // in the inner corner, touching tread and riser
      {0.002, 0.0, corner_held},    // resting 2 mm from the riser
      {0.01, 0.0, corner_held},     // 1 cm from the riser (b.v0 also found vertex-to-edge)
      {0.04, 0.0, corner_held},     // 4 cm: still within the search distance of the riser
      {0.0, 0.005, corner_held},    // falling into the corner along the riser, 5 mm up
      // 10 cm from the riser (beyond the search distance): a square resting on a flat tread
      {0.1, 0.0, {"v1.0 on e0.2", "v1.1 on e0.2"}},
  };
  for (const Case& c : cases) {
    INFO("b's corner at (2 + " << c.dx << ", 1 + " << c.dy << ")");
    const Polygon b = rectangle(2.0 + c.dx, 1.0 + c.dy, 0.5, 0.5);
    std::vector<ContactCandidate> out;
    find_contacts(a, 0, b, 1, kStepSearch, out);
    CHECK(sorted(contacts(a, b, kStepSearch)) == sorted(c.expected));
    // The corner's contacts carry the gaps hand-derived above.
    for (const ContactCandidate& k : out) {
      if (k.vertex_block != 1 || k.vertex != 0) continue;
      const double gap = project_on_edge(b[0], edge_frame(a, k.edge)).gap;
      CHECK_THAT(gap, WithinAbs(k.edge == 2 ? c.dy : c.dx, 1e-12));
    }
  }
}

TEST_CASE("the stepped base as block 1: the same contacts, blocks swapped", "[contact-geometry][concave]") {
  // The convex vertex now belongs to polygon a (lower index), the reflex one to b: the other
  // branch of the pair rule. Same geometry as above with dx = 2 mm.
  const Polygon base = stepped_base();
  const Polygon sq = rectangle(2.002, 1.0, 0.5, 0.5);
  CHECK(sorted(contacts(sq, base, kStepSearch)) ==
        std::vector<std::string>{"v0.0 on e1.2 (vv)", "v0.0 on e1.3 (vv)", "v0.1 on e1.2",
                                 "v0.3 on e1.3"});
}

TEST_CASE("squares on the upper step of a stepped base, at its edge and away from it",
          "[contact-geometry][concave]") {
  const Polygon a = stepped_base();
  SECTION("away from the riser: both bottom corners on the upper tread") {
    // b = [0.5,1] x [2,2.5]: b.v0 (0.5,2) t = 0.75, b.v1 (1,2) t = 0.5 on a.e4, gap 0.
    CHECK(sorted(contacts(a, rectangle(0.5, 2.0, 0.5, 0.5), kStepSearch)) ==
          std::vector<std::string>{"v1.0 on e0.4", "v1.1 on e0.4"});
  }
  SECTION("flush with the top of the riser: a convex corner meets a convex corner") {
    // b = [1.5,2] x [2,2.5]; b.v1 (2,2) meets a.v4 (2,2), both convex: one contact, on the
    // edge of least penetration. Options: b.v1 on the riser a.e3 (b.v1 leaves along (-1,0):
    // score -1, rejected), b.v1 on the upper tread a.e4 (score 0, gap 0: first admitted),
    // a.v4 on b's bottom b.e0 (score 0, gap 0: a tie, not taken), a.v4 on b's right side
    // b.e1 (n (1,0); a.v4 leaves along (-1,0): score -1, rejected). b.v0 (1.5,2) on a.e4, t = 0.25. The riser and
    // the lower tread are 1 m below b.v1 (beyond the search distance).
    CHECK(sorted(contacts(a, rectangle(1.5, 2.0, 0.5, 0.5), kStepSearch)) ==
          std::vector<std::string>{"v1.0 on e0.4", "v1.1 on e0.4 (vv)"});
  }
}

TEST_CASE("a square's corner pushed into the reflex corner: pushed back out across both "
          "walls, and by nothing else",
          "[contact-geometry][concave]") {
  // b = the square moved 1 mm into the corner diagonally: b.v0 (1.999, 0.999) lies behind the
  // tread and behind the riser, 1 mm each; it projects just past the reflex end of both
  // (t = 1.0005 on the tread, -0.001 on the riser), so only the pair rule (|b.v0 - a.v3| =
  // 1.4 mm <= 0.05) gives it contacts: one on each wall, gap -1 mm each. b.v1 (2.499, 0.999)
  // is 1 mm under the tread (t = 0.7505; reach min(0.05, 0.25, 1) = 0.05 >= 1 mm); b.v3
  // (1.999, 1.499) 1 mm behind the riser (t = 0.499). No contact with any other edge: the
  // upper tread a.e4 is 0.501 above b.v3 (deeper than the reach), the reflex vertex a.v3
  // never enters, and a.v4 (2,2) projects past the end of b's left side.
  const double eps = 0.001;
  const Polygon a = stepped_base();
  const Polygon b = rectangle(2.0 - eps, 1.0 - eps, 0.5, 0.5);
  std::vector<ContactCandidate> out;
  find_contacts(a, 0, b, 1, kStepSearch, out);
  std::vector<std::string> names;
  for (const ContactCandidate& k : out) names.push_back(describe(k));
  CHECK(sorted(names) == std::vector<std::string>{"v1.0 on e0.2 (vv)", "v1.0 on e0.3 (vv)",
                                                  "v1.1 on e0.2", "v1.3 on e0.3"});
  for (const ContactCandidate& k : out) {
    INFO(describe(k));
    const double gap = project_on_edge(b[k.vertex], edge_frame(a, k.edge)).gap;
    CHECK_THAT(gap, WithinAbs(-eps, 1e-12));  // every contact pushes back by the 1 mm
    CHECK(reaches_edge(b, k.vertex, a, k.edge));
  }
}

TEST_CASE("the concave stepped base gives the constraints of the same base cut into two "
          "convex pieces",
          "[contact-geometry][concave]") {
  // Independent reference: the step cut along y = 1 into lower = [0,4] x [0,1] and upper =
  // [0,2] x [1,2], both convex, whose contacts use only the convex rules. A square with its
  // corner near the reflex corner, offset (dx, dy) (penetrating by up to 1 mm, or open by up
  // to 3 cm), must meet the same constraints in both descriptions: each of its vertices the
  // same (edge normal, gap) pairs. With the cut base, b.v0 gets the lower piece's top by the
  // vertex-to-edge rule and the riser by the pair rule at the upper piece's convex corner
  // (2,1) (b.v0 on the riser, gap dx, ties with the corner on b's left side and comes first).
  const Polygon base = stepped_base();
  const Polygon lower = rectangle(0, 0, 4, 1);
  const Polygon upper = rectangle(0, 1, 2, 1);
  const double offsets[] = {-0.001, 0.0, 0.001, 0.002, 0.01, 0.03};
  for (double dx : offsets) {
    for (double dy : offsets) {
      INFO("b's corner at (2 + " << dx << ", 1 + " << dy << ")");
      const Polygon b = rectangle(2.0 + dx, 1.0 + dy, 0.5, 0.5);
      std::vector<ContactCandidate> concave;
      find_contacts(base, 0, b, 1, kStepSearch, concave);
      // The cut base: lower is block 0, upper block 1, the square block 2 (the two fixed
      // pieces are not a pair: fixed blocks never meet).
      std::vector<ContactCandidate> cut;
      find_contacts(lower, 0, b, 2, kStepSearch, cut);
      find_contacts(upper, 1, b, 2, kStepSearch, cut);
      std::vector<Constraint> want = constraints({lower, upper, b}, cut);
      std::vector<Constraint> got = constraints({base, b}, concave);
      // Only the square's vertices enter in either description (no corner of the base is
      // near one of its edges), so the lists compare vertex by vertex.
      for (const Constraint& c : want) CHECK(c.vertex_block == 2);
      for (const Constraint& c : got) CHECK(c.vertex_block == 1);
      CHECK(got.size() == want.size());
      for (const Constraint& w : want) {
        INFO("cut base: b.v" << w.vertex << " n (" << w.normal.transpose() << ") gap " << w.gap);
        CHECK(std::any_of(got.begin(), got.end(),
                          [&](const Constraint& g) { return same_constraint(g, w); }));
      }
    }
  }
}

TEST_CASE("wedges meeting a reflex corner: the corner vertex is held by both walls, every "
          "contact reaches its edge, the reflex vertex never enters",
          "[contact-geometry][concave]") {
  // A triangle with a 60-degree corner c near the reflex corner (2,1), its sides leaving c at
  // 15 + th and 75 + th degrees (th from -10 to 10: the wedge fits in the 90-degree notch,
  // facing both walls), 0.4 m long; c offset from (2,1) by up to 1 mm into the base or 2 cm
  // out of it. Properties checked for every contact found:
  //  - the base's reflex vertex a.v3 never enters;
  //  - the segment from the vertex to the nearest point of its edge crosses no other edge of
  //    the edge's block (a vertex never meets an edge it cannot reach along the edge's normal
  //    through the block's interior, or, outside it, through free space);
  //  - and when c is within the search distance of the corner, c is held by the tread and by
  //    the riser (both its sides leave on the outer side of both walls: wedge scores
  //    sin(15 + th) and cos(75 + th) > 0).
  const Polygon a = stepped_base();
  const double offsets[] = {-0.001, 0.0, 0.0005, 0.002, 0.01, 0.02};
  int corner_checks = 0;
  for (int th_deg = -10; th_deg <= 10; th_deg += 5) {
    for (double dx : offsets) {
      for (double dy : offsets) {
        INFO("th " << th_deg << " deg, c = (2 + " << dx << ", 1 + " << dy << ")");
        const double p1 = (15.0 + th_deg) * M_PI / 180.0;
        const double p2 = (75.0 + th_deg) * M_PI / 180.0;
        const Vec2 c(2.0 + dx, 1.0 + dy);
        const Polygon b = {c, c + 0.4 * Vec2(std::cos(p1), std::sin(p1)),
                           c + 0.4 * Vec2(std::cos(p2), std::sin(p2))};
        std::vector<ContactCandidate> out;
        find_contacts(a, 0, b, 1, kStepSearch, out);
        bool on_tread = false, on_riser = false;
        for (const ContactCandidate& k : out) {
          INFO(describe(k));
          CHECK_FALSE((k.vertex_block == 0 && k.vertex == 3));
          const Polygon& vp = k.vertex_block == 0 ? a : b;
          const Polygon& ep = k.edge_block == 0 ? a : b;
          CHECK(reaches_edge(vp, k.vertex, ep, k.edge));
          if (k.vertex_block == 1 && k.vertex == 0 && k.edge == 2) on_tread = true;
          if (k.vertex_block == 1 && k.vertex == 0 && k.edge == 3) on_riser = true;
        }
        if ((c - a[3]).norm() <= kStepSearch) {
          ++corner_checks;
          CHECK(on_tread);
          CHECK(on_riser);
        }
      }
    }
  }
  CHECK(corner_checks > 100);  // the premise holds for most of the sweep (5 x 36 cases)
}

TEST_CASE("an L-shaped block resting on a convex floor: its two bottom corners, never its "
          "reflex vertex",
          "[contact-geometry][concave]") {
  // Floor a = [-1,4] x [-1,0], top a.e2 (4,0)->(-1,0), n (0,1), length 5. b = the L
  // (v0 (0,0), v1 (2,0), v2 (2,1), v3 (1,1) reflex, v4 (1,2), v5 (0,2)) standing on it.
  //  b.v0 on a.e2: gap 0, t = 4/5; wedge min((1,0).n, (0,1).n) = 0. b.v1: t = 2/5, wedge 0.
  //  The floor's corners (-1,0), (4,0) are 1 m and 2 m from the L; the L's other vertices
  //  are at least 1 m above the floor.
  const Polygon floor = rectangle(-1, -1, 5, 1);
  CHECK(sorted(contacts(floor, test::l_shape(), kStepSearch)) ==
        std::vector<std::string>{"v1.0 on e0.2", "v1.1 on e0.2"});
  // Standing on its other side (the L turned by 180 degrees about (1,1), a Gamma: v0 (2,2),
  // v1 (0,2), v2 (0,1), v3 (1,1) reflex, v4 (1,0), v5 (2,0)): it rests on its leg, b.v4
  // (1,0) at t = 3/5 and b.v5 (2,0) at t = 2/5; the overhanging arm is 1 m above the floor.
  const Polygon gamma = {{2, 2}, {0, 2}, {0, 1}, {1, 1}, {1, 0}, {2, 0}};
  CHECK(sorted(contacts(floor, gamma, kStepSearch)) ==
        std::vector<std::string>{"v1.4 on e0.2", "v1.5 on e0.2"});
}

TEST_CASE("a square in the notch of an L turned by 90 degrees: held by both walls",
          "[contact-geometry][concave]") {
  // The L turned by 90 degrees counter-clockwise about the origin ((x,y) -> (-y,x)):
  // v0 (0,0), v1 (0,2), v2 (-1,2), v3 (-1,1) reflex, v4 (-2,1), v5 (-2,0). Its notch
  // (x < -1, y > 1) has walls a.e2 (-1,2)->(-1,1), n (-1,0), and a.e3 (-1,1)->(-2,1), n (0,1).
  // b = [-1.5,-1] x [1,1.5]: its corner b.v1 (-1,1) sits in the notch's corner (a pair with
  // the reflex a.v3: both walls); b.v0 (-1.5,1) on the floor a.e3 at t = 0.5; b.v2 (-1,1.5)
  // on the wall a.e2 at t = 0.5. The rule does not depend on which way the notch faces.
  const Polygon l90 = {{0, 0}, {0, 2}, {-1, 2}, {-1, 1}, {-2, 1}, {-2, 0}};
  CHECK(sorted(contacts(l90, rectangle(-1.5, 1.0, 0.5, 0.5), kStepSearch)) ==
        std::vector<std::string>{"v1.0 on e0.3", "v1.1 on e0.2 (vv)", "v1.1 on e0.3 (vv)",
                                 "v1.2 on e0.2"});
}

TEST_CASE("face shares: a vertex carries half of the overlap of its face with the contact edge",
          "[contact-geometry]") {
  // What cohesion and tensile strength act on (Contact::length). The two contacts at the
  // ends of a common face carry it once between them.
  const auto length = [](const Polygon& p, int v, const Vec2& s, const Vec2& e) {
    const FaceShares f = face_shares(p, v, s, e);
    double l = 0.0;
    for (int k = 0; k < f.count; ++k) l += f.halves[static_cast<std::size_t>(k)].norm();
    return l;
  };
  // A 4 m box on a 10 m base (edge (5, 0) -> (-5, 0)): each base vertex half the face, 2 m.
  const Polygon box{{0, 0}, {4, 0}, {4, 1}, {0, 1}};
  CHECK_THAT(length(box, 0, {5, 0}, {-5, 0}), WithinAbs(2.0, kTol));
  CHECK_THAT(length(box, 1, {5, 0}, {-5, 0}), WithinAbs(2.0, kTol));
  // Running bond: a brick over [0.5, 1.5] on a brick of the course below over [0, 1] (its
  // top edge (1, 0) -> (0, 0)): they share [0.5, 1]. The upper brick's vertex at 0.5 and the
  // lower brick's at 1 carry a quarter metre each, half a metre in all, not half a brick
  // each (the former rule: a metre, twice the face they share).
  const Polygon upper{{0.5, 0}, {1.5, 0}, {1.5, 0.5}, {0.5, 0.5}};
  const Polygon lower{{0, -0.5}, {1, -0.5}, {1, 0}, {0, 0}};
  CHECK_THAT(length(upper, 0, {1, 0}, {0, 0}), WithinAbs(0.25, kTol));
  CHECK_THAT(length(lower, 2, {1.5, 0}, {0.5, 0}), WithinAbs(0.25, kTol));
  // The half next to the vertex, from where the overlap starts: water wets [0.5, 0.75].
  const FaceShares f = face_shares(upper, 0, {1, 0}, {0, 0});
  REQUIRE(f.count == 1);
  CHECK_THAT((f.from[0] - Vec2(0.5, 0)).norm(), WithinAbs(0.0, kTol));
  CHECK_THAT((f.from[0] + f.halves[0] - Vec2(0.75, 0)).norm(), WithinAbs(0.0, kTol));
  // Two cells of a mesh whose faces meet end to end on one line (the bottom triangles of
  // neighbouring cells, touching at (1, 0) only): no face in common, no share.
  const Polygon right_cell{{1, 0}, {2, 0}, {1.5, 0.5}};
  CHECK(face_shares(right_cell, 0, {1, 0}, {0, 0}).count == 0);
  // A vertex meeting the edge at an angle: a point contact.
  const Polygon wedge{{0, 0}, {1, 1}, {-1, 1}};
  CHECK(face_shares(wedge, 0, {5, 0}, {-5, 0}).count == 0);
}

TEST_CASE("a corner sliding across the joint of two fixed blocks meets the next top, not "
          "its covered side", "[contact][covered]") {
  // Two fixed unit squares side by side, their shared faces at x = 1; a block slides along
  // their top with its bottom face 1e-7 m below it (the penalty's penetration) and its
  // leading corner 1e-4 m before the joint. The right square's left face is covered by the
  // left square's right face (mark_covered_edges), so the corner's contact with the right
  // square is on its top edge (edge 2); unmarked, the least-penetration rule puts it on the
  // left face (edge 3), a step 1e-7 m high that stops the block.
  const Polygon left{{0.0, -1.0}, {1.0, -1.0}, {1.0, 0.0}, {0.0, 0.0}};
  const Polygon right{{1.0, -1.0}, {2.0, -1.0}, {2.0, 0.0}, {1.0, 0.0}};
  const double x1 = 1.0 - 1e-4, y0 = -1e-7;
  const Polygon slider{{x1 - 0.5, y0}, {x1, y0}, {x1, 0.5}, {x1 - 0.5, 0.5}};
  PolygonFeatures fl, fr, fs;
  polygon_features(left, fl);
  polygon_features(right, fr);
  polygon_features(slider, fs);
  const auto contacts_with_right = [&](const PolygonFeatures& f_right) {
    std::vector<ContactCandidate> out;
    find_contacts(right, f_right, 1, slider, fs, 2, 0.01, out);
    std::vector<int> edges;
    for (const ContactCandidate& c : out) {
      if (c.vertex_block == 2 && c.vertex == 1 && c.edge_block == 1) edges.push_back(c.edge);
    }
    return edges;
  };
  CHECK(contacts_with_right(fr) == std::vector<int>{3});  // the catch, unmarked
  mark_covered_edges(fl, 0, fr, 1, 0.0);
  CHECK(fr[3].covered_by == 0);   // the right square's left face
  CHECK(fl[1].covered_by == 1);   // the left square's right face
  CHECK(fr[2].covered_by == -1);
  CHECK(fl[2].covered_by == -1);
  CHECK(contacts_with_right(fr) == std::vector<int>{2});
  // The right square's corner at the joint pushes on no face of the slider parallel to its
  // covered side: not on the slider's front (edge 1); on its base, if at all (bearing).
  std::vector<ContactCandidate> out;
  find_contacts(right, fr, 1, slider, fs, 2, 0.01, out);
  for (const ContactCandidate& c : out) CHECK_FALSE((c.vertex_block == 1 && c.edge == 1));
  // The two squares' own contact across the covered faces is not affected: each face is
  // covered by the other, which it still meets.
  std::vector<ContactCandidate> between;
  find_contacts(left, fl, 0, right, fr, 1, 0.01, between);
  CHECK(between.size() >= 2);
}

TEST_CASE("a face covered only in part, or offset, stays a surface", "[contact][covered]") {
  // A taller right neighbour covers the left square's side whole; a shorter one covers it
  // only in part (the rest is a real face a block can meet); one 1e-3 m away does not touch.
  const Polygon left{{0.0, -1.0}, {1.0, -1.0}, {1.0, 0.0}, {0.0, 0.0}};
  const auto covered_side = [&](const Polygon& right) {
    PolygonFeatures fl, fr;
    polygon_features(left, fl);
    polygon_features(right, fr);
    mark_covered_edges(fl, 0, fr, 1, 0.0);
    return fl[1].covered_by == 1;
  };
  CHECK(covered_side({{1.0, -1.0}, {2.0, -1.0}, {2.0, 0.5}, {1.0, 0.5}}));
  CHECK_FALSE(covered_side({{1.0, -1.0}, {2.0, -1.0}, {2.0, -0.5}, {1.0, -0.5}}));
  CHECK_FALSE(covered_side({{1.001, -1.0}, {2.0, -1.0}, {2.0, 0.0}, {1.001, 0.0}}));
}

TEST_CASE("a cover between free blocks steers the vertex-pair rule but leaves diagonal "
          "neighbours their contact", "[contact][covered]") {
  // Four unit squares around the node (1, 0): A bottom left, B bottom right, C top left, D
  // top right, each touching its two neighbours face to face. C and B meet only at the
  // node. Covered firmly (all fixed: they never part), C's corner has no option left
  // against B; covered softly (free blocks, which may part), the pair keeps its contact:
  // once A and B part, C's corner meets B's top.
  const Polygon a{{0.0, -1.0}, {1.0, -1.0}, {1.0, 0.0}, {0.0, 0.0}};
  const Polygon b{{1.0, -1.0}, {2.0, -1.0}, {2.0, 0.0}, {1.0, 0.0}};
  const Polygon c{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  const Polygon d{{1.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 1.0}};
  const auto c_b_contacts = [&](bool firm) {
    std::vector<PolygonFeatures> f(4);
    const std::vector<const Polygon*> p{&a, &b, &c, &d};
    for (int i = 0; i < 4; ++i) polygon_features(*p[static_cast<std::size_t>(i)], f[static_cast<std::size_t>(i)]);
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 1}, {2, 3}, {0, 2}, {1, 3}}) {
      mark_covered_edges(f[static_cast<std::size_t>(i)], i, f[static_cast<std::size_t>(j)], j,
                         firm ? 0.0 : 1e-4, firm);
    }
    std::vector<ContactCandidate> out;
    find_contacts(b, f[1], 1, c, f[2], 2, 0.01, out);
    return out.size();
  };
  CHECK(c_b_contacts(true) == 0);
  CHECK(c_b_contacts(false) >= 1);
}

TEST_CASE("a cover between free blocks steers only among contacts that pass the wedge test",
          "[contact][covered]") {
  // The surface node (0, 0) of a crossed triangle mesh, its cells below y = 0: the left
  // cell's north and east triangles (LN, LE) and the right cell's west and north ones (RW,
  // RN), each sharing a face with the next. LN and RN meet at the node only, with LE and RW
  // between them, which cover every face of theirs at the node but the surface's. Each of
  // the pair's four options fails the wedge test (the two are not face to face). The
  // uncovered ones are the surface edges, end to end with the vertex's own: a support that
  // held the columns of a mesh against shearing past each other (verification/vertical-cut);
  // the pair must take what it takes without covers.
  const Polygon ln{{-0.5, -0.5}, {0.0, 0.0}, {-1.0, 0.0}};
  const Polygon le{{-0.5, -0.5}, {0.0, -1.0}, {0.0, 0.0}};
  const Polygon rw{{0.5, -0.5}, {0.0, 0.0}, {0.0, -1.0}};
  const Polygon rn{{0.5, -0.5}, {1.0, 0.0}, {0.0, 0.0}};
  const std::vector<const Polygon*> p{&ln, &le, &rw, &rn};
  const auto ln_rn = [&](bool cover) {
    std::vector<PolygonFeatures> f(4);
    for (int i = 0; i < 4; ++i) polygon_features(*p[static_cast<std::size_t>(i)], f[static_cast<std::size_t>(i)]);
    if (cover) {
      for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {2, 3}}) {
        mark_covered_edges(f[static_cast<std::size_t>(i)], i, f[static_cast<std::size_t>(j)], j, 1e-4, false);
      }
    }
    std::vector<ContactCandidate> out;
    find_contacts(ln, f[0], 0, rn, f[3], 3, 0.01, out);
    return out;
  };
  const std::vector<ContactCandidate> plain = ln_rn(false);
  const std::vector<ContactCandidate> covered = ln_rn(true);
  REQUIRE(plain.size() == covered.size());
  for (std::size_t k = 0; k < plain.size(); ++k) {
    CHECK(covered[k].vertex_block == plain[k].vertex_block);
    CHECK(covered[k].vertex == plain[k].vertex);
    CHECK(covered[k].edge == plain[k].edge);
  }
  // And none of them on a surface edge (LN's edge 1 from (0,0) to (-1,0), RN's edge 1
  // from (1,0) to (0,0)).
  for (const ContactCandidate& c : covered) {
    CHECK_FALSE((c.edge_block == 0 && c.edge == 1));
    CHECK_FALSE((c.edge_block == 3 && c.edge == 1));
  }
}
