// Scene energy totals against closed forms.
#include <catch2/catch.hpp>

#include "scene_builders.hpp"
#include "solver/energy.hpp"
#include "solver/world.hpp"

using namespace dda;
using Catch::Matchers::WithinRel;

TEST_CASE("scene energy of a moving, strained block", "[energy]") {
  Scene s = test::base_scene(1, 0.01);
  s.blocks.push_back(test::block(test::rectangle(1.0, 2.0, 2.0, 1.0)));  // 2 m x 1 m, centroid (2, 2.5)
  s.blocks[0].velocity = Vec3(1.0, -2.0, 3.0);
  BlockSpec fixed = test::block(test::rectangle(-5.0, -5.0, 1.0, 1.0));
  fixed.fixed = true;  // fixed blocks carry no energy
  s.blocks.push_back(fixed);
  World w = make_world(s);
  w.blocks[0].strain = Vec3(1e-3, -2e-3, 5e-4);
  const EnergyTotals e = scene_energy(w);
  const double m = 2700.0 * 2.0;
  const double inertia = m * (4.0 + 1.0) / 12.0;  // rectangle about its centroid: m (a^2 + b^2) / 12
  // Kinetic: 1/2 m v^2 + 1/2 I omega^2 (no strain rates); potential: -m g . xc; strain:
  // area/2 e^T D e with plane-strain D (E = 1 GPa, nu = 0.25: lambda = 0.4 GPa, G = 0.4 GPa).
  const double lambda = 0.4e9, g = 0.4e9;
  const double ex = 1e-3, ey = -2e-3, gxy = 5e-4;
  const double w_strain = 0.5 * lambda * (ex + ey) * (ex + ey) + g * (ex * ex + ey * ey) + 0.5 * g * gxy * gxy;
  // Round-off only (a few operations on O(1) values): 1e-13 relative.
  CHECK_THAT(e.kinetic, WithinRel(0.5 * m * 5.0 + 0.5 * inertia * 9.0, 1e-13));
  CHECK_THAT(e.potential, WithinRel(m * 9.81 * 2.5, 1e-13));
  CHECK_THAT(e.strain_energy, WithinRel(2.0 * w_strain, 1e-13));
}
