// polygons_overlap (kinematics/overlap): hand-made pairs whose answer is plain from the
// drawing. Touching in every way (shared edge, part of an edge, a corner, a vertex on an
// edge, a square sitting in a concave notch) is not overlap; sharing interior is, including
// the cases a vertex-inside test alone misses (crossing bars, identical polygons, a square
// with its corners on another's sides, a "pinwheel" meeting only at vertices on edges).
// Every pair is checked both ways round, since the answer must not depend on the order.
//
// Tolerance: kTol = 1e-9 on shapes of size ~1, the reader's touching tolerance at that
// size. Every coordinate below is a small binary fraction or integer, exact in doubles, so
// touching cases touch exactly and overlapping ones overlap by >= 0.25: the answers do not
// hinge on kTol, except in the test that probes kTol itself.
#include <catch2/catch.hpp>
#include <cmath>

#include "kinematics/overlap.hpp"
#include "support/scene_builders.hpp"

namespace {

using dda::Polygon;
using dda::test::rectangle;

constexpr double kTol = 1e-9;

// The answer for (a, b) and (b, a); both must agree.
bool overlap(const Polygon& a, const Polygon& b, double tol = kTol) {
  const bool ab = dda::polygons_overlap(a, b, tol);
  const bool ba = dda::polygons_overlap(b, a, tol);
  CHECK(ab == ba);
  return ab && ba;
}

Polygon translated(Polygon p, double dx, double dy) {
  for (dda::Vec2& v : p) v += dda::Vec2(dx, dy);
  return p;
}

}  // namespace

TEST_CASE("blocks that touch do not overlap", "[overlap]") {
  const Polygon unit = rectangle(0, 0, 1, 1);
  SECTION("a whole shared edge") { CHECK_FALSE(overlap(unit, rectangle(1, 0, 1, 1))); }
  SECTION("part of an edge shared") { CHECK_FALSE(overlap(unit, rectangle(1, 0.5, 1, 1))); }
  SECTION("an edge inside a longer edge") {
    CHECK_FALSE(overlap(rectangle(0, 0, 4, 1), rectangle(1, 1, 2, 1)));
  }
  SECTION("corners touching") { CHECK_FALSE(overlap(unit, rectangle(1, 1, 1, 1))); }
  SECTION("a vertex on an edge") {
    // A triangle standing on its apex at the middle of the square's top.
    CHECK_FALSE(overlap(unit, Polygon{{0.5, 1}, {1, 2}, {0, 2}}));
  }
  SECTION("a vertex on a sloping edge") {
    // (1.5, 0.5) lies exactly on the hypotenuse from (0, 0) to (3, 1).
    const Polygon wedge{{0, 0}, {3, 0}, {3, 1}};
    CHECK_FALSE(overlap(wedge, Polygon{{1.5, 0.5}, {2, 2}, {0, 2}}));
  }
  SECTION("far apart") { CHECK_FALSE(overlap(unit, rectangle(5, 5, 1, 1))); }
  SECTION("two L-shapes interlocked, touching at two corners") {
    // L1 holds the bottom and left arms of [0,3]^2, L2 (L1 turned half a turn about (2, 2))
    // the top and right arms of [1,4]^2; they meet only at (3, 1) and (1, 3).
    const Polygon l1{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    const Polygon l2{{4, 4}, {1, 4}, {1, 3}, {3, 3}, {3, 1}, {4, 1}};
    CHECK_FALSE(overlap(l1, l2));
  }
}

TEST_CASE("a square in a concave notch touches, a wider one overlaps", "[overlap]") {
  // A U: the block [0,3] x [0,2] with the notch [1,2] x [1,2] cut out of its top. Its
  // bounding box holds the square, and the square's corners are the U's corners, so neither
  // a box test nor a convex-only test can tell this from overlap.
  const Polygon u{{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  CHECK_FALSE(overlap(u, rectangle(1, 1, 1, 1)));  // fills the notch exactly
  CHECK_FALSE(overlap(u, rectangle(1, 1, 1, 3)));  // fills it and sticks out above
  CHECK(overlap(u, rectangle(0.75, 1, 1.25, 1)));  // 0.25 into the left arm
  CHECK(overlap(u, rectangle(1, 0.75, 1, 1)));     // 0.25 into the floor
}

TEST_CASE("blocks that share interior overlap", "[overlap]") {
  const Polygon unit = rectangle(0, 0, 1, 1);
  SECTION("identical squares") { CHECK(overlap(unit, unit)); }
  SECTION("identical concave L-shapes") {
    CHECK(overlap(dda::test::l_shape(), dda::test::l_shape()));
  }
  SECTION("one strictly inside the other") {
    CHECK(overlap(unit, rectangle(0.25, 0.25, 0.5, 0.5)));
  }
  SECTION("a vertex of one inside the other") {
    CHECK(overlap(unit, rectangle(0.5, 0.5, 1, 1)));
  }
  SECTION("shifted along a shared edge line") {
    // Bottom and top edges coincide over [1, 2] with both interiors above / below them;
    // no edges cross and no vertex is inside the other.
    CHECK(overlap(rectangle(0, 0, 2, 1), rectangle(1, 0, 2, 1)));
  }
  SECTION("a bar across another (a plus sign)") {
    // Edges cross properly; no vertex of either is inside the other.
    CHECK(overlap(rectangle(0, 1, 3, 1), rectangle(1, 0, 1, 3)));
  }
  SECTION("crossing L-shapes") {
    // L1: bottom and left arms of [0,3]^2; L2: L1 turned half a turn about (1.5, 1.5), the
    // top and right arms. They share [2,3] x [0,1] and [0,1] x [2,3]; L2's inner edge
    // x = 2 crosses L1's inner edge y = 1 at (2, 1).
    const Polygon l1{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    const Polygon l2{{3, 3}, {0, 3}, {0, 2}, {2, 2}, {2, 0}, {3, 0}};
    CHECK(overlap(l1, l2));
  }
  SECTION("a diamond with its corners on the sides of a square") {
    // All contacts are vertices on edges: no crossing, no vertex strictly inside.
    CHECK(overlap(rectangle(0, 0, 2, 2), Polygon{{1, 0}, {2, 1}, {1, 2}, {0, 1}}));
  }
  SECTION("a pinwheel meeting only at vertices on edges") {
    // The two share exactly the unit square [0,1]^2. Its corners (0,0) and (1,1) are
    // vertices of `a` on edges of `b`, (1,0) and (0,1) vertices of `b` on edges of `a`;
    // each side of the square is a short part of a long edge whose midpoint lies outside
    // the other polygon. No edges cross, no vertex is strictly inside, and no edge midpoint
    // (nor a point just inside one) is inside the other: only cutting the edges at the
    // contact points finds this overlap.
    const Polygon a{{0, 0}, {10, 0}, {10, 2}, {1, 1}, {-10, 1}, {-10, -1}};
    const Polygon b{{1, 0}, {1, 10}, {-1, 10}, {0, 1}, {0, -10}, {2, -10}};
    CHECK(overlap(a, b));
  }
  SECTION("the same shapes far from the origin") {
    CHECK(overlap(translated(unit, 1e4, -1e4), translated(rectangle(0.5, 0, 1, 1), 1e4, -1e4)));
    CHECK_FALSE(overlap(translated(unit, 1e4, -1e4), translated(rectangle(1, 0, 1, 1), 1e4, -1e4)));
  }
}

TEST_CASE("overlaps up to the tolerance count as touching", "[overlap]") {
  // The right square reaches 2^-31 (4.7e-10) or 2^-26 (1.5e-8) into the unit square. 2^-31
  // is below kTol (1e-9), so it is touching; 2^-26 is 15 x kTol, so it is overlap. Powers of
  // two keep 1 - depth exact, so the depth is exactly what the test says.
  const Polygon unit = rectangle(0, 0, 1, 1);
  const double shallow = std::ldexp(1.0, -31);
  const double deep = std::ldexp(1.0, -26);
  CHECK_FALSE(overlap(unit, rectangle(1 - shallow, 0, 1, 1)));
  CHECK(overlap(unit, rectangle(1 - deep, 0, 1, 1)));
  // A gap of the same sizes is never overlap.
  CHECK_FALSE(overlap(unit, rectangle(1 + shallow, 0, 1, 1)));
  CHECK_FALSE(overlap(unit, rectangle(1 + deep, 0, 1, 1)));
}
