// kinematics/polygon: polygon integrals against hand-derived values, the sweep's simplicity
// verdict against the all-pairs reference, orientation and containment. (T and the mass
// matrix: test_block_matrices.cpp; frame rotations: test_frames.cpp.)
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>

#include "kinematics/polygon.hpp"
#include "support/scene_builders.hpp"

using namespace dda;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

// Exact polygon integration is a handful of flops per edge: round-off of a few ulps,
// so 1e-14 (relative to the quantity, or absolute for values that vanish) is ample.
constexpr double kRoundOff = 1e-14;

TEST_CASE("polygon moments: unit square", "[kinematics]") {
  const Moments m = polygon_moments(test::rectangle(0, 0, 1, 1));
  CHECK_THAT(m.area, WithinRel(1.0, kRoundOff));
  CHECK_THAT(m.centroid.x(), WithinRel(0.5, kRoundOff));
  CHECK_THAT(m.centroid.y(), WithinRel(0.5, kRoundOff));
  CHECK_THAT(m.sxx, WithinRel(1.0 / 12.0, kRoundOff));  // b h^3 / 12
  CHECK_THAT(m.syy, WithinRel(1.0 / 12.0, kRoundOff));
  CHECK_THAT(m.sxy, WithinAbs(0.0, kRoundOff));
}

TEST_CASE("polygon moments: right triangle with legs 3 and 6", "[kinematics]") {
  // Legs a = 3 along x, b = 6 along y: area ab/2 = 9, centroid (a/3, b/3) = (1, 2),
  // central moments A a^2/18 = 4.5, A b^2/18 = 18, product -a^2 b^2/72 = -4.5.
  const Moments m = polygon_moments({{0, 0}, {3, 0}, {0, 6}});
  CHECK_THAT(m.area, WithinRel(9.0, kRoundOff));
  CHECK_THAT(m.centroid.x(), WithinRel(1.0, kRoundOff));
  CHECK_THAT(m.centroid.y(), WithinRel(2.0, kRoundOff));
  CHECK_THAT(m.sxx, WithinRel(4.5, kRoundOff));
  CHECK_THAT(m.syy, WithinRel(18.0, kRoundOff));
  CHECK_THAT(m.sxy, WithinRel(-4.5, kRoundOff));
}

TEST_CASE("polygon moments: regular octagon", "[kinematics]") {
  // Circumradius R: area 2 sqrt(2) R^2; polar moment A R^2 (1 + 2 cos^2(pi/8)) / 6 split
  // equally between the axes by symmetry (docs/closed-forms.md, rigid pendulum).
  const double r = 0.5;  // the paper's octagon: diameter 1 m, area 0.707107 m^2
  const Moments m = polygon_moments(test::regular_polygon(8, r, {3.0, -2.0}, 0.3));
  const double area = 2.0 * std::sqrt(2.0) * r * r;
  const double c = std::cos(M_PI / 8.0);
  const double axis = area * r * r * (1.0 + 2.0 * c * c) / 12.0;
  CHECK_THAT(m.area, WithinRel(area, kRoundOff));
  CHECK_THAT(m.area, WithinRel(0.707107, 1e-6));  // the paper's printed value, 6 digits
  CHECK_THAT(m.centroid.x(), WithinRel(3.0, kRoundOff));
  CHECK_THAT(m.centroid.y(), WithinRel(-2.0, kRoundOff));
  CHECK_THAT(m.sxx, WithinRel(axis, 1e-13));  // trig round-off in the vertices
  CHECK_THAT(m.syy, WithinRel(axis, 1e-13));
  CHECK_THAT(m.sxy, WithinAbs(0.0, 1e-15));
}

TEST_CASE("polygon moments: concave L-shape", "[kinematics]") {
  // Two unit-height rectangles [0,2]x[0,1] and [0,1]x[1,2] (parallel-axis theorem by hand):
  // area 3, centroid (5/6, 5/6), sxx = syy = 11/12, sxy = -1/3.
  const Moments m = polygon_moments(test::l_shape());
  CHECK_THAT(m.area, WithinRel(3.0, kRoundOff));
  CHECK_THAT(m.centroid.x(), WithinRel(5.0 / 6.0, kRoundOff));
  CHECK_THAT(m.centroid.y(), WithinRel(5.0 / 6.0, kRoundOff));
  CHECK_THAT(m.sxx, WithinRel(11.0 / 12.0, kRoundOff));
  CHECK_THAT(m.syy, WithinRel(11.0 / 12.0, kRoundOff));
  CHECK_THAT(m.sxy, WithinRel(-1.0 / 3.0, kRoundOff));
}

TEST_CASE("the sweep's simplicity verdict is the all-pairs reference's on random and "
          "degenerate polygons",
          "[kinematics]") {
  // Vertices on a 5 x 5 integer grid: coordinates and orientations are exact, so shared
  // vertices, a vertex on another edge, collinear overlapping edges and zero-length edges all
  // occur often (about half the polygons are not simple), and the two paths must agree on
  // every one. Star-shaped polygons on a fine grid add simple ones with many vertices.
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> coordinate(0, 4), count(3, 12);
  int simple = 0, not_simple = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Polygon poly(static_cast<std::size_t>(count(rng)));
    for (Vec2& v : poly) v = Vec2(coordinate(rng), coordinate(rng));
    const bool reference = is_self_intersecting_reference(poly);
    INFO("trial " << trial);
    REQUIRE(is_self_intersecting(poly) == reference);
    (reference ? not_simple : simple) += 1;
  }
  std::uniform_real_distribution<double> radius(0.5, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    Polygon star(200);
    for (std::size_t k = 0; k < star.size(); ++k) {
      const double angle = 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(star.size());
      // Rounded to 1/64: neighbouring spokes may land on the same line or point.
      star[k] = (64.0 * radius(rng) * Vec2(std::cos(angle), std::sin(angle))).array().round() / 64.0;
    }
    if (trial % 2 == 1) std::swap(star[17], star[18 + trial % 50]);  // a crossing, mostly
    const bool reference = is_self_intersecting_reference(star);
    INFO("star " << trial);
    REQUIRE(is_self_intersecting(star) == reference);
    (reference ? not_simple : simple) += 1;
  }
  // Both verdicts were exercised many times.
  CHECK(simple > 1000);
  CHECK(not_simple > 1000);
}

TEST_CASE("first_crossing names the edges, and gives up past its pair budget", "[kinematics]") {
  const EdgeCrossing bow = first_crossing({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 1000);
  CHECK(bow.found);
  CHECK(bow.edge_a == 0);  // (0,0)-(1,1) crosses (1,0)-(0,1)
  CHECK(bow.edge_b == 2);
  // A comb: 40 teeth 9.5 m long on a spine 0.5 m wide. Every tooth's edges lie side by side
  // in x with every other's (about 160 x 160 / 2 pairs), so a budget of 100 is spent before
  // the sweep ends; with room enough it finds the comb simple.
  Polygon comb{{0.0, 0.0}};
  for (int t = 0; t < 40; ++t) {
    comb.push_back(Vec2(10.0, 2.0 * t));
    comb.push_back(Vec2(10.0, 2.0 * t + 1.0));
    if (t < 39) {
      comb.push_back(Vec2(0.5, 2.0 * t + 1.0));
      comb.push_back(Vec2(0.5, 2.0 * t + 2.0));
    }
  }
  comb.push_back(Vec2(0.0, 79.0));
  REQUIRE_FALSE(is_self_intersecting_reference(comb));
  const EdgeCrossing limited = first_crossing(comb, 100);
  CHECK(limited.too_intricate);
  CHECK_FALSE(limited.found);
  const EdgeCrossing enough = first_crossing(comb, 1'000'000);
  CHECK_FALSE(enough.too_intricate);
  CHECK_FALSE(enough.found);
}

TEST_CASE("polygon orientation, simplicity and containment", "[kinematics]") {
  Polygon ccw = test::l_shape();
  CHECK(signed_area(ccw) > 0.0);
  Polygon cw(ccw.rbegin(), ccw.rend());
  CHECK_THAT(signed_area(cw), WithinRel(-3.0, kRoundOff));
  CHECK_FALSE(is_self_intersecting(ccw));
  CHECK(is_self_intersecting({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));        // bow tie
  CHECK(is_self_intersecting({{0, 0}, {2, 0}, {1, 0}, {1, 1}}));        // edge folds back
  CHECK(is_self_intersecting({{0, 0}, {1, 0}, {1, 0}, {1, 1}}));        // repeated vertex
  CHECK(contains_point(ccw, {0.5, 1.5}));
  CHECK_FALSE(contains_point(ccw, {1.5, 1.5}));  // the notch of the L
  CHECK(contains_point(ccw, {2.0, 0.5}));        // on the boundary counts as inside
}
