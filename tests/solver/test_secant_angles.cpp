// finite_rotation's secant-angle iteration (solver/rotation/secant_angles.hpp): the tolerance a
// block is held to, free or in contact, against the secant's displacement error
// l |r0| |r0 - r*| / 2.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "support/scene_builders.hpp"
#include "solver/rotation/secant_angles.hpp"
#include "solver/world.hpp"

using namespace dda;

namespace {

// A 1 m square (block 1) on a fixed 4 m x 1 m floor (block 0): w0 = 2 m, so the strict
// tolerance is 2e-12 m; the square's corners are sqrt(1/2) m from its centroid.
World square_on_floor() {
  Scene s = test::base_scene(1, 0.01);
  BlockSpec floor = test::block(test::rectangle(-2.0, -1.0, 4.0, 1.0));
  floor.fixed = true;
  s.blocks.push_back(floor);
  s.blocks.push_back(test::block(test::rectangle(-0.5, 0.0, 1.0, 1.0)));
  return make_world(s);
}

Contact floor_contact(ContactMode mode, double allowance) {
  Contact c;
  c.key = {1, 0, 0, 2};  // the square's corner on the floor's top edge
  c.state.mode = mode;
  c.allowed_penetration = allowance;
  return c;
}

}  // namespace

TEST_CASE("the secant angle: a free block is held to 1e-12 of w0, a block in closed contact "
          "to 1e-3 of its contacts' allowance",
          "[finite-rotation][secant]") {
  World world = square_on_floor();
  REQUIRE(world.w0 == 2.0);
  const double l = std::sqrt(0.5);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(world.dof_count);
  // A rattle: r0 = 1e-4 where the step started from the last step's -1e-4. The secant's
  // error is l |r0| |r0 - r*| / 2 = 7.1e-9 m: above the strict 2e-12 m, below 1e-3 of an
  // allowance of 5e-5 m (5e-8 m).
  const double r0 = 1e-4;
  d[world.blocks[1].first_dof + kR0] = r0;
  const double error = 0.5 * l * r0 * 2.0 * r0;
  REQUIRE(error > kSecantDisplacementShare * world.w0);
  REQUIRE(error < kSecantContactShare * 5e-5);
  const auto moved = [&](const std::vector<Contact>& contacts) {
    std::vector<double> angles{0.0, -r0};
    const int n = follow_secant_angles(world, contacts, d, angles);
    CHECK(angles[1] == r0);  // the angle follows the solve either way
    return n;
  };
  CHECK(moved({}) == 1);                                         // free: one more solve
  CHECK(moved({floor_contact(ContactMode::Open, 5e-5)}) == 1);   // an open contact holds nothing
  CHECK(moved({floor_contact(ContactMode::Lock, 5e-5)}) == 0);   // in contact: done
  CHECK(moved({floor_contact(ContactMode::Slide, 5e-5)}) == 0);
  // The smallest allowance of the block's closed contacts rules: 1e-6 m makes it 1e-9 m.
  CHECK(moved({floor_contact(ContactMode::Lock, 5e-5), floor_contact(ContactMode::Lock, 1e-6)}) == 1);
  // A turn the contact tolerance does not cover: r0 = 1e-2 from -1e-2, 7.1e-5 m.
  d[world.blocks[1].first_dof + kR0] = 1e-2;
  std::vector<double> angles{0.0, -1e-2};
  CHECK(follow_secant_angles(world, {floor_contact(ContactMode::Lock, 5e-5)}, d, angles) == 1);
}
