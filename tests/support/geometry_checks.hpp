// Exact-geometry checks shared by the contact room's tests (contact/test_narrow_phase.cpp,
// contact/test_broad_phase.cpp).
#pragma once

#include <catch2/catch.hpp>

#include "kinematics/types.hpp"

namespace dda::test {

// Every expected geometric value in those tests is O(1) and is computed by the code with a
// handful of flops (a difference, a square root, a division, a dot product): the round-off
// is a few ulps of 1 (~1e-16 each). 1e-14 (about 45 ulps) is far above that and far below
// any difference that would mean a wrong formula (the smallest hand-derived quantity checked
// is 1e-3).
constexpr double kTol = 1e-14;

// A point's two coordinates against hand-derived values, to kTol.
inline void check_vec(const Vec2& got, double x, double y) {
  CHECK_THAT(got.x(), Catch::Matchers::WithinAbs(x, kTol));
  CHECK_THAT(got.y(), Catch::Matchers::WithinAbs(y, kTol));
}

}  // namespace dda::test
