// The block-frame treatments' area test (a block placed as xc + R U (X - Xc) has area
// A0 det U): a pinned L-shaped block (concave, so rotation and strain couple through its
// inertia) with an initial stress that sets it vibrating, swinging and spinning under
// gravity, 2000 steps of 0.005 s, the worst relative area error against A0 det(I + E^).
#pragma once

#include <algorithm>
#include <cmath>

#include "kinematics/point_maps.hpp"
#include "solver/configuration_update.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"
#include "support/scene_builders.hpp"

namespace dda::test {

struct AreaRun {
  bool diverged = false;
  double worst = 0.0;             // max |A - A0 det(I + E^)| / A0 over the steps
  double largest_strain = 0.0;    // max |E^| component: the test is not vacuous
  double largest_rotation = 0.0;  // max |r| (rad)
};

inline AreaRun pinned_l_block_area(RotationUpdate treatment, double energy_tolerance) {
  Scene s = base_scene(2000, 0.005);
  s.control.rotation_update = treatment;
  s.control.penalty = 1e10;
  s.control.energy_tolerance = energy_tolerance;
  s.blocks.push_back(block(l_shape()));
  s.blocks[0].initial_stress = Vec3(2e6, -1e6, 5e5);
  s.blocks[0].velocity = Vec3(0.0, 0.0, 2.0);
  s.pins.push_back(PinSpec{{0.25, 0.25}, 0});
  World world = make_world(s);
  const double a0 = world.blocks[0].initial_area;
  AreaRun out;
  const RunStats stats = run(world, [&](const World& w, const RunStats&) {
    const Block& b = w.blocks[0];
    // U = I + E^, E^ the Biot strain (finite_rotation_polar keeps ln U: stretch_strain).
    const Mat2 stretch = Mat2::Identity() + strain_tensor(stretch_strain(treatment, b));
    out.worst = std::max(out.worst, std::abs(b.moments.area - a0 * stretch.determinant()) / a0);
    out.largest_strain = std::max(out.largest_strain, b.local_strain.cwiseAbs().maxCoeff());
    out.largest_rotation = std::max(out.largest_rotation, std::abs(b.rotation));
    return true;
  });
  out.diverged = stats.diverged;
  return out;
}

}  // namespace dda::test
