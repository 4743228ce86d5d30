// kinematics/frames: a strain seen from a turned frame, against the tensor rotation by hand.
#include <catch2/catch.hpp>
#include <cmath>

#include "kinematics/frames.hpp"

using namespace dda;
using Catch::Matchers::WithinAbs;

TEST_CASE("strain in a turned frame: the tensor rotation", "[kinematics]") {
  // A stretch along x seen from a frame turned by 90 degrees is a stretch along y'.
  const Vec3 e(1e-3, 0.0, 0.0);
  const Vec3 at90 = strain_in_turned_frame(e, M_PI / 2);
  CHECK_THAT(at90[0], WithinAbs(0.0, 1e-18));  // cos(pi) round-off times 1e-3
  CHECK_THAT(at90[1], WithinAbs(1e-3, 1e-18));
  CHECK_THAT(at90[2], WithinAbs(0.0, 1e-18));
  // At 45 degrees: e'x = e'y = 5e-4, g'xy = -(ex - ey) = -1e-3 (Mohr's circle).
  const Vec3 at45 = strain_in_turned_frame(e, M_PI / 4);
  CHECK_THAT(at45[0], WithinAbs(5e-4, 1e-18));
  CHECK_THAT(at45[1], WithinAbs(5e-4, 1e-18));
  CHECK_THAT(at45[2], WithinAbs(-1e-3, 1e-18));
  // Turning forth and back is the identity.
  const Vec3 g(3e-4, -1e-4, 2e-4);
  CHECK((strain_in_turned_frame(strain_in_turned_frame(g, 0.7), -0.7) - g).norm() <= 1e-19);
}

TEST_CASE("strain in a frame not turned at all is the strain itself, bit for bit", "[kinematics]") {
  const Vec3 g(1e-3, -2.5e-4, 3.3e-4);
  CHECK(strain_in_turned_frame(g, 0.0) == g);
}
